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

from ...features.basic_curve import KINDS, is_basic_curve
from ...features.design_spline import is_samples_source
from ...features.design_spline import is_design_spline
from ...features.edit_polygon import is_edit_polygon
from .. import command_name
from .common import QT_TRANSLATE_NOOP, create, edit_later, link_code, one_edge, resources, selected_links

KIND_COMMANDS = {kind: command_name(kind) for kind in KINDS}
GROUP = "FairSplines_BasicCurves"
DESIGN_COMMANDS = (
    GROUP,
    "FairSplines_DesignSpline",
    "FairSplines_MarkPoints",
    "FairSplines_EditPolygon",
    "FairSplines_ProfileTest",
)
SECTION = "Design with basic curves"

_KIND_TIPS = {
    "Line segment": QT_TRANSLATE_NOOP("FairSplines_LineSegment", "A line segment, to join to curved pieces"),
    "Circle arc": QT_TRANSLATE_NOOP("FairSplines_CircleArc", "A circle arc (kept exact in a design)"),
    "Ellipse arc": QT_TRANSLATE_NOOP("FairSplines_EllipseArc", "An ellipse arc (kept exact in a design)"),
    "Parabola arc": QT_TRANSLATE_NOOP("FairSplines_ParabolaArc", "A parabola arc (kept exact in a design)"),
    "Hyperbola arc": QT_TRANSLATE_NOOP("FairSplines_HyperbolaArc", "A hyperbola arc (kept exact in a design)"),
    "Archimedean spiral": QT_TRANSLATE_NOOP(
        "FairSplines_ArchimedeanSpiral", "An Archimedean spiral (followed to about 1e-8 of its size in a design)"),
    "Circle involute": QT_TRANSLATE_NOOP(
        "FairSplines_CircleInvolute", "An involute of a circle (followed closely in a design)"),
    "Rational cubic": QT_TRANSLATE_NOOP(
        "FairSplines_RationalCubic", "A rational Bezier curve of degree at most 3 (kept exact in a design)"),
}
_KIND_MENU = {
    "Line segment": QT_TRANSLATE_NOOP("FairSplines_LineSegment", "Line segment"),
    "Circle arc": QT_TRANSLATE_NOOP("FairSplines_CircleArc", "Circle arc"),
    "Ellipse arc": QT_TRANSLATE_NOOP("FairSplines_EllipseArc", "Ellipse arc"),
    "Parabola arc": QT_TRANSLATE_NOOP("FairSplines_ParabolaArc", "Parabola arc"),
    "Hyperbola arc": QT_TRANSLATE_NOOP("FairSplines_HyperbolaArc", "Hyperbola arc"),
    "Archimedean spiral": QT_TRANSLATE_NOOP("FairSplines_ArchimedeanSpiral", "Archimedean spiral"),
    "Circle involute": QT_TRANSLATE_NOOP("FairSplines_CircleInvolute", "Circle involute"),
    "Rational cubic": QT_TRANSLATE_NOOP("FairSplines_RationalCubic", "Rational cubic"),
}


def usable_piece(obj, sub):
    """Whether a selection entry can be a piece of a design (a quick check: an edge or a
    BasicCurve; whether the edge is a line or conic is checked when the design computes;
    or sampled data: a whole Points object or sketch of points)."""
    return is_basic_curve(obj) or one_edge(obj, sub) or (not sub and is_samples_source(obj))


class BasicCurveCommand:
    """Create a BasicCurve of one kind at the origin (XY plane) and open its panel."""

    def __init__(self, kind):
        self.kind = kind
        self.name = KIND_COMMANDS[kind]

    def GetResources(self):
        return resources(self.name, _KIND_MENU[self.kind], _KIND_TIPS[self.kind], SECTION)

    def IsActive(self):
        return FreeCAD.ActiveDocument is not None

    def Activated(self):
        obj = create(FreeCAD.ActiveDocument, "basic_curve", "make_basic_curve", repr(self.kind))
        if obj is not None:
            edit_later(obj)


class BasicCurvesGroup:
    """Drop-down button of the basic curve commands."""

    def GetCommands(self):
        return tuple(KIND_COMMANDS[k] for k in KINDS)

    def GetDefaultCommand(self):
        return KINDS.index("Circle arc")

    def GetResources(self):
        return resources(
            GROUP,
            QT_TRANSLATE_NOOP(GROUP, "Basic curve"),
            QT_TRANSLATE_NOOP(GROUP, "Create a basic curve: line, conic arc, spiral, involute, rational cubic"),
            SECTION,
        )

    def IsActive(self):
        return FreeCAD.ActiveDocument is not None


class DesignSplineCommand:
    NAME = "FairSplines_DesignSpline"

    def GetResources(self):
        return resources(
            self.NAME,
            QT_TRANSLATE_NOOP("FairSplines_DesignSpline", "Design spline"),
            QT_TRANSLATE_NOOP(
                "FairSplines_DesignSpline",
                "One smooth (C2) spline through the selected basic curves, in pick order: edges of\n"
                "sketches or Part objects (lines, arcs, conics) or Basic curve objects; a Points object or a\n"
                "sketch of points is a sampled piece (its csr-spline). Then mark points on them.",
            ),
            SECTION,
            accel="F, D",
        )

    def IsActive(self):
        links = selected_links()
        return bool(links) and all(usable_piece(o, s) for o, s in links)

    def Activated(self):
        links = selected_links()
        if not links:
            return
        pieces = "[" + ", ".join(f"({link_code(o, s)}, None)" for o, s in links) + "]"
        obj = create(links[0][0].Document, "design_spline", "make_design_spline", pieces)
        FreeCADGui.Selection.clearSelection()
        if obj is not None:
            edit_later(obj)


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
        return resources(
            self.NAME,
            QT_TRANSLATE_NOOP("FairSplines_MarkPoints", "Mark points"),
            QT_TRANSLATE_NOOP(
                "FairSplines_MarkPoints",
                "Move, add and remove the points marked on the pieces of the selected Design spline,\n"
                "with sliders (live preview)"),
            SECTION,
        )

    def IsActive(self):
        return _selected_design() is not None and not FreeCADGui.Control.activeDialog()

    def Activated(self):
        obj = _selected_design()
        if obj is not None:
            FreeCADGui.Selection.clearSelection()
            edit_later(obj)


def _selected_spline():
    """The one selected (obj, sub) with one B-spline-able edge, or None."""
    links = selected_links()
    if len(links) != 1:
        return None
    obj, sub = links[0]
    return (obj, sub) if one_edge(obj, sub) else None


class EditPolygonCommand:
    NAME = "FairSplines_EditPolygon"

    def GetResources(self):
        return resources(
            self.NAME,
            QT_TRANSLATE_NOOP("FairSplines_EditPolygon", "Edit control points"),
            QT_TRANSLATE_NOOP(
                "FairSplines_EditPolygon",
                "Move control points of the selected spline (a Design spline, a spline through points or any\n"
                "B-spline edge). The edited curve follows the design; a moved point changes the curve only\n"
                "near it (the four spans it supports).",
            ),
            SECTION,
            accel="F, E",
        )

    def IsActive(self):
        return _selected_spline() is not None and not FreeCADGui.Control.activeDialog()

    def Activated(self):
        link = _selected_spline()
        if link is None:
            return
        obj, sub = link
        FreeCADGui.Selection.clearSelection()
        if is_edit_polygon(obj):
            edit_later(obj)
            return
        source = link_code(obj)
        created = create(obj.Document, "edit_polygon", "make_edit_polygon", link_code(obj, sub))
        if created is not None:
            FreeCADGui.doCommand(f"{source}.ViewObject.Visibility = False")
            edit_later(created)


class ProfileTestCommand:
    NAME = "FairSplines_ProfileTest"

    def GetResources(self):
        return resources(
            self.NAME,
            QT_TRANSLATE_NOOP("FairSplines_ProfileTest", "Profile test"),
            QT_TRANSLATE_NOOP(
                "FairSplines_ProfileTest",
                "Revolve the selected profile curve into its exact surface of revolution, with zebra shading:\n"
                "kinks or wobbles of the stripes show curvature flaws of the profile. Axis: the sketch's\n"
                "vertical axis, or Z (change AxisPoint / AxisDirection).",
            ),
            SECTION,
        )

    def IsActive(self):
        return _selected_spline() is not None

    def Activated(self):
        link = _selected_spline()
        if link is None:
            return
        obj, sub = link
        create(obj.Document, "profile_test", "make_profile_test", link_code(obj, sub))
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
