"""The FairSplines commands (GUI only). Each records a replayable macro line.

FairSplines_CsrFit          csr fit of the selected vertices, Points, sketch or edges
FairSplines_CurvatureComb   show/hide curvature combs of the selected edges
FairSplines_CurvaturePlot   plot curvature against arc length of the selected edges
"""
import FreeCAD
import FreeCADGui

from ..features.csr_fit import usable_source
from . import comb, icon_path

translate = FreeCAD.Qt.translate
QT_TRANSLATE_NOOP = FreeCAD.Qt.QT_TRANSLATE_NOOP

COMMANDS = ("FairSplines_CsrFit", "FairSplines_CurvatureComb", "FairSplines_CurvaturePlot")


def selected_links(doc=None):
    """The selection in the active document as [(obj, subname)] in pick order (a whole
    object has subname '')."""
    doc = doc or FreeCAD.ActiveDocument
    if doc is None:
        return []
    links = []
    for sel in FreeCADGui.Selection.getCompleteSelection():
        obj = sel.Object
        if obj.Document.Name != doc.Name:
            continue
        subs = sel.SubElementNames or ("",)
        links.extend((obj, sub) for sub in subs)
    return links


def _edge_links(links):
    """The links that hold edges: an EdgeN element, or a whole object with edges."""
    result = []
    for obj, sub in links:
        element = sub.rsplit(".", 1)[-1]
        if element:
            if element.startswith("Edge"):
                result.append((obj, sub))
        elif comb.edges_of(obj):
            result.append((obj, sub))
    return result


def _links_code(links):
    """Python source of a links list, for the macro recording."""
    items = [f"(FreeCAD.getDocument({obj.Document.Name!r}).getObject({obj.Name!r}), {sub!r})" for obj, sub in links]
    return "[" + ", ".join(items) + "]"


class CsrFitCommand:
    def GetResources(self):
        return {
            "Pixmap": icon_path("FairSplines_CsrFit"),
            "MenuText": QT_TRANSLATE_NOOP("FairSplines_CsrFit", "Csr fit"),
            "ToolTip": QT_TRANSLATE_NOOP(
                "FairSplines_CsrFit",
                "Fit a csr-spline to the selected vertices, Points object, sketch points or edges.\n"
                "Select points in order; edges are sampled.",
            ),
        }

    def IsActive(self):
        links = selected_links()
        return bool(links) and all(usable_source(obj, sub) for obj, sub in links)

    def Activated(self):
        links = selected_links()
        if not links:
            return
        FreeCADGui.doCommand("import FreeCAD")
        FreeCADGui.doCommand("from freecad_workbench.features.csr_fit import make_csr_fit")
        FreeCADGui.doCommand(f"make_csr_fit(FreeCAD.getDocument({links[0][0].Document.Name!r}), {_links_code(links)})")
        FreeCADGui.Selection.clearSelection()


class CurvatureCombCommand:
    def GetResources(self):
        return {
            "Pixmap": icon_path("FairSplines_CurvatureComb"),
            "MenuText": QT_TRANSLATE_NOOP("FairSplines_CurvatureComb", "Curvature comb"),
            "ToolTip": QT_TRANSLATE_NOOP(
                "FairSplines_CurvatureComb",
                "Show or hide the curvature comb of the selected edges.\nWith nothing selected, hide all combs.",
            ),
        }

    def IsActive(self):
        return bool(comb.shown()) or bool(_edge_links(selected_links()))

    def Activated(self):
        links = _edge_links(selected_links())
        FreeCADGui.doCommand("import FreeCAD")
        FreeCADGui.doCommand("import freecad_workbench.gui.comb")
        FreeCADGui.doCommand(f"freecad_workbench.gui.comb.toggle({_links_code(links)})")
        if comb.shown():
            if not FreeCADGui.Control.activeDialog():
                FreeCADGui.Control.showDialog(CombTaskPanel())
        elif isinstance(_active_panel(), CombTaskPanel):
            _active_panel()._close()
        FreeCADGui.updateGui()


class CurvaturePlotCommand:
    def GetResources(self):
        return {
            "Pixmap": icon_path("FairSplines_CurvaturePlot"),
            "MenuText": QT_TRANSLATE_NOOP("FairSplines_CurvaturePlot", "Curvature plot"),
            "ToolTip": QT_TRANSLATE_NOOP(
                "FairSplines_CurvaturePlot", "Plot curvature against arc length of the selected edges, one line each."
            ),
        }

    def IsActive(self):
        return bool(_edge_links(selected_links()))

    def Activated(self):
        links = _edge_links(selected_links())
        if not links:
            return
        FreeCADGui.doCommand("import FreeCAD")
        FreeCADGui.doCommand("import freecad_workbench.gui.plot")
        FreeCADGui.doCommand(f"freecad_workbench.gui.plot.plot_links({_links_code(links)})")


_panel = None


def _active_panel():
    return _panel if FreeCADGui.Control.activeDialog() else None


class CombTaskPanel:
    """Scale and sample count of the curvature combs, applied while you edit them.
    Cancel restores the values the panel opened with."""

    def __init__(self):
        from .qt import QtGui, QtWidgets

        global _panel
        _panel = self
        self.initial = comb.get_style()
        self.form = QtWidgets.QWidget()
        self.form.setWindowTitle(translate("FairSplines", "Curvature comb"))
        self.form.setWindowIcon(QtGui.QIcon(icon_path("FairSplines_CurvatureComb")))
        layout = QtWidgets.QFormLayout(self.form)
        self.scale = QtWidgets.QDoubleSpinBox()
        self.scale.setRange(-1000.0, 1000.0)
        self.scale.setDecimals(3)
        self.scale.setSingleStep(0.1)
        self.scale.setValue(self.initial[0])
        self.scale.setToolTip(
            translate("FairSplines", "1 makes the longest tooth a quarter of the curve's size; negative flips the side")
        )
        self.samples = QtWidgets.QSpinBox()
        self.samples.setRange(8, 100000)
        self.samples.setValue(self.initial[1])
        self.samples.setToolTip(translate("FairSplines", "Teeth per edge (at least)"))
        layout.addRow(translate("FairSplines", "Scale"), self.scale)
        layout.addRow(translate("FairSplines", "Teeth"), self.samples)
        self.scale.valueChanged.connect(self.apply)
        self.samples.valueChanged.connect(self.apply)

    def apply(self, *_):
        comb.set_style(self.scale.value(), self.samples.value())

    def accept(self):
        self.apply()
        self._close()
        return True

    def reject(self):
        comb.set_style(*self.initial)
        self._close()
        return True

    def _close(self):
        global _panel
        _panel = None
        FreeCADGui.Control.closeDialog()


def register():
    """Add the commands to FreeCADGui (once)."""
    for name, command in zip(COMMANDS, (CsrFitCommand(), CurvatureCombCommand(), CurvaturePlotCommand())):
        if name not in FreeCADGui.listCommands():
            FreeCADGui.addCommand(name, command)


register()
