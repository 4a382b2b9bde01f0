"""Task panel of a BasicCurve: its kind, its dimensions (lengths in model units, angles in
degrees), and where it lies (plane and position of its placement). Every change
recomputes at once; OK keeps the changes as one undo step, Cancel restores the curve the
panel opened with."""
import FreeCAD

from ...features.basic_curve import KIND_DEFAULTS, KIND_PROPERTIES, KINDS
from .. import icon_path
from .form import LiveEdit, LiveEditPanel, compact, fit_table, form_rows, show_status, vector_rows, wrapped_label

translate = FreeCAD.Qt.translate
QT_TRANSLATE_NOOP = FreeCAD.Qt.QT_TRANSLATE_NOOP

# Rotations that put the curve's XY plane onto a global plane (X and Y of the curve to
# the first and second axis named).
PLANES = {
    "XY": FreeCAD.Rotation(),
    "XZ": FreeCAD.Rotation(FreeCAD.Vector(1, 0, 0), 90),
    "YZ": FreeCAD.Rotation(FreeCAD.Vector(1, 1, 1), 120),
}

_LABELS = {
    "Start": QT_TRANSLATE_NOOP("FairSplines", "Start point"),
    "End": QT_TRANSLATE_NOOP("FairSplines", "End point"),
    "Radius": QT_TRANSLATE_NOOP("FairSplines", "Radius"),
    "MajorRadius": QT_TRANSLATE_NOOP("FairSplines", "Major radius"),
    "MinorRadius": QT_TRANSLATE_NOOP("FairSplines", "Minor radius"),
    "StartAngle": QT_TRANSLATE_NOOP("FairSplines", "Start angle"),
    "EndAngle": QT_TRANSLATE_NOOP("FairSplines", "End angle"),
    "Focal": QT_TRANSLATE_NOOP("FairSplines", "Focal distance"),
    "StartY": QT_TRANSLATE_NOOP("FairSplines", "Start y"),
    "EndY": QT_TRANSLATE_NOOP("FairSplines", "End y"),
    "StartParameter": QT_TRANSLATE_NOOP("FairSplines", "Start parameter t"),
    "EndParameter": QT_TRANSLATE_NOOP("FairSplines", "End parameter t"),
    "Pitch": QT_TRANSLATE_NOOP("FairSplines", "Pitch (per turn)"),
    "Turns": QT_TRANSLATE_NOOP("FairSplines", "Turns"),
    "Poles": QT_TRANSLATE_NOOP("FairSplines", "Poles and weights"),
}


def plane_of(rotation):
    """The name of the plane a placement rotation puts the curve in, or None."""
    for name, candidate in PLANES.items():
        if all(abs(a - b) < 1e-12 for a, b in zip(rotation.Q, candidate.Q)) or all(
            abs(a + b) < 1e-12 for a, b in zip(rotation.Q, candidate.Q)
        ):
            return name
    return None


class BasicCurvePanel(LiveEditPanel):
    """Task panel editing a BasicCurve object live."""

    def __init__(self, obj):
        from ..qt import QtGui, QtWidgets

        self.obj = obj
        self.doc = obj.Document
        dimensions = sorted({p for props in KIND_PROPERTIES.values() for p in props})
        self.session = LiveEdit(obj, translate("FairSplines", "Edit basic curve"),
                                ["Kind", "Placement"] + dimensions)
        self._updating = False
        self.widgets = {}

        self.form = QtWidgets.QWidget()
        self.form.setWindowTitle(translate("FairSplines", "Basic curve"))
        self.form.setWindowIcon(QtGui.QIcon(icon_path("FairSplines_BasicCurves")))
        layout = QtWidgets.QVBoxLayout(self.form)
        top = form_rows()
        self.kind = compact(QtWidgets.QComboBox(), 120)
        self.kind.addItems([translate("FairSplines", k) for k in KINDS])
        self.kind.setCurrentIndex(KINDS.index(obj.Kind))
        self.kind.currentIndexChanged.connect(lambda i: self.set_kind(KINDS[i]))
        top.addRow(translate("FairSplines", "Kind"), self.kind)
        self.plane = compact(QtWidgets.QComboBox(), 120)
        self.plane.addItems(list(PLANES) + [translate("FairSplines", "other")])
        self.plane.currentIndexChanged.connect(self._plane_changed)
        top.addRow(translate("FairSplines", "Plane"), self.plane)
        layout.addLayout(top)
        position_box = QtWidgets.QGroupBox(translate("FairSplines", "Position"))
        position_box.setToolTip(translate("FairSplines", "Where the curve's own origin lies (its Placement)"))
        self.position = vector_rows(form_rows(box=position_box), [self._spin(-1e9, 1e9, " mm") for _ in range(3)])
        for spin in self.position:
            spin.valueChanged.connect(self._position_changed)
        layout.addWidget(position_box)
        self.dimensions_box = QtWidgets.QGroupBox(translate("FairSplines", "Dimensions"))
        self.dimensions = form_rows(box=self.dimensions_box)
        layout.addWidget(self.dimensions_box)
        self.status_label = wrapped_label()
        layout.addWidget(self.status_label)
        layout.addStretch(1)
        self._build_dimensions()
        self._show_placement()
        self.refresh()

    # --- widgets ---------------------------------------------------------------------

    def _build_dimensions(self):
        """Rows for the dimensions of the current kind."""
        from ..qt import QtWidgets

        while self.dimensions.rowCount():
            self.dimensions.removeRow(0)
        self.widgets = {}
        self._updating = True
        try:
            for name in KIND_PROPERTIES[self.obj.Kind]:
                if name == "Weights":
                    continue
                label = translate("FairSplines", _LABELS.get(name, name))
                if name in ("Start", "End"):
                    self.dimensions.addRow(QtWidgets.QLabel(label))
                    spins = vector_rows(self.dimensions, (self._spin(-1e9, 1e9, " mm") for _ in range(3)))
                    for spin, value in zip(spins, getattr(self.obj, name)):
                        spin.setValue(value)
                        spin.valueChanged.connect(lambda _v, n=name: self._vector_changed(n))
                    self.widgets[name] = spins
                elif name == "Poles":
                    table = QtWidgets.QTableWidget(0, 4)
                    table.setHorizontalHeaderLabels(["X", "Y", "Z", translate("FairSplines", "Weight")])
                    weights = list(self.obj.Weights) + [1.0] * len(self.obj.Poles)
                    for i, pole in enumerate(self.obj.Poles):
                        table.insertRow(i)
                        for j, value in enumerate((pole.x, pole.y, pole.z, weights[i])):
                            table.setItem(i, j, QtWidgets.QTableWidgetItem(repr(float(value))))
                    table.itemChanged.connect(lambda _item: self._table_changed())
                    fit_table(table)
                    self.dimensions.addRow(QtWidgets.QLabel(label))
                    self.dimensions.addRow(table)
                    self.widgets[name] = table
                else:
                    value = getattr(self.obj, name)
                    unit = str(getattr(value, "Unit", ""))
                    if "Angle" in name:
                        spin = self._spin(-360.0, 360.0, " °")
                    elif name in ("StartParameter", "EndParameter"):
                        spin = self._spin(-50.0, 50.0)
                    elif name == "Turns":
                        spin = self._spin(0.0, 1000.0)
                    elif name in ("StartY", "EndY"):
                        spin = self._spin(-1e9, 1e9, " mm")
                    else:
                        spin = self._spin(0.0, 1e9, " mm")
                    spin.setValue(float(getattr(value, "Value", value)))
                    spin.valueChanged.connect(lambda v, n=name: self.set_dimension(n, v))
                    spin.setToolTip(unit)
                    self.dimensions.addRow(label, spin)
                    self.widgets[name] = spin
        finally:
            self._updating = False

    def _show_placement(self):
        self._updating = True
        try:
            plane = plane_of(self.obj.Placement.Rotation)
            self.plane.setCurrentIndex(list(PLANES).index(plane) if plane else len(PLANES))
            for spin, value in zip(self.position, self.obj.Placement.Base):
                spin.setValue(value)
        finally:
            self._updating = False

    # --- edits -----------------------------------------------------------------------

    def set_dimension(self, name, value):
        """Set one dimension (float, Vector or list) and recompute."""
        if not self._updating:
            self._apply([(name, value)])

    def set_kind(self, kind):
        """Switch to another kind, with that kind's default dimensions."""
        if self._updating or kind == self.obj.Kind:
            return
        self._apply([("Kind", kind)] + list(KIND_DEFAULTS[kind].items()))
        self._build_dimensions()
        if self.kind.currentIndex() != KINDS.index(kind):
            self._updating = True
            self.kind.setCurrentIndex(KINDS.index(kind))
            self._updating = False

    def set_plane(self, name):
        if self._updating or name not in PLANES:
            return
        placement = FreeCAD.Placement(self.obj.Placement.Base, PLANES[name])
        self._apply([("Placement", placement)])

    def set_position(self, point):
        if self._updating:
            return
        placement = FreeCAD.Placement(FreeCAD.Vector(point), self.obj.Placement.Rotation)
        self._apply([("Placement", placement)])

    def _plane_changed(self, index):
        if index < len(PLANES):
            self.set_plane(list(PLANES)[index])

    def _position_changed(self, _value):
        self.set_position(FreeCAD.Vector(*(s.value() for s in self.position)))

    def _vector_changed(self, name):
        self.set_dimension(name, FreeCAD.Vector(*(s.value() for s in self.widgets[name])))

    def _table_changed(self):
        if self._updating:
            return
        table = self.widgets["Poles"]
        poles, weights = [], []
        try:
            for i in range(table.rowCount()):
                values = [float(table.item(i, j).text()) for j in range(4)]
                poles.append(FreeCAD.Vector(*values[:3]))
                weights.append(values[3])
        except (AttributeError, ValueError):
            return  # a cell being typed in
        self._apply([("Poles", poles), ("Weights", weights)])

    def refresh(self):
        show_status(self.status_label, self.obj.Status)

    # --- task dialog -----------------------------------------------------------------
