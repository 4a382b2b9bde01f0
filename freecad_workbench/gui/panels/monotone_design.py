"""The Monotone design task panel (monotone-curvature paper, Algorithm 1): edit the control
vectors of a cubic B-spline while every difference is kept where the curvature stays
monotone. OK keeps the edit, Cancel restores the design as it was."""
import FreeCAD
import FreeCADGui

from ... import monotone
from ...errors import InputError
from .. import icon_path
from .form import button_column, fit_table, wrapped_label

translate = FreeCAD.Qt.translate

_panel = None


def active_design_panel():
    """The open Monotone design task panel, if any."""
    return _panel if FreeCADGui.Control.activeDialog() else None


class MonotoneDesignTaskPanel:
    """Edits a Monotone design's control vectors: V_0 and the differences dV_i. Whatever is
    typed, each dV_i is moved at once to the nearest vector that keeps C^2_i in its fair
    location (the table shows what is used, the last column how far it moved); the curve
    follows. OK keeps the edit, Cancel restores the design as it was."""

    COLUMNS = 3
    DIGITS = 6

    def __init__(self, obj):
        from ..qt import QtGui, QtWidgets

        global _panel
        _panel = self
        self.obj = obj
        self.doc = obj.Document
        self.editing = False  # the undo step opens with the first change (not inside the command)
        self.form = QtWidgets.QWidget()
        self.form.setWindowTitle(translate("FairSplines", "Monotone design"))
        self.form.setWindowIcon(QtGui.QIcon(icon_path("FairSplines_MonotoneDesign")))
        layout = QtWidgets.QVBoxLayout(self.form)
        intro = wrapped_label(translate(
            "FairSplines",
            "The curve's control points, as where it starts and the step to each next one. A step "
            "that would make the curvature change direction is moved at once to the nearest one "
            "that keeps it rising (or falling); the last column says how far.",
        ))
        intro.setToolTip(translate(
            "FairSplines",
            "Algorithm 1 of the monotone-curvature paper: V0 is the first control vector, dV_i = V_(i+1) - V_i; "
            "each dV_i is kept where the second-derivative control point C2_i lies in its fair location "
            "(Theorem 2), so the curvature is monotone."))
        layout.addWidget(intro)
        self.table = QtWidgets.QTableWidget(0, self.COLUMNS)
        self.table.setHorizontalHeaderLabels(
            [translate("FairSplines", "X (mm)"), translate("FairSplines", "Y (mm)"), translate("FairSplines", "Moved")])
        fit_table(self.table)
        layout.addWidget(self.table)
        self.add_button = QtWidgets.QPushButton(translate("FairSplines", "Add vector"))
        self.remove_button = QtWidgets.QPushButton(translate("FairSplines", "Remove last"))
        layout.addLayout(button_column(self.add_button, self.remove_button))
        self.status = wrapped_label()
        layout.addWidget(self.status)
        first = obj.FirstVector
        diffs = [(v.x, v.y) for v in (obj.UsedDifferences or obj.Differences)]
        self._fill((first.x, first.y), diffs, [0.0] * len(diffs))
        self.table.itemChanged.connect(self.apply)
        self.add_button.clicked.connect(self.add_vector)
        self.remove_button.clicked.connect(self.remove_vector)
        self.status.setText(self._clamp(*self.vectors())[2])

    # -- table <-> vectors
    def _fill(self, first, diffs, moved):
        from ..qt import QtCore, QtWidgets

        self.table.blockSignals(True)
        self.table.setRowCount(1 + len(diffs))
        self.table.setVerticalHeaderLabels(
            [translate("FairSplines", "Start")]
            + [translate("FairSplines", "Step {}").format(i + 1) for i in range(len(diffs))])
        rows = [first] + list(diffs)
        for r, (x, y) in enumerate(rows):
            for c, value in enumerate((x, y)):
                # Shown with DIGITS digits; the item keeps the exact value while its text is unchanged.
                item = QtWidgets.QTableWidgetItem(f"{value:.{self.DIGITS}g}")
                item.setData(QtCore.Qt.UserRole, float(value))
                self.table.setItem(r, c, item)
            note = "" if r == 0 or moved[r - 1] == 0.0 else f"{moved[r - 1]:.3g}"
            item = QtWidgets.QTableWidgetItem(note)
            item.setFlags(item.flags() & ~QtCore.Qt.ItemIsEditable)
            self.table.setItem(r, 2, item)
        self.table.blockSignals(False)

    def vectors(self):
        """(V0, [dV_i]) as shown: exact where a cell was not retyped; a cell that is not a
        number counts as 0."""
        from ..qt import QtCore

        rows = []
        for r in range(self.table.rowCount()):
            row = []
            for c in range(2):
                item = self.table.item(r, c)
                exact = item.data(QtCore.Qt.UserRole) if item is not None else None
                if exact is not None and item.text() == f"{exact:.{self.DIGITS}g}":
                    row.append(exact)
                    continue
                try:
                    row.append(float(item.text()) if item is not None else 0.0)
                except ValueError:
                    row.append(0.0)
            rows.append(tuple(row))
        return rows[0], rows[1:]

    def set_vectors(self, first, diffs):
        """Put vectors in the table and apply them (as typing them would)."""
        self._fill(first, diffs, [0.0] * len(diffs))
        self.apply()

    # -- editing
    def _knots(self, diffs):
        """The design's knots if they still fit the number of vectors, else None (default)."""
        knots = list(self.obj.Knots)
        return knots if len(knots) == len(diffs) + 6 else None

    def _clamp(self, first, diffs):
        """(used differences, how far each moved, status text); used is None on bad input."""
        try:
            used, moved = monotone.clamp_to_fair_locations(first, diffs, self._knots(diffs))
        except InputError as exc:
            return None, None, str(exc)
        rows = [str(i + 1) for i, m in enumerate(moved) if m > 0.0]
        text = (
            translate("FairSplines", "Steps moved to keep the curvature monotone: {}").format(", ".join(rows))
            if rows
            else translate("FairSplines", "No step needed moving: the curvature is monotone.")
        )
        return used, moved, text

    def apply(self, *_):
        """Clamp what is in the table into the fair locations, show it, update the design."""
        first, diffs = self.vectors()
        used, moved, text = self._clamp(first, diffs)
        self.status.setText(text)
        if used is None:
            return
        self._fill(first, [tuple(u) for u in used], list(moved))
        if not self.editing:
            self.doc.openTransaction("Edit monotone design")
            self.editing = True
        if self._knots(diffs) is None and self.obj.Knots:
            self.obj.Knots = []  # the rows changed: back to clamped, uniform knots
        self.obj.FirstVector = FreeCAD.Vector(first[0], first[1], 0)
        self.obj.Differences = [FreeCAD.Vector(x, y, 0) for x, y in used]
        self.doc.recompute()

    def add_vector(self):
        first, diffs = self.vectors()
        self.set_vectors(first, diffs + [(0.0, 0.0)])

    def remove_vector(self):
        first, diffs = self.vectors()
        if len(diffs) > 2:
            self.set_vectors(first, diffs[:-1])

    def accept(self):
        if self.editing:
            self.doc.commitTransaction()
        self._close()
        return True

    def reject(self):
        if self.editing:
            self.doc.abortTransaction()
            self.doc.recompute()
        self._close()
        return True

    def _close(self):
        global _panel
        _panel = None
        gui_doc = FreeCADGui.getDocument(self.doc.Name)
        if gui_doc is not None and gui_doc.getInEdit() is not None:
            gui_doc.resetEdit()
        if FreeCADGui.Control.activeDialog():
            FreeCADGui.Control.closeDialog()
