"""The Face blend feature (issue 29): built headless from two faces' edges, follows its sources,
saves, reopens and recomputes identically; bad sources keep the last good shape with the message
in Status. Geometry judged by OCCT (fw.blend_errors), not by the construction."""
import numpy as np

import FreeCAD
import Part

import freecad_workbench as fw
from freecad_workbench.features import FaceBlend, make_face_blend
from tests.scenes import rim_edge

V = FreeCAD.Vector


def _cylinders(doc, offset=0.0):
    a = doc.addObject("Part::Cylinder", "A")
    a.Radius, a.Height = 1.0, 1.0
    b = doc.addObject("Part::Cylinder", "B")
    b.Radius, b.Height = 1.5, 1.0
    b.Placement = FreeCAD.Placement(V(offset, 0, 2.0), FreeCAD.Rotation())
    doc.recompute()
    return a, b


def _poles(obj):
    return np.array([[tuple(p) for p in row] for row in obj.Shape.Faces[0].Surface.getPoles()])


def _make(doc, a, b):
    return make_face_blend(doc, (a, "Face1"), (a, rim_edge(a, 1.0)), (b, "Face1"), (b, rim_edge(b, 2.0)))


def test_feature_is_g2_and_follows_its_sources(doc):
    a, b = _cylinders(doc)
    blend = _make(doc, a, b)
    assert blend.Status.startswith("ok: G2, exact / exact"), blend.Status
    surface = blend.Shape.Faces[0].Surface
    errors = fw.blend_errors(surface, a.Shape.Faces[0], a.Shape.getElement(rim_edge(a, 1.0)), 0.0)
    assert errors["gap"] < 1e-7 and errors["angle"] < 1e-4 and errors["curvature_jump"] < 1e-4, errors
    before = _poles(blend)
    b.Placement = FreeCAD.Placement(V(0.3, 0, 2.0), FreeCAD.Rotation())
    doc.recompute()
    moved = blend.Shape.Faces[0].Surface
    assert not np.allclose(_poles(blend), before)
    errors = fw.blend_errors(moved, b.Shape.Faces[0], b.Shape.getElement(rim_edge(b, 2.0)), 1.0)
    assert errors["gap"] < 1e-7 and errors["curvature_jump"] < 1e-4, errors


def test_save_reopen_recompute_is_identical(doc, tmp_path):
    a, b = _cylinders(doc, offset=0.2)
    blend = _make(doc, a, b)
    before = _poles(blend)
    path = str(tmp_path / "face_blend.FCStd")
    doc.saveAs(path)
    FreeCAD.closeDocument(doc.Name)
    reopened = FreeCAD.openDocument(path)
    try:
        blend = reopened.getObject("FaceBlend")
        assert isinstance(blend.Proxy, FaceBlend)
        assert (blend.Version, blend.ContinuityA, blend.ContinuityB) == (FaceBlend.VERSION, "G2", "G2")
        # The saved shape and the recompute from the saved sources agree to rounding (the sources'
        # BRep text in the file keeps 17 digits, not every bit of a zero: 5e-18 was seen).
        np.testing.assert_allclose(_poles(blend), before, rtol=0, atol=1e-14)
        blend.touch()
        reopened.recompute()
        assert blend.Status.startswith("ok: G2"), blend.Status
        np.testing.assert_allclose(_poles(blend), before, rtol=0, atol=1e-14)
    finally:
        FreeCAD.closeDocument(reopened.Name)


def test_bad_sources_keep_the_last_good_shape(doc):
    a, b = _cylinders(doc)
    blend = _make(doc, a, b)
    good = _poles(blend)
    blend.EdgeB = (a, rim_edge(a, 0.0))  # an edge of the other face
    doc.recompute()
    assert "edge_b is not an edge of face_b" in blend.Status
    assert "Invalid" in blend.State
    np.testing.assert_array_equal(_poles(blend), good)
    blend.EdgeB = (b, rim_edge(b, 2.0))
    blend.ContinuityA = blend.ContinuityB = "G1"
    doc.recompute()
    assert blend.Status.startswith("ok: G1"), blend.Status
    assert isinstance(blend.Shape.Faces[0].Surface, Part.BSplineSurface)


def test_continuity_per_side_and_a_version_1_file_migrates(doc, tmp_path):
    """G2 at the first face, G1 at the second: the status says so and the surface is a quartic
    across (OCCT's VDegree). A file of version 1 (one Continuity for both sides) reopens with
    that value on both sides, the old property gone, and recomputes to the same blend."""
    a, b = _cylinders(doc, offset=0.2)
    blend = _make(doc, a, b)
    blend.ContinuityB = "G1"
    doc.recompute()
    assert blend.Status.startswith("ok: G2 / G1"), blend.Status
    assert blend.Shape.Faces[0].Surface.VDegree == 4
    # Made old: the one property of version 1, set to G1.
    blend.ContinuityA = blend.ContinuityB = "G1"
    doc.recompute()
    g1 = _poles(blend)
    blend.removeProperty("ContinuityA")
    blend.removeProperty("ContinuityB")
    blend.addProperty("App::PropertyEnumeration", "Continuity", "Face blend", "")
    blend.Continuity = ["G1", "G2"]
    blend.Continuity = "G1"
    blend.Version = 1
    path = str(tmp_path / "face_blend_v1.FCStd")
    doc.saveAs(path)
    FreeCAD.closeDocument(doc.Name)
    reopened = FreeCAD.openDocument(path)
    try:
        blend = reopened.getObject("FaceBlend")
        assert "Continuity" not in blend.PropertiesList
        assert (blend.Version, blend.ContinuityA, blend.ContinuityB) == (2, "G1", "G1")
        blend.touch()
        reopened.recompute()
        assert blend.Status.startswith("ok: G1,"), blend.Status
        np.testing.assert_allclose(_poles(blend), g1, rtol=0, atol=1e-14)
    finally:
        FreeCAD.closeDocument(reopened.Name)
