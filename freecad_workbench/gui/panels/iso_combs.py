"""Task panel of the combs on isolines and sections: which curves (U, V, both, or cross
sections normal to X, Y or Z), how many, and the comb's scale, applied at once. Close
removes the combs."""
import FreeCAD
import FreeCADGui

from .. import icon_path
from .form import compact, form_rows, new_form, standard_buttons

translate = FreeCAD.Qt.translate
QT_TRANSLATE_NOOP = FreeCAD.Qt.QT_TRANSLATE_NOOP

LINE_TEXT = (
    ("U", QT_TRANSLATE_NOOP("FairSplines", "U isolines")),
    ("V", QT_TRANSLATE_NOOP("FairSplines", "V isolines")),
    ("UV", QT_TRANSLATE_NOOP("FairSplines", "U and V isolines")),
    ("X", QT_TRANSLATE_NOOP("FairSplines", "Sections across X")),
    ("Y", QT_TRANSLATE_NOOP("FairSplines", "Sections across Y")),
    ("Z", QT_TRANSLATE_NOOP("FairSplines", "Sections across Z")),
)

_panel = None


def active_iso_panel():
    return _panel if FreeCADGui.Control.activeDialog() else None


class IsoCombsTaskPanel:
    def __init__(self, links, lines="UV", count=5, scale=1.0):
        from ..qt import QtWidgets

        global _panel
        _panel = self
        self.links = list(links)
        self.form, layout = new_form(translate("FairSplines", "Combs on isolines"), icon_path("FairSplines_IsoCombs"))
        rows = form_rows()
        self.lines = compact(QtWidgets.QComboBox())
        for key, text in LINE_TEXT:
            self.lines.addItem(translate("FairSplines", text), key)
        self.lines.setCurrentIndex([k for k, _ in LINE_TEXT].index(lines))
        self.lines.setToolTip(translate(
            "FairSplines", "Isolines: the face's own parameter lines. Sections: cuts by evenly spaced planes "
            "across the faces' box, normal to that axis."))
        self.count = compact(QtWidgets.QSpinBox())
        self.count.setRange(1, 100)
        self.count.setValue(count)
        self.count.setToolTip(translate("FairSplines", "Curves per face and direction, evenly spaced"))
        self.scale = compact(QtWidgets.QDoubleSpinBox())
        self.scale.setRange(-100.0, 100.0)
        self.scale.setDecimals(2)
        self.scale.setSingleStep(0.1)
        self.scale.setValue(scale)
        self.scale.setToolTip(translate(
            "FairSplines", "1: the longest tooth a quarter of the curves' size and short of its centre of "
            "curvature. Negative: the comb on the other side."))
        rows.addRow(translate("FairSplines", "Curves"), self.lines)
        rows.addRow(translate("FairSplines", "How many"), self.count)
        rows.addRow(translate("FairSplines", "Scale"), self.scale)
        layout.addLayout(rows)
        layout.addStretch(1)
        self.lines.currentIndexChanged.connect(self.apply)
        self.count.valueChanged.connect(self.apply)
        self.scale.valueChanged.connect(self.apply)

    def apply(self, *_):
        code = ", ".join(f"(FreeCAD.getDocument({o.Document.Name!r}).getObject({o.Name!r}), {s!r})"
                         for o, s in self.links)
        FreeCADGui.doCommand("import FreeCAD")
        FreeCADGui.doCommand("import freecad_workbench.gui.iso_combs")
        FreeCADGui.doCommand(f"freecad_workbench.gui.iso_combs.show([{code}], lines={self.lines.currentData()!r}, "
                             f"count={self.count.value()}, scale={self.scale.value()!r})")
        FreeCADGui.updateGui()

    def getStandardButtons(self):
        from ..qt import QtWidgets

        return standard_buttons(QtWidgets.QDialogButtonBox.Close)

    def accept(self):
        return self.reject()

    def reject(self):
        global _panel
        _panel = None
        FreeCADGui.doCommand("import freecad_workbench.gui.iso_combs")
        FreeCADGui.doCommand("freecad_workbench.gui.iso_combs.hide()")
        FreeCADGui.Control.closeDialog()
        return True
