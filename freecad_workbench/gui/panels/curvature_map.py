"""Task panel of the curvature map: the quantity, the automatic or a manual range (applied
at once, recolouring without re-meshing), and the value under the cursor. Close keeps the
map; Turn off removes it and restores the object's look."""
import math

import FreeCAD
import FreeCADGui

from .. import curvature_map, icon_path
from .form import SPIN_MAX_WIDTH, compact, form_rows, new_form, short_spin_box, standard_buttons, wrapped_label

translate = FreeCAD.Qt.translate

_panel = None


def _run(code):
    """A line of the map's API, run and recorded in the macro."""
    FreeCADGui.doCommand("import FreeCAD")
    FreeCADGui.doCommand("import freecad_workbench.gui.curvature_map")
    FreeCADGui.doCommand(code)


def active_map_panel():
    """The open curvature map panel, if any."""
    return _panel if FreeCADGui.Control.activeDialog() else None


class CurvatureMapTaskPanel:
    def __init__(self, obj):
        from ..qt import QtWidgets

        global _panel
        _panel = self
        self.obj = obj
        node = curvature_map.map_of(obj)
        self.form, layout = new_form(translate("FairSplines", "Curvature map"), icon_path("FairSplines_CurvatureMap"))
        rows = form_rows()
        self.quantity = compact(QtWidgets.QComboBox())
        for quantity in curvature_map.QUANTITIES:
            self.quantity.addItem(translate("FairSplines", curvature_map.QUANTITY_TEXT[quantity][0]), quantity)
        self.quantity.setToolTip(translate(
            "FairSplines",
            "Gaussian: k1 k2 (1/mm\u00b2), negative on saddles. Mean: (k1 + k2) / 2. Largest |curvature|: "
            "max(|k1|, |k2|). Minimum and maximum: the principal curvatures k2 and k1. Radius: 1 / largest "
            "|curvature|. Convex is positive, seen from the face's outside."))
        self.auto = QtWidgets.QCheckBox(translate("FairSplines", "Automatic range"))
        self.auto.setToolTip(translate(
            "FairSplines",
            "From the 2nd to the 98th percentile of the values, so that a few extreme points do not wash out "
            "the colours of the rest."))
        self.lower, self.upper = self._spin(), self._spin()
        self.lower.setToolTip(translate("FairSplines", "Blue from here down"))
        self.upper.setToolTip(translate("FairSplines", "Red from here up"))
        rows.addRow(translate("FairSplines", "Show"), self.quantity)
        rows.addRow(self.auto)
        rows.addRow(translate("FairSplines", "Lowest"), self.lower)
        rows.addRow(translate("FairSplines", "Highest"), self.upper)
        layout.addLayout(rows)
        self.value = wrapped_label(translate("FairSplines", "Move the cursor over the map to read its value."))
        self.value.setMinimumWidth(120)
        layout.addWidget(self.value)
        self.off = QtWidgets.QPushButton(translate("FairSplines", "Turn off"))
        self.off.setToolTip(translate("FairSplines", "Remove the map and show the object as before"))
        layout.addWidget(self.off)
        layout.addStretch(1)
        if node is not None:
            self.quantity.setCurrentIndex(curvature_map.QUANTITIES.index(node.quantity))
            self.auto.setChecked(node.manual is None)
        else:
            self.auto.setChecked(True)
        self._show_range()
        self.quantity.currentIndexChanged.connect(self._quantity_changed)
        self.auto.toggled.connect(self._range_changed)
        self.lower.valueChanged.connect(self._range_changed)
        self.upper.valueChanged.connect(self._range_changed)
        self.off.clicked.connect(self.turn_off)
        curvature_map._listeners.append(self.show_value)

    def _spin(self):
        spin = short_spin_box()
        spin.setRange(-1e9, 1e9)
        spin.setDecimals(6)
        spin.setKeyboardTracking(False)
        spin.setMaximumWidth(SPIN_MAX_WIDTH)
        return compact(spin)

    def _ref(self):
        return f"FreeCAD.getDocument({self.obj.Document.Name!r}).getObject({self.obj.Name!r})"

    def _unit(self):
        return " " + curvature_map.QUANTITY_TEXT[self.quantity.currentData()][1]

    def _show_range(self):
        node = curvature_map.map_of(self.obj)
        lower, upper = node.range if node is not None else (0.0, 1.0)
        span = abs(upper - lower) or abs(upper) or 1.0
        decimals = int(min(8, max(1, 3 - math.floor(math.log10(span)))))  # about 4 digits of the range
        for spin, value in ((self.lower, lower), (self.upper, upper)):
            spin.blockSignals(True)
            spin.setDecimals(decimals)
            spin.setSuffix(self._unit())
            spin.setSingleStep(max(abs(upper - lower) / 20, 1e-6))
            spin.setValue(value)
            spin.setEnabled(not self.auto.isChecked())
            spin.blockSignals(False)

    def _quantity_changed(self, *_):
        quantity = self.quantity.currentData()
        _run(f"freecad_workbench.gui.curvature_map.set_quantity({self._ref()}, {quantity!r})")
        self.auto.blockSignals(True)
        self.auto.setChecked(True)
        self.auto.blockSignals(False)
        self._show_range()
        FreeCADGui.updateGui()

    def _range_changed(self, *_):
        ref = self._ref()
        if self.auto.isChecked():
            _run(f"freecad_workbench.gui.curvature_map.set_range({ref})")
        else:
            lower, upper = self.lower.value(), self.upper.value()
            if upper <= lower:
                return
            _run(f"freecad_workbench.gui.curvature_map.set_range({ref}, {lower!r}, {upper!r})")
        self._show_range()
        FreeCADGui.updateGui()

    def set_range(self, lower=None, upper=None):
        """As the user would: a manual range, or the automatic one for None."""
        if lower is None:
            self.auto.setChecked(True)
            return
        self.auto.setChecked(False)
        self.upper.setValue(upper)
        self.lower.setValue(lower)

    def show_value(self, text):
        if text:
            self.value.setText(text)

    def turn_off(self):
        _run(f"freecad_workbench.gui.curvature_map.hide({self._ref()})")
        self.close()

    def getStandardButtons(self):
        from ..qt import QtWidgets

        return standard_buttons(QtWidgets.QDialogButtonBox.Close)

    def reject(self):
        self.close()
        return True

    def accept(self):
        self.close()
        return True

    def close(self):
        global _panel
        _panel = None
        if self.show_value in curvature_map._listeners:
            curvature_map._listeners.remove(self.show_value)
        FreeCADGui.Control.closeDialog()
