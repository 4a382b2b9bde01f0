"""Design with basic curves in a real FreeCAD GUI under Xvfb: the commands on selected
sketch edges, the Mark points panel driven through its sliders (the feature follows),
the Edit polygon panel (typed and dragged poles), the Profile test's zebra shading, reopen
with the view providers; screenshots in out/test-artifacts/."""
import math
import os

import numpy as np
import pytest

import FreeCAD
import Part
import Sketcher  # noqa: F401  (registers Sketcher::SketchObject)

import freecad_workbench as fw
from freecad_workbench.features.basic_curve import KINDS
from freecad_workbench.features.design_spline import get_marks, piece_links, reversed_curve
from freecad_workbench.gui import icon_path

V = FreeCAD.Vector
SKETCH_COLOR = (0.55, 0.55, 0.55)
DESIGN_COLOR = (0.85, 0.1, 0.1)


def gui():
    import FreeCADGui

    return FreeCADGui


def select(doc, *items):
    g = gui()
    g.Selection.clearSelection()
    for item in items:
        obj, sub = item if isinstance(item, tuple) else (item, "")
        if sub:
            g.Selection.addSelection(doc.Name, obj.Name, sub)
        else:
            g.Selection.addSelection(obj)


def run(name):
    """Run a command and let the panel it opens afterwards (a zero-delay timer) appear."""
    g = gui()
    g.runCommand(name)
    for _ in range(3):
        g.updateGui()


def is_active(name):
    return gui().Command.get(name).isActive()


def new_objects(doc, before):
    return [o for o in doc.Objects if o.Name not in before]


def edge_named(sketch, a, b):
    """The EdgeN of the sketch edge from a to b (either way)."""
    for i, edge in enumerate(sketch.Shape.Edges):
        ends = [v.Point for v in edge.Vertexes]
        if any((p - a).Length < 1e-9 for p in ends) and any((p - b).Length < 1e-9 for p in ends):
            return f"Edge{i + 1}"
    raise AssertionError(f"no edge from {a} to {b}")


def expected_curve(design, marks=None):
    """fw.design_spline of the design's pieces (sketch edges, turned as Reversed says)."""
    marks = get_marks(design) if marks is None else marks
    pieces = []
    for (source, sub), flag, m in zip(piece_links(design), list(design.Reversed), marks):
        curve = fw.basic.from_edge(Part.getShape(source, sub, needSubElement=True))
        pieces.append((reversed_curve(curve) if flag else curve, m))
    return fw.design_spline(pieces)


def poles(curve_or_obj):
    curve = curve_or_obj.Shape.Edges[0].Curve if hasattr(curve_or_obj, "Shape") else curve_or_obj
    return np.array([tuple(p) for p in curve.getPoles()])


def pixels_near(image, rgb, tolerance=40):
    return int((np.abs(image[..., :3].astype(int) - np.array(rgb)).max(axis=-1) <= tolerance).sum())


def screenshot(doc, path, view="top"):
    from PIL import Image

    g = gui()
    v = g.getDocument(doc.Name).ActiveView
    if isinstance(view, tuple):
        v.setViewDirection(view)
    else:
        getattr(v, {"top": "viewTop", "iso": "viewIsometric", "front": "viewFront"}[view])()
    v.fitAll()
    g.updateGui()
    if os.path.exists(path):
        os.remove(path)
    v.saveImage(path, 800, 600, "White")
    return np.asarray(Image.open(path).convert("RGB"))


@pytest.fixture
def scene(doc):
    """A sketch (XY plane) with the Fig. 14 chain: a line, a quarter circle touching it, a
    line touching that; the document active, nothing selected. Task panels are closed and
    the selection cleared afterwards."""
    g = gui()
    FreeCAD.setActiveDocument(doc.Name)
    g.ActiveDocument = g.getDocument(doc.Name)
    sketch = doc.addObject("Sketcher::SketchObject", "Profile")
    sketch.addGeometry(Part.LineSegment(V(20, 0, 0), V(20, 10, 0)))
    sketch.addGeometry(Part.ArcOfCircle(Part.Circle(V(15, 10, 0), V(0, 0, 1), 5), 0, math.pi / 2))
    sketch.addGeometry(Part.LineSegment(V(15, 15, 0), V(0, 15, 0)))
    doc.recompute()
    sketch.ViewObject.LineColor = SKETCH_COLOR
    sketch.ViewObject.PointColor = SKETCH_COLOR
    chain = [edge_named(sketch, V(20, 0, 0), V(20, 10, 0)), edge_named(sketch, V(20, 10, 0), V(15, 15, 0)),
             edge_named(sketch, V(15, 15, 0), V(0, 15, 0))]
    g.Selection.clearSelection()
    yield doc, sketch, chain
    g.Selection.clearSelection()
    if g.Control.activeDialog():
        panel = _active_panel(doc)
        if panel is not None:
            panel.reject()
        else:
            g.Control.closeDialog()
    g.updateGui()


def _active_panel(doc):
    try:
        gui_doc = gui().getDocument(doc.Name)
    except (ReferenceError, NameError):
        return None
    vp = gui_doc.getInEdit() if gui_doc is not None else None
    proxy = getattr(vp, "Proxy", None) if vp is not None else None
    return getattr(proxy, "panel", None)


def design_from_command(doc, sketch, chain):
    select(doc, *[(sketch, name) for name in chain])
    assert is_active("FairSplines_DesignSpline")
    before = {o.Name for o in doc.Objects}
    run("FairSplines_DesignSpline")
    (design,) = new_objects(doc, before)
    return design


# --- basic curves -----------------------------------------------------------------------

@pytest.mark.parametrize("kind", KINDS)
def test_basic_curve_command_creates_its_kind_and_opens_the_dimensions_panel(scene, kind):
    from freecad_workbench.gui.panels.basic_curve import BasicCurvePanel
    from freecad_workbench.gui.commands.design import KIND_COMMANDS
    from freecad_workbench.gui.view_providers import ViewProviderBasicCurve

    doc, _, _ = scene
    before = {o.Name for o in doc.Objects}
    run(KIND_COMMANDS[kind])
    (obj,) = new_objects(doc, before)
    assert obj.Kind == kind and obj.Status == "ok"
    assert isinstance(obj.ViewObject.Proxy, ViewProviderBasicCurve)
    assert obj.ViewObject.Proxy.getIcon() == icon_path(KIND_COMMANDS[kind])
    panel = obj.ViewObject.Proxy.panel
    assert isinstance(panel, BasicCurvePanel) and gui().Control.activeDialog()
    panel.reject()
    gui().updateGui()
    assert not gui().Control.activeDialog()


def test_basic_curve_panel_edits_dimensions_and_plane_live(scene):
    from freecad_workbench.gui.commands.design import KIND_COMMANDS

    doc, _, _ = scene
    before = {o.Name for o in doc.Objects}
    run(KIND_COMMANDS["Circle arc"])
    (arc,) = new_objects(doc, before)
    panel = arc.ViewObject.Proxy.panel
    panel.widgets["Radius"].setValue(12.5)
    panel.widgets["EndAngle"].setValue(135)
    assert arc.Radius.Value == 12.5 and arc.EndAngle.Value == 135
    edge = arc.Shape.Edges[0]
    assert edge.Curve.Radius == pytest.approx(12.5)
    assert (edge.valueAt(edge.LastParameter) - V(12.5 * math.cos(math.radians(135)),
                                                 12.5 * math.sin(math.radians(135)), 0)).Length < 1e-12
    panel.plane.setCurrentIndex(1)  # XZ
    for spin, value in zip(panel.position, (1, 2, 3)):
        spin.setValue(value)
    assert tuple(arc.Placement.Base) == (1, 2, 3)
    start = arc.Shape.Edges[0].valueAt(arc.Shape.Edges[0].FirstParameter)
    assert (start - V(13.5, 2, 3)).Length < 1e-12 and abs(arc.Shape.Edges[0].Curve.Axis.y) == pytest.approx(1)
    panel.widgets["Radius"].setValue(0)  # degenerate: the panel says so, the shape stays
    assert "degenerate circle arc" in panel.status_label.text() and "degenerate" in arc.Status
    panel.widgets["Radius"].setValue(8)
    panel.accept()
    gui().updateGui()
    assert doc.UndoNames[0] == "Edit basic curve" and doc.UndoNames[1] == "Create basic curve"
    doc.undo()
    doc.recompute()
    assert arc.Radius.Value == 10 and tuple(arc.Placement.Base) == (0, 0, 0)


def test_basic_curve_panel_cancel_restores_kind_and_dimensions(scene):
    from freecad_workbench.features.basic_curve import make_basic_curve

    doc, _, _ = scene
    arc = make_basic_curve(doc, "Circle arc", Radius=7)
    before = poles(arc.Shape.Edges[0].Curve.toBSpline())
    gui().getDocument(doc.Name).setEdit(arc.Name, 0)
    panel = arc.ViewObject.Proxy.panel
    panel.kind.setCurrentIndex(KINDS.index("Parabola arc"))
    assert arc.Kind == "Parabola arc" and set(panel.widgets) == {"Focal", "StartY", "EndY"}
    panel.widgets["Focal"].setValue(3)
    panel.reject()
    gui().updateGui()
    assert arc.Kind == "Circle arc" and arc.Radius.Value == 7
    np.testing.assert_array_equal(poles(arc.Shape.Edges[0].Curve.toBSpline()), before)
    assert not gui().Control.activeDialog()


def test_rational_cubic_panel_edits_poles_and_weights_in_its_table(scene):
    from freecad_workbench.features.basic_curve import make_basic_curve

    doc, _, _ = scene
    cubic = make_basic_curve(doc, "Rational cubic")
    gui().getDocument(doc.Name).setEdit(cubic.Name, 0)
    panel = cubic.ViewObject.Proxy.panel
    table = panel.widgets["Poles"]
    assert (table.rowCount(), table.columnCount()) == (4, 4)
    table.item(1, 1).setText("20")
    table.item(2, 3).setText("3")
    assert cubic.Poles[1] == V(10, 20, 0) and list(cubic.Weights) == [1, 1, 3, 1]
    curve = cubic.Shape.Edges[0].Curve
    assert curve.getWeights() == [1, 1, 3, 1] and curve.getPole(2) == V(10, 20, 0)
    panel.accept()
    gui().updateGui()
    assert doc.UndoNames[0] == "Edit basic curve"


# --- design spline and mark points --------------------------------------------------------

def test_design_spline_command_takes_selected_edges_in_pick_order(scene):
    from freecad_workbench.gui.view_providers import ViewProviderDesignSpline
    from freecad_workbench.gui.panels.mark_points import MarkPointsPanel

    doc, sketch, chain = scene
    select(doc, (sketch, chain[0]))
    assert is_active("FairSplines_DesignSpline")
    select(doc, (sketch, chain[0]), sketch)  # a whole sketch of three edges is no piece
    assert not is_active("FairSplines_DesignSpline")
    design = design_from_command(doc, sketch, chain)
    assert design.Status == "ok"
    assert [(source.Name, sub) for source, sub in piece_links(design)] == [(sketch.Name, n) for n in chain]
    np.testing.assert_array_equal(poles(design), poles(expected_curve(design)))
    assert isinstance(design.ViewObject.Proxy, ViewProviderDesignSpline)
    assert design.ViewObject.Proxy.getIcon() == icon_path("FairSplines_DesignSpline")
    assert isinstance(design.ViewObject.Proxy.panel, MarkPointsPanel)  # marking starts at once
    assert doc.UndoNames[0] == "Create design spline"


def test_mark_points_panel_sliders_drive_the_design(scene, artifacts):
    from freecad_workbench.gui.panels.mark_points import GAP, SCALE

    doc, sketch, chain = scene
    design = design_from_command(doc, sketch, chain)
    design.ViewObject.LineColor = DESIGN_COLOR
    design.ViewObject.LineWidth = 3
    panel = design.ViewObject.Proxy.panel
    initial_marks, initial_poles = get_marks(design), poles(design)
    assert [len(rows) for rows in panel.rows] == [len(m) for m in initial_marks]

    # a slider moves its mark; the feature recomputes at once
    panel.rows[1][1].slider.setValue(3000)
    assert get_marks(design)[1][1] == pytest.approx(0.3)
    np.testing.assert_array_equal(poles(design), poles(expected_curve(design)))
    assert (not np.allclose(poles(design)[: len(initial_poles)], initial_poles)
            or poles(design).shape != initial_poles.shape)
    # a slider pushed past its neighbour stops one step short of it
    neighbour = get_marks(design)[1][2]
    panel.rows[1][1].slider.setValue(SCALE - 1)
    assert get_marks(design)[1][1] == pytest.approx(neighbour - GAP)
    assert panel.rows[1][1].slider.value() == round((neighbour - GAP) * SCALE)
    # the spin box sets the exact value
    panel.rows[0][0].spin.setValue(0.125)
    assert get_marks(design)[0][0] == 0.125
    # add a mark in the widest gap, remove another
    marks = get_marks(design)[2]
    gaps = np.diff([0.0] + marks + [1.0])
    widest = int(np.argmax(gaps))
    index = panel.add_mark(2)
    assert index == widest and len(panel.rows[2]) == len(marks) + 1
    assert get_marks(design)[2][index] == pytest.approx(([0.0] + marks + [1.0])[widest] + gaps[widest] / 2)
    panel.rows[0][1].remove.click()
    gui().updateGui()
    assert len(get_marks(design)[0]) == len(initial_marks[0]) - 1 and len(panel.rows[0]) == len(initial_marks[0]) - 1
    np.testing.assert_array_equal(poles(design), poles(expected_curve(design)))
    assert design.Status == "ok"
    # the overlay: a black marker per mark on the basic curves, the green control polygon
    assert len(panel.overlay.mark_points()) == sum(len(m) for m in get_marks(design))
    np.testing.assert_allclose(np.array(panel.overlay.polygon_points()), poles(design), atol=1e-4)
    assert panel.overlay.root in [gui().getDocument(doc.Name).ActiveView.getSceneGraph().getChild(i) for i in
                                  range(gui().getDocument(doc.Name).ActiveView.getSceneGraph().getNumChildren())]

    image = screenshot(doc, os.path.join(artifacts, "design_mark_points.png"))
    from freecad_workbench.gui.overlay import MARK_COLOR, POLYGON_COLOR

    assert pixels_near(image, tuple(int(255 * c) for c in DESIGN_COLOR)) > 500  # the curve
    assert pixels_near(image, tuple(int(255 * c) for c in POLYGON_COLOR)) > 200  # poles and polygon
    assert pixels_near(image, tuple(int(255 * c) for c in MARK_COLOR), tolerance=30) > 200  # marks
    pixmap = panel.form.grab()
    pixmap.save(os.path.join(artifacts, "design_mark_points_panel.png"))
    del pixmap

    panel.accept()
    gui().updateGui()
    assert not gui().Control.activeDialog()
    assert panel.overlay.root not in [gui().getDocument(doc.Name).ActiveView.getSceneGraph().getChild(i) for i in
                                      range(gui().getDocument(doc.Name).ActiveView.getSceneGraph().getNumChildren())]
    assert doc.UndoNames[:2] == ["Mark points", "Create design spline"]
    changed = get_marks(design)
    doc.undo()
    doc.recompute()
    assert get_marks(design) == initial_marks
    np.testing.assert_array_equal(poles(design), initial_poles)
    doc.redo()
    doc.recompute()
    assert get_marks(design) == changed


def test_mark_points_cancel_restores_the_marks_and_shape(scene):
    doc, sketch, chain = scene
    design = design_from_command(doc, sketch, chain)
    panel = design.ViewObject.Proxy.panel
    marks, before = get_marks(design), poles(design)
    undo = list(doc.UndoNames)
    panel.rows[0][0].slider.setValue(1000)
    panel.add_mark(1)
    assert get_marks(design) != marks
    panel.reject()
    gui().updateGui()
    assert get_marks(design) == marks
    np.testing.assert_array_equal(poles(design), before)
    assert list(doc.UndoNames) == undo and not gui().Control.activeDialog()


def test_reversed_box_turns_a_piece_and_keeps_its_marked_points(scene):
    doc, sketch, chain = scene
    design = design_from_command(doc, sketch, chain)
    panel = design.ViewObject.Proxy.panel
    points = panel.mark_points()
    flags = list(design.Reversed)
    panel.reverse_boxes[2].setChecked(not flags[2])
    assert list(design.Reversed) == flags[:2] + [not flags[2]]
    np.testing.assert_allclose(np.array([tuple(p) for p in panel.mark_points()]),
                               np.array([tuple(p) for p in points[:-4]] + [tuple(p) for p in points[-4:]][::-1]),
                               atol=1e-12)
    assert "edge" in list(design.Joins)  # the last line now starts at its far end
    np.testing.assert_array_equal(poles(design), poles(expected_curve(design)))
    panel.reject()


def test_mark_points_command_and_double_click_open_the_panel(scene):
    from freecad_workbench.gui.panels.mark_points import MarkPointsPanel

    doc, sketch, chain = scene
    design = design_from_command(doc, sketch, chain)
    design.ViewObject.Proxy.panel.accept()
    gui().updateGui()
    select(doc, design)
    assert is_active("FairSplines_MarkPoints")
    run("FairSplines_MarkPoints")
    assert isinstance(design.ViewObject.Proxy.panel, MarkPointsPanel)
    assert not is_active("FairSplines_MarkPoints")  # one panel at a time
    design.ViewObject.Proxy.panel.accept()
    gui().updateGui()
    assert design.ViewObject.Proxy.doubleClicked(design.ViewObject)
    gui().updateGui()
    assert isinstance(design.ViewObject.Proxy.panel, MarkPointsPanel)


def test_failed_design_shows_the_error_icon_and_keeps_its_shape(scene):
    doc, sketch, chain = scene
    design = design_from_command(doc, sketch, chain)
    design.ViewObject.Proxy.panel.accept()
    good = poles(design)
    design.Marks = [0.9] + list(design.Marks)[1:]
    doc.recompute()
    assert "marks must increase" in design.Status
    assert design.ViewObject.Proxy.getIcon() == icon_path("FairSplines_DesignSplineError")
    np.testing.assert_array_equal(poles(design), good)


def test_design_spline_command_records_a_replayable_macro(scene, monkeypatch):
    g = gui()
    doc, sketch, chain = scene
    recorded = []
    do_command = g.doCommand
    monkeypatch.setattr(g, "doCommand", lambda line: (recorded.append(line), do_command(line))[1])
    design = design_from_command(doc, sketch, chain)
    design.ViewObject.Proxy.panel.accept()
    g.updateGui()
    expected = poles(design)
    assert any("make_design_spline(" in line for line in recorded)
    doc.removeObject(design.Name)
    before = {o.Name for o in doc.Objects}
    namespace = {}
    for line in recorded:
        if "setEdit" not in line:
            exec(line, namespace)
    (replayed,) = new_objects(doc, before)
    np.testing.assert_array_equal(poles(replayed), expected)


# --- edit polygon ------------------------------------------------------------------------

def test_edit_polygon_panel_moves_poles_typed_and_dragged(scene, artifacts):
    from freecad_workbench.gui.panels.edit_polygon import EditPolygonPanel

    doc, sketch, chain = scene
    design = design_from_command(doc, sketch, chain)
    design.ViewObject.Proxy.panel.accept()
    gui().updateGui()
    select(doc, design)
    assert is_active("FairSplines_EditPolygon")
    before = {o.Name for o in doc.Objects}
    run("FairSplines_EditPolygon")
    (edited,) = new_objects(doc, before)
    assert edited.Status == "ok" and not design.ViewObject.Visibility
    panel = edited.ViewObject.Proxy.panel
    assert isinstance(panel, EditPolygonPanel)
    edited.ViewObject.LineColor = DESIGN_COLOR
    edited.ViewObject.LineWidth = 3
    base = edited.Shape.Edges[0].Curve
    k = base.NbPoles // 2

    # typed: pick pole k in the list, set its x
    panel.list.setCurrentRow(k)
    assert panel.selected == k
    panel.spins[0].setValue(base.getPole(k + 1).x + 4.0)
    moved = edited.Shape.Edges[0].Curve
    assert moved.getPole(k + 1).x == pytest.approx(base.getPole(k + 1).x + 4.0)
    knots, flat = base.getKnots(), base.KnotSequence
    for i, (a, b) in enumerate(zip(knots[:-1], knots[1:])):
        t = 0.5 * (a + b)
        inside = a >= flat[k] and b <= flat[k + 4]
        change = (moved.value(t) - base.value(t)).Length
        assert (change > 1e-6) if inside else (change == 0.0), (i, change)

    # dragged: press on pole k - 2 in the view, move the mouse, release
    view = gui().getDocument(doc.Name).ActiveView
    view.viewTop()
    view.fitAll()
    gui().updateGui()
    j = k - 2
    pole = edited.Shape.Edges[0].Curve.getPole(j + 1)
    x, y = view.getPointOnScreen(pole)
    assert panel.press(x + 3, y - 2)  # within the pick radius
    assert panel.selected == j and panel.dragging is not None
    target = (x + 60, y + 40)
    assert panel.drag(*target)
    assert panel.release()
    dragged = edited.Shape.Edges[0].Curve.getPole(j + 1)
    assert dragged.z == pytest.approx(0.0, abs=1e-9)  # moved in the curve's plane
    sx, sy = view.getPointOnScreen(dragged)
    # it kept its place relative to the mouse: grabbed 3 px left of and 2 px above the mouse
    assert abs(sx - (target[0] - 3)) <= 1.5 and abs(sy - (target[1] + 2)) <= 1.5, (sx, sy, target)
    assert not panel.press(5, 5)  # nothing to grab there
    assert sorted(panel.moved()) == [j, k]
    np.testing.assert_allclose(np.array(panel.overlay.polygon_points()), poles(edited), atol=1e-4)

    image = screenshot(doc, os.path.join(artifacts, "design_edit_polygon.png"))
    from freecad_workbench.gui.overlay import HIGHLIGHT_COLOR, MOVED_COLOR, POLYGON_COLOR

    assert pixels_near(image, tuple(int(255 * c) for c in DESIGN_COLOR)) > 500
    assert pixels_near(image, tuple(int(255 * c) for c in POLYGON_COLOR)) > 200
    assert pixels_near(image, tuple(int(255 * c) for c in MOVED_COLOR)) > 20
    assert pixels_near(image, tuple(int(255 * c) for c in HIGHLIGHT_COLOR), tolerance=30) > 20

    panel.reset(j)
    assert panel.moved() == [k]
    panel.accept()
    gui().updateGui()
    assert doc.UndoNames[0] == "Edit polygon"
    doc.undo()
    doc.recompute()
    assert list(edited.PoleOffsets) == []
    np.testing.assert_array_equal(poles(edited), poles(design))


def test_edit_polygon_cancel_restores_the_poles(scene):
    from freecad_workbench.features.edit_polygon import make_edit_polygon

    doc, sketch, chain = scene
    design = design_from_command(doc, sketch, chain)
    design.ViewObject.Proxy.panel.accept()
    edited = make_edit_polygon(doc, design)
    assert edited.ViewObject.ControlPolygon  # shown by default, with the object
    before = poles(edited)
    proxy = edited.ViewObject.Proxy
    np.testing.assert_allclose(np.array(proxy.overlay.polygon_points()), before, atol=1e-4)
    assert proxy.switch.whichChild.getValue() == 0
    assert not design.ViewObject.ControlPolygon and design.ViewObject.Proxy.switch.whichChild.getValue() == -1
    design.ViewObject.ControlPolygon = True
    assert design.ViewObject.Proxy.switch.whichChild.getValue() == 0
    np.testing.assert_allclose(np.array(design.ViewObject.Proxy.overlay.polygon_points()), poles(design), atol=1e-4)
    gui().getDocument(doc.Name).setEdit(edited.Name, 0)
    panel = edited.ViewObject.Proxy.panel
    panel.move_pole(3, V(1, 2, 0))
    panel.reset_all_button.click()
    panel.move_pole(4, V(3, 2, 0))
    panel.reject()
    gui().updateGui()
    np.testing.assert_array_equal(poles(edited), before)
    assert list(edited.PoleOffsets) == []


# --- profile test ------------------------------------------------------------------------

def _zebra_pixels(image):
    black = int((image.max(axis=-1) < 40).sum())
    white = int((image.min(axis=-1) > 215).sum())
    return black, white


def test_profile_test_command_shows_zebra_stripes(scene, artifacts):
    from freecad_workbench.gui.view_providers import ViewProviderProfileTest

    doc, sketch, chain = scene
    design = design_from_command(doc, sketch, chain)
    design.ViewObject.Proxy.panel.accept()
    gui().updateGui()
    select(doc, design)
    assert is_active("FairSplines_ProfileTest")
    before = {o.Name for o in doc.Objects}
    run("FairSplines_ProfileTest")
    (test,) = new_objects(doc, before)
    assert test.Status == "ok"
    vp = test.ViewObject.Proxy
    assert isinstance(vp, ViewProviderProfileTest) and test.ViewObject.DisplayMode == "Zebra"
    assert "Zebra" in test.ViewObject.listDisplayModes()
    assert vp.zebra.vertex_count > 1000
    assert vp.doubleClicked(test.ViewObject) is False and not gui().Control.activeDialog()  # nothing to edit
    # the sketch's own axis: its vertical (Y) axis, the surface of revolution of the design
    assert tuple(test.AxisDirection) == pytest.approx((0, 1, 0))
    for obj in (design, sketch):
        obj.ViewObject.Visibility = False

    stripes = screenshot(doc, os.path.join(artifacts, "design_profile_test_zebra.png"), "iso")
    black, white = _zebra_pixels(stripes)
    assert black > 5000 and white > 5000, (black, white)  # black and white stripes on the surface
    test.ViewObject.DisplayMode = "Shaded"
    gui().updateGui()
    shaded = screenshot(doc, os.path.join(artifacts, "design_profile_test_shaded.png"), "iso")
    assert _zebra_pixels(shaded)[0] < black / 10  # plain shading has no black stripes
    test.ViewObject.DisplayMode = "Zebra"
    test.ViewObject.Stripes = 4
    gui().updateGui()
    fewer = screenshot(doc, os.path.join(artifacts, "design_profile_test_zebra_4.png"), "iso")
    assert not np.array_equal(fewer, stripes)

    # the surface follows the profile: new marks, new mesh
    count = vp.zebra.vertex_count
    mesh_shape = vp.meshed
    from freecad_workbench.features.design_spline import set_marks

    set_marks(design, [[0.5], [0.2, 0.5, 0.8], [0.5]])
    doc.recompute()
    gui().updateGui()
    assert vp.meshed is not mesh_shape and test.Status == "ok"
    assert vp.zebra.vertex_count > 0 and count > 0


def test_zebra_stripes_are_reflections_that_follow_the_view(scene, artifacts):
    """The stripes are the reflection of an environment fixed to the viewer: turning the
    camera about the axis of a surface of revolution shows the same picture (it is
    symmetric), whereas stripes painted on the surface would turn with it."""
    from freecad_workbench.features.profile_test import make_profile_test

    doc, sketch, chain = scene
    test = make_profile_test(doc, (sketch, chain[1]), axis_point=V(0, 0, 0), axis_direction=V(0, 1, 0))
    assert test.Status == "ok" and test.ViewObject.DisplayMode == "Zebra"
    sketch.ViewObject.Visibility = False
    view = gui().getDocument(doc.Name).ActiveView
    images = []
    for angle in (0.0, 37.0):
        view.setCameraOrientation(FreeCAD.Rotation(V(0, 1, 0), angle).multiply(FreeCAD.Rotation(V(1, 0, 0), -60)))
        view.fitAll()
        gui().updateGui()
        path = os.path.join(artifacts, f"design_zebra_turned_{int(angle)}.png")
        view.saveImage(path, 800, 600, "White")
        from PIL import Image

        images.append(np.asarray(Image.open(path).convert("L")).astype(int))
    surface = images[0] < 250
    assert surface.sum() > 20000 and (images[0][surface] < 40).sum() > 0.1 * surface.sum()
    differ = (np.abs(images[0] - images[1]) > 100).sum()
    assert differ < 0.03 * surface.sum(), (differ, surface.sum())


KINK_VIEW = (0.0, 0.35, 1.0)  # across the axis (Y), a little along it: stripes cross the joins


def test_zebra_shows_the_kink_of_the_raw_g1_pieces(scene, artifacts):
    """Fig. 14 (d), (e): the pieces as drawn (G1 at the joins) against the designed C2
    profile. Both pictures are kept; the designed one differs and has stripes."""
    from freecad_workbench.features.design_spline import make_design_spline
    from freecad_workbench.features.profile_test import make_profile_test

    doc, sketch, chain = scene
    tests = [make_profile_test(doc, (sketch, name), axis_point=V(0, 0, 0), axis_direction=V(0, 1, 0),
                               name=f"Piece{i}") for i, name in enumerate(chain)]
    design = make_design_spline(doc, [((sketch, name), None) for name in chain])
    designed = make_profile_test(doc, design, axis_point=V(0, 0, 0), axis_direction=V(0, 1, 0), name="Designed")
    sketch.ViewObject.Visibility = design.ViewObject.Visibility = False
    designed.ViewObject.Visibility = False
    pieces = screenshot(doc, os.path.join(artifacts, "design_profile_test_g1_pieces.png"), KINK_VIEW)
    for t in tests:
        t.ViewObject.Visibility = False
    designed.ViewObject.Visibility = True
    smooth = screenshot(doc, os.path.join(artifacts, "design_profile_test_designed.png"), KINK_VIEW)
    assert all(t.Status == "ok" for t in tests + [designed])
    for image in (pieces, smooth):
        black, white = _zebra_pixels(image)
        assert black > 5000 and white > 5000
    assert not np.array_equal(pieces, smooth)


# --- reopen -----------------------------------------------------------------------------

def test_saved_design_reopens_with_its_view_providers(scene, tmp_path):
    from freecad_workbench.features.edit_polygon import make_edit_polygon
    from freecad_workbench.features.profile_test import make_profile_test
    from freecad_workbench.gui import view_providers as vps
    from freecad_workbench.gui.panels.mark_points import MarkPointsPanel

    doc, sketch, chain = scene
    design = design_from_command(doc, sketch, chain)
    design.ViewObject.Proxy.panel.accept()
    gui().updateGui()
    edited = make_edit_polygon(doc, design)
    test = make_profile_test(doc, edited)
    expected = poles(design)
    names = design.Name, edited.Name, test.Name
    path = str(tmp_path / "design_gui.FCStd")
    doc.saveAs(path)
    FreeCAD.closeDocument(doc.Name)
    reopened = FreeCAD.openDocument(path)
    try:
        design, edited, test = (reopened.getObject(name) for name in names)
        assert isinstance(design.ViewObject.Proxy, vps.ViewProviderDesignSpline)
        assert isinstance(edited.ViewObject.Proxy, vps.ViewProviderEditPolygon)
        assert isinstance(test.ViewObject.Proxy, vps.ViewProviderProfileTest)
        assert test.ViewObject.DisplayMode == "Zebra" and test.ViewObject.Stripes > 0
        assert edited.ViewObject.ControlPolygon
        for obj in reopened.Objects:
            obj.touch()
        reopened.recompute()
        gui().updateGui()
        np.testing.assert_array_equal(poles(design), expected)
        assert test.ViewObject.Proxy.zebra.vertex_count > 0
        assert design.ViewObject.Proxy.getIcon() == icon_path("FairSplines_DesignSpline")
        gui().getDocument(reopened.Name).setEdit(design.Name, 0)
        panel = design.ViewObject.Proxy.panel
        assert isinstance(panel, MarkPointsPanel)
        panel.rows[0][0].slider.setValue(500)
        assert get_marks(design)[0][0] == pytest.approx(0.05)
        panel.reject()
        gui().updateGui()
    finally:
        FreeCAD.closeDocument(reopened.Name)


def test_overlay_draws_markers_only_where_its_points_are(doc, artifacts):
    """No marker where no point is (the unused marker sets used to draw their default point at
    the origin), and the highlighted and moved poles are drawn over the pole markers."""
    from PIL import Image

    import Part
    from freecad_workbench.gui.overlay import HIGHLIGHT_COLOR, MOVED_COLOR, POLE_COLOR, Overlay

    frame = doc.addObject("Part::Feature", "Frame")  # makes the view frame the origin too
    frame.Shape = Part.makeLine(V(-3, -3, 0), V(-2, -3, 0))
    doc.recompute()
    poles = [V(2, 2, 0), V(4, 5, 0), V(6, 3, 0), V(8, 6, 0), V(10, 2, 0)]
    overlay = Overlay()
    g = gui()
    view = g.getDocument(doc.Name).ActiveView
    overlay.attach(view)
    try:
        overlay.set_polygon(poles)
        overlay.set_moved([poles[2]])
        overlay.set_highlight([poles[4]])
        view.viewTop()
        view.fitAll()
        g.updateGui()
        width, height = view.getSize()
        path = os.path.join(artifacts, "overlay_markers.png")
        view.saveImage(path, width, height, "White")
        image = np.asarray(Image.open(path).convert("RGB"))
    finally:
        overlay.detach()

    def near(point, rgb, radius=7):
        x, y = view.getPointOnScreen(point)
        counts = []
        for row in (int(round(y)), int(round(height - 1 - y))):  # either convention of y
            patch = image[max(0, row - radius):row + radius + 1, max(0, int(x) - radius):int(x) + radius + 1]
            counts.append(pixels_near(patch, tuple(int(255 * c) for c in rgb), tolerance=30))
        return max(counts)

    assert near(poles[0], POLE_COLOR) > 10
    assert near(poles[2], MOVED_COLOR) > 10
    assert near(poles[4], HIGHLIGHT_COLOR) > 10
    for color in (MOVED_COLOR, HIGHLIGHT_COLOR, (0.0, 0.0, 0.0)):
        assert near(V(0, 0, 0), color) == 0, color  # nothing drawn at the origin


def test_mark_points_shows_a_sampled_piece_without_sliders(scene):
    """A Points object as a piece (the unifying spline): its group has no sliders and no Add
    mark, says what it is, draws its samples; the other pieces keep their sliders."""
    import Points

    from freecad_workbench.features.design_spline import make_design_spline
    from freecad_workbench.gui.panels.mark_points import MarkPointsPanel

    doc, sketch, chain = scene
    # Samples of a quarter circle of radius 5 about (25, 0), ending where the chain's line starts.
    a = np.linspace(1.5 * math.pi, math.pi, 15)
    cloud = doc.addObject("Points::Feature", "Samples")
    cloud.Points = Points.Points([V(25 + 5 * math.cos(x), 5 * math.sin(x), 0) for x in a])
    doc.recompute()
    design = make_design_spline(doc, [(cloud, None)] + [((sketch, name), None) for name in chain])
    assert design.Status == "ok", design.Status
    assert list(design.MarkCounts)[0] == 0
    panel = MarkPointsPanel(design)
    try:
        assert panel.rows[0] == [] and not panel.add_buttons[0].isVisibleTo(panel.form)
        assert all(panel.add_buttons[p].isVisibleTo(panel.form) for p in (1, 2, 3))
        assert all(len(panel.rows[p]) == 4 for p in (1, 2, 3))
        assert "15 samples" in panel.info_labels[0].text()
        assert len(panel.mark_points()) == 15 + 3 * 4
        panel.set_mark(2, 0, 0.3)  # the other pieces' sliders still drive the design
        assert design.Status == "ok" and get_marks(design)[2][0] == pytest.approx(0.3)
        assert isinstance(panel, MarkPointsPanel)
    finally:
        panel.reject()


def test_design_spline_command_takes_a_selected_points_object_as_a_sampled_piece(scene):
    import Points

    from freecad_workbench.gui.panels.mark_points import MarkPointsPanel

    doc, sketch, chain = scene
    a = np.linspace(1.5 * math.pi, math.pi, 12)
    cloud = doc.addObject("Points::Feature", "Samples")
    cloud.Points = Points.Points([V(25 + 5 * math.cos(x), 5 * math.sin(x), 0) for x in a])
    doc.recompute()
    select(doc, cloud, (sketch, chain[0]))
    assert is_active("FairSplines_DesignSpline")
    before = {o.Name for o in doc.Objects}
    run("FairSplines_DesignSpline")
    (design,) = new_objects(doc, before)
    assert design.Status == "ok", design.Status
    assert [(source.Name, sub) for source, sub in piece_links(design)] == [(cloud.Name, ""), (sketch.Name, chain[0])]
    assert list(design.MarkCounts) == [0, 4]
    expected = fw.design_spline([fw.basic.Samples(cloud.Points.Points),
                                 (fw.basic.from_edge(sketch.Shape.getElement(chain[0])), get_marks(design)[1])])
    np.testing.assert_array_equal(poles(design), poles(expected))
    panel = design.ViewObject.Proxy.panel
    assert isinstance(panel, MarkPointsPanel) and panel.rows[0] == [] and len(panel.rows[1]) == 4
    panel.reject()
