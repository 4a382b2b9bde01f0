"""Issue 15, part 2: the default ring for any shape. The ring adapts its extent to the room
the shape leaves towards the axis, and the default interface (at=None, the feature's Auto)
picks the end of the profile that has room. Judged by OCCT evaluation of the returned Part
geometry, as the other blend tests are: the basic patches on the exact shape within 1e-10
of its size, the strip C2 along u (Part getDN on both sides of every seam), the single
surface C2 by OCCT, the shell valid."""
import itertools
import math

import numpy as np
import pytest

import freecad_workbench as fw

from .test_blend import _strip_jump, samples

LON = [0.0, 0.9, 1.7, 2.8, 3.6, 4.4, 5.3, 2 * math.pi]


def _check_blend(shape, result, on_shape, size):
    basic = [s for role, s in result.patches if role == "basic"]
    assert max(abs(on_shape(p)) for s in basic for p in samples(s, 5)) < 1e-10 * size
    assert result.surface is not None and result.surface.Continuity == "C2"
    assert result.shell.isValid()
    assert _strip_jump(result.patches, fw.freeform_knots(shape, "sigma")) < 1e-8  # sigma: one patch per arc


def _on_sphere(radius):
    return lambda p: p.Length - radius


# Every latitude range in steps of 15 degrees away from the poles; one end within 10 degrees of
# a pole is fine as long as the other end has room.
ZONES = [(lo, hi) for lo, hi in itertools.combinations(range(-80, 81, 20), 2)]


@pytest.mark.parametrize("lo, hi", ZONES, ids=[f"{lo}..{hi}" for lo, hi in ZONES])
def test_every_sphere_zone_blends_with_the_default_ring(lo, hi):
    zone = fw.shapes.SphereZone((0, 0, 0), 2.5, LON, np.radians(np.linspace(lo, hi, 4)))
    _check_blend(zone, fw.blend_basic_shape(zone, method="sigma"), _on_sphere(2.5), 2.5)


def test_the_issues_zone_blends_at_the_end_with_a_shorter_ring():
    """latitudes 20..70 raised "the default ring would reach the axis"; the ring now stops
    short of the axis at the top, and still joins C2."""
    zone = fw.shapes.SphereZone((0, 0, 0), 2.5, LON, np.radians([20, 35, 55, 70]))
    result = fw.blend_basic_shape(zone, at="end", method="sigma")
    _check_blend(zone, result, _on_sphere(2.5), 2.5)
    ring = [s for role, s in result.patches if role == "freeform"]
    axis_distance = min(math.hypot(p.x, p.y) for s in ring for p in samples(s, 6))
    assert axis_distance > 0.05 * 2.5  # clear of the axis
    top = max(p.z for s in ring for p in samples(s, 6))
    assert top > 2.5 * math.sin(math.radians(70))  # it continues beyond the interface


def test_auto_picks_the_end_with_room():
    # Latitudes -30..80: the top (end) is 10 degrees from the pole, the bottom has room.
    zone = fw.shapes.SphereZone((0, 0, 0), 2.5, LON, np.radians([-30, 20, 50, 80]))
    auto = fw.blend_basic_shape(zone)
    start = fw.blend_basic_shape(zone, at="start")
    ring_z = [p.z for role, s in auto.patches if role == "freeform" for p in samples(s, 4)]
    assert max(ring_z) < 2.5 * math.sin(math.radians(-30))  # below the zone: the start
    assert [s.getPoles() for _, s in auto.patches] == [s.getPoles() for _, s in start.patches]
    # With a room for both, the end, as before.
    both = fw.shapes.SphereZone((0, 0, 0), 2.5, LON, np.radians([-30, 0, 30]))
    assert max(p.z for role, s in fw.blend_basic_shape(both).patches if role == "freeform"
               for p in samples(s, 4)) > 2.5 * math.sin(math.radians(30))


def test_an_end_with_no_room_says_what_to_change():
    zone = fw.shapes.SphereZone((0, 0, 0), 2.5, LON, np.radians([-30, 20, 60, 88]))
    with pytest.raises(fw.InputError, match="no room at the interface.*other end.*free-form ring"):
        fw.blend_basic_shape(zone, at="end")


@pytest.mark.parametrize("slope", [-1.5, -0.4, 0.0, 0.6, 3.0])
@pytest.mark.parametrize("at", [None, "end", "start"])
def test_cylinders_and_cones_blend_at_either_end(slope, at):
    radius0, heights = 1.2, [0.0, 0.3, 0.7]
    if slope < 0 and at == "end" or slope > 0 and at == "start":
        heights = [0.0, 0.2, 0.45]  # narrowing towards the apex: keep the apex clear of the shape
    cone = fw.shapes.Cone((0, 0, 0), radius0, slope, LON, heights)

    def off(p):
        return math.hypot(p.x, p.y) - (radius0 + slope * p.z)
    _check_blend(cone, fw.blend_basic_shape(cone, at=at, method="sigma"), off, radius0)


TUBES = [(-2.5, -1.0), (-1.0, 0.5), (0.5, 2.0), (2.0, 3.0), (1.0, 2.8), (-3.0, -1.5)]


@pytest.mark.parametrize("v0, v1", TUBES, ids=[f"{a}..{b}" for a, b in TUBES])
@pytest.mark.parametrize("at", [None, "end", "start"])
def test_tori_blend_with_the_default_ring_at_either_end(v0, v1, at):
    torus = fw.shapes.Torus((0, 0, 0), 3.0, 1.0, LON, np.linspace(v0, v1, 4))

    def off(p):
        return math.hypot(math.hypot(p.x, p.y) - 3.0, p.z) - 1.0
    _check_blend(torus, fw.blend_basic_shape(torus, at=at, method="sigma"), off, 3.0)
