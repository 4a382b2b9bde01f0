"""Basic shapes and the sphere-zone blend through the macro API, judged by OCCT
evaluation of the returned Part geometry."""
import math

import numpy as np
import pytest

import freecad_workbench as fw
import FreeCAD
import Part

NON_UNIFORM = [0.0, 0.4, 1.5, 2.1, 3.9, 4.3, 5.2, 2 * math.pi]
LATITUDES = [-0.6, 0.1, 0.5, 0.8]
CENTER = (1.0, -2.0, 0.5)
AXIS = (0.3, -0.2, 1.0)


def samples(surface, n=12):
    u0, u1, v0, v1 = surface.bounds()
    for a in np.linspace(u0, u1, n):
        for b in np.linspace(v0, v1, n):
            yield surface.value(a, b)


def test_sphere_zone_patches_lie_on_the_sphere():
    zone = fw.shapes.SphereZone(CENTER, 2.5, NON_UNIFORM, LATITUDES, axis=AXIS)
    patches = zone.patches()
    assert len(patches) == 7 * 3
    c = FreeCAD.Vector(*CENTER)
    worst = max(abs((p - c).Length - 2.5) for s in patches for p in samples(s))
    assert worst < 1e-10 * 2.5


def test_cylinder_cone_torus_patches_lie_on_their_surfaces():
    frame_axis = np.array(AXIS) / np.linalg.norm(AXIS)
    c = np.array(CENTER)

    def local(p):
        d = np.array([p.x, p.y, p.z]) - c
        z = d @ frame_axis
        return np.linalg.norm(d - z * frame_axis), z

    cyl = fw.shapes.Cylinder(CENTER, 3.0, [0.2, 1.0, 1.3, 2.9], [-1.0, 0.5, 4.0], axis=AXIS)
    assert max(abs(local(p)[0] - 3.0) for s in cyl.patches() for p in samples(s)) < 1e-10 * 3
    cone = fw.shapes.Cone(CENTER, 2.0, -0.3, NON_UNIFORM, [-1.0, 0.5, 4.0], axis=AXIS)
    assert max(abs(local(p)[0] - (2.0 - 0.3 * local(p)[1])) for s in cone.patches() for p in samples(s)) < 1e-9
    torus = fw.shapes.Torus(CENTER, 3.0, 1.0, NON_UNIFORM, [0.0, 0.7, 2.0, 4.0, 2 * math.pi], axis=AXIS)
    assert max(abs(math.hypot(local(p)[0] - 3.0, local(p)[1]) - 1.0)
               for s in torus.patches() for p in samples(s)) < 1e-9


def test_bad_partitions_raise_input_error():
    with pytest.raises(fw.InputError, match="angles must increase"):
        fw.shapes.SphereZone(CENTER, 1.0, [0.0, 1.0, 1.0, 2 * math.pi], LATITUDES)
    with pytest.raises(fw.InputError, match="positive weight"):
        fw.shapes.Cylinder(CENTER, 1.0, [0.0, 4.3, 2 * math.pi], [0.0, 1.0])
    with pytest.raises(fw.InputError):
        fw.shapes.Torus(CENTER, 1.0, 2.0, NON_UNIFORM, NON_UNIFORM)


def test_blend_is_c2_valid_and_keeps_the_sphere(tmp_path):
    zone = fw.shapes.SphereZone(CENTER, 2.0, NON_UNIFORM, LATITUDES, axis=AXIS)
    result = fw.blend_basic_shape(zone)
    roles = [role for role, _ in result.patches]
    assert {"basic", "transition", "freeform"} == set(roles)
    c = FreeCAD.Vector(*CENTER)
    worst = max(abs((p - c).Length - 2.0) for role, s in result.patches if role == "basic" for p in samples(s, 6))
    assert worst < 1e-10 * 2.0
    assert result.surface is not None
    assert result.surface.Continuity == "C2"
    assert result.shell.isValid()
    assert len(result.shell.Faces) == len(result.patches)
    path = str(tmp_path / "blend.step")
    result.shell.exportStep(path)
    back = Part.read(path)
    assert len(back.Faces) == len(result.patches)
    assert all(isinstance(f.Surface, Part.BSplineSurface) for f in back.Faces)


def _strip_jump(patches, knots):
    """Largest relative C2 jump between neighbouring transition patches along u (Part
    getDN on both sides, derivatives scaled by the knot-interval ratio)."""
    strip = [s for role, s in patches if role == "transition"]
    worst = 0.0
    n = len(strip)
    for k in range(n):
        left, right = strip[k - 1], strip[k]
        beta = (knots[k + 1] - knots[k]) / (knots[k] - knots[k - 1]) if k > 0 else \
            (knots[1] - knots[0]) / (knots[n] - knots[n - 1])
        for v in np.linspace(0, 1, 7):
            for order in (1, 2):
                dl, dr = left.getDN(1.0, v, order, 0), right.getDN(0.0, v, order, 0)
                scale = max(left.getDN(1.0, v, 1, 0).Length, left.getDN(1.0, v, 2, 0).Length)
                worst = max(worst, (dr - dl * beta ** order).Length / scale)
    return worst


def test_naive_baseline_fails_the_seam_check_the_blend_passes():
    zone = fw.shapes.SphereZone(CENTER, 2.0, NON_UNIFORM, LATITUDES, axis=AXIS)
    naive = fw.blend_naive(zone)
    assert naive.surface is None
    assert naive.shell.isValid()
    assert _strip_jump(naive.patches, fw.freeform_knots(zone, "sigma")) > 1e-3
    sigma = fw.blend_basic_shape(zone, method="sigma")
    assert _strip_jump(sigma.patches, fw.freeform_knots(zone, "sigma")) < 1e-8


def test_user_ring_must_match_the_interface():
    zone = fw.shapes.SphereZone(CENTER, 2.0, NON_UNIFORM, LATITUDES, axis=AXIS)
    # The default ring, handed back as a user net, is accepted; a plain uniform one is not.
    ring = [s for role, s in fw.blend_basic_shape(zone, method="sigma").patches if role == "freeform"]
    assert ring
    bad = Part.BSplineSurface()
    poles = [[FreeCAD.Vector(math.cos(a), math.sin(a), z) for z in (2.0, 2.2, 2.4, 2.6)]
             for a in np.linspace(0, 2 * math.pi, 7, endpoint=False)]
    bad.buildFromPolesMultsKnots(poles, [1] * 8, [4, 4], list(range(8)), [0.0, 1.0], True, False, 3, 3)
    with pytest.raises(fw.InputError, match="does not match the interface"):
        fw.blend_basic_shape(zone, freeform=bad)


@pytest.mark.parametrize("shape", [
    fw.shapes.Cylinder(CENTER, 1.0, NON_UNIFORM, [0.0, 0.4, 1.0], axis=AXIS),
    fw.shapes.Cone(CENTER, 1.5, -0.4, NON_UNIFORM, [0.0, 0.4, 1.0], axis=AXIS),
    fw.shapes.Torus(CENTER, 3.0, 1.0, NON_UNIFORM, [-1.0, -0.2, 0.4, 0.9], axis=AXIS),
], ids=["cylinder", "cone", "torus"])
def test_every_shape_blends_c2_and_naive_does_not(shape):
    result = fw.blend_basic_shape(shape, method="sigma")
    assert result.surface.Continuity == "C2"
    assert result.shell.isValid()
    knots = fw.freeform_knots(shape, "sigma")
    assert _strip_jump(result.patches, knots) < 1e-8
    naive = fw.blend_naive(shape)
    assert naive.surface is None
    assert _strip_jump(naive.patches, knots) > 1e-3


def test_bad_blend_requests():
    zone = fw.shapes.SphereZone(CENTER, 2.0, NON_UNIFORM, LATITUDES)
    with pytest.raises(fw.InputError, match="continuity"):
        fw.blend_basic_shape(zone, continuity="G7")
    with pytest.raises(fw.InputError, match="more than a full turn"):
        fw.blend_basic_shape(fw.shapes.Cylinder(CENTER, 1.0, [0.0, 3.0, 6.0, 6.5], [0.0, 1.0]))
    with pytest.raises(fw.InputError, match="no boundary"):
        fw.blend_basic_shape(fw.shapes.Torus(CENTER, 3.0, 1.0, NON_UNIFORM, NON_UNIFORM))
    with pytest.raises(fw.InputError, match="pole"):
        fw.blend_basic_shape(fw.shapes.SphereZone(CENTER, 1.0, NON_UNIFORM, [0.0, math.pi / 2]), at="end")
    with pytest.raises(fw.InputError, match="at must be"):
        fw.blend_basic_shape(zone, at="top")


def test_dome_blends_at_its_bottom():
    # A dome's end is its pole: the ring joins at the start of the profile, below the dome.
    dome = fw.shapes.SphereZone(CENTER, 2.0, NON_UNIFORM, [0.3, 0.9, math.pi / 2], axis=AXIS)
    result = fw.blend_basic_shape(dome)
    assert result.surface.Continuity == "C2"
    assert result.shell.isValid()
    c = FreeCAD.Vector(*CENTER)
    basic = [s for role, s in result.patches if role == "basic"]
    assert max(abs((p - c).Length - 2.0) for s in basic for p in samples(s, 6)) < 1e-10 * 2.0
    axis = FreeCAD.Vector(*AXIS).normalize()
    ring = [s for role, s in result.patches if role == "freeform"]
    assert max((p - c).dot(axis) for s in ring for p in samples(s, 4)) < 2.0 * math.sin(0.3)


def test_user_ring_on_the_interface_knots_blends_c2():
    zone = fw.shapes.SphereZone((0, 0, 0), 1.0, NON_UNIFORM, LATITUDES)
    knots = list(fw.freeform_knots(zone))
    n = len(knots) - 1
    angles = NON_UNIFORM[:-1]
    # OCCT's periodic pole j is centred on knot j + 1: rotate by one (as the kernel does).
    rows = [[FreeCAD.Vector(0.8 * math.cos(a), 0.8 * math.sin(a), 0.75 + 0.15 * j) for j in range(4)] for a in angles]
    rows = rows[1:] + rows[:1]
    ring = Part.BSplineSurface()
    ring.buildFromPolesMultsKnots(rows, [1] * (n + 1), [4, 4], knots, [0.0, 1.0], True, False, 3, 3)
    result = fw.blend_basic_shape(zone, freeform=ring)
    assert result.surface.Continuity == "C2"
    # the ring's poles are in the complex
    freeform = [s for role, s in result.patches if role == "freeform"]
    top = max(p.z for s in freeform for row in s.getPoles() for p in row)
    assert abs(top - (0.75 + 0.45)) < 1e-12


def test_any_periodic_bicubic_ring_around_the_axis_blends_c2():
    # A ring on its own uniform knots (not freeform_knots): both sides get each other's knots.
    zone = fw.shapes.SphereZone((0, 0, 0), 1.0, NON_UNIFORM, LATITUDES)
    m = 9
    rows = [[FreeCAD.Vector(0.8 * math.cos(a), 0.8 * math.sin(a), 0.75 + 0.15 * j) for j in range(4)]
            for a in np.linspace(0, 2 * math.pi, m, endpoint=False)]
    ring = Part.BSplineSurface()
    ring.buildFromPolesMultsKnots(rows, [1] * (m + 1), [4, 4], [10.0 + 2 * k for k in range(m + 1)], [0.0, 1.0],
                                  True, False, 3, 3)
    result = fw.blend_basic_shape(zone, freeform=ring)
    assert result.surface.Continuity == "C2"
    assert result.shell.isValid()
    basic = [s for role, s in result.patches if role == "basic"]
    assert max(abs(p.Length - 1.0) for s in basic for p in samples(s, 6)) < 1e-10
    # every free-form patch lies on the user's ring
    freeform = [s for role, s in result.patches if role == "freeform"]
    worst = 0.0
    for s in freeform:
        for p in samples(s, 4):
            u, v = ring.parameter(p)
            worst = max(worst, (ring.value(u, v) - p).Length)
    assert worst < 1e-9
    reversed_ring = ring.copy()
    reversed_ring.exchangeUV()  # no longer periodic in u
    with pytest.raises(fw.InputError, match="does not match the interface"):
        fw.blend_basic_shape(zone, freeform=reversed_ring)


def test_edited_control_structure_blends_c2_along_the_interface():
    # Fig. 1c/d, 4a: one control point of the sphere's G2 structure moved outwards.
    zone = fw.shapes.SphereZone(CENTER, 2.0, NON_UNIFORM, LATITUDES, axis=AXIS)
    plain = fw.blend_basic_shape(zone, method="sigma")
    point, weight = zone.control_point(2, 2, 1, 2)
    c = np.array(CENTER)
    zone.set_control(2, 2, 1, 2, c + 1.2 * (np.array(point) - c))
    assert zone.edited and zone.control_point(2, 2, 1, 2)[1] == weight
    moved = max(abs((p - FreeCAD.Vector(*CENTER)).Length - 2.0) for s in zone.patches() for p in samples(s, 6))
    assert moved > 1e-2  # the edited patch left the sphere
    edited = fw.blend_basic_shape(zone, method="sigma")
    assert edited.surface is None  # G2 across the profile
    assert edited.shell.isValid()
    knots = fw.freeform_knots(zone, "sigma")
    assert _strip_jump(edited.patches, knots) < 1e-8
    # basic patches of arcs away from the edit (sigma: one piece an arc) stay on the sphere,
    # those of the edited arc do not
    basic = [s for role, s in edited.patches if role == "basic"]
    rows = len(LATITUDES) - 1
    assert len(basic) == rows * (len(NON_UNIFORM) - 1) and plain.surface is not None

    def off_sphere(arc):
        return max(abs((p - FreeCAD.Vector(*CENTER)).Length - 2.0)
                   for j in range(rows) for p in samples(basic[arc * rows + j], 6))

    assert off_sphere(5) < 1e-10 and off_sphere(0) < 1e-10
    assert off_sphere(2) > 1e-2
    with pytest.raises(fw.InputError, match="unedited"):
        fw.blend_naive(zone)
    with pytest.raises(fw.InputError, match="positive weight"):
        zone.set_control(0, 0, 1, 1, (0, 0, 0), weight=0.0)
    zone.reset_control()
    assert fw.blend_basic_shape(zone).surface.Continuity == "C2"


def _conic_residual(q, p0, m, p2, c):
    """|tau1^2 - 4 c^2 tau0 tau2| for the barycentric coordinates of q in the triangle
    p0, m, p2: zero exactly on the rational quadratic (weights 1, c, 1) with those poles."""
    a = np.array([[p0[0], m[0], p2[0]], [p0[1], m[1], p2[1]], [1.0, 1.0, 1.0]])
    t0, t1, t2 = np.linalg.solve(a, [q[0], q[1], 1.0])
    return abs(t1 * t1 - 4 * c * c * t0 * t2)


def test_circular_and_hyperbolic_cylinder_ensemble_blends_c2():
    # Fig. 9's ensemble as an edited structure: two arcs of a circular cylinder become
    # hyperbolic (middle weight 1.4 > 1 instead of cos(alpha/2)); eq. (11) joins them C2 to
    # the circular arcs, and the rho pieces in the middle of each arc keep their conic exact.
    R = 3.0
    angles = np.array([0.0, 1.0, 2.2, 3.1, 4.05, 5.3, 2 * math.pi])  # no uniform or symmetric run: rho in thirds
    n = len(angles) - 1
    cylinder = fw.shapes.Cylinder((0, 0, 0), R, angles, [0.0, 1.0, 2.0])
    hyperbolic = {1: 1.4, 4: 1.4}

    def poles(arc):
        half = (angles[arc + 1] - angles[arc]) / 2
        p0 = R * np.array([math.cos(angles[arc]), math.sin(angles[arc])])
        p2 = R * np.array([math.cos(angles[arc + 1]), math.sin(angles[arc + 1])])
        m = R / math.cos(half) * np.array([math.cos(angles[arc] + half), math.sin(angles[arc] + half)])
        return p0, m, p2

    for arc, c in hyperbolic.items():
        p0, m, p2 = poles(arc)
        for j in range(2):
            for s in range(4):
                for r, end in ((1, p0), (2, p2)):
                    point, _ = cylinder.control_point(arc, j, r, s)
                    xy = (end + 2 * c * m) / (1 + 2 * c)  # the degree-raised conic, as eq. (2), weight c
                    cylinder.set_control(arc, j, r, s, (xy[0], xy[1], point[2]), (1 + 2 * c) / 3)
    result = fw.blend_basic_shape(cylinder, method="rho")
    assert result.shell.isValid()
    arcs = fw.freeform_knots(cylinder, "rho")  # rho: each arc in three equal pieces (scalar 1 inside)
    knots = np.r_[[a + (b - a) * t for a, b in zip(arcs[:-1], arcs[1:]) for t in (0, 1 / 3, 2 / 3)], arcs[-1]]
    assert _strip_jump(result.patches, knots) < 1e-8
    basic = [s for role, s in result.patches if role == "basic"]
    rows = 2
    assert len(basic) == 3 * n * rows  # rho: three pieces an arc
    for arc in range(n):
        points = list(samples(basic[(3 * arc + 1) * rows], 5))  # middle third of the arc, lower row
        if arc in hyperbolic:
            assert max(_conic_residual((p.x, p.y), *poles(arc), hyperbolic[arc]) for p in points) < 1e-10
            assert max(abs(math.hypot(p.x, p.y) - R) for p in points) > 1e-3  # not the circle
        else:  # circular arcs: the middle third stays exact (eq. (11) only moves the ends)
            assert max(abs(math.hypot(p.x, p.y) - R) for p in points) < 1e-10


def test_partial_turn_blends_c2_open_in_u():
    # A sphere zone over part of a turn: the complex is open in u, its ring clamped.
    zone = fw.shapes.SphereZone(CENTER, 2.0, [0.3, 1.0, 2.2, 2.6, 3.9], LATITUDES, axis=AXIS)
    result = fw.blend_basic_shape(zone, method="sigma")
    assert result.surface.Continuity == "C2" and result.shell.isValid()
    assert not result.surface.isUPeriodic()
    c = FreeCAD.Vector(*CENTER)
    basic = [s for role, s in result.patches if role == "basic"]
    assert max(abs((p - c).Length - 2.0) for s in basic for p in samples(s, 6)) < 1e-10 * 2.0
    strip = [s for role, s in result.patches if role == "transition"]
    knots = fw.freeform_knots(zone, "sigma")
    worst = 0.0
    for k in range(1, len(strip)):  # no closing seam
        left, right = strip[k - 1], strip[k]
        beta = (knots[k + 1] - knots[k]) / (knots[k] - knots[k - 1])
        for v in np.linspace(0, 1, 7):
            scale = max(left.getDN(1.0, v, 1, 0).Length, left.getDN(1.0, v, 2, 0).Length)
            for order in (1, 2):
                worst = max(worst, (right.getDN(0.0, v, order, 0) - left.getDN(1.0, v, order, 0) * beta ** order).Length
                            / scale)
    assert worst < 1e-8


def _angle(point):
    return math.atan2(point.y, point.x)


@pytest.mark.parametrize("case", ["sphere", "cyclide", "cyclide_naive", "chain"])
def test_default_ring_strip_joins_each_arc_to_the_ring_above_it(case):
    # The strip's patch k joins the shape's arc k to the ring's span k: both ends of a
    # transition patch at the same angles around the axis (OCCT's evaluation). The default
    # ring's span k once lay two arcs further round (periodicCubic's pole layout): the strip
    # twisted by 120 degrees on 6 arcs and narrowed to a waist (radius 7.07 -> 3.25 -> 5.5 on
    # a sphere zone of radius 10), still C2.
    lon = np.radians(np.linspace(0, 360, 7))
    if case == "sphere":
        result = fw.blend_basic_shape(fw.shapes.SphereZone((0, 0, 0), 10, lon, np.radians([-40, -10, 20, 45])))
    elif case.startswith("cyclide"):
        blend = fw.blend_naive if case == "cyclide_naive" else fw.blend_basic_shape
        result = blend(fw.shapes.DupinCyclide((0, 0, 0), 10, 2, 4, lon, np.radians([-60, 0, 60])))
    else:
        result = fw.blend_chain(fw.shapes.Cylinder((0, 0, 0), 5, lon, [0, 2, 4]), start="default", end="default")
    strips = [s for role, s in result.patches if role == "transition"]
    assert strips
    for strip in strips:
        u0, u1, v0, v1 = strip.bounds()
        for u in (u0, 0.5 * (u0 + u1), u1):
            a, b = _angle(strip.value(u, v0)), _angle(strip.value(u, v1))
            assert abs(math.remainder(a - b, 2 * math.pi)) < 0.2, (case, math.degrees(a), math.degrees(b))
