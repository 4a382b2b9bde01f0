"""Surface fairness analysis (issue 27): curvature on any face against closed forms and
against OCCT's own evaluation (getDN, Surface.curvature) with the sign convention applied;
continuity verdicts across edges checked with Part's normalAt and getDN; the curvature map
against the exact values. Referees never use the kernel's formulas."""
import math

import numpy as np
import pytest

import FreeCAD
import Part

import freecad_workbench as fw

V = FreeCAD.Vector
REL = 1e-10


def _grid(face, n=5):
    u0, u1, v0, v1 = face.ParameterRange
    u, v = np.meshgrid(u0 + (u1 - u0) * (np.arange(n) + 0.37) / n, v0 + (v1 - v0) * (np.arange(n) + 0.61) / n)
    return np.c_[u.ravel(), v.ravel()]


def _reversed(face):
    g = face.copy()
    g.reverse()
    return g


def _rho(p, centre=V(0, 0, 0), axis=V(0, 0, 1)):
    d = p - centre
    return (d - axis * d.dot(axis)).Length


# ---- closed forms: principal curvatures of a forward face (convex positive, outward normal)

def _sphere(p):
    return 1 / 2.5, 1 / 2.5


def _cylinder(p):
    return 1 / 1.5, 0.0


def _cone(p):  # across: cos(alpha) / rho, alpha the half-angle; along the generator: 0
    alpha = math.atan2(2.0 - 1.0, 3.0)
    return math.cos(alpha) / _rho(p), 0.0


def _torus(p):  # around the tube 1/r; around the axis cos(v) / rho with cos(v) = (rho - R) / r
    R, r = 4.0, 1.25
    rho = _rho(p)
    return 1 / r, (rho - R) / r / rho


ANALYTIC = {
    "sphere": (lambda: Part.makeSphere(2.5).Faces[0], _sphere),
    "cylinder": (lambda: Part.makeCylinder(1.5, 4).Faces[0], _cylinder),
    "cone": (lambda: Part.makeCone(2.0, 1.0, 3.0).Faces[0], _cone),
    "torus": (lambda: Part.makeTorus(4.0, 1.25).Faces[0], _torus),
}


@pytest.mark.parametrize("reverse", [False, True], ids=["forward", "reversed"])
@pytest.mark.parametrize("name", sorted(ANALYTIC))
def test_analytic_faces_match_closed_forms(name, reverse):
    make, closed_form = ANALYTIC[name]
    face = make()
    assert face.Orientation == "Forward"
    if reverse:
        face = _reversed(face)
    uv = _grid(face)
    c = fw.surface_curvature(face, uv)
    sign = -1.0 if reverse else 1.0
    for i, (u, v) in enumerate(uv):
        p = face.valueAt(u, v)
        a, b = (sign * k for k in closed_form(p))
        k1, k2 = max(a, b), min(a, b)
        scale = max(abs(k1), abs(k2))
        assert c.k1[i] == pytest.approx(k1, rel=REL, abs=REL * scale)
        assert c.k2[i] == pytest.approx(k2, rel=REL, abs=REL * scale)
        assert c.gaussian[i] == pytest.approx(k1 * k2, rel=REL, abs=REL * scale ** 2)
        assert c.mean[i] == pytest.approx((k1 + k2) / 2, rel=REL, abs=REL * scale)
        n = face.normalAt(u, v)
        assert np.allclose(c.normal[i], [n.x, n.y, n.z], atol=1e-12)
        assert np.allclose(c.points[i], [p.x, p.y, p.z], atol=1e-12)
        # Directions: unit, orthogonal, dir1 x dir2 = normal.
        assert np.allclose(np.cross(c.dir1[i], c.dir2[i]), c.normal[i], atol=1e-12)


def _referee_normal_curvature(face, u, v, d):
    """II(d, d) / I(d, d) from Part's getDN and Face.normalAt, convex positive as seen from the
    face normal (SURFACES.md): d a 3D tangent direction."""
    s = face.Surface
    su, sv = s.getDN(u, v, 1, 0), s.getDN(u, v, 0, 1)
    suu, suv, svv = s.getDN(u, v, 2, 0), s.getDN(u, v, 1, 1), s.getDN(u, v, 0, 2)
    n = face.normalAt(u, v)
    first = np.array([[su.dot(su), su.dot(sv)], [su.dot(sv), sv.dot(sv)]])
    second = -np.array([[suu.dot(n), suv.dot(n)], [suv.dot(n), svv.dot(n)]])
    d = V(*d)
    a = np.linalg.solve(first, [su.dot(d), sv.dot(d)])
    return a @ second @ a / (a @ first @ a)


def _bspline(rational, bezier=False):
    poles = [[V(i, j, 0.3 * math.sin(1.7 * i + 0.9 * j) + 0.1 * i * j) for j in range(4)] for i in range(4)]
    weights = [[1.0 + 0.2 * ((i + 2 * j) % 3) if rational else 1.0 for j in range(4)] for i in range(4)]
    if bezier:
        s = Part.BezierSurface()
        s.increase(3, 3)
        for i in range(4):
            for j in range(4):
                s.setPole(i + 1, j + 1, poles[i][j], weights[i][j])
        return s
    s = Part.BSplineSurface()
    s.buildFromPolesMultsKnots(poles, [4, 4], [4, 4], [0, 1], [0, 1], False, False, 3, 3, weights)
    return s


@pytest.mark.parametrize("reverse", [False, True], ids=["forward", "reversed"])
@pytest.mark.parametrize("kind", ["bspline", "rational", "bezier-rational"])
def test_freeform_faces_match_occt_with_the_sign_convention(kind, reverse):
    face = Part.Face(_bspline(kind != "bspline", kind.startswith("bezier")))
    if reverse:
        face = _reversed(face)
    uv = _grid(face, 6)
    c = fw.surface_curvature(face, uv)
    sign = 1.0 if reverse else -1.0  # OCCT: convex negative whatever the orientation (SURFACES.md)
    for i, (u, v) in enumerate(uv):
        a, b = sign * face.Surface.curvature(u, v, "Max"), sign * face.Surface.curvature(u, v, "Min")
        scale = max(abs(a), abs(b), 1e-3)
        assert c.k1[i] == pytest.approx(max(a, b), abs=1e-10 * scale)
        assert c.k2[i] == pytest.approx(min(a, b), abs=1e-10 * scale)
        assert _referee_normal_curvature(face, u, v, c.dir1[i]) == pytest.approx(c.k1[i], abs=1e-10 * scale)
        assert _referee_normal_curvature(face, u, v, c.dir2[i]) == pytest.approx(c.k2[i], abs=1e-10 * scale)


def test_offset_extrusion_revolution_and_trimmed_faces():
    sphere = Part.Sphere()
    sphere.Radius = 2.0
    offset = Part.OffsetSurface(sphere, 0.5).toShape()
    circle = Part.Circle(V(0, 0, 0), V(0, 0, 1), 3.0)
    extrusion = Part.SurfaceOfExtrusion(circle, V(0, 0, 1)).toShape(0, 6, -1, 2)
    line = Part.LineSegment(V(2, 0, 0), V(2, 0, 5))
    revolution = Part.SurfaceOfRevolution(line, V(0, 0, 0), V(0, 0, 1)).toShape()
    trimmed = Part.makeSphere(2.0).cut(Part.makeBox(4, 4, 4)).Faces
    trimmed = max(trimmed, key=lambda f: f.Area)
    for face, k in [(offset, 1 / 2.5), (trimmed, 1 / 2.0)]:
        c = fw.surface_curvature(face, _grid(face, 4))
        assert np.allclose(c.k1, k, rtol=REL) and np.allclose(c.k2, k, rtol=REL)
    for face, r in [(extrusion, 3.0), (revolution, 2.0)]:
        u0, u1, v0, v1 = face.ParameterRange
        uv = np.c_[np.linspace(u0, u1, 7)[:-1] + 0.1, np.full(6, 0.5 * (v0 + v1))]
        c = fw.surface_curvature(face, uv)
        for i, (u, v) in enumerate(uv):
            p, n = face.valueAt(u, v), face.normalAt(u, v)
            convex = np.sign(n.x * p.x + n.y * p.y)  # the normal points away from the axis
            k1, k2 = sorted([convex / r, 0.0], reverse=True)
            assert c.k1[i] == pytest.approx(k1, abs=REL / r) and c.k2[i] == pytest.approx(k2, abs=REL / r)


def test_umbilics_and_poles_are_finite():
    face = Part.makeSphere(3.0).Faces[0]
    c = fw.surface_curvature(face, [[1.0, math.pi / 2], [2.0, -math.pi / 2], [0.5, 0.2]])
    assert np.isfinite(np.c_[c.k1, c.k2, c.dir1, c.dir2, c.normal]).all()
    assert np.allclose(c.k1, 1 / 3, rtol=1e-8) and np.allclose(c.k2, 1 / 3, rtol=1e-8)
    assert list(c.degenerate) == [True, True, False] and c.umbilic[2]
    assert np.allclose(np.abs(c.normal[:2, 2]), 1.0, atol=1e-8)
    plane = Part.makePlane(2, 3).Faces[0]
    c = fw.surface_curvature(plane, [[0.5, 0.5]])
    assert c.umbilic[0] and c.k1[0] == 0 and c.k2[0] == 0
    assert np.allclose(np.cross(c.dir1[0], c.dir2[0]), c.normal[0])


def test_umbilic_of_a_freeform_face_is_finite():
    """The paraboloid z = x^2 + y^2 as a biquadratic Bezier patch: at its apex every direction
    is principal, with curvature 2 (OCCT's Surface.curvature as the referee, sign applied)."""
    a = [1.0, -1.0, 1.0]
    poles = [[V(-1 + i, -1 + j, a[i] + a[j]) for j in range(3)] for i in range(3)]
    s = Part.BSplineSurface()
    s.buildFromPolesMultsKnots(poles, [3, 3], [3, 3], [0, 1], [0, 1], False, False, 2, 2)
    face = Part.Face(s)
    c = fw.surface_curvature(face, [[0.5, 0.5], [0.5 + 1e-9, 0.5]])
    assert np.isfinite(np.c_[c.dir1, c.dir2, c.normal]).all() and c.umbilic[0]
    occt = -face.Surface.curvature(0.5, 0.5, "Max")
    assert abs(occt) == pytest.approx(2.0, rel=1e-12)
    assert c.k1 == pytest.approx([occt] * 2, rel=1e-8) and c.k2 == pytest.approx([occt] * 2, rel=1e-8)
    assert np.allclose(np.cross(c.dir1, c.dir2), c.normal, atol=1e-12)


def test_a_cone_apex_is_refused_naming_the_point():
    face = next(f for f in Part.makeCone(2.0, 0.0, 3.0).Faces if isinstance(f.Surface, Part.Cone))
    u0, u1, v0, v1 = face.ParameterRange
    apex = v1 if face.valueAt(0, v1).z > face.valueAt(0, v0).z else v0
    with pytest.raises(fw.InputError, match="point 1 .*singular"):
        fw.surface_curvature(face, [[0.3, 0.5 * (v0 + v1)], [0.3, apex]])


@pytest.mark.parametrize("uv, message", [
    ([[math.nan, 0.5]], "point 0 is not finite"),
    (np.zeros((3, 3)), "shape"),
    (np.zeros((0, 2)), "empty"),
    ([[1e6, 0.5]], "outside the face's parameter range"),
    ("uv", "array"),
])
def test_bad_uv_raises_input_error(uv, message):
    with pytest.raises(fw.InputError, match=message):
        fw.surface_curvature(Part.makeSphere(1.0).Faces[0], uv)


def test_bad_faces_raise_input_error():
    with pytest.raises(fw.InputError, match="2 faces"):
        fw.surface_curvature(Part.makeShell(Part.makeBox(1, 1, 1).Faces[:2]), [[0.5, 0.5]])
    with pytest.raises(fw.InputError, match="Part shape"):
        fw.surface_curvature(3.0, [[0.5, 0.5]])
    with pytest.raises(fw.InputError, match="null"):
        fw.surface_curvature(Part.Shape(), [[0.5, 0.5]])


def _multi_span_face():
    """A bicubic rational B-spline of 10 x 10 poles, 7 x 7 knot spans on non-uniform knots."""
    n = 10
    poles = [[V(i, j, 0.5 * math.sin(0.9 * i) * math.cos(0.7 * j) + 0.02 * i * j) for j in range(n)]
             for i in range(n)]
    weights = [[1.0 + 0.3 * ((i * j) % 4) / 3 for j in range(n)] for i in range(n)]
    knots = [0.0, 0.5, 1.5, 2.0, 3.2, 4.0, 5.5, 6.0]
    mults = [4] + [1] * (n - 4) + [4]
    s = Part.BSplineSurface()
    s.buildFromPolesMultsKnots(poles, mults, mults, knots, knots, False, False, 3, 3, weights)
    return Part.Face(s)


@pytest.mark.parametrize("reverse", [False, True], ids=["forward", "reversed"])
def test_results_are_views_of_one_block_and_match_occt(reverse):
    """The arrays are views of one float64 block the kernel wrote in place (no copies: numpy's
    memory), each of its documented shape, disjoint; and at scattered points over every span
    their values are OCCT's: Face.curvatureAt's pair (convex negative whatever the orientation,
    so times -1 on a forward face and +1 on a reversed one; its order differs between FreeCAD
    versions, so sorted), Surface.curvature's Gaussian, Face.normalAt, Face.valueAt, and
    Surface.curvatureDirections for Surface.curvature's "Max" and "Min"."""
    face = _multi_span_face()
    if reverse:
        face = _reversed(face)
    u0, u1, v0, v1 = face.ParameterRange
    rng = np.random.default_rng(5)
    n = 400
    uv = np.c_[rng.uniform(u0, u1, n), rng.uniform(v0, v1, n)]
    c = fw.surface_curvature(face, uv)
    arrays = {"k1": (n,), "k2": (n,), "gaussian": (n,), "mean": (n,),
              "dir1": (n, 3), "dir2": (n, 3), "normal": (n, 3), "points": (n, 3)}
    block = c.k1.base
    assert isinstance(block, np.ndarray) and block.dtype == np.float64 and block.size == 16 * n
    for name, shape in arrays.items():
        a = getattr(c, name)
        assert a.shape == shape and a.dtype == np.float64, name
        assert a.base is block, f"{name} is not a view of the block"
    names = list(arrays)
    for i, a in enumerate(names):
        for b in names[i + 1:]:
            assert not np.shares_memory(getattr(c, a), getattr(c, b)), (a, b)
    assert c.umbilic.shape == c.degenerate.shape == (n,) and c.umbilic.dtype == bool
    sign = 1.0 if reverse else -1.0
    for i, (u, v) in enumerate(uv):
        k1, k2 = sorted((sign * k for k in face.curvatureAt(u, v)), reverse=True)
        scale = max(abs(k1), abs(k2), 1e-3)
        assert c.k1[i] == pytest.approx(k1, abs=1e-10 * scale) and c.k2[i] == pytest.approx(k2, abs=1e-10 * scale)
        assert c.gaussian[i] == pytest.approx(face.Surface.curvature(u, v, "Gauss"), abs=1e-10 * scale ** 2)
        assert c.mean[i] == pytest.approx((k1 + k2) / 2, abs=1e-10 * scale)
        assert np.allclose(c.normal[i], face.normalAt(u, v), rtol=0, atol=1e-12)
        assert np.allclose(c.points[i], face.valueAt(u, v), rtol=0, atol=1e-12)
        if k1 - k2 > 1e-3 * scale:  # directions defined (away from umbilics), up to their sign
            d_max, d_min = face.Surface.curvatureDirections(u, v)  # for OCCT's "Max" and "Min"
            occt_max = sign * face.Surface.curvature(u, v, "Max")
            d1, d2 = (d_max, d_min) if occt_max == pytest.approx(k1, abs=1e-10 * scale) else (d_min, d_max)
            assert abs(np.dot(c.dir1[i], d1)) == pytest.approx(1.0, abs=1e-8)
            assert abs(np.dot(c.dir2[i], d2)) == pytest.approx(1.0, abs=1e-8)
        assert np.allclose(np.cross(c.dir1[i], c.dir2[i]), c.normal[i], atol=1e-12)
    # uv is read in place when C-ordered; other layouts (Fortran order, every other row, every
    # other column of a wider array) give the same values.
    for other in (np.asfortranarray(uv), np.repeat(uv, 2, axis=0)[::2], np.repeat(uv, 2, axis=1)[:, ::2]):
        assert not other.flags.c_contiguous
        o = fw.surface_curvature(face, other)
        assert np.array_equal(o.k1, c.k1) and np.array_equal(o.dir1, c.dir1) and np.array_equal(o.points, c.points)


def test_threads_give_the_same_bits_and_bad_counts_are_refused():
    """A call of 50,000 points (3 ranges of 16,384 points or more: threads share it past
    32,768) gives the same bits with one thread, three and the default; spot checks against
    Face.curvatureAt in the last range. A bad thread count is refused by name."""
    face = _multi_span_face()
    u0, u1, v0, v1 = face.ParameterRange
    rng = np.random.default_rng(11)
    n = 50000
    uv = np.c_[rng.uniform(u0, u1, n), rng.uniform(v0, v1, n)]
    one = fw.surface_curvature(face, uv, threads=1)
    for threads in (None, 3):
        other = fw.surface_curvature(face, uv, threads=threads)
        for name in ("k1", "k2", "gaussian", "mean", "dir1", "dir2", "normal", "points", "umbilic", "degenerate"):
            assert np.array_equal(getattr(other, name), getattr(one, name)), (threads, name)
    for i in range(n - 50, n):
        k1, k2 = sorted((-k for k in face.curvatureAt(*uv[i])), reverse=True)
        scale = max(abs(k1), abs(k2), 1e-3)
        assert one.k1[i] == pytest.approx(k1, abs=1e-10 * scale) and one.k2[i] == pytest.approx(k2, abs=1e-10 * scale)
    for bad in (0, -1, 1.5, "2", True):
        with pytest.raises(fw.InputError, match="threads"):
            fw.surface_curvature(face, uv[:10], threads=bad)


# ---- continuity across edges

def _face_of(shape, name):
    return shape.Faces[int(name[4:]) - 1]


def _shared(shape):
    records = [r for r in fw.edge_continuity(shape) if r.kind == "shared"]
    assert len(records) == 1
    return records[0]


def _pair(faces):
    shell = Part.makeShell(faces)
    shell.sewShape()
    assert len(shell.Faces) == 2
    return shell


def _surface(poles, u_knots, u_mults, v_knots, v_mults):
    s = Part.BSplineSurface()
    s.buildFromPolesMultsKnots(poles, u_mults, v_mults, u_knots, v_knots, False, False, 3, 3)
    return s


def _split_pair(u_mults):
    """A bicubic surface with an inner u-knot of multiplicity u_mults[1] (1: C2, 2: C1 only),
    cut into two faces there."""
    nu = sum(u_mults) - 4
    poles = [[V(i, j, 0.4 * math.sin(1.3 * i + 0.7 * j) + 0.05 * i * i * (j - 1.5)) for j in range(4)]
             for i in range(nu)]
    s = _surface(poles, [0, 0.5, 1], u_mults, [0, 1], [4, 4])
    halves = []
    for a, b in [(0, 0.5), (0.5, 1)]:
        h = s.copy()
        h.segment(a, b, 0, 1)
        halves.append(Part.Face(h))
    return _pair(halves)


def _referee_cross_jump(shape, record, n=101):
    """The largest jump of the normal curvature across the edge (n x T), from getDN, over the
    largest normal curvature (three directions) along it: the referee of curvature_jump."""
    edge = shape.Edges[int(record.edge[4:]) - 1]
    fa, fb = (_face_of(shape, name) for name in record.faces)
    jumps, scale = [], 0.0
    for t in np.linspace(edge.FirstParameter, edge.LastParameter, n)[1:-1]:
        p, tangent = edge.valueAt(t), edge.tangentAt(t)
        ka, kb = [], []
        for face, out in [(fa, ka), (fb, kb)]:
            u, v = face.Surface.parameter(p)
            n_ = face.normalAt(u, v)
            across = n_.cross(tangent) if face is fa else fa.normalAt(*fa.Surface.parameter(p)).cross(tangent)
            for d in (tangent, across):
                out.append(_referee_normal_curvature(face, u, v, d))
        jumps.append(abs(ka[1] - kb[1]))
        scale = max(scale, *map(abs, ka + kb))
    return max(jumps) / scale


def test_filleted_box_fillet_edges_are_g1_and_sharp_edges_g0_at_90_degrees():
    box = Part.makeBox(10, 10, 10)
    solid = box.makeFillet(2, [box.Edges[0], box.Edges[5]])
    records = fw.edge_continuity(solid)
    assert [r.edge for r in records] == [f"Edge{i + 1}" for i in range(len(solid.Edges))]
    seen = set()
    for r in records:
        edge = solid.Edges[int(r.edge[4:]) - 1]
        faces = [_face_of(solid, name) for name in r.faces]
        assert r.kind == "shared" and len(faces) == 2
        assert all(edge.isSame(e) for e in [edge]) and all(any(edge.isSame(e) for e in f.Edges) for f in faces)
        # Referee: the normals of both faces at the edge's middle (Part's normalAt).
        p = edge.valueAt(0.5 * (edge.FirstParameter + edge.LastParameter))
        na, nb = (f.normalAt(*f.Surface.parameter(p)) for f in faces)
        angle = math.degrees(na.getAngle(nb))
        fillet = any(isinstance(f.Surface, Part.Cylinder) for f in faces)
        if fillet and isinstance(edge.Curve, Part.Line):  # fillet to wall: tangent, curvature jumps
            assert angle < 1e-6
            assert r.continuity == "G1", r
            assert r.angle < 1e-6 and r.curvature_jump == pytest.approx(1.0, rel=1e-9)
            seen.add("G1")
        else:
            assert angle == pytest.approx(90.0, abs=1e-6)
            assert r.continuity == "G0", r
            assert r.angle == pytest.approx(90.0, abs=1e-9)
            seen.add("G0")
        assert r.gap < 1e-9
    assert seen == {"G0", "G1"}


def test_c1_but_not_c2_faces_are_g1():
    shell = _split_pair([4, 2, 4])
    r = _shared(shell)
    referee = _referee_cross_jump(shell, r)
    assert referee > 0.05  # the pair really is not G2
    assert r.continuity == "G1" and r.angle < 1e-6
    assert r.curvature_jump >= referee * (1 - 1e-9)


def test_curvature_matched_pair_split_at_a_knot_is_g2():
    shell = _split_pair([4, 1, 4])
    r = _shared(shell)
    assert _referee_cross_jump(shell, r) < 1e-9
    assert r.continuity == "G2" and r.curvature_jump < 1e-9 and r.angle < 1e-9


def test_planted_kink_of_half_a_degree_is_g0_with_its_angle():
    a = math.radians(0.5)
    left = Part.Face(Part.makePolygon([V(-1, 0, 0), V(0, 0, 0), V(0, 1, 0), V(-1, 1, 0), V(-1, 0, 0)]))
    right = Part.Face(Part.makePolygon([V(0, 0, 0), V(math.cos(a), 0, math.sin(a)), V(math.cos(a), 1, math.sin(a)),
                                        V(0, 1, 0), V(0, 0, 0)]))
    r = _shared(_pair([left, right]))
    assert r.continuity == "G0"
    assert r.angle == pytest.approx(0.5, abs=1e-3)


def _defect_pair():
    """Two bicubic faces sharing the edge x = 0; the right one's cross tangent turns only for
    v in [0.52, 0.56] (one pole moved), between the 17 samples a uniform sampling would take."""
    v_knots, v_mults = [0, 0.25, 0.52, 0.53, 0.54, 0.55, 0.56, 0.75, 1], [4, 1, 1, 1, 1, 1, 1, 1, 4]
    nv = sum(v_mults) - 4
    ys = [sum(v_knots_flat[j + 1:j + 4]) / 3 for v_knots_flat in [_flat(v_knots, v_mults)] for j in range(nv)]
    left = [[V(-1 + i / 3, y, 0) for y in ys] for i in range(4)]
    right = [[V(i / 3, y, 0) for y in ys] for i in range(4)]
    bump = next(j for j in range(nv) if _flat(v_knots, v_mults)[j] >= 0.52)
    right[1][bump] = V(1 / 3, ys[bump], 0.02)
    faces = [Part.Face(_surface(p, [0, 1], [4, 4], v_knots, v_mults)) for p in (left, right)]
    return _pair(faces)


def _flat(knots, mults):
    return [k for k, m in zip(knots, mults) for _ in range(m)]


def test_a_defect_between_uniform_samples_is_found():
    shell = _defect_pair()
    r = _shared(shell)
    fa, fb = (_face_of(shell, name) for name in r.faces)
    edge = shell.Edges[int(r.edge[4:]) - 1]

    def angle_at(t):
        p = edge.valueAt(t)
        return math.degrees(fa.normalAt(*fa.Surface.parameter(p)).getAngle(fb.normalAt(*fb.Surface.parameter(p))))

    t0, t1 = edge.FirstParameter, edge.LastParameter
    dense = max(angle_at(t) for t in np.linspace(t0, t1, 4001))
    uniform = max(angle_at(t) for t in np.linspace(t0, t1, 17))
    assert dense > 1.0 and uniform < 0.1 * dense  # the defect hides between uniform samples
    assert r.continuity == "G0"
    assert r.angle == pytest.approx(dense, rel=1e-5)
    assert 0.52 < r.angle_point.y < 0.56


def test_our_c2_blend_is_g2_across_every_interior_edge():
    zone = fw.shapes.SphereZone((0, 0, 0), 2.0, [0.0, 1.5, 3.0, 2 * math.pi], [-0.5, 0.2, 0.7])
    shell = fw.blend_basic_shape(zone).shell
    records = fw.edge_continuity(shell)
    interior = [r for r in records if r.kind in ("shared", "seam")]
    assert len(interior) > 10
    for r in interior:
        assert r.continuity == "G2", r
    assert {r.kind for r in records} <= {"shared", "seam", "boundary"}
    assert any(r.kind == "boundary" for r in records)


def test_faces_oriented_against_each_other_are_compared_the_right_way_round():
    shell = _split_pair([4, 1, 4])
    a, b = shell.Faces
    b.reverse()  # this face only, still sharing the edge (Part.Shell would turn it back)
    flipped = Part.Compound([a, b])
    assert [f.Orientation for f in flipped.Faces] == ["Forward", "Reversed"]
    r = _shared(flipped)
    assert r.continuity == "G2" and r.angle < 1e-9 and r.curvature_jump < 1e-9


def test_cylinder_seam_is_compared_with_itself_and_box_edges_have_two_faces():
    records = fw.edge_continuity(Part.makeCylinder(1.0, 2.0))
    seams = [r for r in records if r.kind == "seam"]
    assert len(seams) == 1 and seams[0].continuity == "G2" and len(seams[0].faces) == 1
    assert [r.continuity for r in records if r.kind == "shared"] == ["G0", "G0"]
    open_face = fw.edge_continuity(Part.makePlane(1, 1))
    assert {r.continuity for r in open_face} == {"boundary"}
    loose = fw.edge_continuity(Part.Compound([Part.makePlane(1, 1), Part.makeLine(V(5, 0, 0), V(6, 0, 0))]))
    assert [r.kind for r in loose].count("free") == 1 and loose[-1].faces == []


def test_tolerances_decide_the_verdict_and_bad_ones_are_refused():
    shell = _split_pair([4, 2, 4])
    r = _shared(shell)
    assert fw.edge_continuity(shell, curvature_tolerance=2 * r.curvature_jump)[0].continuity in ("G2", "boundary")
    assert _shared_of(fw.edge_continuity(shell, curvature_tolerance=2 * r.curvature_jump)).continuity == "G2"
    assert _shared_of(fw.edge_continuity(shell, gap_tolerance=0, angle_tolerance=0)).continuity in ("gap", "G0")
    for bad in [dict(angle_tolerance=-1), dict(samples=0), dict(gap_tolerance=math.nan), dict(samples="x")]:
        with pytest.raises(fw.InputError):
            fw.edge_continuity(shell, **bad)
    with pytest.raises(fw.InputError, match="no edges"):
        fw.edge_continuity(Part.Vertex(0, 0, 0))


def _shared_of(records):
    return next(r for r in records if r.kind == "shared")


# ---- the curvature map

def _outward(m):
    """> 0 for a triangle counter-clockwise seen from the side away from the origin."""
    a, b, c = (m.points[m.triangles[:, i]] for i in range(3))
    return np.einsum("ij,ij->i", np.cross(b - a, c - a), a + b + c)


def _edge_jumps(m):
    values = m.values[m.triangles]
    return np.abs(values - np.roll(values, 1, axis=1)).max()


def test_curvature_map_of_a_sphere_is_exact_and_faces_outward():
    m = fw.curvature_map(Part.makeSphere(2.0), "mean")
    assert np.allclose(m.values, 0.5, rtol=1e-9)
    assert np.allclose(np.linalg.norm(m.points, axis=1), 2.0, rtol=1e-9)
    outward = _outward(m)
    assert outward.min() > -1e-12 and (outward > 0).mean() > 0.95
    reversed_sphere = _reversed(Part.makeSphere(2.0).Faces[0])
    assert np.allclose(fw.curvature_map(reversed_sphere, "max").values, -0.5, rtol=1e-9)


def test_curvature_map_values_are_exact_and_refined_where_they_change_fast():
    R, r = 4.0, 1.25
    torus = Part.makeTorus(R, r)
    coarse = fw.curvature_map(torus, "gaussian", levels=0)
    fine = fw.curvature_map(torus, "gaussian", fraction=0.05, levels=3)
    rho = np.hypot(fine.points[:, 0], fine.points[:, 1])
    cos_v = (rho - R) / r
    assert np.allclose(fine.values, cos_v / (r * (R + r * cos_v)), atol=1e-9)
    lo, hi = fine.values.min(), fine.values.max()
    assert lo == pytest.approx(-1 / (r * (R - r)), rel=1e-3) and hi == pytest.approx(1 / (r * (R + r)), rel=1e-3)
    assert len(fine.triangles) > len(coarse.triangles)
    a, b, c = (fine.points[fine.triangles[:, i]] for i in range(3))
    g = (a + b + c) / 3
    centre = np.c_[g[:, :2] * (R / np.hypot(g[:, 0], g[:, 1]))[:, None], np.zeros(len(g))]  # the tube's axis
    assert (np.einsum("ij,ij->i", np.cross(b - a, c - a), g - centre) > 0).all()  # split triangles face outward
    assert _edge_jumps(coarse) > 0.05 * (hi - lo) >= _edge_jumps(fine)
    assert fine.face_ranges.tolist() == [[fine.values.min(), fine.values.max()]] and set(fine.face) == {1}


def test_curvature_map_normals_are_each_faces_own_exact_normal():
    """The map's normals (zebra on any shape reflects them) are OCCT's Face.normalAt at the
    vertex (to 1e-6 rad), face orientation included (a solid's reversed faces point out), on planes,
    cylinders, tori and a reversed B-spline face; a cone's apex gets a finite unit normal."""
    box = Part.makeBox(10, 8, 6)
    solid = box.makeFillet(1.5, box.Edges)
    patch = _reversed(Part.makeSphere(3.0, V(20, 0, 0)).Faces[0].toNurbs().Faces[0])
    shape = Part.Compound([solid, patch])  # Part.makeCompound of these crashes FreeCAD 1.1
    faces = shape.Faces
    assert any(f.Orientation == "Reversed" for f in faces)
    m = fw.curvature_map(shape, "mean")
    assert m.normals.shape == m.points.shape
    np.testing.assert_allclose(np.linalg.norm(m.normals, axis=1), 1.0, atol=1e-12)
    face_of_point = np.zeros(len(m.points), dtype=int)
    face_of_point[m.triangles.ravel()] = np.repeat(m.face, 3)
    checked = 0
    for i in np.random.default_rng(5).choice(len(m.points), 300, replace=False):
        face = faces[face_of_point[i] - 1]
        u, v = face.Surface.parameter(V(*m.points[i]))
        expected = np.array(tuple(face.normalAt(u, v)))
        # 1e-6 rad: at a sphere's pole the normal is the limit from 1e-7 inside (2e-7 rad off).
        assert np.dot(m.normals[i], expected) > math.cos(1e-6), (face_of_point[i], m.points[i], m.normals[i], expected)
        checked += 1
    assert checked == 300
    outward = np.einsum("ij,ij->i", m.normals[face_of_point == len(faces)],
                        m.points[face_of_point == len(faces)] - np.array([20.0, 0, 0]))
    assert (outward < 0).all()  # the reversed sphere patch's normals point inwards
    cone = fw.curvature_map(Part.makeCone(2.0, 0.0, 3.0), "max_abs")
    np.testing.assert_allclose(np.linalg.norm(cone.normals, axis=1), 1.0, atol=1e-12)


def test_curvature_map_radius_on_a_filleted_box_and_a_cone_apex_is_finite():
    box = Part.makeBox(10, 10, 10)
    solid = box.makeFillet(0.5, box.Edges[:4])
    m = fw.curvature_map(solid, "radius")
    size = solid.BoundBox.DiagonalLength  # the cap of flat faces is 1000 times the size, to OCCT's box margin
    for i, face in enumerate(solid.Faces):
        if isinstance(face.Surface, Part.Cylinder):
            assert m.face_ranges[i] == pytest.approx([0.5, 0.5], rel=1e-9)
        elif isinstance(face.Surface, Part.Plane):
            assert m.face_ranges[i] == pytest.approx([1e3 * size, 1e3 * size], rel=1e-6)
    cone = fw.curvature_map(Part.makeCone(2.0, 0.0, 3.0), "max_abs")
    assert np.isfinite(cone.values).all() and cone.values.max() < 1e3


@pytest.mark.parametrize("kwargs, message", [
    (dict(quantity="curvy"), "quantity"),
    (dict(deflection=-1.0), "deflection"),
    (dict(deflection=1e-12), "deflection"),
    (dict(levels=9), "levels"),
    (dict(fraction=2.0), "fraction"),
])
def test_curvature_map_bad_arguments_raise_input_error(kwargs, message):
    with pytest.raises(fw.InputError, match=message):
        fw.curvature_map(Part.makeSphere(1.0), **kwargs)
