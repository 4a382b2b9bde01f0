"""Analysis commands (GUI only): judge the fairness of any edge. Each records a
replayable macro line.

FairSplines_CurvatureComb   show/hide curvature combs of the selected edges
FairSplines_CurvaturePlot   plot curvature against arc length of the selected edges
FairSplines_CheckMonotone   certify whether the curvature of the selected planar edges is
                            monotone: report view + curvature plot with extrema marked
"""
import FreeCAD
import FreeCADGui

from ... import monotone
from ...errors import InputError
from .. import comb, plot
from .common import QT_TRANSLATE_NOOP, edge_links, links_code, resources, run_on_selected_edges, selected_links

GROUP = "FairSplines_AnalysisGroup"
COMMANDS = ("FairSplines_CurvatureComb", "FairSplines_CurvaturePlot", "FairSplines_CheckMonotone")


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
                                         "Curvature comb, curvature plot, monotonicity check, zebra profile test"),
        }

    def IsActive(self):
        return True


def command_objects():
    """{name: command} of every command in this module."""
    return {
        CurvatureCombCommand.NAME: CurvatureCombCommand(),
        CurvaturePlotCommand.NAME: CurvaturePlotCommand(),
        CheckMonotoneCommand.NAME: CheckMonotoneCommand(),
        GROUP: AnalysisGroup(),
    }
