"""Several interfaces on one shape (issue 15, part 3): free-form at both ends of a profile,
shape to shape plus free-form, edited structures on both sides of a join, through
fw.blend_chain, judged by OCCT evaluation of the returned Part geometry: basic patches on
the exact shape within 1e-10 of its size, every patch on the single surface, C2 across every
seam of the grid by Part's derivatives, and the naive baseline failing the same check."""
import math

import numpy as np
import pytest

import freecad_workbench as fw
import Part

from tests.kernel.test_join import AXIS, CENTER, NON_UNIFORM, OTHER, off_cone, radial, samples


def off_sphere(surface, center, radius):
    return max(abs(np.linalg.norm(p - center) - radius) for p in samples(surface))


def grid(result):
    """The patches as a grid [k][v] (the complex's order: u piece by u piece, rows along v)
    with the single surface's knots (every patch boundary is one of its knots)."""
    knots_u, knots_v = result.surface.getUKnots(), result.surface.getVKnots()
    pieces_u, rows_v = len(knots_u) - 1, len(knots_v) - 1
    assert len(result.patches) == pieces_u * rows_v
    cells = [[result.patches[k * rows_v + v] for v in range(rows_v)] for k in range(pieces_u)]
    return cells, knots_u, knots_v


def off_single_surface(result):
    """Largest distance, relative to the complex's size, of a patch from the single surface
    over its own knot cell."""
    cells, ku, kv = grid(result)
    size = max(np.linalg.norm(p) for _, s in result.patches for p in samples(s, 3))
    worst = 0.0
    for k, column in enumerate(cells):
        for v, (_, patch) in enumerate(column):
            for a in np.linspace(0, 1, 4):
                for b in np.linspace(0, 1, 4):
                    q = result.surface.value(ku[k] + a * (ku[k + 1] - ku[k]), kv[v] + b * (kv[v + 1] - kv[v]))
                    worst = max(worst, (patch.value(a, b) - q).Length / size)
    return worst


def seam_jump(cells, knots_u, knots_v, closed=True):
    """Largest relative jump of position, first and second derivatives across every seam of
    the grid, along u (closing seam included when closed) and along v: Part's getDN on both
    sides, scaled by the knot-interval ratio."""
    worst = 0.0
    pieces_u, rows_v = len(cells), len(cells[0])

    def compare(left, right, at_left, at_right, du, beta):
        nonlocal worst
        # Relative to the derivatives there, or to the patch's extent where they vanish (a pole).
        corners = [left.value(a, b) for a in (0, 1) for b in (0, 1)]
        extent = max((p - q).Length for p in corners for q in corners)
        for t in np.linspace(0, 1, 5):
            pl, pr = (at_left(t), at_right(t))
            d = (lambda s, p, o: s.getDN(p[0], p[1], o, 0)) if du else (lambda s, p, o: s.getDN(p[0], p[1], 0, o))
            scale = max(d(left, pl, 1).Length, d(left, pl, 2).Length, extent)
            worst = max(worst, (right.value(*pr) - left.value(*pl)).Length / scale)
            for order in (1, 2):
                worst = max(worst, (d(right, pr, order) - d(left, pl, order) * beta ** order).Length / scale)

    for k in range(0 if closed else 1, pieces_u):
        left_k = k - 1
        previous = knots_u[k] - knots_u[k - 1] if k > 0 else knots_u[pieces_u] - knots_u[pieces_u - 1]
        beta = (knots_u[k + 1] - knots_u[k]) / previous
        for v in range(rows_v):
            compare(cells[left_k][v][1], cells[k][v][1], lambda t: (1.0, t), lambda t: (0.0, t), True, beta)
    for v in range(1, rows_v):
        beta = (knots_v[v + 1] - knots_v[v]) / (knots_v[v] - knots_v[v - 1])
        for k in range(pieces_u):
            compare(cells[k][v - 1][1], cells[k][v][1], lambda t: (t, 1.0), lambda t: (t, 0.0), False, beta)
    return worst


def roles_along_v(result):
    """The roles of the rows along v, runs of one role shown once (a shape's profile may be
    split into several rows by its conversion)."""
    cells, _, _ = grid(result)
    roles = [role for role, _ in cells[0]]
    return [r for i, r in enumerate(roles) if i == 0 or roles[i - 1] != r]


def least_rise_along_v(result):
    """The least axial component of the v derivative over every patch, relative to its
    length: positive when the complex runs on along the axis from row to row without
    folding back (a ring placed backwards would fold)."""
    worst = math.inf
    for _, s in result.patches:
        for a in np.linspace(0, 1, 4):
            for b in np.linspace(0.05, 0.95, 4):
                d = s.getDN(a, b, 0, 1)
                worst = min(worst, (d.x * AXIS[0] + d.y * AXIS[1] + d.z * AXIS[2]) / d.Length)
    return worst


def check_c2_complex(result):
    assert result.surface is not None and result.surface.Continuity == "C2"
    assert least_rise_along_v(result) > 0
    assert off_single_surface(result) < 1e-9
    cells, ku, kv = grid(result)
    assert seam_jump(cells, ku, kv) < 1e-8
    assert result.shell.isValid()


def test_ball_joint_band_free_form_on_both_sides():
    # A ball joint: a spherical band with the default free-form ring above and below it.
    band = fw.shapes.SphereZone(CENTER, 2.5, NON_UNIFORM, [-0.5, 0.1, 0.6], axis=AXIS)
    result = fw.blend_chain(band, start="default", end="default")
    assert roles_along_v(result) == ["freeform", "transition", "basic", "transition", "freeform"]
    basic = [s for role, s in result.patches if role == "basic"]
    assert basic and max(off_sphere(s, CENTER, 2.5) for s in basic) < 1e-10 * 2.5
    check_c2_complex(result)
    # The rings leave the band on either side: below its lowest and above its highest latitude.
    rings = [s for role, s in result.patches if role == "freeform"]
    heights = [radial(p)[1] for s in rings for p in samples(s, 3)]
    assert min(heights) < 2.5 * math.sin(-0.5) - 0.1 and max(heights) > 2.5 * math.sin(0.6) + 0.1
    # The same check fails for the naive baseline of Fig. 2a at either end.
    for at in ("start", "end"):
        naive = fw.blend_naive(band, at=at)
        strip = [[(role, s)] for role, s in naive.patches if role == "transition"]
        assert seam_jump(strip, fw.freeform_knots(band, "sigma"), [0, 1]) > 1e-3


def test_cylinder_joined_at_both_ends_to_given_rings():
    cylinder = fw.shapes.Cylinder(CENTER, 1.5, NON_UNIFORM, [0.0, 0.7, 2.0], axis=AXIS)
    knots = fw.freeform_knots(cylinder)

    def ring(z0, dz, flare):
        # A bicubic ring on the shape's knots, 4 rows leaving the cylinder along the axis by dz.
        n = len(knots) - 1
        poles = []
        for i in range(n):
            theta = NON_UNIFORM[i]
            row = []
            for j in range(4):
                r = 1.6 * (1 + flare * j)
                x = np.array(cylinder.x_axis) * math.cos(theta) + np.array(cylinder.y_axis) * math.sin(theta)
                p = CENTER + r * x + (z0 + dz * (1.9 + 0.5 * j)) * AXIS
                row.append(fw_vector(p))
            poles.append(row)
        surface = Part.BSplineSurface()
        surface.buildFromPolesMultsKnots(poles, [1] * (n + 1), [4, 4], list(knots), [0.0, 1.0], True, False, 3, 3)
        return surface

    below, above = ring(0.0, -0.3, 0.1), ring(2.0, 0.3, -0.05)
    result = fw.blend_chain(cylinder, start=below, end=above)
    check_c2_complex(result)
    basic = [s for role, s in result.patches if role == "basic"]
    assert max(off_cone(s, 1.5, 0.0) for s in basic) < 1e-10 * 2
    # The free-form patches are the given rings, untouched.
    for role, s in result.patches:
        if role != "freeform":
            continue
        centre = np.mean([p for p in samples(s, 2)], axis=0)
        target = below if radial(centre)[1] < 1.0 else above
        assert max(target.toShape().distToShape(Part.Vertex(fw_vector(p)))[0] for p in samples(s, 3)) < 1e-9


def fw_vector(p):
    import FreeCAD

    return FreeCAD.Vector(*map(float, p))


def test_post_and_dome_with_free_form_below_the_post():
    post = fw.shapes.Cylinder(CENTER, 1.0, NON_UNIFORM, [0.0, 1.0, 1.8], axis=AXIS)
    dome = fw.shapes.SphereZone(CENTER + 2.5 * AXIS, 1.0, OTHER, [0.2, 0.9, math.pi / 2], axis=AXIS)
    result = fw.blend_chain([post, dome], start="default")
    assert roles_along_v(result) == ["freeform", "transition", "basic", "transition", "basic"]
    check_c2_complex(result)
    basic = [s for role, s in result.patches if role == "basic"]
    on_dome = [s for s in basic if off_sphere(s, CENTER + 2.5 * AXIS, 1.0) < 1e-10]
    on_post = [s for s in basic if off_cone(s, 1.0, 0.0) < 1e-10]
    assert on_dome and on_post and len(on_dome) + len(on_post) == len(basic)


def test_three_shapes_and_two_rings_in_one_c2_surface():
    # Cone, cylinder, torus-like bulge: three strips' worth of joins plus rings at both ends,
    # every shape on its own angles (the scalars averaged geometrically).
    cone = fw.shapes.Cone(CENTER, 2.0, 0.3, NON_UNIFORM, [-2.0, -1.2, -0.6], axis=AXIS)
    cylinder = fw.shapes.Cylinder(CENTER, 1.8, OTHER, [0.0, 0.8], axis=AXIS)
    zone = fw.shapes.SphereZone(CENTER + 3.0 * AXIS, 2.0, NON_UNIFORM, [-0.6, 0.0, 0.4], axis=AXIS)
    result = fw.blend_chain([cone, cylinder, zone], start="default", end="default", method="sigma")
    assert roles_along_v(result).count("transition") == 4
    check_c2_complex(result)
    basic = [s for role, s in result.patches if role == "basic"]
    exact = [s for s in basic if off_cone(s, 2.0, 0.3) < 1e-9 or off_cone(s, 1.8, 0.0) < 1e-9
             or off_sphere(s, CENTER + 3.0 * AXIS, 2.0) < 1e-9]
    assert len(exact) == len(basic)


def test_two_edited_structures_joined():
    # Fig. 1c/d edits on both sides of a join: C2 along u everywhere and across the strip.
    lower = fw.shapes.Cylinder(CENTER, 1.5, NON_UNIFORM, [0.0, 0.8, 1.5], axis=AXIS)
    upper = fw.shapes.Cylinder(CENTER, 1.5, NON_UNIFORM, [2.0, 2.6, 3.4], axis=AXIS)
    for shape, (i, j) in ((lower, (1, 1)), (upper, (4, 0))):
        point, _ = shape.control_point(i, j, 1, 2)
        shape.set_control(i, j, 1, 2, CENTER + 1.25 * (np.array(point) - CENTER))
    result = fw.blend_chain([lower, upper], method="sigma")
    assert result.surface is None  # G2 along the profiles of edited structures
    assert result.shell.isValid()
    knots_u = fw.freeform_knots(lower, "sigma")
    rows = 2 + 1 + 2
    cells = [[result.patches[k * rows + v] for v in range(rows)] for k in range(len(knots_u) - 1)]
    assert [role for role, _ in cells[0]] == ["basic", "basic", "transition", "basic", "basic"]
    # C2 along u in every row, and across both seams of the strip (rows 1-2 and 2-3).
    worst = 0.0
    for v in range(rows):
        worst = max(worst, seam_jump([[c[v]] for c in cells], knots_u, [0, 1]))
    assert worst < 1e-8
    strip = [[c[1], c[2], c[3]] for c in cells]
    assert seam_jump(strip, knots_u, [0, 1, 2, 3]) < 1e-8
    # Both edits are in the result: the edited arcs leave the cylinder, arcs away from them stay.
    off = [[off_cone(cells[k][v][1], 1.5, 0.0) for v in (0, 1, 3, 4)] for k in range(len(cells))]
    assert off[1][1] > 1e-3 and off[4][2] > 1e-3
    assert off[6][0] < 1e-10 and off[6][3] < 1e-10


def test_bad_chains():
    band = fw.shapes.SphereZone(CENTER, 2.5, NON_UNIFORM, [-0.5, 0.6], axis=AXIS)
    dome = fw.shapes.SphereZone(CENTER, 1.0, NON_UNIFORM, [0.2, math.pi / 2], axis=AXIS)
    six = fw.shapes.Cylinder(CENTER, 1.0, [0, 1, 2, 3, 4, 5, 2 * math.pi], [0.0, 1.0], axis=AXIS)
    with pytest.raises(fw.InputError, match="nothing to join"):
        fw.blend_chain(band)
    with pytest.raises(fw.InputError, match="at least one shape"):
        fw.blend_chain([])
    with pytest.raises(fw.InputError, match="profile meets the axis .* at its end"):
        fw.blend_chain(dome, end="default")
    with pytest.raises(fw.InputError, match="shape 2's profile meets the axis"):
        fw.blend_chain([band, dome], end="default")
    with pytest.raises(fw.InputError, match="shape 3 has 6"):
        fw.blend_chain([band, band, six])
    with pytest.raises(fw.InputError, match="start"):
        fw.blend_chain(band, start="automatic")
