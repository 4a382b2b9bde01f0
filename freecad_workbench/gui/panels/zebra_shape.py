"""Task panel of zebra and isophotes on any shape: stripes (how many, which way) or
isophote angles and the light's direction, applied at once. Close keeps the shading; Turn
off removes it and restores the object's look."""
import FreeCAD
import FreeCADGui

from .. import icon_path, zebra_shape
from .form import button_column, compact, form_rows, new_form, standard_buttons

translate = FreeCAD.Qt.translate

_panel = None


def active_zebra_panel():
    return _panel if FreeCADGui.Control.activeDialog() else None


def parse_angles(text):
    """'30, 60 90' -> (30.0, 60.0, 90.0); angles outside 0-180 dropped."""
    angles = []
    for part in text.replace(";", " ").replace(",", " ").split():
        try:
            value = float(part)
        except ValueError:
            continue
        if 0.0 <= value <= 180.0:
            angles.append(value)
    return tuple(angles)


class ZebraTaskPanel:
    def __init__(self, obj):
        from ..qt import QtWidgets

        global _panel
        _panel = self
        self.obj = obj
        node = zebra_shape.node_of(obj)
        self.form, layout = new_form(translate("FairSplines", "Zebra"), icon_path("FairSplines_Zebra"))
        rows = form_rows()
        self.mode = compact(QtWidgets.QComboBox())
        self.mode.addItem(translate("FairSplines", "Zebra stripes"), "zebra")
        self.mode.addItem(translate("FairSplines", "Isophotes"), "isophotes")
        self.mode.setToolTip(translate(
            "FairSplines", "Zebra: the faces reflect black and white stripes; kinks in the stripes show G1 joins, "
            "breaks show G0. Isophotes: lines where the surface meets the light at the same angle."))
        self.stripes = compact(QtWidgets.QSpinBox())
        self.stripes.setRange(1, 256)
        self.stripes.setToolTip(translate("FairSplines", "Black and white stripe pairs around the reflected sky"))
        self.direction = compact(QtWidgets.QComboBox())
        self.direction.addItem(translate("FairSplines", "Vertical"), True)
        self.direction.addItem(translate("FairSplines", "Horizontal"), False)
        self.angles = QtWidgets.QLineEdit()
        self.angles.setToolTip(translate(
            "FairSplines", "Angles between the surface normal and the light, in degrees, separated by commas"))
        self.angles.setMinimumWidth(60)
        self.light = QtWidgets.QPushButton(translate("FairSplines", "Light from the view"))
        self.light.setToolTip(translate("FairSplines", "The light shines along the current view direction"))
        rows.addRow(translate("FairSplines", "Show"), self.mode)
        rows.addRow(translate("FairSplines", "Stripes"), self.stripes)
        rows.addRow(translate("FairSplines", "Direction"), self.direction)
        rows.addRow(translate("FairSplines", "Angles (\u00b0)"), self.angles)
        layout.addLayout(rows)
        self.off = QtWidgets.QPushButton(translate("FairSplines", "Turn off"))
        self.off.setToolTip(translate("FairSplines", "Remove the shading and show the object as before"))
        layout.addLayout(button_column(self.light, self.off))
        layout.addStretch(1)
        if node is not None:
            self.mode.setCurrentIndex(1 if node.isophotes else 0)
            self.stripes.setValue(node.stripes)
            self.direction.setCurrentIndex(0 if node.vertical else 1)
            self.angles.setText(", ".join(f"{a:g}" for a in (node.isophotes or (30.0, 60.0, 90.0))))
        self._enable()
        self.mode.currentIndexChanged.connect(self.apply)
        self.stripes.valueChanged.connect(self.apply)
        self.direction.currentIndexChanged.connect(self.apply)
        self.angles.editingFinished.connect(self.apply)
        self.light.clicked.connect(self.light_from_view)
        self.off.clicked.connect(self.turn_off)

    def _enable(self):
        zebra = self.mode.currentData() == "zebra"
        self.stripes.setEnabled(zebra)
        self.direction.setEnabled(zebra)
        self.angles.setEnabled(not zebra)
        self.light.setEnabled(not zebra)

    def _ref(self):
        return f"FreeCAD.getDocument({self.obj.Document.Name!r}).getObject({self.obj.Name!r})"

    def _run(self, arguments):
        FreeCADGui.doCommand("import FreeCAD")
        FreeCADGui.doCommand("import freecad_workbench.gui.zebra_shape")
        FreeCADGui.doCommand(f"freecad_workbench.gui.zebra_shape.show({self._ref()}, {arguments})")
        FreeCADGui.updateGui()

    def apply(self, *_):
        self._enable()
        if self.mode.currentData() == "zebra":
            self._run(f"stripes={self.stripes.value()}, vertical={bool(self.direction.currentData())}, isophotes=()")
        else:
            self._run(f"isophotes={parse_angles(self.angles.text()) or (45.0,)!r}")

    def light_from_view(self):
        view = FreeCADGui.ActiveDocument.ActiveView if FreeCADGui.ActiveDocument else None
        if view is None or not hasattr(view, "getViewDirection"):
            return
        d = view.getViewDirection()
        self._run(f"light={(-d.x, -d.y, -d.z)!r}")

    def turn_off(self):
        FreeCADGui.doCommand("import freecad_workbench.gui.zebra_shape")
        FreeCADGui.doCommand(f"freecad_workbench.gui.zebra_shape.hide({self._ref()})")
        self.close()

    def getStandardButtons(self):
        from ..qt import QtWidgets

        return standard_buttons(QtWidgets.QDialogButtonBox.Close)

    def accept(self):
        self.close()
        return True

    def reject(self):
        self.close()
        return True

    def close(self):
        global _panel
        _panel = None
        FreeCADGui.Control.closeDialog()
