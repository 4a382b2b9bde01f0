"""The Mark points task panel of a Design spline (csr paper, Section 3.2: "use a slider
interface to move the points on the curve, rather than asking the designer to free-hand
place the points").

One slider per mark on each piece, with a spin box for the exact value. A slider spans
the whole piece, so its handle shows where the mark is; marks stay strictly increasing
inside (0, 1): a mark moved onto or past a neighbour stops one step (1e-4) short of it.
Every move recomputes the design at once (live preview) and redraws, in the 3D view, the
marked points on the basic curves (black, the one being moved red) and the control
polygon of the result (green, Fig. 10a). "Add mark" puts a new mark in the middle
of the piece's widest gap; "Remove" drops a mark; "Reversed" runs the piece the other
way (its marks stay on the same points). OK keeps the changes as one undo step, Cancel
restores the marks the panel opened with.

A sampled piece (a Points object or a sketch of points: the unifying spline of the csr
paper's Fig. 1) has no marks: its group shows no sliders and no "Add mark", only what it
is and "Reversed"; its samples are drawn as the piece's points.
"""
import FreeCAD

from ...basic import Samples
from ...features.design_spline import get_marks, piece_curves, set_marks
from .. import icon_path
from .form import LiveEdit, LiveEditPanel, button_column, show_status, wrapped_label
from ..overlay import Overlay, active_view

translate = FreeCAD.Qt.translate

QT_TRANSLATE_NOOP = FreeCAD.Qt.QT_TRANSLATE_NOOP
# How consecutive pieces were joined (the design's Joins), in words.
JOIN_WORDS = {
    "agree": QT_TRANSLATE_NOOP("FairSplines", "meet end to start"),
    "averaged": QT_TRANSLATE_NOOP("FairSplines", "ends a little apart, averaged into one point"),
    "edge": QT_TRANSLATE_NOOP("FairSplines", "ends apart, joined by a straight edge"),
}

SCALE = 10000  # slider steps over [0, 1]
GAP = 1.0 / SCALE  # marks stay at least this far apart, and from 0 and 1
DECIMALS = 4


class MarkRow:
    """The widgets of one mark: slider, spin box, remove button."""

    def __init__(self, slider, spin, remove):
        self.slider, self.spin, self.remove = slider, spin, remove


class MarkPointsPanel(LiveEditPanel):
    """Task panel: sliders for the marks of a Design spline, with live preview."""

    def __init__(self, obj):
        from ..qt import QtGui, QtWidgets

        self.obj = obj
        self.doc = obj.Document
        self.session = LiveEdit(obj, translate("FairSplines", "Mark points"), ("Marks", "MarkCounts", "Reversed"))
        self.curves = piece_curves(obj)
        count = len(self.curves)
        try:
            marks = get_marks(obj)
        except Exception:
            marks = []
        self.marks = [list(m) for m in marks[:count]] + [[] for _ in range(count - len(marks))]
        self.reversed = [bool(r) for r in list(obj.Reversed)[:count]] + [False] * max(0, count - len(obj.Reversed))
        self.active = None  # (piece, index) of the mark last moved
        self._updating = False
        self.rows = [[] for _ in range(count)]

        self.form = QtWidgets.QWidget()
        self.form.setWindowTitle(translate("FairSplines", "Mark points"))
        self.form.setWindowIcon(QtGui.QIcon(icon_path("FairSplines_MarkPoints")))
        layout = QtWidgets.QVBoxLayout(self.form)
        # The task box pads the panel already: the form's own side margins (9 px each under
        # some styles) pushed it past PANEL_WIDTH when it was the first panel opened.
        layout.setContentsMargins(0, layout.contentsMargins().top(), 0, layout.contentsMargins().bottom())
        hint = QtWidgets.QLabel(translate(
            "FairSplines",
            "Slide the marks along each basic curve. A conic stays exact from its second to its "
            "second-last mark; the joins are rounded off in between.",
        ))
        hint.setWordWrap(True)
        layout.addWidget(hint)
        # The side panel scrolls by itself: the pieces go straight into the form (no inner scroll area).
        self.pieces_layout = QtWidgets.QVBoxLayout()
        self.pieces_layout.setContentsMargins(0, 0, 0, 0)
        self.groups, self.grids, self.reverse_boxes, self.add_buttons, self.info_labels = [], [], [], [], []
        for piece, (label, curve, error) in enumerate(self.curves):
            group = QtWidgets.QGroupBox(translate("FairSplines", "Piece {}: {}").format(piece + 1, label))
            group_layout = QtWidgets.QVBoxLayout(group)
            grid_widget = QtWidgets.QWidget()
            grid = QtWidgets.QGridLayout(grid_widget)
            grid.setContentsMargins(0, 0, 0, 0)
            grid.setColumnStretch(1, 1)
            group_layout.addWidget(grid_widget)
            info = QtWidgets.QLabel()
            info.setWordWrap(True)
            group_layout.addWidget(info)
            add = QtWidgets.QPushButton(translate("FairSplines", "Add mark"))
            add.setToolTip(translate("FairSplines", "Add a mark in the middle of the widest gap"))
            add.clicked.connect(lambda checked=False, p=piece: self.add_mark(p))
            reverse = QtWidgets.QCheckBox(translate("FairSplines", "Reversed"))
            reverse.setToolTip(translate("FairSplines", "Run this piece from its end to its start"))
            reverse.setChecked(self.reversed[piece])
            reverse.toggled.connect(lambda flag, p=piece: self.set_reversed(p, flag))
            group_layout.addLayout(button_column(add, reverse))
            if isinstance(curve, Samples):  # no marks: its samples are its knots
                grid_widget.setVisible(False)
                add.setVisible(False)
            self.pieces_layout.addWidget(group)
            self.groups.append(group)
            self.grids.append(grid)
            self.reverse_boxes.append(reverse)
            self.add_buttons.append(add)
            self.info_labels.append(info)
            self._build_rows(piece)
        layout.addLayout(self.pieces_layout)
        self.joins_label = QtWidgets.QLabel()
        self.joins_label.setWordWrap(True)
        layout.addWidget(self.joins_label)
        self.status_label = wrapped_label()
        layout.addWidget(self.status_label)
        layout.addStretch(1)

        self.overlay = Overlay("FairSplinesMarkPoints")
        self.overlay.attach(active_view(self.doc))
        self.refresh()

    # --- widgets ---------------------------------------------------------------------

    def _build_rows(self, piece):
        """(Re)create the slider rows of a piece from self.marks."""
        from ..qt import QtCore, QtWidgets

        grid = self.grids[piece]
        while grid.count():
            widget = grid.takeAt(0).widget()
            if widget is not None:
                widget.setParent(None)
                widget.deleteLater()
        self.rows[piece] = []
        for index in range(len(self.marks[piece])):
            slider = QtWidgets.QSlider(QtCore.Qt.Horizontal)
            slider.setTracking(True)
            slider.setMinimumWidth(36)
            spin = QtWidgets.QDoubleSpinBox()
            spin.setDecimals(DECIMALS)
            spin.setSingleStep(0.01)
            spin.setKeyboardTracking(False)
            spin.setButtonSymbols(QtWidgets.QAbstractSpinBox.NoButtons)
            spin.setMinimumWidth(50)
            spin.setMaximumWidth(64)
            remove = QtWidgets.QToolButton()
            remove.setText("\u2212")
            remove.setToolTip(translate("FairSplines", "Remove this mark"))
            slider.valueChanged.connect(lambda value, p=piece, i=index: self._slider_moved(p, i, value))
            spin.valueChanged.connect(lambda value, p=piece, i=index: self._spin_changed(p, i, value))
            remove.clicked.connect(lambda checked=False, p=piece, i=index: self.remove_mark(p, i))
            number = QtWidgets.QLabel(str(index + 1))
            number.setToolTip(
                translate("FairSplines", "Mark {} of this piece (its parameter u in 0..1)").format(index + 1))
            grid.addWidget(number, index, 0)
            grid.addWidget(slider, index, 1)
            grid.addWidget(spin, index, 2)
            grid.addWidget(remove, index, 3)
            self.rows[piece].append(MarkRow(slider, spin, remove))
        self._sync(piece)

    def bounds(self, piece, index):
        """The open range mark `index` of `piece` may take: one GAP inside its neighbours."""
        marks = self.marks[piece]
        lower = marks[index - 1] if index > 0 else 0.0
        upper = marks[index + 1] if index + 1 < len(marks) else 1.0
        return lower + GAP, upper - GAP

    def _sync(self, piece):
        """Put slider and spin box ranges and values of a piece in line with self.marks."""
        self._updating = True
        try:
            for index, row in enumerate(self.rows[piece]):
                lower, upper = self.bounds(piece, index)
                u = self.marks[piece][index]
                row.slider.setRange(1, SCALE - 1)  # the whole piece: the handle shows where the mark is
                row.slider.setValue(int(round(u * SCALE)))
                row.spin.setRange(lower, upper)
                row.spin.setValue(u)
                row.remove.setEnabled(True)
        finally:
            self._updating = False

    def _slider_moved(self, piece, index, value):
        if not self._updating:
            self.set_mark(piece, index, value / SCALE)

    def _spin_changed(self, piece, index, value):
        if not self._updating:
            self.set_mark(piece, index, value)

    # --- edits -----------------------------------------------------------------------

    def set_mark(self, piece, index, u):
        """Move a mark to u, kept strictly between its neighbours; preview at once."""
        lower, upper = self.bounds(piece, index)
        u = min(max(float(u), lower), upper)
        self.marks[piece][index] = u
        self.active = (piece, index)
        self._sync(piece)
        self.apply()
        return u

    def add_mark(self, piece):
        """Add a mark in the middle of the widest gap of a piece; returns its index, or
        None when every gap is too small."""
        knots = [0.0] + self.marks[piece] + [1.0]
        gaps = [b - a for a, b in zip(knots[:-1], knots[1:])]
        widest = max(range(len(gaps)), key=lambda k: gaps[k])
        if gaps[widest] < 2 * GAP:
            return None
        u = 0.5 * (knots[widest] + knots[widest + 1])
        self.marks[piece].insert(widest, u)
        self.active = (piece, widest)
        self._build_rows(piece)
        self.apply()
        return widest

    def remove_mark(self, piece, index):
        del self.marks[piece][index]
        self.active = None
        self._build_rows(piece)
        self.apply()

    def set_reversed(self, piece, flag):
        """Run a piece the other way; its marks stay on the same points (u -> 1 - u)."""
        flag = bool(flag)
        if self.reversed[piece] == flag:
            return
        self.reversed[piece] = flag
        self.marks[piece] = [1.0 - u for u in reversed(self.marks[piece])]
        label, curve, error = self.curves[piece]
        if curve is not None:
            from ...features.design_spline import reversed_curve

            curve = reversed_curve(curve)
        self.curves[piece] = (label, curve, error)
        self.active = None
        self._build_rows(piece)
        if self.reverse_boxes[piece].isChecked() != flag:
            self.reverse_boxes[piece].setChecked(flag)
        self.apply()

    def apply(self):
        """Write the marks to the feature and recompute (inside the panel's undo step)."""
        self.session.begin()
        set_marks(self.obj, self.marks)
        if [bool(r) for r in self.obj.Reversed] != self.reversed:
            self.obj.Reversed = self.reversed
        self.doc.recompute()
        self.refresh()

    # --- display ---------------------------------------------------------------------

    def mark_points(self):
        """The marked points in the document, piece after piece."""
        points = []
        for piece, (_, curve, _) in enumerate(self.curves):
            if isinstance(curve, Samples):
                points.extend(FreeCAD.Vector(*p) for p in curve.points)
            elif curve is not None:
                points.extend(curve.value(u) for u in self.marks[piece])
        return points

    def refresh(self):
        """Status, joins, per-piece notes and the 3D overlay."""
        obj = self.obj
        show_status(self.status_label, obj.Status)
        joins = list(obj.Joins)
        pair = translate("FairSplines", "Pieces {} and {}: {}")
        self.joins_label.setText("\n".join(
            pair.format(k + 1, k + 2, translate("FairSplines", JOIN_WORDS.get(j, j))) for k, j in enumerate(joins)))
        added = list(obj.MarksAdded)
        for piece, info in enumerate(self.info_labels):
            label, curve, error = self.curves[piece]
            notes = []
            if isinstance(curve, Samples):
                notes.append(translate("FairSplines", "{} samples, no marks: the curve follows them closely "
                                       "here").format(len(curve.points)))
                info.setToolTip(translate("FairSplines", "This part of the curve is the csr-spline of the samples "
                                          "(curvature-sensitive spline, Section 4 of the paper): close to every "
                                          "sample, without added curvature wiggles"))
            if error:
                notes.append(error)
            if piece < len(added) and added[piece]:
                notes.append(
                    translate("FairSplines", "{} mark(s) added to keep the weights positive").format(added[piece]))
            info.setText("; ".join(notes))
            info.setVisible(bool(notes))
        self.overlay.set_points(self.mark_points())
        highlight = []
        if self.active is not None:
            piece, index = self.active
            curve = self.curves[piece][1]
            if curve is not None and index < len(self.marks[piece]):
                highlight = [curve.value(self.marks[piece][index])]
        self.overlay.set_highlight(highlight)
        poles = []
        if not obj.Shape.isNull() and obj.Shape.Edges:
            curve = obj.Shape.Edges[0].Curve
            if hasattr(curve, "getPoles"):
                poles = curve.getPoles()
        self.overlay.set_polygon(poles)

    # --- task dialog -----------------------------------------------------------------

    def finish(self):
        """Remove the overlay (called when the edit ends, however it ends)."""
        self.overlay.detach()
