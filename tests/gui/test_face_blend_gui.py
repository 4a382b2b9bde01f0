"""The Blend faces command (issue 29) in a real FreeCAD GUI under Xvfb: two edges picked on two
Part cylinders' faces make the feature in one undo step and open its panel; the panel drives
continuity, flip, the covered part and the depth per side live, and the blend follows (judged by
OCCT: fw.blend_errors and the derivatives of the returned surface); Cancel restores; the blend
shows with zebra; the continuity check colours the joins of blend and faces; a failing input
shows FreeCAD's error state and keeps the last good shape; the document saves, reopens and
recomputes to the same poles; the panel fits the side panel."""
import numpy as np
import pytest

import FreeCAD

import freecad_workbench as fw

from test_blend_gui import gui, panel_of, run  # tests/gui is on the path
from tests.scenes import rim_edge, wavy_floor_and_wall
from test_blend_gui import scene as blend_scene  # noqa: F401  (a fixture, used by name)

NAME = "FairSplines_BlendFaces"
V = FreeCAD.Vector


@pytest.fixture
def scene(blend_scene):  # noqa: F811  (the fixture imported above, by name)
    """An active document with undo and two coaxial cylinders, 1 mm apart; afterwards no dialog,
    no zebra, no continuity check."""
    from freecad_workbench.gui import continuity, zebra_shape

    doc = blend_scene
    a = doc.addObject("Part::Cylinder", "A")
    a.Radius, a.Height = 1.0, 1.0
    b = doc.addObject("Part::Cylinder", "B")
    b.Radius, b.Height = 1.5, 1.0
    b.Placement = FreeCAD.Placement(V(0, 0, 2.0), FreeCAD.Rotation())
    doc.recompute()
    yield doc, a, b
    continuity.hide()
    zebra_shape.hide()


def lateral(obj):
    return next(f"Face{i + 1}" for i, f in enumerate(obj.Shape.Faces) if f.Surface.__class__.__name__ == "Cylinder")


def select(*links):
    sel = gui().Selection
    sel.clearSelection()
    for obj, sub in links:
        sel.addSelection(obj.Document.Name, obj.Name, sub)


def blend_by_command(doc, a, b):
    """Select each rim with its lateral face, run the command: the new object."""
    select((a, lateral(a)), (a, rim_edge(a, 1.0)), (b, lateral(b)), (b, rim_edge(b, 2.0)))
    before = {o.Name for o in doc.Objects}
    run(NAME)
    created = [o for o in doc.Objects if o.Name not in before]
    assert len(created) == 1, [o.Name for o in created]
    return created[0]


def errors(blend, a, b):
    """OCCT's measure of the blend against each face along its rim (side A at v = 0, B at v = 1)."""
    surface = blend.Shape.Faces[0].Surface
    sa = fw.blend_errors(surface, a.Shape.getElement(lateral(a)), a.Shape.getElement(rim_edge(a, 1.0)), 0.0)
    sb = fw.blend_errors(surface, b.Shape.getElement(lateral(b)), b.Shape.getElement(rim_edge(b, 2.0)), 1.0)
    return sa, sb


def poles(obj):
    return np.array([[tuple(p) for p in row] for row in obj.Shape.Faces[0].Surface.getPoles()])


def cross_speed(obj, s=0.0, u=0.3):
    """|d/dv| of the blend at (u, s), by OCCT: how far it runs along the face at that side."""
    surface = obj.Shape.Faces[0].Surface
    return FreeCAD.Vector(*surface.getDN(u, s, 0, 1)).Length


def zebra_normals_point_out(zebra):
    """Whether every normal of the zebra mesh points away from the cylinders' axis (as their
    lateral faces' normals do)."""
    points = np.array([tuple(p.getValue()) for p in zebra.coords.point])
    normals = np.array([tuple(n.getValue()) for n in zebra.normals.vector])
    assert len(points) == len(normals) > 100
    return bool((np.einsum("ij,ij->i", normals[:, :2], points[:, :2]) > 0).all())


def test_zebra_normals_follow_the_first_face_whichever_way_the_blend_runs(scene):
    from freecad_workbench.features.face_blend import make_face_blend

    doc, a, b = scene
    # from B down to A: the blend surface's own normal points into the cylinders here
    back = make_face_blend(doc, (b, lateral(b)), (b, rim_edge(b, 2.0)), (a, lateral(a)), (a, rim_edge(a, 1.0)))
    surface = back.Shape.Faces[0].Surface
    assert FreeCAD.Vector(*surface.normal(0.5, 0.0)).dot(surface.value(0.5, 0.0) - V(0, 0, 2.0)) < 0
    assert zebra_normals_point_out(back.ViewObject.Proxy.zebra)


def test_command_needs_two_edges_and_the_face_of_each(scene):
    from freecad_workbench.gui.commands.face_blend import blend_selection

    doc, a, b = scene
    select((a, rim_edge(a, 1.0)))
    assert isinstance(blend_selection(), str)  # one edge
    select((a, rim_edge(a, 1.0)), (b, rim_edge(b, 2.0)))
    message = blend_selection()  # each rim bounds the lateral face and a cap: which one?
    assert isinstance(message, str) and "select the face" in message, message
    before = len(doc.Objects)
    run(NAME)
    assert len(doc.Objects) == before and not gui().Control.activeDialog()
    select((a, lateral(a)), (a, rim_edge(a, 1.0)), (b, lateral(b)), (b, rim_edge(b, 2.0)))
    assert blend_selection() == (((a, lateral(a)), (a, rim_edge(a, 1.0))), ((b, lateral(b)), (b, rim_edge(b, 2.0))))
    cap = next(f"Face{i + 1}" for i, f in enumerate(a.Shape.Faces) if f.Surface.__class__.__name__ == "Plane"
               and abs(f.CenterOfMass.z - 1.0) < 1e-9)
    select((a, cap), (a, rim_edge(a, 1.0)), (b, lateral(b)), (b, rim_edge(b, 2.0)))
    assert blend_selection()[0][0] == (a, cap)  # the face picked with the edge, not the first


def test_command_creates_a_g2_blend_in_one_undo_step_with_zebra_and_its_panel(scene):
    from freecad_workbench.gui.panels.face_blend import FaceBlendPanel
    from freecad_workbench.gui.view_providers import ViewProviderFaceBlend

    doc, a, b = scene
    blend = blend_by_command(doc, a, b)
    assert blend.Status.startswith("ok: G2"), blend.Status
    sa, sb = errors(blend, a, b)
    for e in (sa, sb):
        assert e["gap"] < 1e-7 and e["angle"] < 1e-4 and e["curvature_jump"] < 1e-4, e
    vp = blend.ViewObject.Proxy
    assert isinstance(vp, ViewProviderFaceBlend)
    assert blend.ViewObject.DisplayMode == "Zebra" and vp.zebra.vertex_count > 100
    # the zebra's normals point as face A's do (out of the cylinders), so that its stripes run on
    # into the faces' zebra
    assert zebra_normals_point_out(vp.zebra)
    panel = panel_of(blend)
    assert isinstance(panel, FaceBlendPanel) and gui().Control.activeDialog()
    assert doc.UndoNames[0] == "Create face blend"
    text = panel.report.text()
    assert "Side A" in text and "Side B" in text and "exact" in text and "mm" in text and "of 13" in text, text
    panel.accept()
    gui().updateGui()
    assert not gui().Control.activeDialog()
    name = blend.Name
    doc.undo()
    assert doc.getObject(name) is None
    doc.redo()
    assert doc.getObject(name) is not None


def test_panel_drives_the_blend_and_cancel_restores(scene):
    doc, a, b = scene
    blend = blend_by_command(doc, a, b)
    panel = panel_of(blend)
    good = poles(blend)
    undo_count = len(doc.UndoNames)

    # G1 at face A: the blend keeps position and tangent plane there, loses the curvature match;
    # face B keeps it (a quartic across)
    panel.continuities[0].setCurrentIndex(1)
    assert (blend.ContinuityA, blend.ContinuityB) == ("G1", "G2") and blend.Status.startswith("ok: G1 / G2"), \
        blend.Status
    sa, sb = errors(blend, a, b)
    assert sa["gap"] < 1e-7 and sa["angle"] < 1e-4 and sa["curvature_jump"] > 1e-3, sa
    assert sb["gap"] < 1e-7 and sb["angle"] < 1e-4 and sb["curvature_jump"] < 1e-4, sb
    assert blend.Shape.Faces[0].Surface.VDegree == 4
    panel.continuities[0].setCurrentIndex(0)
    np.testing.assert_allclose(poles(blend), good, rtol=0, atol=1e-12)

    # the depth of side A: off "Fair", then the slider; the derivative across follows
    fair_speed = cross_speed(blend, 0.0)
    chosen = blend.Proxy.report.sides[0]["scale"]  # what the fairness search chose
    assert panel.depths[0].value.text() == f"\u00d7 {chosen:.2f}"
    panel.depths[0].fair.setChecked(False)  # the slider starts there: the shape hardly moves
    assert abs(blend.ScaleA - chosen) < 0.05 * chosen, (blend.ScaleA, chosen)
    panel.depths[0].slider.setValue(panel.depths[0].slider.maximum())  # 5 x the default
    assert abs(blend.ScaleA - 5.0) < 1e-9
    deeper = cross_speed(blend, 0.0)
    assert deeper > 2.0 * fair_speed, (deeper, fair_speed)
    sa, sb = errors(blend, a, b)
    assert sa["curvature_jump"] < 1e-4 and sb["curvature_jump"] < 1e-4, (sa, sb)
    panel.depths[0].fair.setChecked(True)
    assert blend.ScaleA == 0 and not panel.depths[0].slider.isEnabled()
    np.testing.assert_allclose(poles(blend), good, rtol=0, atol=1e-12)

    # side B alone
    panel.depths[1].fair.setChecked(False)
    panel.depths[1].slider.setValue(0)  # 0.2 x
    assert abs(blend.ScaleB - 0.2) < 1e-9 and blend.ScaleA == 0
    assert cross_speed(blend, 1.0) < cross_speed(blend, 0.0)

    # flip pairs the start of one rim with the end of the other: on coaxial circles running the
    # same way the blend would twist through itself, refused; the panel says so in red and the
    # last good shape stays
    shown = poles(blend)
    panel.flip.setChecked(True)
    assert blend.Flip and "cross itself" in blend.Status and "Invalid" in blend.State, blend.Status
    np.testing.assert_array_equal(poles(blend), shown)
    assert blend.Status in panel.status.text() and "c00000" in panel.status.styleSheet()
    panel.flip.setChecked(False)
    assert blend.Status.startswith("ok") and not panel.status.text(), blend.Status

    # the covered part, in percent
    panel.start.setValue(25.0)
    panel.end.setValue(75.0)
    assert (blend.Start, blend.End) == (0.25, 0.75) and blend.Status.startswith("ok"), blend.Status
    covered = blend.Shape.Faces[0].Area
    # one step, opened at the first change, still pending
    assert len(doc.UndoNames) == undo_count + 1 and doc.UndoNames[0] == "Edit face blend"
    panel.reject()
    gui().updateGui()
    assert (blend.ContinuityA, blend.ContinuityB, blend.Flip, blend.Start, blend.End, blend.ScaleA,
            blend.ScaleB) == ("G2", "G2", False, 0.0, 1.0, 0.0, 0.0)
    np.testing.assert_allclose(poles(blend), good, rtol=0, atol=1e-12)
    assert blend.Shape.Faces[0].Area > 1.5 * covered
    assert not gui().Control.activeDialog() and len(doc.UndoNames) == undo_count


def test_ok_keeps_the_edit_as_one_undo_step(scene):
    doc, a, b = scene
    blend = blend_by_command(doc, a, b)
    panel = panel_of(blend)
    undo_count = len(doc.UndoNames)
    panel.continuities[1].setCurrentIndex(1)
    panel.flip.setChecked(True)
    panel.accept()
    gui().updateGui()
    assert len(doc.UndoNames) == undo_count + 1 and doc.UndoNames[0] == "Edit face blend"
    doc.undo()
    assert (blend.ContinuityB, blend.Flip) == ("G2", False)


def test_zebra_on_the_faces_and_the_continuity_check_of_the_joins(scene):
    from freecad_workbench.gui import continuity, zebra_shape

    doc, a, b = scene
    blend = blend_by_command(doc, a, b)
    panel = panel_of(blend)
    panel.zebra.setChecked(True)
    assert {o.Name for o in zebra_shape.shown()} >= {a.Name, b.Name}
    panel.check.setChecked(True)
    check = continuity.current()
    assert check is not None
    joins = [r for r in check.records if r.kind == "shared"]
    # the two rims (the blend's own seam is a seam, not a join)
    assert [r.continuity for r in joins] == ["G2", "G2"], joins
    assert "G2" in panel.joins.text()
    panel.continuities[1].setCurrentIndex(1)  # re-checked after the recompute: G1 at face B now
    joins = [r for r in continuity.current().records if r.kind == "shared"]
    assert sorted(r.continuity for r in joins) == ["G1", "G2"], joins
    panel.reject()
    gui().updateGui()
    assert continuity.current() is None and not zebra_shape.shown()


def test_a_failing_input_shows_the_error_state_and_keeps_the_last_good_shape(scene):
    from freecad_workbench.gui import icon_path

    doc, a, b = scene
    blend = blend_by_command(doc, a, b)
    panel = panel_of(blend)
    good = poles(blend)
    b.Radius = 1.0
    b.Placement = FreeCAD.Placement(V(0, 0, 1.0), FreeCAD.Rotation())  # B's rim on A's: the faces touch
    doc.recompute()
    gui().updateGui()
    assert "the faces touch" in blend.Status and "Invalid" in blend.State, blend.Status
    assert blend.ViewObject.Proxy.getIcon() == icon_path("FairSplines_BlendFacesError")
    np.testing.assert_array_equal(poles(blend), good)
    panel.refresh()
    assert panel.status.isVisible() or panel.status.text(), "no failure shown in the panel"
    assert blend.Status in panel.status.text()
    b.Radius = 1.5
    b.Placement = FreeCAD.Placement(V(0, 0, 2.0), FreeCAD.Rotation())
    doc.recompute()
    assert blend.Status.startswith("ok") and "Invalid" not in blend.State
    np.testing.assert_allclose(poles(blend), good, rtol=0, atol=1e-12)


def test_save_reopen_recompute_is_identical(scene, tmp_path):
    from freecad_workbench.gui.view_providers import ViewProviderFaceBlend

    doc, a, b = scene
    blend = blend_by_command(doc, a, b)
    panel_of(blend).accept()
    gui().updateGui()
    before, name = poles(blend), blend.Name
    path = str(tmp_path / "face_blend_gui.FCStd")
    doc.saveAs(path)
    FreeCAD.closeDocument(doc.Name)
    reopened = FreeCAD.openDocument(path)
    try:
        blend = reopened.getObject(name)
        assert isinstance(blend.ViewObject.Proxy, ViewProviderFaceBlend)
        assert blend.ViewObject.DisplayMode == "Zebra"
        np.testing.assert_allclose(poles(blend), before, rtol=0, atol=1e-14)
        blend.touch()
        reopened.recompute()
        assert blend.Status.startswith("ok: G2"), blend.Status
        np.testing.assert_allclose(poles(blend), before, rtol=0, atol=1e-14)
        gui().getDocument(reopened.Name).setEdit(blend.Name, 0)
        gui().updateGui()
        panel = panel_of(blend)
        assert panel is not None and "Side A" in panel.report.text()
        panel.reject()
        gui().updateGui()
    finally:
        FreeCAD.closeDocument(reopened.Name)


def test_panel_fits_the_side_panel(scene, artifacts):
    from test_panels import assert_fits, picture

    doc, a, b = scene
    blend = blend_by_command(doc, a, b)
    panel = panel_of(blend)
    panel.depths[0].fair.setChecked(False)
    panel.check.setChecked(True)
    assert_fits(panel, "Face blend panel")
    picture(panel, "face_blend", artifacts)


def test_command_on_the_edges_of_two_b_spline_sheets_takes_their_only_faces(scene):
    """A wavy floor and a wavy wall (one bicubic face each, different in every way from the
    cylinders): two edges alone are enough; the blend is G2 along both, by OCCT's measure."""
    doc = scene[0]
    floor, edge_f, wall, edge_w = wavy_floor_and_wall(doc)
    select((floor, edge_f), (wall, edge_w))
    before = {o.Name for o in doc.Objects}
    run(NAME)
    blend = next(o for o in doc.Objects if o.Name not in before)
    links = [(link[0], list(link[1])) for link in (blend.FaceA, blend.EdgeA, blend.FaceB, blend.EdgeB)]
    assert links == [(floor, ["Face1"]), (floor, [edge_f]), (wall, ["Face1"]), (wall, [edge_w])], links
    assert blend.Status.startswith("ok: G2"), blend.Status
    surface = blend.Shape.Faces[0].Surface
    for face, edge, s in ((floor, edge_f, 0.0), (wall, edge_w, 1.0)):
        e = fw.blend_errors(surface, face.Shape.Faces[0], face.Shape.getElement(edge), s)
        assert e["gap"] < 1e-7 and e["angle"] < 1e-4 and e["curvature_jump"] < 1e-4, e


def test_a_trimmed_edge_is_fitted_and_the_panel_says_so(scene, artifacts):
    """A plane with a hole cut by Part's boolean (its circle is no isoline) picked with the command:
    the blend is made by the fitted route, the panel reports that side "fitted" with its spans, and
    OCCT finds the tolerances along the whole circle."""
    import Part

    from test_panels import assert_fits, picture

    doc, a, b = scene
    plane = Part.makePlane(5, 5, V(-2.5, -2.5, 3.5))
    holed = doc.addObject("Part::Feature", "Holed")
    holed.Shape = plane.cut(Part.Face(Part.Wire(Part.makeCircle(1.8, V(0, 0, 3.5)))))
    doc.recompute()
    circle = next(f"Edge{i + 1}" for i, e in enumerate(holed.Shape.Edges) if e.Curve.__class__.__name__ == "Circle")
    select((b, lateral(b)), (b, rim_edge(b, 3.0)), (holed, "Face1"), (holed, circle))
    before = {o.Name for o in doc.Objects}
    run(NAME)
    blend = next(o for o in doc.Objects if o.Name not in before)
    panel = panel_of(blend)
    text = panel.report.text()
    assert "Side A: exact" in text and "Side B: fitted (" in text, text
    surface = blend.Shape.Faces[0].Surface
    measured = fw.blend_errors(surface, holed.Shape.Faces[0], holed.Shape.getElement(circle), 1.0)
    assert measured["within"] and measured["curvature_jump"] <= 1e-4, measured
    assert_fits(panel, "Face blend panel (fitted side)")
    picture(panel, "face_blend_fitted", artifacts)
    panel.reject()
    gui().updateGui()
