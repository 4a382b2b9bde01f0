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
