"""Basic shape to basic shape (blending paper, Figs. 9, 11, 12) through the macro API,
judged by OCCT evaluation of the returned Part geometry."""
import math

import numpy as np
import pytest

import freecad_workbench as fw
import Part

NON_UNIFORM = [0.0, 0.4, 1.5, 2.1, 3.9, 4.3, 5.2, 2 * math.pi]
OTHER = [0.3, 1.1, 1.6, 2.9, 3.4, 4.8, 5.9, 0.3 + 2 * math.pi]  # as many arcs, other angles
CENTER = np.array([1.0, -2.0, 0.5])
AXIS = np.array([0.3, -0.2, 1.0]) / np.linalg.norm([0.3, -0.2, 1.0])


def samples(surface, n=8):
    u0, u1, v0, v1 = surface.bounds()
    for a in np.linspace(u0, u1, n):
        for b in np.linspace(v0, v1, n):
            p = surface.value(a, b)
            yield np.array([p.x, p.y, p.z])


def radial(p):
    d = p - CENTER
    z = d @ AXIS
    return np.linalg.norm(d - z * AXIS), z


def off_cone(surface, radius0, slope):
    return max(abs(radial(p)[0] - (radius0 + slope * radial(p)[1])) / math.hypot(1, slope) for p in samples(surface))


def strip_jump(patches, knots):
    """Largest relative C2 jump between neighbouring transition patches along u (Part getDN
    on both sides, derivatives scaled by the knot-interval ratio, closing seam included)."""
    strip = [s for role, s in patches if role == "transition"]
    n = len(strip)
    assert n == len(knots) - 1
    worst = 0.0
    for k in range(n):
        left, right = strip[k - 1], strip[k]
        previous = knots[k] - knots[k - 1] if k > 0 else knots[n] - knots[n - 1]
        beta = (knots[k + 1] - knots[k]) / previous
        for v in np.linspace(0, 1, 7):
            scale = max(left.getDN(1.0, v, 1, 0).Length, left.getDN(1.0, v, 2, 0).Length)
            worst = max(worst, (right.value(0.0, v) - left.value(1.0, v)).Length / scale)
            for order in (1, 2):
                dl, dr = left.getDN(1.0, v, order, 0), right.getDN(0.0, v, order, 0)
                worst = max(worst, (dr - dl * beta ** order).Length / scale)
    return worst


def test_two_differently_partitioned_cones_join_c2_and_stay_exact(tmp_path):
    # Fig. 11: the scalars differ around the two cones; both stay exact, the complex is C2.
    lower = fw.shapes.Cone(CENTER, 2.0, 0.3, NON_UNIFORM, [-2.0, -1.2, 0.0], axis=AXIS)
    upper = fw.shapes.Cone(CENTER, 2.8, -0.4, OTHER, [1.0, 1.5, 2.6], axis=AXIS)
    result = fw.join_basic_shapes(lower, upper)
    basic = [s for role, s in result.patches if role == "basic"]
    on_lower = [s for s in basic if off_cone(s, 2.0, 0.3) < 1e-10 * 4]
    on_upper = [s for s in basic if off_cone(s, 2.8, -0.4) < 1e-10 * 4]
    assert len(on_lower) + len(on_upper) == len(basic) and on_lower and on_upper
    assert len(on_lower) == len(on_upper)  # two rows of lines on each side, as many pieces around
    assert result.surface.Continuity == "C2"
    assert strip_jump(result.patches, result.surface.getUKnots()) < 1e-8
    assert result.shell.isValid()
    path = str(tmp_path / "join.step")
    result.shell.exportStep(path)
    assert len(Part.read(path).Faces) == len(result.patches)
    naive = fw.join_naive(lower, upper)
    assert naive.surface is None
    assert strip_jump(naive.patches, fw.freeform_knots(lower, "sigma")) > 1e-3


def test_tori_with_different_cross_sections_join_c2():
    # Fig. 12: the same torus, its tube partitioned differently on the two sides.
    a = fw.shapes.Torus(CENTER, 3.0, 1.0, NON_UNIFORM, [-1.4, -1.1, -0.3], axis=AXIS)
    b = fw.shapes.Torus(CENTER, 3.0, 1.0, OTHER, [0.2, 0.5, 1.3, 1.6], axis=AXIS)
    result = fw.join_basic_shapes(a, b, method="sigma")
    basic = [s for role, s in result.patches if role == "basic"]
    assert max(abs(math.hypot(radial(p)[0] - 3.0, radial(p)[1]) - 1.0) for s in basic for p in samples(s)) < 1e-9
    assert result.surface.Continuity == "C2"
    assert strip_jump(result.patches, result.surface.getUKnots()) < 1e-8


def test_cylinder_into_a_spherical_dome():
    # Figs. 9-10: a dome with spherical top on a circular cylinder; the pole is included.
    post = fw.shapes.Cylinder(CENTER, 1.0, NON_UNIFORM, [0.0, 1.0, 1.8], axis=AXIS)
    dome = fw.shapes.SphereZone(CENTER + 2.5 * AXIS, 1.0, NON_UNIFORM, [0.2, 0.9, math.pi / 2], axis=AXIS)
    result = fw.join_basic_shapes(post, dome)
    assert result.surface.Continuity == "C2"
    assert result.shell.isValid()
    top = CENTER + 2.5 * AXIS
    basic = [s for role, s in result.patches if role == "basic"]
    on_dome = [s for s in basic if max(abs(np.linalg.norm(p - top) - 1.0) for p in samples(s)) < 1e-10]
    on_post = [s for s in basic if off_cone(s, 1.0, 0.0) < 1e-10]
    assert on_dome and on_post and len(on_dome) + len(on_post) == len(basic)
    assert strip_jump(result.patches, result.surface.getUKnots()) < 1e-8
    with pytest.raises(fw.InputError, match="pole"):
        fw.join_basic_shapes(dome, post)


def test_bad_join_requests():
    a = fw.shapes.Cylinder(CENTER, 1.0, NON_UNIFORM, [0.0, 1.0], axis=AXIS)
    with pytest.raises(fw.InputError, match="same number of arcs"):
        fw.join_basic_shapes(a, fw.shapes.Cylinder(CENTER, 1.0, [0, 2, 4, 2 * math.pi], [2.0, 3.0], axis=AXIS))
    with pytest.raises(fw.InputError, match="full turn around the axis, or both a partial one"):
        fw.join_basic_shapes(a, fw.shapes.Cylinder(CENTER, 1.0, [0, 0.5, 1, 1.5, 2, 2.5, 3, 3.5], [2.0, 3.0],
                                                   axis=AXIS))
    with pytest.raises(fw.InputError, match="shape must be"):
        fw.join_basic_shapes(a, "cone")
