"""Task panel of the continuity check: the tolerances (applied at once) and a table of the
edges, one row each: its name, its faces, gap (mm), angle (degrees), curvature jump (%) and
verdict in its colour. Clicking a row selects the edge and marks its worst point. Close
removes the drawing."""
import FreeCAD
import FreeCADGui

from .. import continuity, icon_path
from .form import SPIN_MAX_WIDTH, compact, form_rows, new_form, short_spin_box, standard_buttons, wrapped_label

translate = FreeCAD.Qt.translate

COLUMNS = (
    (FreeCAD.Qt.QT_TRANSLATE_NOOP("FairSplines", "Edge"), FreeCAD.Qt.QT_TRANSLATE_NOOP("FairSplines", "Edge")),
    (FreeCAD.Qt.QT_TRANSLATE_NOOP("FairSplines", "Faces"),
     FreeCAD.Qt.QT_TRANSLATE_NOOP("FairSplines", "The faces that meet at the edge")),
    (FreeCAD.Qt.QT_TRANSLATE_NOOP("FairSplines", "Gap"),
     FreeCAD.Qt.QT_TRANSLATE_NOOP("FairSplines", "Largest gap between the faces, mm")),
    (FreeCAD.Qt.QT_TRANSLATE_NOOP("FairSplines", "Angle"),
     FreeCAD.Qt.QT_TRANSLATE_NOOP("FairSplines", "Largest angle between the faces' normals, degrees")),
    (FreeCAD.Qt.QT_TRANSLATE_NOOP("FairSplines", "Jump"),
     FreeCAD.Qt.QT_TRANSLATE_NOOP("FairSplines", "Largest jump of curvature across the edge, % of the "
                                                 "largest curvature along it")),
    (FreeCAD.Qt.QT_TRANSLATE_NOOP("FairSplines", "Verdict"),
     FreeCAD.Qt.QT_TRANSLATE_NOOP("FairSplines", "Gap, G0 (a kink), G1 (tangent), G2 (curvature continuous) "
                                                 "or boundary (one face only)")),
)

_panel = None


def active_continuity_panel():
    return _panel if FreeCADGui.Control.activeDialog() else None


def _short(value, digits=2):
    return "0" if value == 0 else f"{value:.{digits}g}"


class ContinuityTaskPanel:
    def __init__(self, check):
        from ..qt import QtWidgets

        global _panel
        _panel = self
        self.check = check
        self.form, layout = new_form(translate("FairSplines", "Check continuity"),
                                     icon_path("FairSplines_CheckContinuity"))
        rows = form_rows()
        tolerances = check.tolerances
        self.angle = self._spin(0.0, 180.0, " \u00b0", 4, tolerances["angle_tolerance"])
        self.angle.setToolTip(translate("FairSplines", "Normals closer than this: tangent (G1)"))
        self.curvature = self._spin(0.0, 1000.0, " %", 3, 100.0 * tolerances["curvature_tolerance"])
        self.curvature.setToolTip(translate(
            "FairSplines", "Curvature jumps smaller than this, in % of the largest curvature along the edge: G2"))
        self.gap = self._spin(0.0, 1e6, " mm", 6, tolerances["gap_tolerance"] or 0.0)
        self.gap.setToolTip(translate(
            "FairSplines", "Faces farther apart than this: a gap. 0: twice the edge's own tolerance"))
        rows.addRow(translate("FairSplines", "Angle"), self.angle)
        rows.addRow(translate("FairSplines", "Curvature"), self.curvature)
        rows.addRow(translate("FairSplines", "Gap"), self.gap)
        layout.addLayout(rows)
        # Six columns do not fit the side panel's width: each as wide as its texts, and the
        # table scrolls sideways (the panel itself stays within PANEL_WIDTH).
        self.table = QtWidgets.QTableWidget(0, len(COLUMNS))
        self.table.setMinimumWidth(120)
        self.table.horizontalHeader().setSectionResizeMode(QtWidgets.QHeaderView.ResizeToContents)
        self.table.setSelectionBehavior(QtWidgets.QAbstractItemView.SelectRows)
        self.table.setSelectionMode(QtWidgets.QAbstractItemView.SingleSelection)
        self.table.setEditTriggers(QtWidgets.QAbstractItemView.NoEditTriggers)
        self.table.verticalHeader().setVisible(False)
        self.table.setMinimumHeight(220)
        for k, (name, tip) in enumerate(COLUMNS):
            item = QtWidgets.QTableWidgetItem(translate("FairSplines", name))
            item.setToolTip(translate("FairSplines", tip))
            self.table.setHorizontalHeaderItem(k, item)
        layout.addWidget(self.table)
        self.summary = wrapped_label()
        layout.addWidget(self.summary)
        self.fill()
        self.table.itemSelectionChanged.connect(self._row_chosen)
        for spin in (self.angle, self.curvature, self.gap):
            spin.valueChanged.connect(self.recheck)

    def _spin(self, lower, upper, suffix, decimals, value):
        spin = short_spin_box()
        spin.setRange(lower, upper)
        spin.setDecimals(decimals)
        spin.setSuffix(suffix)
        spin.setValue(value)
        spin.setKeyboardTracking(False)
        spin.setMaximumWidth(SPIN_MAX_WIDTH)
        return compact(spin)

    def fill(self):
        from ..qt import QtGui, QtWidgets

        records = self.check.records
        self.table.blockSignals(True)
        self.table.setRowCount(len(records))
        counts = {}
        for row, r in enumerate(records):
            jump = 100.0 * r.curvature_jump if r.continuity in ("G1", "G2") else float("nan")
            faces = ", ".join(f.replace("Face", "") for f in r.faces)
            texts = (self.check.object_edge(row).replace("Edge", ""), faces,
                     _short(r.gap), _short(r.angle, 3), "" if jump != jump else _short(jump),
                     r.continuity)
            colour = QtGui.QColor(*[int(255 * c) for c in continuity.colour_of(r.continuity)])
            for column, text in enumerate(texts):
                item = QtWidgets.QTableWidgetItem(text)
                if column == len(texts) - 1:
                    item.setBackground(colour)
                    item.setForeground(QtGui.QColor("white" if r.continuity in ("gap", "boundary") else "black"))
                self.table.setItem(row, column, item)
            counts[r.continuity] = counts.get(r.continuity, 0) + 1
        self.table.blockSignals(False)
        words = {v: translate("FairSplines", continuity.VERDICTS.get(v, continuity.OTHER)[1]) for v in counts}
        self.summary.setText(", ".join(f"{n} \u00d7 {words[v]}" for v, n in counts.items()))

    def recheck(self, *_):
        links = self.check.links
        gap = self.gap.value() or None
        code = ", ".join(f"(FreeCAD.getDocument({o.Document.Name!r}).getObject({o.Name!r}), {s!r})" for o, s in links)
        FreeCADGui.doCommand("import FreeCAD")
        FreeCADGui.doCommand("import freecad_workbench.gui.continuity")
        FreeCADGui.doCommand(f"freecad_workbench.gui.continuity.show([{code}], gap_tolerance={gap!r}, "
                             f"angle_tolerance={self.angle.value()!r}, "
                             f"curvature_tolerance={self.curvature.value() / 100.0!r})")
        self.check = continuity.current()
        self.fill()
        FreeCADGui.updateGui()

    def choose(self, row):
        """As a click on a row would."""
        self.table.selectRow(row)

    def _row_chosen(self):
        rows = self.table.selectionModel().selectedRows()
        self.check.mark(rows[0].row() if rows else None)
        FreeCADGui.updateGui()

    def getStandardButtons(self):
        from ..qt import QtWidgets

        return standard_buttons(QtWidgets.QDialogButtonBox.Close)

    def accept(self):
        return self.reject()

    def reject(self):
        global _panel
        _panel = None
        FreeCADGui.doCommand("import freecad_workbench.gui.continuity")
        FreeCADGui.doCommand("freecad_workbench.gui.continuity.hide()")
        FreeCADGui.Control.closeDialog()
        return True
