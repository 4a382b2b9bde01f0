"""Blend basic shape feature, headless: builds for every kind (the patches themselves are
judged in tests/kernel/test_blend.py), recompute after a change, the naive variant, uniform
lists, save/reopen, undo, and the error state that keeps the last good shape."""

import numpy as np
import pytest

import FreeCAD

import freecad_workbench as fw
from freecad_workbench.errors import InputError
from freecad_workbench.features.blend_shape import (
    KIND_LISTS,
    KINDS,
    BlendShape,
    angle_lists,
    is_blend_shape,
    make_blend_shape,
)


def surface_points(shape, n=4):
    """A few points of every face's surface, face by face."""
    points = []
    for face in shape.Faces:
        u0, u1, v0, v1 = face.ParameterRange
        for u in np.linspace(u0, u1, n):
            for v in np.linspace(v0, v1, n):
                p = face.valueAt(float(u), float(v))
                points.append((p.x, p.y, p.z))
    return np.array(points)


@pytest.mark.parametrize("kind", KINDS)
def test_every_kind_builds_a_valid_shell_of_shared_edges(doc, kind):
    obj = make_blend_shape(doc, kind)
    assert is_blend_shape(obj) and isinstance(obj.Proxy, BlendShape)
    assert obj.Status == "ok" and obj.Uniform
    shape = obj.Shape
    assert shape.ShapeType == "Shell" and shape.isValid()
    assert obj.Patches == "basic 18, transition 6, freeform 6" and len(shape.Faces) == 30
    # 6 pieces around a full turn, 5 rows: neighbours share their edges, only both ends are free
    assert len(shape.Edges) == 6 * 6 + 6 * 5 and len(shape.getFreeEdges().Edges) == 2 * 6
    # the object's own editor shows the kind's dimensions only
    for name in KIND_LISTS[kind]:
        assert obj.getEditorMode(name) == ["Hidden"]  # uniform: the lists are generated
    assert obj.getEditorMode("AroundCount") == []


@pytest.mark.parametrize("method", ["rho", "sigma", "mixed"])
def test_shell_is_the_macro_api_blend(doc, method):
    longitudes = [0.0, 40.0, 100.0, 170.0, 260.0, 360.0]
    latitudes = [-40.0, -5.0, 25.0, 45.0]
    obj = make_blend_shape(doc, "Sphere zone", Radius=8.0, Longitudes=longitudes, Latitudes=latitudes,
                           method=method)
    assert obj.Status == "ok" and not obj.Uniform
    zone = fw.shapes.SphereZone((0, 0, 0), 8.0, np.radians(longitudes), np.radians(latitudes))
    expected = fw.blend_basic_shape(zone, method=method).shell
    np.testing.assert_allclose(surface_points(obj.Shape), surface_points(expected), atol=1e-12)


def test_uniform_lists_come_from_counts_and_range(doc):
    obj = make_blend_shape(doc, "Cylinder", AroundCount=4, ProfileCount=2, ProfileStart=-3.0, ProfileEnd=5.0)
    assert angle_lists(obj) == ([0.0, 90.0, 180.0, 270.0, 360.0], [-3.0, 1.0, 5.0])
    assert obj.Patches == "basic 8, transition 4, freeform 4"
    obj.Uniform = False  # back to the (default) lists
    doc.recompute()
    assert obj.Status == "ok" and obj.Patches == "basic 18, transition 6, freeform 6"
    assert obj.getEditorMode("Heights") == [] and obj.getEditorMode("ProfileCount") == ["Hidden"]


def test_recompute_after_a_dimension_change_changes_the_shape(doc):
    obj = make_blend_shape(doc, "Torus")
    before = surface_points(obj.Shape)
    obj.MinorRadius = 7.0
    doc.recompute()
    assert obj.Status == "ok" and obj.Shape.isValid()
    after = surface_points(obj.Shape)
    assert after.shape == before.shape and np.abs(after - before).max() > 1.0
    obj.Placement = FreeCAD.Placement(FreeCAD.Vector(0, 0, 30), FreeCAD.Rotation())
    doc.recompute()
    np.testing.assert_allclose(surface_points(obj.Shape), after + (0, 0, 30), atol=1e-9)


def test_naive_flag_builds_the_naive_blend(doc):
    obj = make_blend_shape(doc, "Sphere zone", Longitudes=[0.0, 40.0, 100.0, 170.0, 260.0, 360.0],
                           Latitudes=[-40.0, -5.0, 25.0, 45.0], method="sigma")
    c2 = surface_points(obj.Shape)
    obj.Naive = True
    doc.recompute()
    assert obj.Status == "ok" and obj.Shape.isValid()
    zone = fw.shapes.SphereZone((0, 0, 0), 10.0, np.radians([0.0, 40.0, 100.0, 170.0, 260.0, 360.0]),
                                np.radians([-40.0, -5.0, 25.0, 45.0]))
    np.testing.assert_allclose(surface_points(obj.Shape), surface_points(fw.blend_naive(zone).shell), atol=1e-12)
    naive = surface_points(obj.Shape)
    assert naive.shape != c2.shape or np.abs(naive - c2).max() > 1e-6


def test_save_reopen_recompute_gives_the_same_shape(doc, tmp_path):
    obj = make_blend_shape(doc, "Cone", Radius0=12.0, Slope=-0.25, Angles=[0.0, 70.0, 150.0, 240.0, 360.0],
                           Heights=[0.0, 3.0, 9.0], method="mixed")
    points = surface_points(obj.Shape)
    path = str(tmp_path / "blend.FCStd")
    doc.saveAs(path)
    name, obj_name = doc.Name, obj.Name
    FreeCAD.closeDocument(name)
    reopened = FreeCAD.openDocument(path)
    try:
        again = reopened.getObject(obj_name)
        assert is_blend_shape(again) and again.Kind == "Cone" and again.Method == "mixed"
        np.testing.assert_allclose(surface_points(again.Shape), points, atol=1e-12)
        again.touch()
        reopened.recompute()
        assert again.Status == "ok"
        np.testing.assert_allclose(surface_points(again.Shape), points, atol=1e-12)
    finally:
        FreeCAD.closeDocument(reopened.Name)
        FreeCAD.newDocument(name)  # for the fixture to close


def test_undo_removes_the_feature(doc):
    doc.UndoMode = 1
    make_blend_shape(doc, "Cylinder")
    assert doc.getObject("BlendShape") is not None
    assert doc.UndoNames and doc.UndoNames[0] == "Create blend basic shape"
    doc.undo()
    assert doc.getObject("BlendShape") is None


@pytest.mark.parametrize(
    "change, message",
    [
        (dict(Uniform=False, Longitudes=[0.0, 90.0, 90.0, 360.0]),
         "longitudes: value 2 (90°) must be greater than value 1 (90°)"),
        (dict(Uniform=False, Longitudes=[0.0, 180.0, 360.0, 400.0]), "more than a full turn"),
        (dict(Radius=0.0), "radius"),
        (dict(AroundCount=0), "at least 1"),
        (dict(Interface="End", ProfileEnd=89.5), "no room at the interface"),
    ],
)
def test_bad_input_keeps_the_last_good_shape_with_the_message(doc, change, message):
    obj = make_blend_shape(doc, "Sphere zone")
    points = surface_points(obj.Shape)
    for key, value in change.items():
        setattr(obj, key, value)
    doc.recompute()
    assert message in obj.Status.lower(), obj.Status
    assert obj.Status != "ok"
    np.testing.assert_array_equal(surface_points(obj.Shape), points)
    # fixing it recovers
    for key, value in change.items():
        setattr(obj, key, {"Uniform": True, "Longitudes": [0.0, 120.0, 240.0, 360.0], "Radius": 10.0,
                           "AroundCount": 6, "ProfileEnd": 45.0, "Interface": "Auto"}[key])
    doc.recompute()
    assert obj.Status == "ok"


def test_factory_rejects_unknown_kinds_methods_and_dimensions(doc):
    with pytest.raises(InputError, match="unknown kind"):
        make_blend_shape(doc, "Ellipsoid")
    with pytest.raises(InputError, match="unknown method"):
        make_blend_shape(doc, "Torus", method="tau")
    with pytest.raises(InputError, match="no dimension Heights"):
        make_blend_shape(doc, "Torus", Heights=[0, 1])
    assert not doc.Objects


def _ring_object(doc, radius=6.0, z0=8.5, poles=9, name="Ring", dz=0.6):
    """A periodic bicubic ring around the Z axis, on its own uniform knots, as a Part::Feature
    (its rows dz apart along Z)."""
    import math

    import Part

    rows = [[FreeCAD.Vector(radius * math.cos(a), radius * math.sin(a), z0 + dz * j) for j in range(4)]
            for a in np.linspace(0, 2 * math.pi, poles, endpoint=False)]
    ring = Part.BSplineSurface()
    ring.buildFromPolesMultsKnots(rows, [1] * (poles + 1), [4, 4], [float(k) for k in range(poles + 1)], [0.0, 1.0],
                                  True, False, 3, 3)
    obj = doc.addObject("Part::Feature", name)
    obj.Shape = Part.Face(ring)
    doc.recompute()
    return obj


def _distance_to(surface, points):
    worst = 0.0
    for p in points:
        q = FreeCAD.Vector(*p)
        u, v = surface.parameter(q)
        worst = max(worst, (surface.value(u, v) - q).Length)
    return worst


def test_a_linked_bspline_face_is_the_free_form_side_and_moves_with_its_object(doc, tmp_path):
    ring = _ring_object(doc)
    obj = make_blend_shape(doc, "Sphere zone", freeform=(ring, "Face1"))
    assert obj.Status == "ok", obj.Status
    assert obj.Shape.isValid()
    counts = dict(item.split() for item in obj.Patches.split(", "))
    assert int(counts["freeform"]) == int(counts["transition"]) > 6  # the ring's 9 knots merged in
    # the free-form patches are pieces of the linked surface itself
    on_ring = [f for f in obj.Shape.Faces if _distance_to(ring.Shape.Faces[0].Surface, surface_points(f, 3)) < 1e-9]
    assert len(on_ring) == int(counts["freeform"])
    # moving the ring recomputes the blend onto the moved ring
    ring.Placement = FreeCAD.Placement(FreeCAD.Vector(0, 0, 1.5), FreeCAD.Rotation())
    doc.recompute()
    assert obj.Status == "ok"
    moved = ring.Shape.Faces[0].Surface
    assert sum(_distance_to(moved, surface_points(f, 3)) < 1e-9 for f in obj.Shape.Faces) == len(on_ring)
    # save and reopen keep the link
    path = str(tmp_path / "ring.FCStd")
    doc.saveAs(path)
    name, obj_name = doc.Name, obj.Name
    FreeCAD.closeDocument(name)
    reopened = FreeCAD.openDocument(path)
    try:
        again = reopened.getObject(obj_name)
        assert again.FreeForm[0].Name == "Ring" and again.FreeForm[1] == ["Face1"]
        again.touch()
        reopened.recompute()
        assert again.Status == "ok"
    finally:
        FreeCAD.closeDocument(reopened.Name)
        FreeCAD.newDocument(name)


def test_a_face_that_is_no_ring_keeps_the_last_good_shape(doc):
    import Part

    obj = make_blend_shape(doc, "Cylinder")
    points = surface_points(obj.Shape)
    box = doc.addObject("Part::Feature", "Box")
    box.Shape = Part.makeBox(2, 2, 2)
    obj.FreeForm = (box, ["Face1"])
    doc.recompute()
    assert "not a B-spline surface" in obj.Status
    np.testing.assert_array_equal(surface_points(obj.Shape), points)
    away = _ring_object(doc, radius=3.0, name="Away")
    away.Placement = FreeCAD.Placement(FreeCAD.Vector(40, 0, 0), FreeCAD.Rotation())
    obj.FreeForm = (away, ["Face1"])
    doc.recompute()
    assert "does not go once around" in obj.Status
    obj.FreeForm = None
    doc.recompute()
    assert obj.Status == "ok"


def test_a_dome_joins_at_its_start(doc):
    obj = make_blend_shape(doc, "Sphere zone", Uniform=True, ProfileStart=20.0, ProfileEnd=90.0)
    assert obj.Status == "ok" and obj.Shape.isValid()
    z = surface_points(obj.Shape)[:, 2]
    assert z.min() < 10.0 * np.sin(np.radians(20.0)) - 1.0  # the ring hangs below the dome
    obj.Interface = "End"
    doc.recompute()
    assert "pole" in obj.Status


def test_join_to_another_blend_shape_joins_the_two_basic_shapes(doc, tmp_path):
    # Figs. 9-10 in the document: a cylinder post, a spherical dome placed above it.
    dome = make_blend_shape(doc, "Sphere zone", name="Dome", Radius=10.0, Uniform=True, ProfileStart=15.0,
                            ProfileEnd=90.0, ProfileCount=2,
                            placement=FreeCAD.Placement(FreeCAD.Vector(0, 0, 22), FreeCAD.Rotation()))
    post = make_blend_shape(doc, "Cylinder", name="Post", Radius=10.0, join_to=dome)
    assert post.Status == "ok", post.Status
    assert post.Patches.endswith("freeform 0") and post.Shape.isValid()
    # both shapes exact: the post's faces on its cylinder or on the dome's sphere
    points = surface_points(post.Shape)
    radial = np.hypot(points[:, 0], points[:, 1])
    on_post = np.abs(radial - 10.0) < 1e-9
    on_dome = np.abs(np.linalg.norm(points - (0, 0, 22), axis=1) - 10.0) < 1e-9
    assert on_post.sum() > 100 and on_dome.sum() > 100
    assert points[:, 2].max() > 31.9  # the dome's pole
    expected = fw.join_basic_shapes(fw.shapes.Cylinder((0, 0, 0), 10.0, np.radians(np.linspace(0, 360, 7)),
                                                       [0.0, 5.0, 10.0, 15.0]),
                                    fw.shapes.SphereZone((0, 0, 22), 10.0, np.radians(np.linspace(0, 360, 7)),
                                                         np.radians([15.0, 52.5, 90.0])))
    np.testing.assert_allclose(points, surface_points(expected.shell), atol=1e-9)
    # moving the dome recomputes the join
    dome.Placement = FreeCAD.Placement(FreeCAD.Vector(0, 0, 25), FreeCAD.Rotation())
    doc.recompute()
    assert post.Status == "ok" and surface_points(post.Shape)[:, 2].max() > 34.9
    # a join back is refused; clearing JoinTo gives the ring again
    dome.JoinTo = post
    doc.recompute()
    assert "joins back" in post.Status or "joins back" in dome.Status
    dome.JoinTo = None
    post.JoinTo = None
    doc.recompute()
    assert post.Status == "ok" and "freeform 6" in post.Patches
    other = make_blend_shape(doc, "Cone", name="Cone", AroundCount=4)
    post.JoinTo = other
    doc.recompute()
    assert "same number of arcs" in post.Status


@pytest.mark.parametrize("kind", KINDS)
def test_c1_continuity_builds_the_section_5_blend(doc, kind):
    obj = make_blend_shape(doc, kind, continuity="C1")
    assert obj.Status == "ok", obj.Status
    assert obj.Shape.isValid()
    # six arcs around: two quartics an arc, two strip rows
    assert "transition 24" in obj.Patches
    degrees = {(f.Surface.UDegree, f.Surface.VDegree) for f in obj.Shape.Faces}
    assert (4, 2) in degrees
    c2 = make_blend_shape(doc, kind)
    assert c2.Patches != obj.Patches
    obj.Continuity = "C2"
    doc.recompute()
    assert obj.Patches == c2.Patches


def test_a_partial_turn_builds_an_open_blend(doc):
    obj = make_blend_shape(doc, "Cylinder", Angles=[0.0, 60.0, 150.0, 200.0])
    assert obj.Status == "ok", obj.Status
    assert not obj.Uniform and obj.Shape.isValid()
    assert obj.Patches == "basic 27, transition 9, freeform 9"  # rho: three pieces for each of the three arcs
    points = surface_points(obj.Shape)
    angles = np.mod(np.degrees(np.arctan2(points[:, 1], points[:, 0])) + 1e-6, 360.0) - 1e-6
    assert angles.max() < 200.0 + 1e-6 and angles.max() > 199.0  # it spans the partial turn only


def test_an_empty_profile_range_blames_the_range_not_the_count(doc):
    """Issue 13: with Uniform, ProfileEnd == ProfileStart was reported against ProfileCount."""
    from tests.scenes import assert_failed_like_freecad

    blend = make_blend_shape(doc, "Cylinder")
    assert blend.Status == "ok"
    blend.ProfileEnd = blend.ProfileStart
    doc.recompute()
    assert_failed_like_freecad(blend, "ProfileEnd (0) must be greater than ProfileStart (0)")
    assert "ProfileCount" not in blend.Status


def test_both_ends_of_a_band_join_free_form_in_one_complex(doc, tmp_path):
    # The second interface: a sphere band with a linked ring above and one below, as a ball joint.
    above = _ring_object(doc, name="Above")
    below = _ring_object(doc, radius=6.5, z0=-8.5, dz=-0.6, name="Below")
    obj = make_blend_shape(doc, "Sphere zone", interface="Both ends", freeform=(above, "Face1"),
                           freeform_start=(below, "Face1"))
    assert obj.Status == "ok", obj.Status
    assert obj.Shape.isValid()
    counts = dict(item.split() for item in obj.Patches.split(", "))
    strips = int(counts["transition"])
    assert int(counts["freeform"]) == strips  # one ring span per strip patch, two rings
    faces = obj.Shape.Faces
    on_above = [f for f in faces if _distance_to(above.Shape.Faces[0].Surface, surface_points(f, 3)) < 1e-9]
    on_below = [f for f in faces if _distance_to(below.Shape.Faces[0].Surface, surface_points(f, 3)) < 1e-9]
    assert len(on_above) + len(on_below) == int(counts["freeform"]) and on_above and on_below
    points = surface_points(obj.Shape)
    on_sphere = np.abs(np.linalg.norm(points, axis=1) - 10.0) < 1e-9
    assert on_sphere.sum() > 100
    # The default rings where no face is linked: the same counts as the single-interface blend, twice.
    obj.FreeForm = None
    obj.FreeFormStart = None
    doc.recompute()
    single = make_blend_shape(doc, "Sphere zone")
    both = dict(item.split() for item in obj.Patches.split(", "))
    one = dict(item.split() for item in single.Patches.split(", "))
    assert obj.Status == "ok" and int(both["freeform"]) == 2 * int(one["freeform"])
    # C1 and the naive blend join at one end: the message, and the last good shape kept.
    good = surface_points(obj.Shape)
    obj.Continuity = "C1"
    doc.recompute()
    assert "one end" in obj.Status
    np.testing.assert_allclose(surface_points(obj.Shape), good, atol=1e-12)
    obj.Continuity = "C2"
    obj.Naive = True
    doc.recompute()
    assert "Naive off" in obj.Status
    obj.Naive = False
    doc.recompute()
    assert obj.Status == "ok"
    # Save and reopen keep the interface.
    path = str(tmp_path / "both.FCStd")
    doc.saveAs(path)
    name, obj_name = doc.Name, obj.Name
    FreeCAD.closeDocument(name)
    reopened = FreeCAD.openDocument(path)
    try:
        again = reopened.getObject(obj_name)
        assert again.Interface == "Both ends"
        again.touch()
        reopened.recompute()
        assert again.Status == "ok"
        np.testing.assert_allclose(surface_points(again.Shape), good, atol=1e-12)
    finally:
        FreeCAD.closeDocument(reopened.Name)
        FreeCAD.newDocument(name)


def test_a_join_with_free_form_below_the_first_shape(doc):
    dome = make_blend_shape(doc, "Sphere zone", name="Dome", Radius=10.0, Uniform=True, ProfileStart=15.0,
                            ProfileEnd=90.0, ProfileCount=2,
                            placement=FreeCAD.Placement(FreeCAD.Vector(0, 0, 22), FreeCAD.Rotation()))
    post = make_blend_shape(doc, "Cylinder", name="Post", Radius=10.0, join_to=dome, interface="Start")
    assert post.Status == "ok", post.Status
    counts = dict(item.split() for item in post.Patches.split(", "))
    assert int(counts["freeform"]) == 6 and int(counts["transition"]) == 12  # a ring below, two strips
    points = surface_points(post.Shape)
    assert points[:, 2].min() < -1.0 and points[:, 2].max() > 31.9  # below the post, up to the dome's pole
    # End would be beyond the dome's pole: refused with the reason.
    post.Interface = "End"
    doc.recompute()
    assert "pole" in post.Status


def test_a_revolution_of_a_sketch_like_profile_blends_and_follows_it(doc):
    # Issue 32: the Revolution kind revolves a linked profile (here a shape of a line and a
    # tangent arc, as a sketch's edges), exactly, and recomputes when the profile moves.
    import math

    import Part

    h = math.sqrt(0.5)
    line = Part.LineSegment(FreeCAD.Vector(4, 0, 0), FreeCAD.Vector(4, 0, 3)).toShape()
    arc = Part.Arc(FreeCAD.Vector(4, 0, 3), FreeCAD.Vector(5 - h, 0, 3 + h), FreeCAD.Vector(5, 0, 4)).toShape()
    source = doc.addObject("Part::Feature", "ProfileSource")
    source.Shape = Part.Compound([line, arc])
    obj = make_blend_shape(doc, "Revolution", profile=source)
    assert obj.Status == "ok", obj.Status
    assert obj.Shape.isValid()
    # the macro API's blend of the same profile, split at thirds of its parameter range
    curve = fw.shapes.joined_profile(source.Shape)
    a, b = curve.FirstParameter, curve.LastParameter
    shape = fw.shapes.Revolution(curve, (0, 0, 0), (0, 0, 1), np.radians(np.linspace(0, 360, 7)),
                                 [a + (b - a) / 3, a + 2 * (b - a) / 3])
    expected = fw.blend_basic_shape(shape).shell
    np.testing.assert_allclose(surface_points(obj.Shape), surface_points(expected), atol=1e-12)
    source.Placement.Base = FreeCAD.Vector(0, 0, 1)
    doc.recompute()
    assert obj.Status == "ok" and surface_points(obj.Shape)[:, 2].min() > 0.9
    bad = doc.addObject("Part::Feature", "Crossing")
    bad.Shape = Part.LineSegment(FreeCAD.Vector(1, 0, 0), FreeCAD.Vector(-1, 0, 1)).toShape()
    obj.Profile = bad
    doc.recompute()
    assert "axis" in obj.Status
