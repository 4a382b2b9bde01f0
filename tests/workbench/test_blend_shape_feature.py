"""Blend basic shape feature, headless: builds for every kind (the patches themselves are
judged in tests/kernel/test_blend.py), recompute after a change, the naive variant, uniform
lists, save/reopen, undo, and the error state that keeps the last good shape."""
import os

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
def test_every_kind_builds_a_valid_sewn_shell(doc, kind):
    obj = make_blend_shape(doc, kind)
    assert is_blend_shape(obj) and isinstance(obj.Proxy, BlendShape)
    assert obj.Status == "ok" and obj.Uniform
    shape = obj.Shape
    assert shape.ShapeType == "Shell" and shape.isValid()
    assert obj.Patches == "basic 18, transition 6, freeform 6" and len(shape.Faces) == 30
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
        (dict(Uniform=False, Longitudes=[0.0, 90.0, 90.0, 360.0]), "longitudes: value 2 (90°) must be greater than value 1 (90°)"),
        (dict(Uniform=False, Longitudes=[0.0, 90.0, 180.0]), "full turn"),
        (dict(Radius=0.0), "radius"),
        (dict(AroundCount=0), "at least 1"),
        (dict(ProfileEnd=89.0), "axis"),
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
                           "AroundCount": 6, "ProfileEnd": 45.0}[key])
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
