"""The workbench in a real FreeCAD GUI under Xvfb: commands run through
FreeCADGui.runCommand on selected sources, the comb annotation, the plot window, and a
screenshot of the 3D view in out/test-artifacts/."""
import os

import numpy as np
import pytest

import FreeCAD
import Part
import Points
import Sketcher  # noqa: F401

import freecad_workbench as fw
from freecad_workbench.gui import comb, icon_path, plot

DATA = [(0, 0, 0), (10, 6, 0), (20, 8, 0), (30, 4, 0), (40, -4, 0), (50, -8, 0), (60, -6, 0), (70, 0, 0)]


def poles(obj):
    return np.array([tuple(p) for p in obj.Shape.Edges[0].Curve.getPoles()])


def select(doc, *items):
    """Select (obj, sub) or whole objects, in this order."""
    import FreeCADGui

    FreeCADGui.Selection.clearSelection()
    for item in items:
        obj, sub = item if isinstance(item, tuple) else (item, "")
        if sub:
            FreeCADGui.Selection.addSelection(doc.Name, obj.Name, sub)
        else:
            FreeCADGui.Selection.addSelection(obj)


def is_active(name):
    import FreeCADGui

    return FreeCADGui.Command.get(name).isActive()


def run(name):
    import FreeCADGui

    FreeCADGui.runCommand(name)
    FreeCADGui.updateGui()


def new_object(doc, before):
    created = [o for o in doc.Objects if o.Name not in before]
    assert len(created) == 1, [o.Name for o in created]
    return created[0]


@pytest.fixture
def scene(doc):
    """Vertices of an S-curve in the active document, nothing selected; combs, task
    dialogs and plot windows are cleaned up afterwards and the comb style restored."""
    import FreeCADGui

    style = comb.get_style()
    FreeCAD.setActiveDocument(doc.Name)
    objs = []
    for x, y, z in DATA:
        v = doc.addObject("Part::Vertex", "V")
        v.X, v.Y, v.Z = x, y, z
        objs.append(v)
    doc.recompute()
    FreeCADGui.Selection.clearSelection()
    yield doc, objs
    FreeCADGui.Selection.clearSelection()
    comb.hide()
    if FreeCADGui.Control.activeDialog():
        FreeCADGui.Control.closeDialog()
    comb.set_style(*style)
    import matplotlib.pyplot as plt

    plt.close("all")
    plot.close_plot_tabs()


def fit_of(doc, objs):
    from freecad_workbench.features.csr_fit import make_csr_fit

    return make_csr_fit(doc, objs)


def test_workbench_has_icon_toolbar_and_menu():
    import FreeCADGui

    assert "FairSplinesWorkbench" in FreeCADGui.listWorkbenches()
    workbench = FreeCADGui.getWorkbench("FairSplinesWorkbench")
    assert workbench.MenuText == "FairSplines"
    assert os.path.isfile(workbench.Icon) and workbench.Icon.endswith("FairSplines.svg")
    FreeCADGui.activateWorkbench("FairSplinesWorkbench")
    assert FreeCADGui.activeWorkbench().name() == "FairSplinesWorkbench"
    assert "FairSplines" in FreeCADGui.activeWorkbench().listMenus()


def test_csr_fit_command_fits_selected_vertices_in_pick_order(scene):
    doc, objs = scene
    picked = [objs[0], objs[2], objs[1]] + objs[3:]  # pick order, not creation order
    select(doc, *[(v, "Vertex1") for v in picked])
    assert is_active("FairSplines_CsrFit")
    before = {o.Name for o in doc.Objects}
    run("FairSplines_CsrFit")
    fit = new_object(doc, before)
    from freecad_workbench.gui.view_providers import ViewProviderCsrFit

    assert fit.Status == "ok"
    assert [(o.Name, subs) for o, subs in fit.Sources] == [(v.Name, ("Vertex1",)) for v in picked]
    points = [DATA[0], DATA[2], DATA[1]] + DATA[3:]
    np.testing.assert_array_equal(poles(fit), np.array([tuple(p) for p in fw.csr_spline(points).getPoles()]))
    assert isinstance(fit.ViewObject.Proxy, ViewProviderCsrFit)
    assert fit.ViewObject.Proxy.getIcon() == icon_path("FairSplines_CsrFit")
    assert doc.UndoNames[0] == "Create csr fit"
    name = fit.Name
    doc.undo()
    assert doc.getObject(name) is None


def _points_source(doc, objs):
    cloud = doc.addObject("Points::Feature", "Cloud")
    cloud.Points = Points.Points([FreeCAD.Vector(*p) for p in DATA])
    return [cloud], DATA


def _sketch_source(doc, objs):
    sketch = doc.addObject("Sketcher::SketchObject", "Sketch")
    for x, y, _ in DATA:
        sketch.addGeometry(Part.Point(FreeCAD.Vector(x, y, 0)))
    return [sketch], DATA


def _edge_source(doc, objs):
    line = doc.addObject("Part::Feature", "Classic")
    line.Shape = fw.interpolate_classic(DATA).toShape()
    doc.recompute()
    return [(line, "Edge1")], line.Shape.Edges[0].discretize(Number=50)


@pytest.mark.parametrize("make_source", [_points_source, _sketch_source, _edge_source],
                         ids=["points", "sketch", "edge"])
def test_csr_fit_command_takes_points_objects_sketches_and_edges(scene, make_source):
    doc, objs = scene
    sources, points = make_source(doc, objs)
    doc.recompute()
    select(doc, *sources)
    assert is_active("FairSplines_CsrFit")
    before = {o.Name for o in doc.Objects}
    run("FairSplines_CsrFit")
    fit = new_object(doc, before)
    assert fit.Status == "ok"
    np.testing.assert_allclose(poles(fit), np.array([tuple(p) for p in fw.csr_spline(points).getPoles()]), atol=1e-12)


def test_csr_fit_command_needs_a_suitable_selection(scene):
    doc, objs = scene
    box = doc.addObject("Part::Box", "Box")
    doc.recompute()
    select(doc)
    assert not is_active("FairSplines_CsrFit")
    select(doc, (box, "Face1"))
    assert not is_active("FairSplines_CsrFit")
    select(doc, box)  # a solid has several wires
    assert not is_active("FairSplines_CsrFit")
    select(doc, (box, "Vertex1"), (box, "Edge2"), objs[0])
    assert is_active("FairSplines_CsrFit")


def test_csr_fit_command_records_a_replayable_macro(scene, monkeypatch):
    import FreeCADGui

    doc, objs = scene
    recorded = []
    do_command = FreeCADGui.doCommand
    monkeypatch.setattr(FreeCADGui, "doCommand", lambda line: (recorded.append(line), do_command(line))[1])
    select(doc, *[(v, "Vertex1") for v in objs])
    before = {o.Name for o in doc.Objects}
    run("FairSplines_CsrFit")
    first = new_object(doc, before)
    assert any("make_csr_fit(" in line for line in recorded)
    expected = poles(first)
    doc.removeObject(first.Name)
    namespace = {}
    for line in recorded:  # the macro, replayed in a clean namespace
        exec(line, namespace)
    replayed = new_object(doc, before)
    assert [o.Name for o, _ in replayed.Sources] == [v.Name for v in objs]
    np.testing.assert_array_equal(poles(replayed), expected)


def test_failed_fit_shows_the_error_icon_and_keeps_its_shape(scene):
    doc, objs = scene
    fit = fit_of(doc, objs)
    good = poles(fit)
    assert fit.ViewObject.Proxy.getIcon() == icon_path("FairSplines_CsrFit")
    objs[4].X, objs[4].Y = objs[3].X, objs[3].Y
    doc.recompute()
    assert fit.Status.startswith("points 3 and 4 coincide")
    assert fit.ViewObject.Proxy.getIcon() == icon_path("FairSplines_CsrFitError")
    np.testing.assert_array_equal(poles(fit), good)
    objs[4].X, objs[4].Y = DATA[4][:2]
    doc.recompute()
    assert fit.ViewObject.Proxy.getIcon() == icon_path("FairSplines_CsrFit")


def _scene_children(doc):
    import FreeCADGui

    root = FreeCADGui.getDocument(doc.Name).ActiveView.getSceneGraph()
    return [root.getChild(i) for i in range(root.getNumChildren())]


def _teeth(node):
    coords = np.array([tuple(p.getValue()) for p in node.coords.point])
    n = len(coords) // 2
    return coords[:n], coords[n:]


def test_comb_command_toggles_the_comb_in_the_3d_view(scene):
    import FreeCADGui

    doc, objs = scene
    fit = fit_of(doc, objs)
    select(doc, (fit, "Edge1"))
    assert is_active("FairSplines_CurvatureComb")
    run("FairSplines_CurvatureComb")
    key = (doc.Name, fit.Name, "Edge1")
    assert comb.shown() == [key]
    node = comb._combs[key]
    assert node.root in _scene_children(doc)
    base, tip = _teeth(node)
    factor, samples = comb.get_style()
    expected = comb.comb_lines(fit.Shape.Edges[0], factor * comb.auto_scale(fit.Shape.Edges, samples), samples)
    np.testing.assert_allclose(base, expected.base, atol=1e-4)  # coin stores single precision
    np.testing.assert_allclose(tip, expected.tip, atol=1e-4)
    assert FreeCADGui.Control.activeDialog()  # the scale panel

    select(doc, (fit, "Edge1"))
    run("FairSplines_CurvatureComb")  # again: off
    assert comb.shown() == []
    assert node.root not in _scene_children(doc)
    assert not FreeCADGui.Control.activeDialog()


def test_comb_follows_its_curve_and_the_scale_panel(scene):
    import FreeCADGui

    from freecad_workbench.gui.panels.comb import CombTaskPanel, active_comb_panel

    doc, objs = scene
    fit = fit_of(doc, objs)
    select(doc, fit)  # the whole object: all its edges
    run("FairSplines_CurvatureComb")
    node = comb._combs[(doc.Name, fit.Name, "")]
    base0, tip0 = _teeth(node)

    objs[3].Y = 15
    doc.recompute()
    base1, tip1 = _teeth(node)
    assert base1.shape != base0.shape or not np.allclose(base1, base0, atol=1e-3)
    scale, samples = comb.get_style()[:2]
    new = comb.comb_lines(fit.Shape.Edges[0], scale * comb.auto_scale(fit.Shape.Edges), samples)
    np.testing.assert_allclose(base1, new.base, atol=1e-4)
    np.testing.assert_allclose(tip1, new.tip, atol=1e-4)

    assert FreeCADGui.Control.activeDialog()
    panel = active_comb_panel()
    assert isinstance(panel, CombTaskPanel)
    length1 = np.linalg.norm(tip1 - base1, axis=1)
    panel.scale.setValue(2 * panel.scale.value())
    base2, tip2 = _teeth(node)
    np.testing.assert_allclose(np.linalg.norm(tip2 - base2, axis=1), 2 * length1, rtol=1e-4, atol=1e-4)
    panel.reject()  # Cancel: back to the scale it opened with
    base3, tip3 = _teeth(node)
    np.testing.assert_allclose(tip3, tip1, atol=1e-4)
    assert not FreeCADGui.Control.activeDialog()


def test_comb_command_with_nothing_selected_hides_all_combs(scene):
    doc, objs = scene
    fit = fit_of(doc, objs)
    select(doc, (fit, "Edge1"))
    run("FairSplines_CurvatureComb")
    assert comb.shown()
    select(doc)
    assert is_active("FairSplines_CurvatureComb")
    run("FairSplines_CurvatureComb")
    assert comb.shown() == []
    assert not is_active("FairSplines_CurvatureComb")


def test_plot_command_opens_a_figure_with_a_line_per_edge(scene, artifacts):
    doc, objs = scene
    fit = fit_of(doc, objs)
    classic = doc.addObject("Part::Feature", "Classic")
    classic.Shape = fw.interpolate_classic(DATA).toShape()
    classic.Label = "Classic C2"
    doc.recompute()
    select(doc, (fit, "Edge1"), classic)
    assert is_active("FairSplines_CurvaturePlot")
    before = plot.figures()
    run("FairSplines_CurvaturePlot")
    new = [f for f in plot.figures() if f not in before]
    assert len(new) == 1
    (fig,) = new  # a tab of the main window
    ax = fig.axes[0]
    legend = [t.get_text() for t in ax.get_legend().get_texts()]
    assert legend == [f"{fit.Label}.Edge1", "Classic C2", "curvature maximum", "curvature minimum"]
    profile = fw.curvature_profile(classic.Shape.Edges[0], 1024)
    line = [artist for artist in ax.get_lines() if artist.get_label() == "Classic C2"][0]
    np.testing.assert_array_equal(line.get_ydata(), profile.kappa)
    fig.savefig(os.path.join(artifacts, "gui_curvature_plot.png"))
    select(doc, (objs[0], "Vertex1"))
    assert not is_active("FairSplines_CurvaturePlot")


def _pixels_near(image, rgb, tolerance=40):
    return int((np.abs(image[..., :3].astype(int) - np.array(rgb)).max(axis=-1) <= tolerance).sum())


def test_screenshot_of_the_3d_view_shows_curve_and_comb(scene, artifacts):
    import FreeCADGui
    from PIL import Image

    doc, objs = scene
    fit = fit_of(doc, objs)
    fit.ViewObject.LineWidth = 3
    fit.ViewObject.LineColor = (0.85, 0.1, 0.1)
    select(doc, (fit, "Edge1"))
    run("FairSplines_CurvatureComb")
    FreeCADGui.Selection.clearSelection()
    view = FreeCADGui.getDocument(doc.Name).ActiveView
    view.viewTop()
    view.fitAll()
    FreeCADGui.updateGui()
    path = os.path.join(artifacts, "csr_fit_with_comb.png")
    if os.path.exists(path):
        os.remove(path)
    view.saveImage(path, 800, 600, "White")
    image = np.asarray(Image.open(path).convert("RGB"))
    assert image.shape == (600, 800, 3)
    assert (image < 250).any(axis=-1).sum() > 2000  # not blank
    curve = _pixels_near(image, (217, 25, 25))
    envelope = _pixels_near(image, tuple(int(255 * c) for c in comb.ENVELOPE_COLOR))
    teeth = _pixels_near(image, tuple(int(255 * c) for c in comb.TOOTH_COLOR))
    assert curve > 500 and envelope > 300 and teeth > 2000, (curve, envelope, teeth)

    select(doc, (fit, "Edge1"))
    run("FairSplines_CurvatureComb")  # comb off: the picture loses it
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.updateGui()
    view.saveImage(path.replace(".png", "_off.png"), 800, 600, "White")
    image = np.asarray(Image.open(path.replace(".png", "_off.png")).convert("RGB"))
    assert _pixels_near(image, tuple(int(255 * c) for c in comb.TOOTH_COLOR)) == 0
    assert _pixels_near(image, (217, 25, 25)) > 500


def test_saved_fit_reopens_in_the_gui_with_its_view_provider(scene, tmp_path):
    import FreeCADGui

    from freecad_workbench.gui.view_providers import ViewProviderCsrFit

    doc, objs = scene
    fit = fit_of(doc, objs)
    expected = poles(fit)
    path = str(tmp_path / "gui_fit.FCStd")
    doc.saveAs(path)
    FreeCAD.closeDocument(doc.Name)
    reopened = FreeCAD.openDocument(path)
    assert reopened is not doc
    try:
        fit = reopened.getObject("CsrFit")
        assert isinstance(fit.ViewObject.Proxy, ViewProviderCsrFit)
        assert fit.ViewObject.Proxy.getIcon() == icon_path("FairSplines_CsrFit")
        fit.touch()
        reopened.recompute()
        np.testing.assert_array_equal(poles(fit), expected)
        assert FreeCADGui.getDocument(reopened.Name).getObject("CsrFit").Visibility
    finally:
        FreeCAD.closeDocument(reopened.Name)


def test_closing_a_document_drops_its_combs(scene):
    doc, objs = scene
    other = FreeCAD.newDocument("CombDoc")
    name = other.Name
    try:
        curve = other.addObject("Part::Feature", "Curve")
        curve.Shape = fw.csr_spline(DATA).toShape()
        other.recompute()
        comb.show(curve, "Edge1")
        assert (other.Name, "Curve", "Edge1") in comb.shown()
    finally:
        FreeCAD.closeDocument(name)
    assert all(key[0] != name for key in comb.shown())
