"""Analysis commands (GUI only): judge the fairness of any edge. Each records a
replayable macro line.

FairSplines_CurvatureComb   show/hide curvature combs of the selected edges
FairSplines_CurvaturePlot   plot curvature against arc length of the selected edges
FairSplines_CurvatureMap    colour the selected shapes or faces by a curvature quantity, with
                            a legend, a range and the value under the cursor
FairSplines_CheckContinuity the verdict of every edge of a shape or of touching faces (gap, G0,
                            G1, G2), drawn in colour and listed in a table
FairSplines_Zebra           zebra stripes or isophotes on any shape
FairSplines_IsoCombs        curvature combs on the isolines or planar sections of any face
FairSplines_CheckMonotone   certify whether the curvature of the selected planar edges is
                            monotone: report view + curvature plot with extrema marked
"""
import FreeCAD
import FreeCADGui

from ... import monotone
from ...errors import InputError
from .. import comb, curvature_map, plot, zebra_shape
from .common import (QT_TRANSLATE_NOOP, edge_links, element, link_code, links_code, resources, run_on_selected_edges,
                     selected_links)

GROUP = "FairSplines_AnalysisGroup"
COMMANDS = ("FairSplines_CurvatureComb", "FairSplines_CurvaturePlot", "FairSplines_CheckMonotone",
            "FairSplines_CurvatureMap", "FairSplines_CheckContinuity",
            "FairSplines_Zebra", "FairSplines_IsoCombs")


class CurvatureCombCommand:
    """Toggle the combs of the selected edges or objects (comb.toggle). A whole object's
    comb is its CurvatureComb view property, saved with the document; creating the command
    (when the workbench starts) installs the comb observers, so documents opened from now
    on, and those open already, draw their saved combs."""

    NAME = "FairSplines_CurvatureComb"

    def __init__(self):
        if FreeCAD.GuiUp:
            comb.install()

    def GetResources(self):
        return resources(
            self.NAME,
            QT_TRANSLATE_NOOP("FairSplines_CurvatureComb", "Curvature comb"),
            QT_TRANSLATE_NOOP(
                "FairSplines_CurvatureComb",
                "Show or hide the curvature comb of the selected edges.\nWith nothing selected, hide all combs.\n"
                "A whole object's comb is its view property Curvature Comb, saved with the document.",
            ),
            "Using it in the FreeCAD GUI",
            accel="F, K",
        )

    def IsActive(self):
        return bool(comb.shown()) or bool(edge_links(selected_links()))

    def Activated(self):
        from ..panels.comb import CombTaskPanel, active_comb_panel

        links = edge_links(selected_links())
        FreeCADGui.doCommand("import FreeCAD")
        FreeCADGui.doCommand("import freecad_workbench.gui.comb")
        FreeCADGui.doCommand(f"freecad_workbench.gui.comb.toggle({links_code(links)})")
        if comb.shown():
            if not FreeCADGui.Control.activeDialog():
                FreeCADGui.Control.showDialog(CombTaskPanel())
        elif active_comb_panel() is not None:
            active_comb_panel().close()
        FreeCADGui.updateGui()


class CurvaturePlotCommand:
    NAME = "FairSplines_CurvaturePlot"

    def GetResources(self):
        return resources(
            self.NAME,
            QT_TRANSLATE_NOOP("FairSplines_CurvaturePlot", "Curvature plot"),
            QT_TRANSLATE_NOOP(
                "FairSplines_CurvaturePlot",
                "Plot curvature against arc length of the selected edges, one line each,\n"
                "in a tab of the main window, with the curvature extrema marked.",
            ),
            "Using it in the FreeCAD GUI",
            accel="F, P",
        )

    def IsActive(self):
        return bool(edge_links(selected_links()))

    def Activated(self):
        run_on_selected_edges("freecad_workbench.gui.plot", "plot_links")


def check_links(links, path=None):
    """The certificate of every edge of selection-style links [(obj, sub)]: one report per edge
    in the report view, and a curvature plot with the extrema marked (written to `path` if
    given, else shown). Returns ([(label, MonotonicityReport or None)], matplotlib Figure)."""
    results, plotted = [], []
    for edge, label in plot.link_edges(links):
        try:
            report = monotone.check_monotone_curvature(edge)
        except InputError as exc:
            FreeCAD.Console.PrintError(f"{label}: {exc}\n")
            results.append((label, None))
            continue
        show = FreeCAD.Console.PrintMessage if report.monotone else FreeCAD.Console.PrintWarning
        show(f"{label}: {report.summary}\n  the proof, span by span (spans counted from 0):\n{report}\n")
        results.append((label, report))
        plotted.append((edge, label, report))
    if not plotted:
        return results, None
    marks = [
        (i, s.extremum[0], f"{label}: curvature {'maximum' if s.extremum[2] else 'minimum'}",
         "v" if s.extremum[2] else "^")
        for i, (_, label, report) in enumerate(plotted)
        for s in report.spans
        if s.extremum
    ]
    fig = plot.curvature_plot(
        [(edge, label) for edge, label, _ in plotted], path=path, title="Curvature monotonicity", marks=marks
    )
    return results, fig


class CheckMonotoneCommand:
    NAME = "FairSplines_CheckMonotone"

    def GetResources(self):
        return resources(
            self.NAME,
            QT_TRANSLATE_NOOP("FairSplines_CheckMonotone", "Check curvature monotonicity"),
            QT_TRANSLATE_NOOP(
                "FairSplines_CheckMonotone",
                "Prove whether the curvature of the selected planar edges only rises or only falls\n"
                "(an exact check, span by span): a report in the report view and a curvature plot\n"
                "with any extremum marked.",
            ),
            "Monotonic-curvature cubic B-splines",
            accel="F, M",
        )

    def IsActive(self):
        return bool(edge_links(selected_links()))

    def Activated(self):
        run_on_selected_edges("freecad_workbench.gui.commands.analysis", "check_links")


def face_links(links):
    """The links that hold faces: a FaceN element, or a whole object with faces."""
    result = []
    for obj, sub in links:
        name = element(sub)
        shape = getattr(obj, "Shape", None)
        if name.startswith("Face") or (not name and shape is not None and not shape.isNull() and shape.Faces):
            result.append((obj, sub))
    return result


class CurvatureMapCommand:
    """Turn the curvature map of the selected shapes or faces on (and open its panel), or
    off for those that have one; with nothing selected, every map off."""

    NAME = "FairSplines_CurvatureMap"

    def GetResources(self):
        return resources(
            self.NAME,
            QT_TRANSLATE_NOOP("FairSplines_CurvatureMap", "Curvature map"),
            QT_TRANSLATE_NOOP(
                "FairSplines_CurvatureMap",
                "Colour the selected shapes or faces by their curvature (Gaussian, mean, largest,\n"
                "minimum, maximum or radius), with a colour bar, an automatic or manual range, and\n"
                "the value under the cursor. Again on a mapped object: turn its map off.",
            ),
            "Surface analysis",
        )

    def IsActive(self):
        return bool(curvature_map.shown()) or bool(face_links(selected_links()))

    def Activated(self):
        from ..panels.curvature_map import CurvatureMapTaskPanel, active_map_panel

        links = face_links(selected_links())
        FreeCADGui.doCommand("import FreeCAD")
        FreeCADGui.doCommand("import freecad_workbench.gui.curvature_map")
        FreeCADGui.doCommand(f"freecad_workbench.gui.curvature_map.toggle({links_code(links)})")
        panel = active_map_panel()
        if panel is not None and curvature_map.map_of(panel.obj) is None:
            panel.close()
        mapped = [obj for obj, _ in links if curvature_map.map_of(obj) is not None]
        if mapped and not FreeCADGui.Control.activeDialog():
            FreeCADGui.Control.showDialog(CurvatureMapTaskPanel(mapped[0]))
        FreeCADGui.updateGui()


class CheckContinuityCommand:
    """Check the edges of the selected shape, or of the selected faces of one object."""

    NAME = "FairSplines_CheckContinuity"

    def GetResources(self):
        return resources(
            self.NAME,
            QT_TRANSLATE_NOOP("FairSplines_CheckContinuity", "Check continuity"),
            QT_TRANSLATE_NOOP(
                "FairSplines_CheckContinuity",
                "How smoothly the faces of the selected shape (or the selected faces) meet at each edge:\n"
                "gap, G0 (a kink), G1 (tangent) or G2 (curvature continuous), drawn in colour on the edges\n"
                "and listed in a table with the gap, angle and curvature jump. Click a row to find the edge.",
            ),
            "Surface analysis",
        )

    def IsActive(self):
        return bool(face_links(selected_links()))

    def Activated(self):
        from .. import continuity
        from ..panels.continuity import ContinuityTaskPanel, active_continuity_panel

        links = face_links(selected_links())
        links = [(obj, sub) for obj, sub in links if obj is links[0][0]]  # one object
        if active_continuity_panel() is not None:
            active_continuity_panel().reject()
        FreeCADGui.doCommand("import FreeCAD")
        FreeCADGui.doCommand("import freecad_workbench.gui.continuity")
        FreeCADGui.doCommand(f"freecad_workbench.gui.continuity.show({links_code(links)})")
        check = continuity.current()
        if check is not None and not FreeCADGui.Control.activeDialog():
            FreeCADGui.Control.showDialog(ContinuityTaskPanel(check))
        FreeCADGui.updateGui()


class ZebraCommand:
    """Zebra or isophotes on the selected objects (on), or off for those that have them."""

    NAME = "FairSplines_Zebra"

    def GetResources(self):
        return resources(
            self.NAME,
            QT_TRANSLATE_NOOP("FairSplines_Zebra", "Zebra"),
            QT_TRANSLATE_NOOP(
                "FairSplines_Zebra",
                "Show the selected shapes reflecting black and white stripes (zebra), or with isophotes:\n"
                "stripes that kink or break show where faces meet only tangent or with a kink.\n"
                "Again on a shaded object: turn it off.",
            ),
            "Surface analysis",
        )

    def IsActive(self):
        return bool(zebra_shape.shown()) or bool(face_links(selected_links()))

    def Activated(self):
        from ..panels.zebra_shape import ZebraTaskPanel, active_zebra_panel

        objects = list({obj.Name: obj for obj, _ in face_links(selected_links())}.values())
        FreeCADGui.doCommand("import FreeCAD")
        FreeCADGui.doCommand("import freecad_workbench.gui.zebra_shape")
        if not objects:
            FreeCADGui.doCommand("freecad_workbench.gui.zebra_shape.hide()")
        on = []
        for obj in objects:
            if zebra_shape.node_of(obj) is not None:
                FreeCADGui.doCommand(f"freecad_workbench.gui.zebra_shape.hide({link_code(obj)})")
            else:
                FreeCADGui.doCommand(f"freecad_workbench.gui.zebra_shape.show({link_code(obj)})")
                on.append(obj)
        panel = active_zebra_panel()
        if panel is not None and zebra_shape.node_of(panel.obj) is None:
            panel.close()
        if on and not FreeCADGui.Control.activeDialog():
            FreeCADGui.Control.showDialog(ZebraTaskPanel(on[0]))
        FreeCADGui.updateGui()


class IsoCombsCommand:
    """Curvature combs on the isolines (or planar sections) of the selected faces."""

    NAME = "FairSplines_IsoCombs"

    def GetResources(self):
        return resources(
            self.NAME,
            QT_TRANSLATE_NOOP("FairSplines_IsoCombs", "Combs on isolines"),
            QT_TRANSLATE_NOOP(
                "FairSplines_IsoCombs",
                "Curvature combs on the U and V isolines, or on planar cross sections, of the selected\n"
                "faces or shapes: how the curvature runs across a surface, not only along its edges.",
            ),
            "Surface analysis",
        )

    def IsActive(self):
        return bool(face_links(selected_links()))

    def Activated(self):
        from .. import iso_combs
        from ..panels.iso_combs import IsoCombsTaskPanel, active_iso_panel

        links = face_links(selected_links())
        if active_iso_panel() is not None:
            active_iso_panel().reject()
        FreeCADGui.doCommand("import FreeCAD")
        FreeCADGui.doCommand("import freecad_workbench.gui.iso_combs")
        FreeCADGui.doCommand(f"freecad_workbench.gui.iso_combs.show({links_code(links)})")
        if iso_combs.current() is not None and not FreeCADGui.Control.activeDialog():
            FreeCADGui.Control.showDialog(IsoCombsTaskPanel(links))
        FreeCADGui.updateGui()


class AnalysisGroup:
    """Drop-down button of the analysis commands, and the zebra profile test."""

    def GetCommands(self):
        return COMMANDS + ("FairSplines_ProfileTest",)

    def GetDefaultCommand(self):
        return 0

    def GetResources(self):
        return {
            "MenuText": QT_TRANSLATE_NOOP(GROUP, "Curvature analysis"),
            "ToolTip": QT_TRANSLATE_NOOP(GROUP,
                                         "Curvature comb, curvature plot, monotonicity check, curvature map,\n"
                                         "continuity check, zebra, combs on isolines, zebra profile test"),
        }

    def IsActive(self):
        return True


def command_objects():
    """{name: command} of every command in this module."""
    return {
        CurvatureCombCommand.NAME: CurvatureCombCommand(),
        CurvaturePlotCommand.NAME: CurvaturePlotCommand(),
        CheckMonotoneCommand.NAME: CheckMonotoneCommand(),
        CurvatureMapCommand.NAME: CurvatureMapCommand(),
        CheckContinuityCommand.NAME: CheckContinuityCommand(),
        ZebraCommand.NAME: ZebraCommand(),
        IsoCombsCommand.NAME: IsoCombsCommand(),
        GROUP: AnalysisGroup(),
    }
