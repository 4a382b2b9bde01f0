"""Task panel of the curvature combs: scale, number of teeth, one scale for all combs and
the torsion comb of space curves, applied while you edit them. Cancel restores the values the panel opened with."""
import FreeCAD
import FreeCADGui

from .. import comb, icon_path
from .form import form_rows, new_form

translate = FreeCAD.Qt.translate

_panel = None


def active_comb_panel():
    """The open comb panel, if any."""
    return _panel if FreeCADGui.Control.activeDialog() else None


class CombTaskPanel:
    def __init__(self):
        from ..qt import QtWidgets

        global _panel
        _panel = self
        self.initial = (*comb.get_style(), comb.common_scale(), comb.torsion_shown())
        self.form, layout = new_form(translate("FairSplines", "Curvature comb"), icon_path("FairSplines_CurvatureComb"))
        rows = form_rows()
        self.scale = QtWidgets.QDoubleSpinBox()
        self.scale.setRange(-1000.0, 1000.0)
        self.scale.setDecimals(3)
        self.scale.setSingleStep(0.1)
        self.scale.setValue(self.initial[0])
        self.scale.setToolTip(translate(
            "FairSplines",
            "1: the longest tooth is at most a quarter of the curve's size, and every tooth ends short of "
            "its centre of curvature (at most 90% of the way), so the teeth of an arc do not cross. "
            "Above 1 teeth may reach past their centres. Negative: the comb on the other side."))
        self.samples = QtWidgets.QSpinBox()
        self.samples.setRange(8, 100000)
        self.samples.setValue(self.initial[1])
        self.samples.setToolTip(translate("FairSplines", "Teeth per edge (at least)"))
        self.common = QtWidgets.QCheckBox(translate("FairSplines", "One scale for all"))
        self.common.setChecked(self.initial[2])
        self.common.setToolTip(translate(
            "FairSplines",
            "On: every comb shown is drawn to one scale, the smallest any of them would get on its own, "
            "so tooth lengths compare between curves. Off: each comb is sized to its own curve."))
        self.torsion = QtWidgets.QCheckBox(translate("FairSplines", "Torsion comb too"))
        self.torsion.setChecked(self.initial[3])
        self.torsion.setToolTip(comb.torsion_tooltip())
        rows.addRow(translate("FairSplines", "Scale"), self.scale)
        rows.addRow(translate("FairSplines", "Teeth"), self.samples)
        rows.addRow(self.common)
        rows.addRow(self.torsion)
        layout.addLayout(rows)
        layout.addStretch(1)
        self.scale.valueChanged.connect(self.apply)
        self.samples.valueChanged.connect(self.apply)
        self.common.toggled.connect(self.apply)
        self.torsion.toggled.connect(self.apply)

    def apply(self, *_):
        comb.set_style(self.scale.value(), self.samples.value(), self.common.isChecked(), self.torsion.isChecked())

    def accept(self):
        self.apply()
        self.close()
        return True

    def reject(self):
        comb.set_style(*self.initial)
        self.close()
        return True

    def close(self):
        global _panel
        _panel = None
        FreeCADGui.Control.closeDialog()
