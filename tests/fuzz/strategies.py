"""Hypothesis strategies for the macro API: numbers at the edges of float64, point lists
with duplicates, collinear runs and wrong shapes, Part geometry valid and not, and wrong
types for every parameter. Part objects are built lazily (FreeCAD is imported by the
conftest before these strategies draw)."""
import functools
import math

import numpy as np
from hypothesis import strategies as st

SPECIAL = [0.0, -0.0, 1.0, -1.0, 0.5, 2.0, 3.0, math.pi, 1e-9, 1e-300, 1e-308, 5e-324, -5e-324,
           1e9, 1e300, 1e308, -1e308, float("inf"), float("-inf"), float("nan")]

# Values of the wrong type for any parameter.
junk = st.sampled_from([None, "x", "", b"1", [], {}, (), object(), complex(1, 1), [[1, 2], [3]],
                        {"a": 1}, np.zeros((2, 2, 2)), np.array(["a", "b"]), float, len])

numbers = st.one_of(st.sampled_from(SPECIAL),
                    st.floats(allow_nan=True, allow_infinity=True),
                    st.floats(-10, 10),
                    st.integers(-5, 5))
# 1e12 and -1e12: coordinates far from the origin for a shape of size 1 (issue 26: faces BRepCheck
# called not valid were returned as success).
finite = st.one_of(st.sampled_from([0.0, 1.0, -1.0, 0.5, 2.0, 1e-9, 1e6, 1e12, -1e12, 1e-300, 1e300]),
                   st.floats(-100, 100))


def maybe_junk(strategy, junk_weight=1):
    """The strategy, or now and then a wrong-typed value."""
    return st.one_of(*([strategy] * 4), *([junk] * junk_weight))


number_arg = st.one_of(finite, finite, maybe_junk(numbers))
small_int = st.one_of(st.integers(-3, 40), st.sampled_from([0, 1, 2, 10 ** 6, 2 ** 31, 2 ** 63, -2 ** 31]))
count_arg = st.one_of(small_int, numbers, junk)
flag_arg = st.one_of(st.booleans(), st.booleans(), st.booleans(),
                     st.sampled_from([0, 1, 2, None, "yes", "", float("nan")]))


def choice_arg(*valid):
    """Mostly a valid choice (so that the other arguments get through), else a wrong one."""
    good = st.sampled_from(valid)
    return st.one_of(good, good, good, good, st.sampled_from([None, "", "nope", 1, valid[0].upper(), b"x"]), junk)


# ---- points and vectors ------------------------------------------------------------------
coord = st.one_of(*([finite] * 20), numbers)  # mostly finite: a list of points is then often valid


def _point(dim):
    return st.tuples(*([coord] * dim))


point2 = _point(2)
point3 = _point(3)


@st.composite
def point_lists(draw):
    kinds = ["2d", "3d"] * 6 + ["dup", "collinear", "mixed", "ragged", "empty",
                                "one", "array", "badarray", "strings", "nested", "vectors", "tiny", "huge"]
    kind = draw(st.sampled_from(kinds))
    if kind in ("2d", "3d"):
        return draw(st.lists(point2 if kind == "2d" else point3, min_size=draw(st.sampled_from([0, 3, 3, 3])),
                             max_size=12))
    if kind == "dup":
        p = draw(point3)
        base = draw(st.lists(point3, min_size=1, max_size=5))
        return base + [p] * draw(st.integers(2, 5)) + base[:1]
    if kind == "collinear":
        a, b = np.array(draw(point3)), np.array(draw(point3))
        n = draw(st.integers(2, 8))
        return [tuple(a + t * b) for t in np.linspace(0, 1, n)]
    if kind == "mixed":
        return [draw(point2), draw(point3), draw(point2)]
    if kind == "ragged":
        return [(0, 0), (1, 2, 3, 4), (1,)]
    if kind == "empty":
        return draw(st.sampled_from([[], (), np.zeros((0, 3)), np.zeros((0, 2)), np.zeros(0)]))
    if kind == "one":
        return [draw(point3)]
    if kind == "array":
        n, d = draw(st.integers(0, 10)), draw(st.sampled_from([2, 3]))
        return np.array([[draw(coord) for _ in range(d)] for _ in range(n)]).reshape(n, d)
    if kind == "badarray":
        return draw(st.sampled_from([np.zeros((4, 4)), np.zeros((3, 1)), np.zeros(6), np.zeros((2, 3, 3)),
                                     np.arange(9).reshape(3, 3).T, np.ones((4, 3), dtype=np.int32),
                                     np.ones((4, 3), dtype=np.float32), np.ones((4, 3), dtype=complex)]))
    if kind == "strings":
        return draw(st.sampled_from(["abc", ["ab", "cd", "ef"], [("a", 1, 2)], [None, None, None], [1, 2, 3]]))
    if kind == "nested":
        return [[[0, 0, 0]], [[1, 1, 1]], [[2, 0, 0]]]
    if kind == "vectors":
        import FreeCAD

        return [FreeCAD.Vector(*draw(point3)) for _ in range(draw(st.integers(0, 6)))]
    if kind == "tiny":
        return [(i * 5e-324, (i % 2) * 5e-324, 0.0) for i in range(5)]
    return [(i * 1e307, (i % 2) * 1e307, 0.0) for i in range(5)]


points_arg = st.one_of(point_lists(), point_lists(), point_lists(), junk)
_good = st.floats(-100, 100, allow_nan=False)
good_points = st.one_of(st.lists(st.tuples(_good, _good), min_size=3, max_size=12, unique=True),
                        st.lists(st.tuples(_good, _good, _good), min_size=3, max_size=12, unique=True))
good_vector = st.tuples(_good, _good)


@st.composite
def _freecad_vector(draw):
    import FreeCAD

    return FreeCAD.Vector(*draw(st.tuples(finite, finite, finite)))


vector_arg = st.one_of(point3, point3, point3, point3, point2, point2, _freecad_vector(),
                       st.sampled_from([(0, 0, 0), (1, 0, 0), (0, 0, 1), (0, 1, 0, 1), (1,), (), "abc", [None, 1, 2]]),
                       junk)
planar_vector = st.one_of(st.tuples(finite, finite), st.tuples(finite, finite, st.just(0.0)), vector_arg)
parameters_arg = st.one_of(st.none(), st.lists(numbers, max_size=12), junk)
angle_list = st.one_of(
    st.lists(finite, min_size=0, max_size=8).map(sorted),
    st.lists(st.floats(0, 2 * math.pi), min_size=2, max_size=6).map(sorted),
    st.lists(numbers, max_size=6),
    st.sampled_from([[0, 0, 1], [0, 2 * math.pi], [0, 1, 0.5], list(np.linspace(0, 2 * math.pi, 5000)),
                     [0, 1e-300, 2e-300], [0, math.pi, 2 * math.pi, 3 * math.pi], "abc", [None, 1]]),
    junk)


# ---- Part geometry -----------------------------------------------------------------------
@functools.lru_cache(maxsize=None)
def sample_curves():
    """Part curves and shapes, valid and not: the curve arguments draw from these."""
    import FreeCAD
    import Part

    V = FreeCAD.Vector
    out = []
    bs = Part.BSplineCurve()
    bs.interpolate([V(0, 0, 0), V(1, 1, 0), V(2, 0, 0), V(3, 1, 0), V(4, 0, 0)])
    out.append(bs)
    out.append(bs.toShape())
    flat = Part.BSplineCurve()
    flat.buildFromPolesMultsKnots([V(0, 0, 0), V(1, 0, 0), V(2, 0, 0), V(3, 0, 0)], [4, 4], [0, 1], False, 3)
    out.append(flat)  # a straight B-spline
    point = Part.BSplineCurve()
    point.buildFromPolesMultsKnots([V(1, 1, 0)] * 4, [4, 4], [0, 1], False, 3)
    out.append(point)  # all poles equal: no tangent anywhere
    huge = Part.BSplineCurve()
    huge.buildFromPolesMultsKnots([V(0, 0, 0), V(1e300, 0, 0), V(1e300, 1e300, 0), V(0, 1e300, 0)], [4, 4], [0, 1],
                                  False, 3)
    out.append(huge)
    tiny = Part.BSplineCurve()
    tiny.buildFromPolesMultsKnots([V(0, 0, 0), V(1e-300, 0, 0), V(1e-300, 1e-300, 0), V(0, 2e-300, 0)], [4, 4],
                                  [0, 1], False, 3)
    out.append(tiny)
    far = bs.copy()
    far.translate(V(1e12, 0, 0))
    out.append(far)  # 1e12 from the origin, 4 long (issue 26: revolve_profile made a face BRepCheck refused)
    rational = Part.BSplineCurve()
    rational.buildFromPolesMultsKnots([V(1, 0, 0), V(1, 1, 0), V(0, 1, 0)], [3, 3], [0, 1], False, 2, [1, 0.7071, 1])
    out.append(rational)
    spatial = Part.BSplineCurve()
    spatial.interpolate([V(0, 0, 0), V(1, 0, 1), V(1, 1, 2), V(0, 1, 3)])
    out.append(spatial)
    periodic = Part.BSplineCurve()
    periodic.interpolate([V(1, 0, 0), V(0, 1, 0), V(-1, 0, 0), V(0, -1, 0)], PeriodicFlag=True)
    out.append(periodic)
    out.append(Part.LineSegment(V(0, 0, 0), V(1, 2, 0)))
    out.append(Part.Line(V(0, 0, 0), V(1, 0, 0)))  # unbounded
    out.append(Part.Circle(V(0, 0, 0), V(0, 0, 1), 2))
    out.append(Part.ArcOfCircle(Part.Circle(V(0, 0, 0), V(0, 0, 1), 2), 0.2, 2.0))
    out.append(Part.ArcOfCircle(Part.Circle(V(0, 0, 0), V(0, 0, 1), 2), 0.2, 2.0).toShape())
    out.append(Part.ArcOfEllipse(Part.Ellipse(V(0, 0, 0), 3, 1), 0.1, 1.5))
    out.append(Part.ArcOfParabola(Part.Parabola(), -1, 1))
    out.append(Part.ArcOfHyperbola(Part.Hyperbola(), -1, 1))
    out.append(Part.Parabola())  # unbounded
    bez = Part.BezierCurve()
    bez.setPoles([V(0, 0, 0), V(1, 2, 0), V(3, 2, 0), V(4, 0, 0)])
    out.append(bez)
    out.append(Part.makePolygon([V(0, 0, 0), V(1, 0, 0), V(1, 1, 0)]))  # two edges
    out.append(Part.Vertex(V(1, 2, 3)))
    out.append(Part.Shape())  # null
    out.append(Part.makeBox(1, 1, 1))
    return tuple(out)


curve_arg = st.one_of(st.integers(0, 100).map(lambda i: sample_curves()[i % len(sample_curves())]), junk)


# ---- basic curves and shapes -------------------------------------------------------------
BASIC_SAMPLES = {  # class name -> keyword arguments of a valid instance
    "LineSegment": dict(start=(0, 0, 0), end=(1, 2, 0)),
    "CircleArc": dict(center=(0, 0, 0), radius=2.0, start_angle=0.1, end_angle=2.0),
    "EllipseArc": dict(center=(1, 0, 0), major_radius=3.0, minor_radius=1.0, start=0.2, end=1.5),
    "ParabolaArc": dict(vertex=(0, 0, 0), focal=1.0, t0=-1.0, t1=1.5),
    "HyperbolaArc": dict(center=(0, 0, 0), major_radius=1.0, minor_radius=2.0, t0=-1.0, t1=1.0),
    "RationalCubic": dict(poles=[(0, 0, 0), (1, 1, 0), (2, 1, 0), (3, 0, 0)], weights=[1, 2, 2, 1]),
    # Issue 26: OCCT has no curvature where the weight 1e12 pulls the curve (CurvatureNotDefined escaped).
    "RationalCubic heavy": dict(poles=[(0, 0, 0), (1, 0, 0)], weights=[3.965, 1e12]),
    "ArchimedeanSpiral": dict(),
    "CircleInvolute": dict(radius=1.0, t0=0.0, t1=2.0),
    "ParametricCurve": dict(function=lambda s: (s, s * s, 0.0), s0=0.0, s1=1.0),
}


def basic_instance(name):
    import freecad_workbench as fw

    return getattr(fw.basic, name.split()[0])(**BASIC_SAMPLES[name])


basic_curve = st.sampled_from(sorted(BASIC_SAMPLES)).map(basic_instance)

SAMPLES_SAMPLES = {  # valid fw.basic.Samples arguments: the pieces of the unifying spline
    "spiral": [(t / 6.28 * math.cos(t), t / 6.28 * math.sin(t)) for t in (1.6, 2.2, 2.9, 3.7, 4.6, 5.5, 6.28)],
    "arc 3D": [(math.cos(a), math.sin(a), 0.1 * a) for a in (0.0, 0.3, 0.7, 1.2)],
    "collinear": [(0, 0), (1, 1), (2, 2)],
    "zigzag": [(0, 0), (1, 1), (2, 0), (3, 1), (4, 0)],
}


def samples_instance(name):
    import freecad_workbench as fw

    return fw.basic.Samples(SAMPLES_SAMPLES[name])


samples_piece = st.sampled_from(sorted(SAMPLES_SAMPLES)).map(samples_instance)

_LONGITUDES = [0, 1, 2.5, 4, 2 * math.pi]
SHAPE_SAMPLES = {  # a fresh valid shape each draw (set_control edits it)
    "SphereZone": lambda fw: fw.shapes.SphereZone((0, 0, 0), 10, _LONGITUDES, [-0.5, 0.2, 0.7]),
    "dome": lambda fw: fw.shapes.SphereZone((0, 0, 3), 1, _LONGITUDES, [0.2, 0.9, math.pi / 2]),
    "Cylinder": lambda fw: fw.shapes.Cylinder((0, 0, 0), 1, _LONGITUDES, [0, 1, 2]),
    "Cone": lambda fw: fw.shapes.Cone((0, 0, 0), 1, 0.2, [0, 1, 2], [0, 1]),
    "Torus": lambda fw: fw.shapes.Torus((0, 0, 0), 3, 1, [0, 2, 4, 2 * math.pi], [0, 1, 2]),
    "Cylinder partial": lambda fw: fw.shapes.Cylinder((0, 0, 0), 1, [0, 1, 2], [0, 1, 2]),
    # Issue 26: far from the origin, and of denormal size (faces BRepCheck refused were returned).
    "SphereZone far": lambda fw: fw.shapes.SphereZone((1e12, 0, 0), 10, _LONGITUDES, [-0.5, 0.2, 0.7]),
    "Torus far": lambda fw: fw.shapes.Torus((0, 0, 1e12), 3, 1, [0, 2, 4, 2 * math.pi], [0, 1, 2]),
    "Cylinder far": lambda fw: fw.shapes.Cylinder((1e12, 1e12, 0), 1, _LONGITUDES, [0, 1, 2]),
    "Cone tiny": lambda fw: fw.shapes.Cone((0, 0, 0), 5e-324, 0.2, [0, 1, 2], [0, 1]),
    "SphereZone tiny": lambda fw: fw.shapes.SphereZone((0, 0, 0), 5e-324, _LONGITUDES, [-0.5, 0.2, 0.7]),
    # Issue 32: every basic shape the blending paper names.
    "Paraboloid": lambda fw: fw.shapes.Paraboloid((0, 0, 0), 1.0, [0.5, 1.0, 2.0], _LONGITUDES),
    "Hyperboloid": lambda fw: fw.shapes.Hyperboloid((0, 0, 0), 1.0, 2.0, [-1.0, 0.0, 1.0], _LONGITUDES),
    "Hyperboloid two sheets": lambda fw: fw.shapes.Hyperboloid((0, 0, 0), 1.0, 1.0, [1.5, 2.0, 3.0], _LONGITUDES,
                                                               sheets=2),
    "Ellipsoid": lambda fw: fw.shapes.Ellipsoid((0, 0, 0), (3.0, 2.0, 1.0), _LONGITUDES, [-0.5, 0.2, 0.7]),
    "HyperbolicCylinder": lambda fw: fw.shapes.HyperbolicCylinder((0, 0, 0), 1.0, 2.0, [-0.6, 0.0, 0.6], [0, 1, 2]),
    "DupinCyclide": lambda fw: fw.shapes.DupinCyclide((0, 0, 0), 5.0, 1.0, 2.0, [0, 2, 4, 2 * math.pi], [0, 1, 2]),
}


def shape_instance(name):
    import freecad_workbench as fw

    return SHAPE_SAMPLES[name](fw)


def revolution_profile(name):
    """A profile for fw.shapes.Revolution in the xz plane: a parabola arc off the z axis
    ("parabola"), or a line crossing it ("crossing", refused)."""
    import FreeCAD
    import Part

    if name == "crossing":
        return Part.LineSegment(FreeCAD.Vector(-1, 0, 0), FreeCAD.Vector(1, 0, 1)).toBSpline()
    curve = Part.BSplineCurve()
    curve.buildFromPolesMultsKnots([FreeCAD.Vector(1, 0, 0.25), FreeCAD.Vector(1.5, 0, 0.5),
                                    FreeCAD.Vector(2, 0, 1)], [3, 3], [0.0, 1.0], False, 2)
    return curve


shape = st.sampled_from(sorted(SHAPE_SAMPLES)).map(shape_instance)
shape_arg = st.one_of(shape, shape, shape, basic_curve, junk)


@functools.lru_cache(maxsize=None)
def sample_surfaces():
    import FreeCAD
    import Part

    plane = Part.BSplineSurface()
    plane.buildFromPolesMultsKnots([[FreeCAD.Vector(i, j, 0) for j in range(2)] for i in range(2)],
                                   [2, 2], [2, 2], [0, 1], [0, 1], False, False, 1, 1)
    return (plane, Part.Face(plane), Part.makeBox(1, 1, 1), Part.Plane())


freeform_arg = st.one_of(st.none(), st.none(), st.integers(0, 3).map(lambda i: sample_surfaces()[i]), junk)


@functools.lru_cache(maxsize=None)
def analysis_shapes():
    """Shapes of every kind of face for the surface analysis: analytic, filleted, freeform."""
    import Part

    box = Part.makeBox(3, 2, 1)
    return [Part.makeSphere(2.0), box, box.makeFillet(0.4, [box.Edges[0]]), Part.makeCone(2, 0, 3),
            Part.makeTorus(3, 1), Part.makeCylinder(1, 2), Part.makePlane(1e-6, 1e-6), Part.makeSphere(1e150)]


analysis_shape = st.integers(0, 7).map(lambda i: analysis_shapes()[i])
analysis_face = analysis_shape.map(lambda s: s.Faces[0])


@functools.lru_cache(maxsize=None)
def blend_sides():
    """(face, edge) pairs for face blends: cylinder rims, a box's faces (sharing edges: faces that
    touch), a sphere (degenerate poles, seam), a cone and a plane at a distance."""
    import FreeCAD
    import Part

    cylinder = Part.makeCylinder(1, 1).Faces[0]
    far = Part.makeCylinder(1.4, 1, FreeCAD.Vector(0.2, 0, 2)).Faces[0]
    box = Part.makeBox(1, 1, 1)
    sphere = Part.makeSphere(1, FreeCAD.Vector(0, 0, -3)).Faces[0]
    cone = Part.makeCone(1, 0.5, 1, FreeCAD.Vector(0, 0, 4)).Faces[0]
    plane = Part.makePlane(2, 2, FreeCAD.Vector(-1, -1, 6))
    faces = [cylinder, far, box.Faces[0], box.Faces[2], sphere, cone, plane]
    return [(f, i + 1) for f in faces for i in range(len(f.Edges))]


blend_side = st.integers(0, 10 ** 6).map(lambda i: blend_sides()[i % len(blend_sides())])
