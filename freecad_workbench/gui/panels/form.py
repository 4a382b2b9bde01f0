"""What the task panels share: a form that fits the side panel, compact spin boxes, a
status line, and live editing of an object's properties: every change is applied and
recomputed at once (the preview), inside one undo step; OK keeps it, Cancel restores the
values the panel opened with.

Fit: FreeCAD's side panel is about 230-300 px wide by default; FreeCAD 1.1's (Qt6) left
200 px beside its vertical scroll bar in the GUI test run. Every panel here keeps its
minimum width within PANEL_WIDTH (tests/gui/test_panels.py opens each one and checks):
one value per row in form layouts, spin boxes that may shrink to SPIN_WIDTH, buttons
stacked (button_column), short labels with the long words in tooltips, long texts
word-wrapped.

FreeCAD closes a transaction a command opened when the command returns, so the step is
opened lazily, at the first change. If another step was already open the changes join
it, and Cancel puts the properties back by assignment.
"""
import FreeCAD

translate = FreeCAD.Qt.translate

PANEL_WIDTH = 185  # px: what a panel's form may need at least: 15 px inside the 200 px seen on FreeCAD 1.1
SPIN_WIDTH = 72  # px: a spin box may shrink to this
ERROR_STYLE = "color: #c00000;"
WARNING_STYLE = "color: #a05a00;"


def new_form(title, icon):
    """(form widget, its vertical layout) of a task panel, with title and icon."""
    from ..qt import QtGui, QtWidgets

    form = QtWidgets.QWidget()
    form.setWindowTitle(title)
    form.setWindowIcon(QtGui.QIcon(icon))
    return form, QtWidgets.QVBoxLayout(form)


def form_rows(parent_layout=None, box=None):
    """A QFormLayout whose rows wrap (label above field) when the panel is narrow."""
    from ..qt import QtWidgets

    rows = QtWidgets.QFormLayout(box) if box is not None else QtWidgets.QFormLayout()
    rows.setRowWrapPolicy(QtWidgets.QFormLayout.WrapLongRows)
    rows.setFieldGrowthPolicy(QtWidgets.QFormLayout.AllNonFixedFieldsGrow)
    if parent_layout is not None:
        parent_layout.addLayout(rows)
    return rows


SPIN_MAX_WIDTH = 160  # px: a dimension's spin box at most (its layout then asks no more)


def compact(widget, width=SPIN_WIDTH):
    """Let a spin box or combo box shrink to `width` (Qt sizes them for their widest value)."""
    widget.setMinimumWidth(width)
    return widget


_SHORT_SPIN_BOX = []


def short_spin_box():
    """A QDoubleSpinBox that shows its value without trailing zeros ("10 mm", "12.5 mm", not
    "10.0000 mm"), at the precision of its decimals: in the side panel's 60-odd pixels of text,
    a dimension with four decimals lost its unit ("10.0000 r", issue 26)."""
    if not _SHORT_SPIN_BOX:
        from ..qt import QtWidgets

        class ShortSpinBox(QtWidgets.QDoubleSpinBox):
            def textFromValue(self, value):
                text = self.locale().toString(float(value), "f", self.decimals())
                if not self.isGroupSeparatorShown():
                    text = text.replace(self.locale().groupSeparator(), "")
                point = self.locale().decimalPoint()
                if point in text:
                    text = text.rstrip("0").rstrip(point)
                return "0" if text in ("-0", "") else text

        _SHORT_SPIN_BOX.append(ShortSpinBox)
    return _SHORT_SPIN_BOX[0]()


def standard_buttons(buttons):
    """A task panel's getStandardButtons value: PySide2's flags convert with int(); PySide6's
    are Python enum flags, with .value."""
    return buttons.value if hasattr(buttons, "value") else int(buttons)


def button_column(*widgets):
    """Buttons (or check boxes) one under the other: two side by side need 166 px or more
    with Qt6's Fusion style (80 px a button at least), too much beside a form's margins."""
    from ..qt import QtWidgets

    column = QtWidgets.QVBoxLayout()
    for widget in widgets:
        column.addWidget(widget)
    return column


def vector_rows(rows, spins, axes="XYZ"):
    """One row per coordinate (X, Y, Z) in a form layout: three spin boxes side by side do
    not fit the side panel. Returns the spin boxes."""
    spins = list(spins)
    for axis, spin in zip(axes, spins):
        rows.addRow(axis, spin)
    return spins


def fit_table(table, width=120):
    """A table whose columns share the panel's width instead of scrolling sideways; it may
    shrink to `width` px."""
    from ..qt import QtCore, QtWidgets

    header = table.horizontalHeader()
    header.setSectionResizeMode(QtWidgets.QHeaderView.Stretch)
    header.setMinimumSectionSize(24)
    table.setHorizontalScrollBarPolicy(QtCore.Qt.ScrollBarAlwaysOff)
    table.setMinimumWidth(width)
    return table


def wrapped_label(text=""):
    from ..qt import QtWidgets

    label = QtWidgets.QLabel(text)
    label.setWordWrap(True)
    return label


def show_status(label, status):
    """A feature's Status in a panel's status line: nothing for ok, amber for a warning,
    red for an error."""
    status = status or "ok"
    if status == "ok":
        label.setText("")
        label.setStyleSheet("")
        label.setVisible(False)
        return
    label.setVisible(True)
    if status.startswith("warning:"):
        label.setText(translate("FairSplines", "Warning: {}").format(status[len("warning:"):].strip()))
        label.setStyleSheet(WARNING_STYLE)
    else:
        label.setText(translate("FairSplines", "Failed: {}").format(status))
        label.setStyleSheet(ERROR_STYLE)


def _snapshot(value):
    if isinstance(value, (list, tuple)):
        return [_snapshot(v) for v in value]
    if isinstance(value, FreeCAD.Vector):
        return FreeCAD.Vector(value)
    if isinstance(value, FreeCAD.Placement):
        return FreeCAD.Placement(value)
    if hasattr(value, "Value") and hasattr(value, "Unit"):  # Quantity
        return float(value.Value)
    return value


def _same(a, b):
    if isinstance(a, list) and isinstance(b, list):
        return len(a) == len(b) and all(_same(x, y) for x, y in zip(a, b))
    if isinstance(a, FreeCAD.Vector) and isinstance(b, FreeCAD.Vector):
        return tuple(a) == tuple(b)
    if isinstance(a, FreeCAD.Placement) and isinstance(b, FreeCAD.Placement):
        return tuple(a.Base) == tuple(b.Base) and tuple(a.Rotation.Q) == tuple(b.Rotation.Q)
    return a == b


class LiveEdit:
    """Transaction and snapshot of some properties of obj, for a task panel."""

    def __init__(self, obj, name, properties):
        self.obj = obj
        self.doc = obj.Document
        self.name = name
        self.properties = tuple(properties)
        self.initial = {p: _snapshot(getattr(obj, p)) for p in self.properties}
        self.opened = False

    def begin(self):
        """Call before changing a property: opens the undo step on the first change."""
        if self.doc.UndoMode and not self.doc.HasPendingTransaction:
            self.doc.openTransaction(self.name)
            self.opened = True

    def changed(self):
        """Whether any of the properties differs from its value at the start."""
        return any(not _same(_snapshot(getattr(self.obj, p)), v) for p, v in self.initial.items())

    def commit(self):
        if self.opened and self.doc.HasPendingTransaction:
            self.doc.commitTransaction()
        self.opened = False

    def abort(self):
        """Undo the changes: abort the step, then re-assign whatever still differs."""
        if self.opened and self.doc.HasPendingTransaction:
            self.doc.abortTransaction()
        self.opened = False
        restored = False
        for prop, value in self.initial.items():
            if not _same(_snapshot(getattr(self.obj, prop)), value):
                setattr(self.obj, prop, value)
                restored = True
        if restored or any("Touched" in o.State for o in self.doc.Objects):
            self.doc.recompute()


class LiveEditPanel:
    """OK / Cancel of a task panel that edits through a LiveEdit `self.session` in the
    document `self.doc`: OK commits the edit as one undo step, Cancel restores. The panel
    defines finish() (remove what it drew); closing goes through the view provider's
    unsetEdit when the object is in edit mode, which calls finish()."""

    def _spin(self, lower, upper, suffix="", decimals=4):
        """A spin box for a dimension: range, decimals, unit suffix; it reports a value
        only when editing ends (no recompute per keystroke); it shows no trailing zeros."""
        spin = short_spin_box()
        spin.setRange(lower, upper)
        spin.setDecimals(decimals)
        spin.setSuffix(suffix)
        spin.setKeyboardTracking(False)
        # Qt sizes a spin box for the text of its range's ends (186 px for "-1000000.0000 mm");
        # FreeCAD 1.1's task box then asks that of the side panel, wider than its 200 px.
        spin.setMaximumWidth(SPIN_MAX_WIDTH)
        return compact(spin)

    def _apply(self, changes):
        """Set [(property, value)] on self.obj inside the panel's undo step, recompute, refresh."""
        self.session.begin()
        for name, value in changes:
            setattr(self.obj, name, value)
        self.doc.recompute()
        self.refresh()

    def getStandardButtons(self):
        from ..qt import QtWidgets

        return standard_buttons(QtWidgets.QDialogButtonBox.Ok | QtWidgets.QDialogButtonBox.Cancel)

    def accept(self):
        self.session.commit()
        self._close()
        return True

    def reject(self):
        self.session.abort()
        self._close()
        return True

    def finish(self):
        pass

    def _close(self):
        import FreeCADGui

        gui_doc = FreeCADGui.getDocument(self.doc.Name)
        if gui_doc is not None and gui_doc.getInEdit() is not None:
            gui_doc.resetEdit()  # unsetEdit calls finish() and closes the dialog
        else:
            self.finish()
            FreeCADGui.Control.closeDialog()
