"""The G1/C1 blend (blending paper, Section 5) through the macro API,
fw.blend_basic_shape(shape, freeform, continuity="C1"), judged by OCCT evaluation of the
returned Part geometry (Part.BSplineSurface.value / getDN)."""
import math

import numpy as np
import pytest

import freecad_workbench as fw
import freecad_workbench.blend_c1  # noqa: F401  (fw.blend_c1)
import FreeCAD
import Part
from freecad_workbench.blend_c1 import complex_c1
from freecad_workbench.kernel import surface_to_part

NON_UNIFORM = [0.0, 0.4, 1.5, 2.1, 3.9, 4.3, 5.2, 2 * math.pi]
LATITUDES = [-0.6, 0.1, 0.5, 0.8]
CENTER = (1.0, -2.0, 0.5)
AXIS = (0.3, -0.2, 1.0)
C1_OR_BETTER = ("C1", "C2", "C3", "CN")


def _local(p):
    axis = np.array(AXIS) / np.linalg.norm(AXIS)
    d = np.array([p.x, p.y, p.z]) - np.array(CENTER)
    z = d @ axis
    return np.linalg.norm(d - z * axis), z


SHAPES = {
    "sphere": (fw.shapes.SphereZone(CENTER, 2.0, NON_UNIFORM, LATITUDES, axis=AXIS),
               lambda p: (p - FreeCAD.Vector(*CENTER)).Length - 2.0, 2.0),
    "cylinder": (fw.shapes.Cylinder(CENTER, 1.0, NON_UNIFORM, [0.0, 0.4, 1.0], axis=AXIS),
                 lambda p: _local(p)[0] - 1.0, 1.0),
    "cone": (fw.shapes.Cone(CENTER, 1.5, -0.4, NON_UNIFORM, [0.0, 0.4, 1.0], axis=AXIS),
             lambda p: (_local(p)[0] - (1.5 - 0.4 * _local(p)[1])) / math.sqrt(1 + 0.16), 1.5),
    "torus": (fw.shapes.Torus(CENTER, 3.0, 1.0, NON_UNIFORM, [-1.0, -0.2, 0.4, 0.9], axis=AXIS),
              lambda p: math.hypot(_local(p)[0] - 3.0, _local(p)[1]) - 1.0, 3.0),
}


def samples(surface, n=9):
    u0, u1, v0, v1 = surface.bounds()
    for a in np.linspace(u0, u1, n):
        for b in np.linspace(v0, v1, n):
            yield surface.value(a, b)


def c1_seams(complex_, knots_u=None, closed=True):
    """Largest relative jump of position and first derivatives across every seam (Part
    getDN on both sides; across a seam the derivative scaled by the knot-interval ratio).
    Returns (along u incl. the closing seam where closed, across v from the basic rows' top
    upwards)."""
    ku = list(complex_.knots_u) if knots_u is None else list(knots_u)
    kv = list(complex_.knots_v)
    at = {(i, j): surface_to_part(s) for _, i, j, s in complex_.patches()}
    n = complex_.pieces_u
    rows = len(kv) - 1
    assert len(at) == n * rows

    def jump(left, right, in_u, beta):
        worst = 0.0
        for t in np.linspace(0.0, 1.0, 9):
            if in_u:
                (pl, lu, lv), (pr, ru, rv) = [(s.value(x, t), s.getDN(x, t, 1, 0), s.getDN(x, t, 0, 1))
                                              for s, x in ((left, 1.0), (right, 0.0))]
            else:
                (pl, lv, lu), (pr, rv, ru) = [(s.value(t, x), s.getDN(t, x, 1, 0), s.getDN(t, x, 0, 1))
                                              for s, x in ((left, 1.0), (right, 0.0))]
            scale = max(lu.Length, lv.Length)
            worst = max(worst, (pl - pr).Length / scale, (ru - lu * beta).Length / scale, (rv - lv).Length / scale)
        return worst

    along = across = 0.0
    for k in range(n):
        beta = (ku[k + 1] - ku[k]) / (ku[k] - ku[k - 1]) if k > 0 else (ku[1] - ku[0]) / (ku[n] - ku[n - 1])
        for v in range(rows):
            if k > 0 or closed:
                along = max(along, jump(at[(k - 1) % n, v], at[k, v], True, beta))
            if v >= complex_.rows_basic:
                across = max(across, jump(at[k, v - 1], at[k, v], False, (kv[v + 1] - kv[v]) / (kv[v] - kv[v - 1])))
    return along, across


@pytest.mark.parametrize("name", list(SHAPES))
def test_c1_blend_is_c1_exact_valid_and_one_c1_surface(name):
    shape, distance, size = SHAPES[name]
    result = fw.blend_basic_shape(shape, continuity="C1")
    assert {"basic", "transition", "freeform"} == {role for role, _ in result.patches}
    basic = [s for role, s in result.patches if role == "basic"]
    assert all(s.UDegree == 4 for s in basic)
    assert max(abs(distance(p)) for s in basic for p in samples(s)) < 1e-10 * size
    strip = [s for role, s in result.patches if role == "transition"]
    assert len(strip) == 2 * 2 * (len(NON_UNIFORM) - 1)  # two rows of two quartics per arc
    assert all((s.UDegree, s.VDegree) == (4, 2) for s in strip)
    assert result.surface is not None
    assert result.surface.Continuity in C1_OR_BETTER
    assert result.shell.isValid()
    assert len(result.shell.Faces) == len(result.patches)
    along, across = c1_seams(complex_c1(shape))
    assert along < 1e-8
    assert across < 1e-8


def test_the_seam_check_fails_with_the_wrong_knot_ratios():
    # Negative control: the same check, judged with uniform knots instead of the ratios
    # betaT = beta of eq. (12), must fail on the non-uniform partition.
    shape = SHAPES["sphere"][0]
    c = complex_c1(shape)
    assert c1_seams(c)[0] < 1e-8
    assert c1_seams(c, knots_u=range(c.pieces_u + 1))[0] > 1e-3


def test_c1_single_surface_keeps_the_sphere_and_step_round_trip_keeps_the_faces(tmp_path):
    shape, distance, size = SHAPES["sphere"]
    result = fw.blend_basic_shape(shape, continuity="C1")
    c = complex_c1(shape)
    u0, u1 = c.knots_u[0], c.knots_u[-1]
    v0, v1 = c.knots_v[0], c.knots_v[c.rows_basic]
    worst = max(abs(distance(result.surface.value(u, v)))
                for u in np.linspace(u0, u1, 29) for v in np.linspace(v0, v1, 13))
    assert worst < 1e-9 * size
    path = str(tmp_path / "blend_c1.step")
    result.shell.exportStep(path)
    back = Part.read(path)
    assert len(back.Faces) == len(result.patches)
    assert all(isinstance(f.Surface, Part.BSplineSurface) for f in back.Faces)
    assert back.isValid()


def test_user_biquadratic_ring_on_the_c1_knots_is_kept():
    zone = fw.shapes.SphereZone((0, 0, 0), 1.0, NON_UNIFORM, LATITUDES)
    knots = list(fw.freeform_knots(zone, continuity="C1"))
    n = len(knots) - 1
    mids = [(a + b) / 2 for a, b in zip(NON_UNIFORM[:-1], NON_UNIFORM[1:])]
    # OCCT's periodic span i is governed by poles i, i+1, i+2: arc i's pole is pole i+1.
    rows = [[FreeCAD.Vector(0.9 * math.cos(a), 0.9 * math.sin(a), 0.8 + 0.2 * j) for j in range(3)] for a in mids]
    rows = rows[-1:] + rows[:-1]
    ring = Part.BSplineSurface()
    ring.buildFromPolesMultsKnots(rows, [1] * (n + 1), [3, 3], knots, [0.0, 1.0], True, False, 2, 2)
    result = fw.blend_basic_shape(zone, freeform=ring, continuity="C1")
    assert result.surface.Continuity in C1_OR_BETTER
    assert result.shell.isValid()
    # every free-form patch lies on the user's ring
    freeform = [s for role, s in result.patches if role == "freeform"]
    worst = max(ring.projectPoint(p, "LowerDistance") for s in freeform for p in samples(s, 5))
    assert worst < 1e-7
    along, across = c1_seams(complex_c1(zone, ring))
    assert max(along, across) < 1e-8


def test_bad_c1_requests_raise_input_error():
    # An arc of pi or more: fine for the G2 cubic (weight 1/3 + 2/3 cos(alpha/2) > 0), not
    # for a rational quadratic; the message names the arc.
    wide = fw.shapes.Cylinder(CENTER, 1.0, [0.0, 3.3, 2 * math.pi], [0.0, 1.0])
    with pytest.raises(fw.InputError, match="longitude arc 0"):
        fw.blend_basic_shape(wide, continuity="C1")
    with pytest.raises(fw.InputError, match="pole"):
        fw.blend_basic_shape(fw.shapes.SphereZone(CENTER, 1.0, NON_UNIFORM, [0.0, math.pi / 2]), continuity="C1",
                             at="end")
    with pytest.raises(fw.InputError, match="no boundary|closed profile"):
        fw.blend_basic_shape(fw.shapes.Torus(CENTER, 3.0, 1.0, NON_UNIFORM, NON_UNIFORM), continuity="C1")
    with pytest.raises(fw.InputError, match="radius"):
        fw.blend_basic_shape(fw.shapes.SphereZone(CENTER, -1.0, NON_UNIFORM, LATITUDES), continuity="C1")
    with pytest.raises(fw.InputError, match="longitude arc 0"):
        fw.freeform_knots(wide, continuity="C1")
    zone = fw.shapes.SphereZone(CENTER, 2.0, NON_UNIFORM, LATITUDES)
    # A bicubic ring (the C2 kind) and a biquadratic one on uniform knots do not match.
    bicubic = [s for role, s in fw.blend_basic_shape(zone, method="sigma").patches if role == "freeform"][0]
    with pytest.raises(fw.InputError, match="does not match the interface"):
        fw.blend_basic_shape(zone, freeform=bicubic, continuity="C1")
    # A biquadratic ring beside the axis (around the world's Z axis, not the zone's).
    poles = [[FreeCAD.Vector(math.cos(a), math.sin(a), z) for z in (2.0, 2.2, 2.4)]
             for a in np.linspace(0, 2 * math.pi, 7, endpoint=False)]
    beside = Part.BSplineSurface()
    beside.buildFromPolesMultsKnots(poles, [1] * 8, [3, 3], list(range(8)), [0.0, 1.0], True, False, 2, 2)
    with pytest.raises(fw.InputError, match="does not match the interface: its first row does not go once around"):
        fw.blend_basic_shape(zone, freeform=beside, continuity="C1")
    with pytest.raises(fw.InputError, match="continuity"):
        fw.blend_basic_shape(zone, continuity="G1")


def test_new_scalars_beta_t_keep_the_blend_c1_and_the_sphere_exact():
    # Appendix 7.3 with new scalars (all 1: uniform arc knots on a non-uniform partition).
    shape, distance, size = SHAPES["sphere"]
    beta_t = [1.0] * (len(NON_UNIFORM) - 1)
    c = complex_c1(shape, beta_t=beta_t)
    assert np.allclose(np.diff(list(c.knots_u)), 0.5)
    assert np.allclose(list(fw.blend_c1.freeform_knots_c1(shape, beta_t)), range(len(NON_UNIFORM)))
    assert max(c1_seams(c)) < 1e-8
    result = fw.blend_c1.blend_basic_shape_c1(shape, beta_t=beta_t)
    basic = [s for role, s in result.patches if role == "basic"]
    assert max(abs(distance(p)) for s in basic for p in samples(s)) < 1e-10 * size
    assert result.surface.Continuity in C1_OR_BETTER
    with pytest.raises(fw.InputError, match="multiply to 1"):
        complex_c1(shape, beta_t=[1.1] * (len(NON_UNIFORM) - 1))
    with pytest.raises(fw.InputError, match="one scalar per arc"):
        complex_c1(shape, beta_t=[1.0, 1.0])


def test_naive_c1_baseline_fails_the_seam_check_the_c1_blend_passes():
    # Without eta (Appendix 7.3) the arcs are only split and raised: the double strip is not
    # C1 along u on a non-uniform partition, and no single C1 surface exists.
    shape = SHAPES["sphere"][0]
    naive = fw.blend_naive(shape, continuity="C1")
    assert naive.surface is None and naive.shell.isValid()
    along, _ = c1_seams(complex_c1(shape, naive=True))
    assert along > 1e-3
    assert c1_seams(complex_c1(shape))[0] < 1e-8


def test_c1_join_of_two_differently_partitioned_tori():
    other = [0.3, 1.1, 1.6, 2.9, 3.4, 4.8, 5.9, 0.3 + 2 * math.pi]
    a = fw.shapes.Torus(CENTER, 3.0, 1.0, NON_UNIFORM, [-1.4, -1.0, -0.3], axis=AXIS)
    b = fw.shapes.Torus(CENTER, 3.0, 1.0, other, [0.2, 0.5, 1.3, 1.6], axis=AXIS)
    result = fw.join_basic_shapes(a, b, continuity="C1")
    basic = [s for role, s in result.patches if role == "basic"]
    assert max(abs(SHAPES["torus"][1](p)) for s in basic for p in samples(s, 5)) < 1e-9
    assert [s.UDegree for role, s in result.patches if role == "transition"] == [4] * 28
    assert result.surface.Continuity in C1_OR_BETTER
    assert result.shell.isValid()
    along, across = c1_seams(fw._kernel.join_shapes_c1(a._revolution(), b._revolution()))
    assert along < 1e-8 and across < 1e-8


def test_biquadratic_ring_on_its_own_knots_blends_c1():
    # Any periodic biquadratic ring around the axis: the knots of both sides are merged.
    zone = fw.shapes.SphereZone(CENTER, 2.0, NON_UNIFORM, LATITUDES)
    c = np.array(CENTER)
    poles = [[FreeCAD.Vector(*(c + (1.6 * math.cos(a), 1.6 * math.sin(a), z))) for z in (1.9, 2.2, 2.5)]
             for a in np.linspace(0, 2 * math.pi, 9, endpoint=False)]
    ring = Part.BSplineSurface()
    ring.buildFromPolesMultsKnots(poles, [1] * 10, [3, 3], [0.5 * k for k in range(10)], [0.0, 1.0], True, False, 2, 2)
    result = fw.blend_basic_shape(zone, freeform=ring, continuity="C1")
    assert result.surface.Continuity in C1_OR_BETTER and result.shell.isValid()
    basic = [s for role, s in result.patches if role == "basic"]
    assert max(abs((p - FreeCAD.Vector(*CENTER)).Length - 2.0) for s in basic for p in samples(s, 5)) < 1e-10
    along, across = c1_seams(complex_c1(zone, ring))
    assert along < 1e-8 and across < 1e-8
    worst = 0.0
    for s in (s for role, s in result.patches if role == "freeform"):
        for p in samples(s, 4):
            u, v = ring.parameter(p)
            worst = max(worst, (ring.value(u, v) - p).Length)
    assert worst < 1e-9


def test_c1_dome_joins_at_its_start():
    dome = fw.shapes.SphereZone(CENTER, 2.0, NON_UNIFORM, [0.3, 0.9, math.pi / 2], axis=AXIS)
    result = fw.blend_basic_shape(dome, continuity="C1")  # its end is the pole: the start
    assert result.surface.Continuity in C1_OR_BETTER and result.shell.isValid()
    basic = [s for role, s in result.patches if role == "basic"]
    assert max(abs((p - FreeCAD.Vector(*CENTER)).Length - 2.0) for s in basic for p in samples(s, 5)) < 1e-10
    along, across = c1_seams(complex_c1(dome, at="start"))
    assert along < 1e-8 and across < 1e-8
    axis = FreeCAD.Vector(*AXIS).normalize()
    ring = [s for role, s in result.patches if role == "freeform"]
    assert max((p - FreeCAD.Vector(*CENTER)).dot(axis) for s in ring for p in samples(s, 3)) < 2.0 * math.sin(0.3)
    with pytest.raises(fw.InputError, match="pole"):
        fw.blend_basic_shape(dome, continuity="C1", at="end")


@pytest.mark.parametrize("kind", ["sphere", "cone"])
def test_partial_turns_join_c1_and_stay_exact(kind):
    # Issue 15: Section 5 over part of a turn (3.7 radians, non-uniform), default ring clamped.
    around = [0.3, 1.0, 2.4, 3.1, 4.0]
    if kind == "sphere":
        shape = fw.shapes.SphereZone(CENTER, 2.0, around, LATITUDES, axis=AXIS)
        off = SHAPES["sphere"][1]
    else:
        shape = fw.shapes.Cone(CENTER, 1.5, -0.4, around, [0.0, 0.4, 1.0], axis=AXIS)
        off = SHAPES["cone"][1]
    result = fw.blend_basic_shape(shape, continuity="C1")
    assert result.surface is not None and result.surface.Continuity in C1_OR_BETTER
    assert not result.surface.isUPeriodic()
    basic = [s for role, s in result.patches if role == "basic"]
    assert max(abs(off(p)) for s in basic for p in samples(s, 5)) < 1e-10 * 2
    along, across = c1_seams(complex_c1(shape), closed=False)
    assert max(along, across) < 1e-8
    assert c1_seams(complex_c1(shape, naive=True), closed=False)[0] > 1e-3  # the check can fail
    assert result.shell.isValid()


def test_different_partitions_join_c1_with_t_joints():
    # Figs. 14, 15e: a post of 7 arcs into a dome of 4 arcs, C1 throughout, both exact.
    post = fw.shapes.Cylinder(CENTER, 1.0, NON_UNIFORM, [0.0, 1.0, 1.8], axis=AXIS)
    top = tuple(np.array(CENTER) + 2.5 * np.array(AXIS) / np.linalg.norm(AXIS))
    dome = fw.shapes.SphereZone(top, 1.0, [0.0, 1.4, 3.3, 4.5, 2 * math.pi], [0.2, 0.9, 1.4], axis=AXIS)
    result = fw.join_basic_shapes(post, dome, continuity="C1")
    assert result.surface is not None and result.surface.Continuity in C1_OR_BETTER
    assert result.shell.isValid()
    basic = [s for role, s in result.patches if role == "basic"]
    on_post = [s for s in basic if max(abs(_local(p)[0] - 1.0) for p in samples(s, 4)) < 1e-10]
    on_dome = [s for s in basic if max(abs((p - FreeCAD.Vector(*top)).Length - 1.0) for p in samples(s, 4)) < 1e-10]
    assert on_post and on_dome and len(on_post) + len(on_dome) == len(basic)
    # C1 across every seam of the surface: compare it with its patches' derivatives at the strip.
    strip = [s for role, s in result.patches if role == "transition"]
    pieces = len(strip) // 2
    assert pieces > 2 * 7  # the two partitions merged
    knots = result.surface.getUKnots()
    worst = 0.0
    for k in range(pieces):
        left, right = strip[2 * (k - 1)], strip[2 * k]
        beta = (knots[k + 1] - knots[k]) / ((knots[k] - knots[k - 1]) if k > 0 else (knots[-1] - knots[-2]))
        for v in np.linspace(0, 1, 5):
            scale = left.getDN(1.0, v, 1, 0).Length
            worst = max(worst, (right.value(0.0, v) - left.value(1.0, v)).Length / scale,
                        (right.getDN(0.0, v, 1, 0) - left.getDN(1.0, v, 1, 0) * beta).Length / scale)
    assert worst < 1e-8
