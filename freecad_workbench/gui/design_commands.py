"""The design-with-basic-curves commands (GUI only). Each records a replayable macro line.

FairSplines_BasicCurves   drop-down of the basic curve commands below
FairSplines_LineSegment, _CircleArc, _EllipseArc, _ParabolaArc, _HyperbolaArc,
FairSplines_ArchimedeanSpiral, _CircleInvolute, _RationalCubic
                          a BasicCurve of that kind; its dimensions panel opens
FairSplines_DesignSpline  a Design spline of the selected edges / basic curves, in pick
                          order; the Mark points panel opens
FairSplines_MarkPoints    the Mark points panel of the selected Design spline
FairSplines_EditPolygon   an Edit polygon of the selected spline (or edit the selected one)
FairSplines_ProfileTest   revolve the selected profile, with zebra shading
"""
import FreeCAD
import FreeCADGui

from ..features.basic_curve import KINDS, is_basic_curve
from ..features.design_spline import is_design_spline
from ..features.edit_polygon import is_edit_polygon
from . import icon_path
from .commands import selected_links

QT_TRANSLATE_NOOP = FreeCAD.Qt.QT_TRANSLATE_NOOP

KIND_COMMANDS = {kind: "FairSplines_" + kind.title().replace(" ", "") for kind in KINDS}
GROUP = "FairSplines_BasicCurves"
DESIGN_COMMANDS = (
    GROUP,
    "FairSplines_DesignSpline",
    "FairSplines_MarkPoints",
    "FairSplines_EditPolygon",
    "FairSplines_ProfileTest",
)

_KIND_TIPS = {
    "Line segment": "A line segment, to join to curved pieces",
    "Circle arc": "A circle arc (kept exact in a design)",
    "Ellipse arc": "An ellipse arc (kept exact in a design)",
    "Parabola arc": "A parabola arc (kept exact in a design)",
    "Hyperbola arc": "A hyperbola arc (kept exact in a design)",
    "Archimedean spiral": "An Archimedean spiral (approximated to about 1e-8 in a design)",
    "Circle involute": "An involute of a circle (approximated closely in a design)",
    "Rational cubic": "A rational Bezier curve of degree at most 3 (kept exact in a design)",
}


def _element(sub):
    return sub.rsplit(".", 1)[-1] if sub else ""


def _one_edge(obj, sub):
    """Whether (obj, sub) names one edge: an EdgeN, or a whole object with one edge."""
    element = _element(sub)
    if element:
        return element.startswith("Edge")
    shape = getattr(obj, "Shape", None)
    return shape is not None and not shape.isNull() and len(shape.Edges) == 1


def usable_piece(obj, sub):
    """Whether a selection entry can be a piece of a design (a quick check: an edge or a
    BasicCurve; whether the edge is a line or conic is checked when the design computes)."""
    return is_basic_curve(obj) or _one_edge(obj, sub)


def _edit(obj):
    FreeCADGui.doCommand("import FreeCADGui")
    FreeCADGui.doCommand(
        f"FreeCADGui.getDocument({obj.Document.Name!r}).setEdit({obj.Name!r}, 0)")


def _edit_later(obj):
    """Open obj's task panel once the command has returned: FreeCAD closes the command's
    own undo step then, so the panel's changes become an undo step of their own."""
    from .qt import QtCore

    doc_name, name = obj.Document.Name, obj.Name

    def edit():
        doc = FreeCAD.listDocuments().get(doc_name)
        target = doc.getObject(name) if doc is not None else None
        if target is not None and not FreeCADGui.Control.activeDialog():
            _edit(target)

    QtCore.QTimer.singleShot(0, edit)


def _new_object(doc, before):
    created = [o for o in doc.Objects if o.Name not in before]
    return created[-1] if created else None


class BasicCurveCommand:
    """Create a BasicCurve of one kind at the origin (XY plane) and open its panel."""

    def __init__(self, kind):
        self.kind = kind
        self.name = KIND_COMMANDS[kind]

    def GetResources(self):
        return {
            "Pixmap": icon_path(self.name),
            "MenuText": QT_TRANSLATE_NOOP(self.name, self.kind.capitalize()),
            "ToolTip": QT_TRANSLATE_NOOP(self.name, _KIND_TIPS[self.kind] + ".\nSet its dimensions in the panel."),
        }

    def IsActive(self):
        return FreeCAD.ActiveDocument is not None

    def Activated(self):
        doc = FreeCAD.ActiveDocument
        before = {o.Name for o in doc.Objects}
        FreeCADGui.doCommand("import FreeCAD")
        FreeCADGui.doCommand("from freecad_workbench.features.basic_curve import make_basic_curve")
        FreeCADGui.doCommand(f"make_basic_curve(FreeCAD.getDocument({doc.Name!r}), {self.kind!r})")
        obj = _new_object(doc, before)
        if obj is not None:
            _edit_later(obj)


class BasicCurvesGroup:
    """Drop-down button of the basic curve commands."""

    def GetCommands(self):
        return tuple(KIND_COMMANDS[k] for k in KINDS)

    def GetDefaultCommand(self):
        return KINDS.index("Circle arc")

    def GetResources(self):
        return {
            "Pixmap": icon_path(GROUP),
            "MenuText": QT_TRANSLATE_NOOP(GROUP, "Basic curve"),
            "ToolTip": QT_TRANSLATE_NOOP(GROUP, "Create a basic curve: line, conic arc, spiral, involute, rational cubic"),
        }

    def IsActive(self):
        return FreeCAD.ActiveDocument is not None


class DesignSplineCommand:
    NAME = "FairSplines_DesignSpline"

    def GetResources(self):
        return {
            "Pixmap": icon_path(self.NAME),
            "MenuText": QT_TRANSLATE_NOOP(self.NAME, "Design spline"),
            "ToolTip": QT_TRANSLATE_NOOP(
                self.NAME,
                "One C2 spline through the selected basic curves, in pick order: edges of sketches or Part\n"
                "objects (lines, arcs, conics) or Basic curve objects. Then mark points on them.",
            ),
        }

    def IsActive(self):
        links = selected_links()
        return bool(links) and all(usable_piece(o, s) for o, s in links)

    def Activated(self):
        links = selected_links()
        if not links:
            return
        doc = links[0][0].Document
        pieces = "[" + ", ".join(f"({code}, None)" for code in _link_codes(links)) + "]"
        before = {o.Name for o in doc.Objects}
        FreeCADGui.doCommand("import FreeCAD")
        FreeCADGui.doCommand("from freecad_workbench.features.design_spline import make_design_spline")
        FreeCADGui.doCommand(f"make_design_spline(FreeCAD.getDocument({doc.Name!r}), {pieces})")
        FreeCADGui.Selection.clearSelection()
        obj = _new_object(doc, before)
        if obj is not None:
            _edit_later(obj)


def _link_codes(links):
    """Python source of each (obj, sub), for the macro recording."""
    return [f"(FreeCAD.getDocument({o.Document.Name!r}).getObject({o.Name!r}), {s!r})" for o, s in links]


def _selected_design():
    links = selected_links()
    objs = {o.Name: o for o, _ in links}
    if len(objs) != 1:
        return None
    obj = next(iter(objs.values()))
    return obj if is_design_spline(obj) else None


class MarkPointsCommand:
    NAME = "FairSplines_MarkPoints"

    def GetResources(self):
        return {
            "Pixmap": icon_path(self.NAME),
            "MenuText": QT_TRANSLATE_NOOP(self.NAME, "Mark points"),
            "ToolTip": QT_TRANSLATE_NOOP(
                self.NAME, "Move, add and remove the marks of the selected Design spline with sliders (live preview)"),
        }

    def IsActive(self):
        return _selected_design() is not None and not FreeCADGui.Control.activeDialog()

    def Activated(self):
        obj = _selected_design()
        if obj is not None:
            FreeCADGui.Selection.clearSelection()
            _edit_later(obj)


def _selected_spline():
    """The one selected (obj, sub) with one B-spline-able edge, or None."""
    links = selected_links()
    if len(links) != 1:
        return None
    obj, sub = links[0]
    return (obj, sub) if _one_edge(obj, sub) else None


class EditPolygonCommand:
    NAME = "FairSplines_EditPolygon"

    def GetResources(self):
        return {
            "Pixmap": icon_path(self.NAME),
            "MenuText": QT_TRANSLATE_NOOP(self.NAME, "Edit polygon"),
            "ToolTip": QT_TRANSLATE_NOOP(
                self.NAME,
                "Move control points of the selected spline (a Design spline, csr fit or any B-spline edge).\n"
                "The edited curve follows the design; a moved pole changes only the four spans it supports.",
            ),
        }

    def IsActive(self):
        return _selected_spline() is not None and not FreeCADGui.Control.activeDialog()

    def Activated(self):
        link = _selected_spline()
        if link is None:
            return
        obj, sub = link
        FreeCADGui.Selection.clearSelection()
        if is_edit_polygon(obj):
            _edit_later(obj)
            return
        doc = obj.Document
        source = f"FreeCAD.getDocument({doc.Name!r}).getObject({obj.Name!r})"
        before = {o.Name for o in doc.Objects}
        FreeCADGui.doCommand("import FreeCAD")
        FreeCADGui.doCommand("from freecad_workbench.features.edit_polygon import make_edit_polygon")
        FreeCADGui.doCommand(f"make_edit_polygon(FreeCAD.getDocument({doc.Name!r}), ({source}, {sub!r}))")
        created = _new_object(doc, before)
        if created is not None:
            FreeCADGui.doCommand(f"{source}.ViewObject.Visibility = False")
            _edit_later(created)


class ProfileTestCommand:
    NAME = "FairSplines_ProfileTest"

    def GetResources(self):
        return {
            "Pixmap": icon_path(self.NAME),
            "MenuText": QT_TRANSLATE_NOOP(self.NAME, "Profile test"),
            "ToolTip": QT_TRANSLATE_NOOP(
                self.NAME,
                "Revolve the selected profile curve into its exact surface of revolution, with zebra shading:\n"
                "kinks or wobbles of the stripes show curvature flaws of the profile. Axis: the sketch's\n"
                "vertical axis, or Z (change AxisPoint / AxisDirection).",
            ),
        }

    def IsActive(self):
        return _selected_spline() is not None

    def Activated(self):
        link = _selected_spline()
        if link is None:
            return
        obj, sub = link
        doc = obj.Document
        FreeCADGui.doCommand("import FreeCAD")
        FreeCADGui.doCommand("from freecad_workbench.features.profile_test import make_profile_test")
        FreeCADGui.doCommand(
            f"make_profile_test(FreeCAD.getDocument({doc.Name!r}), "
            f"(FreeCAD.getDocument({doc.Name!r}).getObject({obj.Name!r}), {sub!r}))")
        FreeCADGui.Selection.clearSelection()


def command_objects():
    """{name: command} of every command in this module."""
    commands = {KIND_COMMANDS[k]: BasicCurveCommand(k) for k in KINDS}
    commands[GROUP] = BasicCurvesGroup()
    commands[DesignSplineCommand.NAME] = DesignSplineCommand()
    commands[MarkPointsCommand.NAME] = MarkPointsCommand()
    commands[EditPolygonCommand.NAME] = EditPolygonCommand()
    commands[ProfileTestCommand.NAME] = ProfileTestCommand()
    return commands


def register():
    """Add the commands to FreeCADGui (once)."""
    existing = FreeCADGui.listCommands()
    for name, command in command_objects().items():
        if name not in existing:
            FreeCADGui.addCommand(name, command)


register()
