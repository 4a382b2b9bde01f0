"""Pictures of the whole FreeCAD main window, at its default layout, with each FairSplines
task panel open in the side panel (and a fair blend with its comb): docs/GUI.md's
section shows them. Run under a virtual display:

    xvfb-run -a -s "-screen 0 1600x1000x24" /usr/bin/python3 tools/gui_screenshots.py [OUT_DIR] [--surface]

--surface: only the surface analysis pictures (curvature map, continuity check, zebra).
--torsion: only the fair blend in space with its curvature and torsion combs.
--face-blend: only the blend of two faces with zebra and its panel (face_blend_panel.png), and with
  the continuity check's table of its joins (face_blend_check.png).

OUT_DIR defaults to docs/gui. Look at every picture before committing it."""
import math
import os
import sys

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
FREECAD_LIB = os.environ.get("FAIRSPLINES_FREECAD_LIB", "/usr/lib/freecad-python3/lib")
os.environ.setdefault("QTWEBENGINE_DISABLE_SANDBOX", "1")
sys.path.append(FREECAD_LIB)

import FreeCAD  # noqa: E402

sys.path.insert(0, REPO)


def start_gui():
    ext = "/usr/share/freecad/Ext"  # FreeCAD's own 'freecad' package: FreeCAD run as itself has it on the path
    if os.path.isdir(ext) and ext not in sys.path:
        sys.path.append(ext)
    for folder in ("/usr/share/freecad/Mod", os.path.join(FreeCAD.getHomePath(), "Mod")):
        for module in ("Part", "Sketcher"):  # Python parts of PartGui and SketcherGui
            path = os.path.join(folder, module)
            if os.path.isdir(path) and path not in sys.path:
                sys.path.append(path)
    import FreeCADGui

    FreeCAD.ParamGet("User parameter:BaseApp/Preferences/View").SetBool("UseNavigationAnimations", False)
    FreeCADGui.showMainWindow()
    if "FairSplinesWorkbench" in FreeCADGui.listWorkbenches():
        FreeCADGui.removeWorkbench("FairSplinesWorkbench")
    with open(os.path.join(REPO, "InitGui.py"), encoding="utf-8") as f:
        exec(compile(f.read(), "InitGui.py", "exec"), {"__name__": "InitGui"})
    FreeCADGui.activateWorkbench("FairSplinesWorkbench")
    FreeCADGui.getMainWindow().showMaximized()
    settle()
    return FreeCADGui


def settle(times=5):
    import FreeCADGui

    from freecad_workbench.gui.qt import QtWidgets

    for _ in range(times):
        FreeCADGui.updateGui()
        QtWidgets.QApplication.processEvents()


def new_doc(name):
    import FreeCADGui

    doc = FreeCAD.newDocument(name)
    FreeCAD.setActiveDocument(doc.Name)
    FreeCADGui.ActiveDocument = FreeCADGui.getDocument(doc.Name)
    return doc


def grab(out, name, direction="viewTop"):
    """The main window, with the 3D view's own rendering put where the view is (a widget
    grab leaves an OpenGL view blank)."""
    import FreeCADGui
    from PIL import Image

    from freecad_workbench.gui.qt import QtCore, QtWidgets

    main = FreeCADGui.getMainWindow()
    for report in main.findChildren(QtWidgets.QTextEdit):
        if report.objectName() == "Report view":
            report.clear()  # start-up chatter of a python-hosted FreeCAD, not ours
    view = FreeCADGui.ActiveDocument.ActiveView if FreeCADGui.ActiveDocument else None
    if view is not None and hasattr(view, "fitAll"):
        getattr(view, direction)()
        view.fitAll()
    settle()
    path = os.path.join(out, name + ".png")
    main.grab().save(path)
    area = main.findChild(QtWidgets.QMdiArea)
    sub = area.activeSubWindow() if area is not None else None
    is_3d = (sub is not None and sub.widget() is not None
             and sub.widget().metaObject().className() == "Gui::View3DInventor")
    if view is not None and is_3d:
        widget = sub.widget()
        corner = widget.mapTo(main, QtCore.QPoint(0, 0))
        rendered = path + ".view.png"
        view.saveImage(rendered, widget.width(), widget.height(), "Current")
        picture = Image.open(path).convert("RGB")
        picture.paste(Image.open(rendered).convert("RGB"), (corner.x(), corner.y()))
        picture.save(path)
        os.remove(rendered)
    print("wrote", path)


def edit(obj):
    import FreeCADGui

    FreeCADGui.getDocument(obj.Document.Name).setEdit(obj.Name, 0)
    settle()
    return obj.ViewObject.Proxy.panel


def close_panel(panel):
    panel.reject()
    settle()


def main(out):
    import Part
    import Sketcher  # noqa: F401

    from freecad_workbench.features.basic_curve import make_basic_curve
    from freecad_workbench.features.blend_shape import make_blend_shape
    from freecad_workbench.features.design_spline import make_design_spline
    from freecad_workbench.features.edit_polygon import make_edit_polygon
    from freecad_workbench.features.fair_blend import make_fair_blend
    from freecad_workbench.gui import comb

    V = FreeCAD.Vector
    os.makedirs(out, exist_ok=True)
    start_gui()

    doc = new_doc("BasicCurve")
    arc = make_basic_curve(doc, "Ellipse arc")
    panel = edit(arc)
    grab(out, "basic_curve_panel")
    close_panel(panel)

    doc = new_doc("Design")
    sketch = doc.addObject("Sketcher::SketchObject", "Profile")
    sketch.addGeometry(Part.LineSegment(V(20, 0, 0), V(20, 10, 0)))
    sketch.addGeometry(Part.ArcOfCircle(Part.Circle(V(15, 10, 0), V(0, 0, 1), 5), 0, math.pi / 2))
    sketch.addGeometry(Part.LineSegment(V(15, 15, 0), V(0, 15, 0)))
    doc.recompute()
    design = make_design_spline(doc, [((sketch, f"Edge{i}"), None) for i in (1, 2, 3)])
    panel = edit(design)
    grab(out, "mark_points_panel")
    close_panel(panel)
    edited = make_edit_polygon(doc, design)
    design.ViewObject.Visibility = False
    panel = edit(edited)
    panel.move_pole(5, edited.Poles[5] + V(2, -1, 0))
    panel.select(5)
    grab(out, "edit_polygon_panel")
    close_panel(panel)

    doc = new_doc("Blend")
    shape = make_blend_shape(doc, "Cylinder")
    panel = edit(shape)
    grab(out, "blend_shape_panel", "viewIsometric")
    close_panel(panel)

    doc = new_doc("BallJoint")
    band = make_blend_shape(doc, "Sphere zone", interface="Both ends")
    panel = edit(band)
    grab(out, "blend_shape_both_ends_panel", "viewIsometric")
    close_panel(panel)

    doc = new_doc("FairBlend")
    sys.path.insert(0, REPO)
    from tests.scenes import line_into_arc

    lead, out_arc = line_into_arc(doc)  # a line, then an arc a clothoid reaches: a monotone G2 blend exists
    blend = make_fair_blend(doc, (lead, "Edge1"), (out_arc, "Edge1"), start_end="last", end_end="first")
    import FreeCADGui

    comb.show(blend)
    FreeCADGui.Selection.clearSelection()
    FreeCADGui.Selection.addSelection(blend)
    grab(out, "fair_blend_comb")
    from freecad_workbench.gui import plot

    plot.plot_links([(blend, "Edge1"), (out_arc, "Edge1")])
    settle()
    grab(out, "curvature_plot_tab")
    plot.close_plot_tabs()
    comb.hide()
    torsion_comb(out)
    surface_analysis(out)


def analysed_part():
    """A part with walls, fillets and a boss: flat, cylindrical, toroidal and saddle faces."""
    import Part

    V = FreeCAD.Vector
    base = Part.makeBox(60, 40, 15)
    boss = Part.makeCylinder(10, 12, V(30, 20, 15))
    shape = base.fuse(boss).removeSplitter()
    return shape.makeFillet(3.0, shape.Edges)


def surface_analysis(out):
    """The curvature map of a part with its panel open."""
    import FreeCADGui

    from freecad_workbench.gui import curvature_map
    from freecad_workbench.gui.panels.curvature_map import CurvatureMapTaskPanel

    doc = new_doc("SurfaceAnalysis")
    part = doc.addObject("Part::Feature", "Part")
    part.Shape = analysed_part()
    doc.recompute()
    FreeCADGui.Selection.clearSelection()
    curvature_map.show([(part, "")], "mean")
    panel = CurvatureMapTaskPanel(part)
    FreeCADGui.Control.showDialog(panel)
    settle()
    view = FreeCADGui.ActiveDocument.ActiveView
    view.viewIsometric()
    view.fitAll()
    settle()
    hit = None
    for x in range(view.getSize()[0] // 2 - 40, view.getSize()[0] // 2 + 40, 4):
        hit = curvature_map.probe_at(doc, (x, view.getSize()[1] // 2))
        if hit is not None and abs(hit[1]) > 1e-6:
            break
    if hit is not None:
        panel.show_value(curvature_map.describe(hit[0], hit[1], hit[2], "mean"))
    grab(out, "curvature_map", "viewIsometric")
    panel.turn_off()
    settle()

    from freecad_workbench.gui import continuity
    from freecad_workbench.gui.panels.continuity import ContinuityTaskPanel

    check = continuity.show([(part, "")])
    panel = ContinuityTaskPanel(check)
    FreeCADGui.Control.showDialog(panel)
    settle()
    kinks = [i for i, r in enumerate(check.records) if r.continuity == "G1"]
    if kinks:
        panel.choose(kinks[0])
    grab(out, "continuity_check", "viewIsometric")
    panel.reject()
    settle()

    import tempfile

    import Part

    from freecad_workbench.gui import zebra_shape
    from freecad_workbench.gui.panels.zebra_shape import ZebraTaskPanel

    step = os.path.join(tempfile.mkdtemp(), "part.step")
    part.Shape.exportStep(step)
    doc.removeObject(part.Name)
    imported = doc.addObject("Part::Feature", "part_step")
    imported.Shape = Part.read(step)
    doc.recompute()
    zebra_shape.show(imported, stripes=12)
    panel = ZebraTaskPanel(imported)
    FreeCADGui.Control.showDialog(panel)
    settle()
    grab(out, "zebra_step_import", "viewIsometric")
    panel.turn_off()
    for name in list(FreeCAD.listDocuments()):
        FreeCAD.closeDocument(name)
    settle()


def torsion_comb(out):
    """A G2 fair blend between a line and a helix end that share no plane, with the comb
    panel open and its torsion comb on."""
    import FreeCADGui
    import Part

    from freecad_workbench.features.fair_blend import make_fair_blend
    from freecad_workbench.gui import comb
    from freecad_workbench.gui.panels.comb import CombTaskPanel

    V = FreeCAD.Vector
    doc = new_doc("SpaceBlend")
    line = doc.addObject("Part::Feature", "Line")
    line.Shape = Part.LineSegment(V(-40, 0, 0), V(0, 0, 0)).toShape()
    helix = doc.addObject("Part::Feature", "Helix")
    helix.Shape = Part.makeHelix(30.0, 45.0, 12.0)
    helix.Placement.Base = V(40, 25, 10)
    doc.recompute()
    blend = make_fair_blend(doc, (line, "Edge1"), (helix, "Edge1"), start_end="last", end_end="first")
    saved = comb.torsion_shown()
    comb.set_style(torsion=True)
    comb.show(blend)
    FreeCADGui.Selection.clearSelection()
    panel = CombTaskPanel()
    FreeCADGui.Control.showDialog(panel)
    settle()
    grab(out, "torsion_comb", "viewIsometric")
    panel.reject()
    comb.set_style(torsion=saved)
    comb.hide()
    settle()


def face_blend(out):
    """A G2 blend from the edge of a wavy floor to the bottom edge of a wavy wall (two bicubic
    B-spline faces), with zebra on the blend and on both faces, the continuity check of the
    joins on, and its panel open."""
    import FreeCADGui

    from freecad_workbench.features.face_blend import make_face_blend
    from tests.scenes import wavy_floor_and_wall

    doc = new_doc("FaceBlend")
    floor, edge_f, wall, edge_w = wavy_floor_and_wall(doc)
    blend = make_face_blend(doc, (floor, "Face1"), (floor, edge_f), (wall, "Face1"), (wall, edge_w))
    FreeCADGui.Selection.clearSelection()
    panel = edit(blend)
    panel.zebra.setChecked(True)
    panel.check.setChecked(True)
    settle()
    print(blend.Status)
    grab(out, "face_blend_panel", "viewIsometric")
    panel.reject()
    settle()

    # The same blend with zebra on it and its faces, and the continuity check's table of the
    # joins (Check continuity on the blend and its two faces).
    from freecad_workbench.gui import continuity, zebra_shape
    from freecad_workbench.gui.panels.continuity import ContinuityTaskPanel
    from freecad_workbench.gui.panels.face_blend import SEWN_GAP

    for obj in (blend, floor, wall):
        zebra_shape.show(obj, stripes=12, vertical=True)
    size = blend.Shape.BoundBox.DiagonalLength
    check = continuity.show([(blend, "Face1"), (floor, "Face1"), (wall, "Face1")], gap_tolerance=SEWN_GAP * size)
    panel = ContinuityTaskPanel(check)
    FreeCADGui.Control.showDialog(panel)
    settle()
    joins = [i for i, r in enumerate(check.records) if r.kind == "shared"]
    if joins:
        panel.choose(joins[0])
    print([(r.edge, r.kind, r.continuity) for r in check.records])
    grab(out, "face_blend_check", "viewIsometric")
    panel.reject()
    zebra_shape.hide()
    settle()


if __name__ == "__main__":
    ARGS = [a for a in sys.argv[1:] if not a.startswith("--")]
    OUT = ARGS[0] if ARGS else os.path.join(REPO, "docs", "gui")
    if "--surface" in sys.argv:  # only the surface analysis pictures
        os.makedirs(OUT, exist_ok=True)
        start_gui()
        surface_analysis(OUT)
    elif "--torsion" in sys.argv:  # only the torsion comb picture
        os.makedirs(OUT, exist_ok=True)
        start_gui()
        torsion_comb(OUT)
    elif "--face-blend" in sys.argv:  # only the face blend picture
        os.makedirs(OUT, exist_ok=True)
        start_gui()
        face_blend(OUT)
    else:
        main(OUT)
    sys.stdout.flush()
    os._exit(0)  # leave without tearing down Qt from Python (Shiboken crashes at exit otherwise)
