"""Failure you can't miss (issue 12, point 4): a feature that cannot be built shows it the
way FreeCAD shows its own failures: the object is invalid (FreeCAD's error mark in the
tree) and carries the FairSplines error icon, the message is in the report view and in
the Status property, its verdicts (a blend's Curvature, a design's Joins) are no longer
shown as valid, its open task panel says so in red, and it keeps its last good shape."""
import math

import pytest

import FreeCAD
import Part

from freecad_workbench.features.base import NOT_KNOWN
from freecad_workbench.gui import icon_path

V = FreeCAD.Vector


def gui():
    import FreeCADGui

    return FreeCADGui


@pytest.fixture
def active(doc):
    g = gui()
    FreeCAD.setActiveDocument(doc.Name)
    g.ActiveDocument = g.getDocument(doc.Name)
    yield doc
    if g.Control.activeDialog():
        g.Control.closeDialog()
    gui_doc = g.getDocument(doc.Name)
    if gui_doc is not None and gui_doc.getInEdit() is not None:
        gui_doc.resetEdit()
    g.updateGui()


def report_view_text():
    from freecad_workbench.gui.qt import QtWidgets

    from freecad_workbench.gui.qt import main_window

    main = main_window()
    views = [w for w in main.findChildren(QtWidgets.QTextEdit) if w.objectName() == "Report view"]
    assert views, "no report view in the main window"
    return views[0].toPlainText()


def poles(obj):
    return [tuple(p) for p in obj.Shape.Edges[0].Curve.getPoles()]


def test_a_blend_whose_ends_meet_fails_visibly_and_keeps_its_last_curve(active):
    from freecad_workbench.features.fair_blend import make_fair_blend

    doc = active
    lead = doc.addObject("Part::Line", "Lead")
    lead.X1, lead.Y1, lead.Z1, lead.X2, lead.Y2, lead.Z2 = -20, 0, 0, 0, 0, 0
    out = doc.addObject("Part::Line", "Out")
    out.X1, out.Y1, out.Z1, out.X2, out.Y2, out.Z2 = 20, 10, 0, 40, 10, 0
    doc.recompute()
    blend = make_fair_blend(doc, (lead, "Edge1"), (out, "Edge1"), start_end="last", end_end="first", continuity="G1")
    assert blend.Status == "ok" and blend.Curvature.startswith("monotone")
    good = poles(blend)
    proxy = blend.ViewObject.Proxy
    assert proxy.getIcon() == icon_path("FairSplines_MonotoneBlend")

    out.X1, out.Y1 = 0, 0  # the run-out now starts where the lead-in ends: no blend between them
    doc.recompute()
    gui().updateGui()

    assert blend.Status != "ok" and "Invalid" in blend.State and not blend.isValid()
    assert blend.Status in blend.getStatusString()
    assert proxy.getIcon() == icon_path("FairSplines_MonotoneBlendError")
    assert blend.Curvature == NOT_KNOWN  # no verdict about a curve that no longer meets its edges
    assert poles(blend) == good  # the last good curve is kept
    assert f"{blend.Label}: {blend.Status}" in report_view_text()

    out.X1, out.Y1 = 20, 10
    doc.recompute()
    assert blend.Status == "ok" and blend.isValid() and blend.Curvature.startswith("monotone")
    assert proxy.getIcon() == icon_path("FairSplines_MonotoneBlend")


def test_a_design_with_bad_marks_says_so_in_its_open_panel_and_drops_its_joins(active):
    import Sketcher  # noqa: F401

    from freecad_workbench.features.design_spline import make_design_spline, set_marks

    doc = active
    sketch = doc.addObject("Sketcher::SketchObject", "Profile")
    sketch.addGeometry(Part.LineSegment(V(20, 0, 0), V(20, 10, 0)))
    sketch.addGeometry(Part.ArcOfCircle(Part.Circle(V(15, 10, 0), V(0, 0, 1), 5), 0, math.pi / 2))
    doc.recompute()
    design = make_design_spline(doc, [((sketch, "Edge1"), None), ((sketch, "Edge2"), None)])
    assert design.Status == "ok" and list(design.Joins)
    gui().getDocument(doc.Name).setEdit(design.Name, 0)
    gui().updateGui()
    panel = design.ViewObject.Proxy.panel
    assert panel.status_label.isHidden()  # nothing to say while all is well

    set_marks(design, [[0.6, 0.3], [0.5]])
    doc.recompute()
    panel.refresh()
    gui().updateGui()
    assert "Invalid" in design.State and list(design.Joins) == []
    assert design.Status.startswith("piece 1:")  # numbered from 1, as a designer counts
    assert not panel.status_label.isHidden()
    assert panel.status_label.text().startswith("Failed: piece 1")
    assert "c00000" in panel.status_label.styleSheet()
    assert design.ViewObject.Proxy.getIcon() == icon_path("FairSplines_DesignSplineError")
    panel.reject()
    gui().updateGui()
    assert design.Status == "ok" and list(design.Joins)  # Cancel put the good marks back


def test_old_documents_find_their_view_providers_where_they_were():
    """FreeCAD stores a view provider's module and class in the file: the old module names
    still give the same classes."""
    from freecad_workbench.gui import blend_commands, design_view_providers, view_providers

    for name in ("ViewProviderBasicCurve", "ViewProviderDesignSpline", "ViewProviderEditPolygon",
                 "ViewProviderProfileTest"):
        assert getattr(design_view_providers, name) is getattr(view_providers, name)
    assert blend_commands.ViewProviderBlendShape is view_providers.ViewProviderBlendShape
    for name in ("ViewProviderCsrFit", "ViewProviderFairBlend", "ViewProviderMonotoneBlend",
                 "ViewProviderMonotoneDesign", "StatusIconViewProvider"):
        assert hasattr(view_providers, name)
