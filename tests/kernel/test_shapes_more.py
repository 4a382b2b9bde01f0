"""Every basic shape the blending paper names (issue 32): surfaces of revolution of a designed
profile, quadrics (paraboloids, hyperboloids, ellipsoids as affine images), through the macro
API, judged by OCCT evaluation of the returned Part geometry: implicit equations at dense
samples (1e-12 relative), second derivatives across every knot of the single surface."""
import math

import numpy as np
import pytest

import freecad_workbench as fw
import FreeCAD
import Part

NON_UNIFORM = [0.0, 0.4, 1.5, 2.1, 3.9, 4.3, 5.2, 2 * math.pi]
CENTER = np.array([1.0, -2.0, 0.5])
AXIS = np.array([0.3, -0.2, 1.0]) / np.linalg.norm([0.3, -0.2, 1.0])


def samples(surface, n=9):
    u0, u1, v0, v1 = surface.bounds()
    for a in np.linspace(u0, u1, n):
        for b in np.linspace(v0, v1, n):
            p = surface.value(a, b)
            yield np.array([p.x, p.y, p.z])


def radial(p, center=CENTER, axis=AXIS):
    d = p - center
    z = d @ axis
    return np.linalg.norm(d - z * axis), z


def basic(result):
    return [s for role, s in result.patches if role == "basic"]


def knot_jump(surface):
    """Largest jump of the first and second derivatives across every interior knot line of a
    single B-spline surface, both ways: the surface cut at the neighbouring knots (Part
    segment, same parameters) and evaluated at the knot from each side (getDN), relative to
    the surface's own derivative scale."""
    u0, u1, v0, v1 = surface.bounds()
    scale = max(max(surface.getDN(a, b, 2, 0).Length, surface.getDN(a, b, 0, 2).Length,
                    surface.getDN(a, b, 1, 0).Length, surface.getDN(a, b, 0, 1).Length)
                for a in np.linspace(u0, u1, 7) for b in np.linspace(v0, v1, 7))
    worst = 0.0
    for direction, knots in (("u", surface.getUKnots()), ("v", surface.getVKnots())):
        for i in range(1, len(knots) - 1):
            left, right = surface.copy(), surface.copy()
            if direction == "u":
                left.segment(knots[i - 1], knots[i], v0, v1)
                right.segment(knots[i], knots[i + 1], v0, v1)
                points = [(knots[i], b) for b in np.linspace(v0, v1, 5)]
                orders = ((1, 0), (2, 0), (1, 1))
            else:
                left.segment(u0, u1, knots[i - 1], knots[i])
                right.segment(u0, u1, knots[i], knots[i + 1])
                points = [(a, knots[i]) for a in np.linspace(u0, u1, 5)]
                orders = ((0, 1), (0, 2), (1, 1))
            for a, b in points:
                for du, dv in orders:
                    worst = max(worst, (right.getDN(a, b, du, dv) - left.getDN(a, b, du, dv)).Length / scale)
    return worst


def on_paraboloid(points, focal):
    return max(abs(z - r * r / (4 * focal)) / (abs(z) + r * r / (4 * focal)) for r, z in points)


def test_parabola_profile_revolves_to_a_paraboloid_exactly_and_blends_c2():
    paraboloid = fw.shapes.Paraboloid(CENTER, 0.7, [0.5, 0.9, 1.6, 2.2], NON_UNIFORM, axis=AXIS)
    assert len(paraboloid.patches()) == 7 * 3
    assert on_paraboloid([radial(p) for s in paraboloid.patches() for p in samples(s)], 0.7) < 1e-12
    result = fw.blend_basic_shape(paraboloid, at="end")
    assert on_paraboloid([radial(p) for s in basic(result) for p in samples(s, 6)], 0.7) < 1e-12
    assert result.surface is not None and result.surface.Continuity == "C2"
    assert knot_jump(result.surface) < 1e-9
    assert result.shell.isValid()


@pytest.mark.parametrize("sheets", [1, 2])
def test_hyperboloids_of_revolution_are_exact(sheets):
    a, c = 1.2, 0.8
    heights = [-0.9, 0.1, 0.6, 1.4] if sheets == 1 else [1.0, 1.3, 2.0]
    shape = fw.shapes.Hyperboloid(CENTER, a, c, heights, NON_UNIFORM, sheets=sheets, axis=AXIS)
    sign = 1 if sheets == 1 else -1
    worst = max(abs(sign * (r * r / a ** 2 - z * z / c ** 2) - 1) / (r * r / a ** 2 + z * z / c ** 2)
                for s in shape.patches() for r, z in (radial(p) for p in samples(s)))
    assert worst < 1e-12
    result = fw.blend_basic_shape(shape, at="end")
    assert result.surface.Continuity == "C2"
    assert knot_jump(result.surface) < 1e-9


def test_ellipsoid_is_the_affine_image_of_the_sphere_and_blends_c2():
    radii = (3.0, 2.0, 1.25)
    x_axis = np.array([1.0, 0.4, 0.0])
    ellipsoid = fw.shapes.Ellipsoid(CENTER, radii, NON_UNIFORM, [-0.6, 0.1, 0.5, 0.8], axis=AXIS, x_axis=x_axis)
    x = x_axis - (x_axis @ AXIS) * AXIS
    x /= np.linalg.norm(x)
    frame = np.column_stack([x, np.cross(AXIS, x), AXIS])

    def implicit(p):
        q = frame.T @ (p - CENTER)
        return abs(sum((q / radii) ** 2) - 1)

    assert max(implicit(p) for s in ellipsoid.patches() for p in samples(s)) < 1e-12
    result = fw.blend_basic_shape(ellipsoid)
    assert max(implicit(p) for s in basic(result) for p in samples(s, 6)) < 1e-12
    assert result.surface.Continuity == "C2"
    assert knot_jump(result.surface) < 1e-9
    assert result.shell.isValid()
    # Commutation: the blend of the image is the image of the sphere's blend, pole by pole.
    sphere = fw.blend_basic_shape(fw.shapes.SphereZone((0, 0, 0), 1.0, NON_UNIFORM, [-0.6, 0.1, 0.5, 0.8]))
    matrix = frame @ np.diag(radii)
    for (_, s), (_, t) in zip(sphere.patches, result.patches):
        mapped = np.array([[matrix @ [p.x, p.y, p.z] + CENTER for p in row] for row in s.getPoles()])
        poles = np.array([[[p.x, p.y, p.z] for p in row] for row in t.getPoles()])
        assert np.abs(mapped - poles).max() < 1e-12 * 4
    # A C1 blend and the naive baseline go through the same map.
    assert fw.blend_basic_shape(ellipsoid, continuity="C1").surface is not None
    assert fw.blend_naive(ellipsoid).surface is None


def _design_profile():
    """A line, an arc and an ellipse arc in the plane y = 0 (x > 0), designed into one C2
    cubic NURBS (the csr paper's Fig. 9) with the details of its exact ranges."""
    plane = dict(normal=(0, -1, 0), x_axis=(1, 0, 0))  # in-plane coordinates (x, z)
    marks = list(np.arange(1, 8) / 8)
    line = fw.basic.LineSegment((1, 0, 0), (1, 0, 1))
    arc = fw.basic.CircleArc((2, 0, 1), 1.0, math.pi, math.pi / 2, **plane)
    ellipse = fw.basic.EllipseArc((2, 0, 1.5), 1.5, 0.5, math.pi / 2, 0.0, **plane)
    design = fw.design_spline([(line, marks), (arc, marks), (ellipse, marks)], details=True)

    def line_error(r, z):
        return abs(r - 1)

    def arc_error(r, z):
        return abs(math.hypot(r - 2, z - 1) - 1)

    def ellipse_error(r, z):
        return abs(((r - 2) / 1.5) ** 2 + ((z - 1.5) / 0.5) ** 2 - 1)

    exact = []
    for k, ((t0, scale), u) in enumerate(zip(design.ranges, design.marks)):
        lo = u[0] if k == 0 else u[2]
        hi = u[-1] if k == 2 else u[-3]
        exact.append((t0 + scale * lo, t0 + scale * hi, (line_error, arc_error, ellipse_error)[k]))
    return design.curve, exact


def test_designed_profile_revolved_and_blended_keeps_each_conic_piece_exact(tmp_path):
    curve, exact = _design_profile()
    angles = [0.0, 1.0, 2.2, 3.0, 4.5, 2 * math.pi]
    shape = fw.shapes.Revolution(curve, (0, 0, 0), (0, 0, 1), angles)
    knots = shape.profile.knots
    rows = len(knots) - 1
    result = fw.blend_basic_shape(shape, at="end")
    assert result.surface.Continuity == "C2"
    assert knot_jump(result.surface) < 1e-9
    assert result.shell.isValid()
    patches = basic(result)
    assert len(patches) % rows == 0
    checked = {0: 0, 1: 0, 2: 0}
    for j in range(rows):
        for k, (t0, t1, error) in enumerate(exact):
            if knots[j] >= t0 - 1e-12 and knots[j + 1] <= t1 + 1e-12:
                for s in patches[j::rows]:
                    worst = max(error(*radial(p, np.zeros(3), np.array([0.0, 0, 1]))) for p in samples(s, 5))
                    assert worst < 1e-12, (j, k, worst)
                checked[k] += 1
    assert all(n >= 2 for n in checked.values()), checked
    # save, reopen and recompute: identical poles
    path = str(tmp_path / "revolution.brep")
    result.shell.exportBrep(path)
    back = Part.read(path)
    assert all(a.Surface.getPoles() == b.Surface.getPoles() for a, b in zip(result.shell.Faces, back.Faces))
    again = fw.blend_basic_shape(fw.shapes.Revolution(curve, (0, 0, 0), (0, 0, 1), angles), at="end")
    assert all(a.getPoles() == b.getPoles() and a.getWeights() == b.getWeights()
               for (_, a), (_, b) in zip(result.patches, again.patches))


def test_revolution_everywhere_the_other_shapes_go():
    curve, _ = _design_profile()
    shape = fw.shapes.Revolution(curve, (0, 0, 0), (0, 0, 1), [0.0, 1.0, 2.2, 3.0, 4.5, 2 * math.pi])
    c1 = fw.blend_basic_shape(shape, continuity="C1", at="end")
    assert c1.surface is not None and c1.shell.isValid()
    sigma = fw.blend_basic_shape(shape, method="sigma", at="end")
    assert sigma.surface.Continuity == "C2"
    assert fw.blend_naive(shape, at="end").surface is None
    # a cylinder below it, a dome above: both joins in one chain
    below = fw.shapes.Cylinder((0, 0, 0), 1.0, [0.0, 1.0, 2.2, 3.0, 4.5, 2 * math.pi], [-1.0, -0.3])
    chain = fw.blend_chain([below, shape], end="default")
    assert chain.surface.Continuity == "C2" and chain.shell.isValid()
    joined = fw.join_basic_shapes(below, shape)
    assert joined.surface.Continuity == "C2"


def test_g2_profile_join_is_made_c2_and_stays_exact():
    # Two circle pieces of eq. (2) with different openings: G2, not C2 in homogeneous space
    # (a knot of multiplicity 3). Section 4.1 reparameterizes the right piece (Appendix 7.2
    # generalised): the sextic rows are C2 and both pieces stay on the circle.
    poles, weights = [], []
    for t0, t1 in ((-0.5, 0.1), (0.1, 0.9)):
        a = t1 - t0
        m = np.array([math.cos((t0 + t1) / 2), math.sin((t0 + t1) / 2)]) / math.cos(a / 2)
        b0, b3 = np.array([math.cos(t0), math.sin(t0)]), np.array([math.cos(t1), math.sin(t1)])
        c = math.cos(a / 2)
        inner = [(b0 + 2 * c * m) / (1 + 2 * c), (2 * c * m + b3) / (1 + 2 * c)]
        w = 1 / 3 + 2 / 3 * c
        pts = ([b0] if not poles else []) + inner + [b3]
        poles += [FreeCAD.Vector(2 * p[0], 0, 2 * p[1]) for p in pts]
        weights += ([1.0] if len(weights) == 0 else []) + [w, w, 1.0]
    curve = Part.BSplineCurve()
    curve.buildFromPolesMultsKnots(poles, [4, 3, 4], [0.0, 1.0, 2.5], False, 3, weights)  # beta = 1.5
    shape = fw.shapes.Revolution(curve, (0, 0, 0), (0, 0, 1), NON_UNIFORM)
    assert max(abs(np.linalg.norm(p) - 2) for s in shape.patches() for p in samples(s)) < 1e-12
    result = fw.blend_basic_shape(shape, at="end")
    assert result.surface is not None and result.surface.Continuity == "C2"
    assert knot_jump(result.surface) < 1e-9
    # Section 4.1 with the generalised transition map keeps both conic pieces exact
    assert max(abs(np.linalg.norm(p) - 2) / 2 for s in basic(result) for p in samples(s, 6)) < 1e-12


def test_bad_profiles_and_quadrics_raise_input_error():
    def bspline(points, degree=3):
        curve = Part.BSplineCurve()
        curve.buildFromPolesMultsKnots([FreeCAD.Vector(*p) for p in points], [degree + 1, degree + 1], [0.0, 1.0],
                                       False, degree)
        return curve

    with pytest.raises(fw.InputError, match="crosses the axis"):
        fw.shapes.Revolution(bspline([(1, 0, 0), (-1, 0, 1), (-1, 0, 2), (1, 0, 3)]), (0, 0, 0), (0, 0, 1),
                             NON_UNIFORM)
    with pytest.raises(fw.InputError, match="touches or crosses the axis"):
        fw.shapes.Revolution(bspline([(1, 0, 0), (0, 0, 1)], 1), (0, 0, 0), (0, 0, 1), NON_UNIFORM)
    with pytest.raises(fw.InputError, match="degree 5"):
        fw.shapes.Revolution(bspline([(1, 0, z) for z in range(6)], 5), (0, 0, 0), (0, 0, 1), NON_UNIFORM)
    with pytest.raises(fw.InputError, match="not in a plane through the axis"):
        fw.shapes.Revolution(bspline([(1, 0, 0), (1, 1, 1), (2, 0, 2), (1, 0, 3)]), (0, 0, 0), (0, 0, 1),
                             NON_UNIFORM)
    with pytest.raises(fw.InputError, match="finite"):
        fw.shapes.Revolution(bspline([(1, 0, 0), (2, 0, 1)], 1), (0, 0, 0), (0, 0, float("nan")), NON_UNIFORM)
    with pytest.raises(fw.InputError, match="degenerate quadric: focal"):
        fw.shapes.Paraboloid(CENTER, 0.0, [0.5, 1.0], NON_UNIFORM)
    with pytest.raises(fw.InputError, match="degenerate quadric: radius b"):
        fw.shapes.Ellipsoid(CENTER, (1.0, 0.0, 2.0), NON_UNIFORM, [0.0, 0.5])
    with pytest.raises(fw.InputError, match="heights must all be greater than"):
        fw.shapes.Hyperboloid(CENTER, 1.0, 1.0, [0.5, 2.0], NON_UNIFORM, sheets=2)


def _cyclide_implicit(p, a, c, mu, center=CENTER, frame=np.eye(3)):
    x, y, z = frame.T @ (p - center)
    b2 = a * a - c * c
    lhs = (x * x + y * y + z * z - mu * mu + b2) ** 2
    rhs = 4 * (a * x - c * mu) ** 2 + 4 * b2 * y * y
    return abs(lhs - rhs) / (lhs + rhs)


def test_dupin_cyclide_is_exact_g2_and_blends_c2_into_its_ring():
    a, c, mu = 3.0, 1.0, 2.0
    angles_v = [-1.2, -0.4, 0.5, 1.1]
    cyclide = fw.shapes.DupinCyclide(CENTER, a, c, mu, NON_UNIFORM, angles_v)
    patches = cyclide.patches()
    assert len(patches) == 7 * 3
    assert max(_cyclide_implicit(p, a, c, mu) for s in patches for p in samples(s)) < 1e-12
    # G2 across the seams around u: the same point, normal and principal curvatures on both sides
    nv = 3
    worst = 0.0
    for i in range(7):
        left, right = patches[((i - 1) % 7) * nv], patches[i * nv]
        for v in np.linspace(0, 1, 5):
            kl, kr = left.curvature(1.0, v, "Mean"), right.curvature(0.0, v, "Mean")
            gl, gr = left.curvature(1.0, v, "Gauss"), right.curvature(0.0, v, "Gauss")
            worst = max(worst, abs(kl - kr), abs(gl - gr), (left.value(1.0, v) - right.value(0.0, v)).Length)
    assert worst < 1e-9
    result = fw.blend_basic_shape(cyclide)
    assert max(_cyclide_implicit(p, a, c, mu) for s in basic(result) for p in samples(s, 6)) < 1e-12
    assert result.surface.Continuity == "C2"
    assert knot_jump(result.surface) < 1e-9
    assert result.shell.isValid()
    with pytest.raises(fw.InputError, match="not a surface of revolution"):
        fw.blend_basic_shape(cyclide, continuity="C1")
    # The naive baseline of Fig. 2a to the same ring: the cyclide's own G2 patches, exact; a
    # valid shell; no single C2 surface (the arcs differ).
    naive = fw.blend_naive(cyclide)
    assert naive.surface is None and naive.shell.isValid()
    assert [role for role, _ in naive.patches].count("transition") == 7
    assert max(_cyclide_implicit(p, a, c, mu) for s in basic(naive) for p in samples(s, 6)) < 1e-12
    assert [role for role, _ in naive.patches].count("freeform") == 7  # the ring on the sigma knots: one per arc
    with pytest.raises(fw.InputError, match="not a surface of revolution"):
        fw.blend_naive(cyclide, continuity="C1")
    with pytest.raises(fw.InputError, match="no real surface"):
        fw.shapes.DupinCyclide(CENTER, 1.0, 2.0, 1.5, NON_UNIFORM, angles_v)
    with pytest.raises(fw.InputError, match="not a ring cyclide"):
        fw.shapes.DupinCyclide(CENTER, 3.0, 1.0, 0.5, NON_UNIFORM, angles_v)


def test_hyperbolic_cylinder_is_exact_and_blends_c2():
    # Fig. 9: x^2/a^2 - y^2/b^2 = 1 extruded along the axis, a projective image of a
    # circular cylinder's partial turn (the paper's recipe (a, b sin t | cos t)).
    a, b = 1.5, 0.8
    x_axis = np.array([1.0, 0.4, 0.0])
    shape = fw.shapes.HyperbolicCylinder(CENTER, a, b, [-1.0, -0.3, 0.4, 1.1], [0.0, 0.5, 1.2], axis=AXIS,
                                         x_axis=x_axis)
    x = x_axis - (x_axis @ AXIS) * AXIS
    x /= np.linalg.norm(x)
    frame = np.column_stack([x, np.cross(AXIS, x), AXIS])

    def implicit(p):
        q = frame.T @ (p - CENTER)
        return abs(q[0] ** 2 / a ** 2 - q[1] ** 2 / b ** 2 - 1) / (q[0] ** 2 / a ** 2 + q[1] ** 2 / b ** 2)

    assert max(implicit(p) for s in shape.patches() for p in samples(s)) < 1e-12
    result = fw.blend_basic_shape(shape, at="end")
    assert max(implicit(p) for s in basic(result) for p in samples(s, 6)) < 1e-12
    assert result.surface.Continuity == "C2"
    assert knot_jump(result.surface) < 1e-9
    assert result.shell.isValid()
    with pytest.raises(fw.InputError, match=r"\(-pi/2, pi/2\)"):
        fw.shapes.HyperbolicCylinder(CENTER, a, b, [-2.0, 0.0], [0.0, 1.0])
    with pytest.raises(fw.InputError, match="degenerate quadric: b"):
        fw.shapes.HyperbolicCylinder(CENTER, a, 0.0, [-1.0, 0.0], [0.0, 1.0])


def test_a_sketch_like_profile_of_several_edges_is_joined_and_revolved():
    # A line and a tangent circle arc as separate edges (a sketch's), the arc listed first and
    # reversed: joined end to end, revolved exactly, blended C2 (eq. (11) at the C1 join).
    line = Part.LineSegment(FreeCAD.Vector(1, 0, 0), FreeCAD.Vector(1, 0, 1)).toShape()
    h = math.sqrt(0.5)
    arc = Part.Arc(FreeCAD.Vector(2, 0, 2), FreeCAD.Vector(2 - h, 0, 1 + h), FreeCAD.Vector(1, 0, 1)).toShape()
    profile = Part.Compound([arc, line])
    shape = fw.shapes.Revolution(profile, (0, 0, 0), (0, 0, 1), NON_UNIFORM)
    worst = 0.0
    for s in shape.patches():
        for p in samples(s, 5):
            r, z = radial(p, np.zeros(3), np.array([0.0, 0, 1]))
            worst = max(worst, min(abs(r - 1) if z <= 1 + 1e-9 else 1.0, abs(math.hypot(r - 2, z - 1) - 1)))
    assert worst < 1e-12
    result = fw.blend_basic_shape(shape)
    assert result.surface is not None and result.surface.Continuity == "C2"
    with pytest.raises(fw.InputError, match="connected wire"):
        far = Part.LineSegment(FreeCAD.Vector(5, 0, 5), FreeCAD.Vector(5, 0, 6)).toShape()
        fw.shapes.Revolution(Part.Compound([line, far]), (0, 0, 0), (0, 0, 1), NON_UNIFORM)


def test_a_split_a_rounding_error_from_a_profile_knot_adds_no_row():
    # A third of a Design spline's range (0 .. 2.999999999999999 on knots 0.2 apart) came out
    # as 0.9999999999999997 beside its knot 1.0: a row of no length, a patch side collapsed.
    curve, _ = _design_profile()
    angles = [0.0, 2.0, 4.0, 2 * math.pi]
    plain = fw.shapes.Revolution(curve, (0, 0, 0), (0, 0, 1), angles)
    knot = float(plain.profile.knots[2])
    near = np.nextafter(np.nextafter(knot, -np.inf), -np.inf)
    split = fw.shapes.Revolution(curve, (0, 0, 0), (0, 0, 1), angles, [near])
    assert list(split.profile.knots) == list(plain.profile.knots)
    assert fw.blend_basic_shape(split, at="end").shell.isValid()
