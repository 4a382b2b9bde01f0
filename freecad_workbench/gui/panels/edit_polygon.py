"""The Edit polygon task panel (csr paper, Fig. 10f): move control points of a designed
spline. Drag a pole in the 3D view (it moves in the curve's plane, or parallel to the
screen for a space curve), or pick it in the list and type its coordinates. Every move
recomputes at once; the polygon is drawn green, moved poles orange, the current one red.
"Reset pole" and "Reset all" put poles back where the design has them. OK keeps the
changes as one undo step, Cancel restores the poles the panel opened with.
"""
import FreeCAD

from ...features.edit_polygon import reset_pole, set_pole, source_edge
from .. import icon_path
from .form import LiveEdit, LiveEditPanel, button_column, compact, form_rows, show_status, wrapped_label
from ..overlay import Overlay, active_view
from ..scene import event_position

translate = FreeCAD.Qt.translate

PICK_RADIUS = 12  # pixels: how near a click must be to a pole to grab it


class EditPolygonPanel(LiveEditPanel):
    """Task panel: pick and move the poles of an Edit polygon feature."""

    def __init__(self, obj):
        from ..qt import QtGui, QtWidgets

        self.obj = obj
        self.doc = obj.Document
        self.session = LiveEdit(obj, translate("FairSplines", "Edit polygon"), ("PoleOffsets",))
        self.selected = None
        self.dragging = None  # (pole index, plane point, plane normal) while dragging
        self._updating = False

        self.form = QtWidgets.QWidget()
        self.form.setWindowTitle(translate("FairSplines", "Edit control points"))
        self.form.setWindowIcon(QtGui.QIcon(icon_path("FairSplines_EditPolygon")))
        layout = QtWidgets.QVBoxLayout(self.form)
        hint = QtWidgets.QLabel(translate(
            "FairSplines",
            "Drag a control point in the 3D view, or pick it in the list and type its position. "
            "A moved point changes the curve only near it (on the four spans it supports).",
        ))
        hint.setWordWrap(True)
        layout.addWidget(hint)
        self.list = QtWidgets.QListWidget()
        self.list.currentRowChanged.connect(self._row_changed)
        layout.addWidget(self.list, 1)
        coords = form_rows()
        self.spins = []
        for axis in "XYZ":
            spin = compact(QtWidgets.QDoubleSpinBox(), 100)
            spin.setDecimals(4)
            spin.setRange(-1e9, 1e9)
            spin.setSuffix(" mm")
            spin.setKeyboardTracking(False)
            spin.valueChanged.connect(self._spin_changed)
            coords.addRow(axis, spin)
            self.spins.append(spin)
        layout.addLayout(coords)
        self.reset_button = QtWidgets.QPushButton(translate("FairSplines", "Reset pole"))
        self.reset_button.clicked.connect(lambda: self.reset(self.selected))
        self.reset_all_button = QtWidgets.QPushButton(translate("FairSplines", "Reset all"))
        self.reset_all_button.clicked.connect(self.reset_all)
        layout.addLayout(button_column(self.reset_button, self.reset_all_button))
        self.count_label = wrapped_label()
        layout.addWidget(self.count_label)
        self.status_label = wrapped_label()
        layout.addWidget(self.status_label)

        self.overlay = Overlay("FairSplinesEditPolygon")
        self.view = active_view(self.doc)
        self.overlay.attach(self.view)
        self._callbacks = []
        if self.view is not None:
            from pivy import coin

            self._callbacks = [
                (coin.SoMouseButtonEvent.getClassTypeId(),
                 self.view.addEventCallbackPivy(coin.SoMouseButtonEvent.getClassTypeId(), self._on_button)),
                (coin.SoLocation2Event.getClassTypeId(),
                 self.view.addEventCallbackPivy(coin.SoLocation2Event.getClassTypeId(), self._on_move)),
            ]
        self.refresh()
        if self.poles():
            self.select(0)

    # --- model -----------------------------------------------------------------------

    def poles(self):
        """The edited poles (as the feature has them now)."""
        return [FreeCAD.Vector(p) for p in self.obj.Poles]

    def moved(self):
        return [i for i, o in enumerate(self.obj.PoleOffsets) if o.Length > 0]

    def select(self, index):
        self.selected = index
        if self.list.currentRow() != index:
            self.list.setCurrentRow(index)
        self._show_selected()

    def move_pole(self, index, point):
        """Move pole `index` to `point` and recompute (the preview)."""
        self.session.begin()
        set_pole(self.obj, index, FreeCAD.Vector(point))
        self.doc.recompute()
        self.selected = index
        self.refresh()

    def reset(self, index):
        if index is None:
            return
        self.session.begin()
        reset_pole(self.obj, index)
        self.doc.recompute()
        self.refresh()

    def reset_all(self):
        if not list(self.obj.PoleOffsets):
            return
        self.session.begin()
        self.obj.PoleOffsets = []
        self.doc.recompute()
        self.refresh()

    # --- display ---------------------------------------------------------------------

    def refresh(self):
        poles = self.poles()
        moved = set(self.moved())
        self._updating = True
        try:
            if self.list.count() != len(poles):
                self.list.clear()
                for i in range(len(poles)):
                    self.list.addItem("")
            for i, p in enumerate(poles):
                mark = translate("FairSplines", "  (moved)") if i in moved else ""
                self.list.item(i).setText(f"{i + 1}:  {p.x:.5g}, {p.y:.5g}, {p.z:.5g}{mark}")
        finally:
            self._updating = False
        self.count_label.setText(
            translate("FairSplines", "{} control points, {} moved").format(len(poles), len(moved)))
        show_status(self.status_label, self.obj.Status)
        self.overlay.set_polygon(poles)
        self.overlay.set_moved([poles[i] for i in sorted(moved) if i < len(poles)])
        self._show_selected()

    def _show_selected(self):
        poles = self.poles()
        index = self.selected
        valid = index is not None and 0 <= index < len(poles)
        self.overlay.set_highlight([poles[index]] if valid else [])
        self._updating = True
        try:
            for spin, value in zip(self.spins, poles[index] if valid else (0, 0, 0)):
                spin.setEnabled(valid)
                spin.setValue(value)
        finally:
            self._updating = False
        self.reset_button.setEnabled(valid)

    def _row_changed(self, row):
        if not self._updating and row >= 0:
            self.selected = row
            self._show_selected()

    def _spin_changed(self, _value):
        if self._updating or self.selected is None:
            return
        self.move_pole(self.selected, FreeCAD.Vector(*(s.value() for s in self.spins)))

    # --- mouse -----------------------------------------------------------------------

    def pick(self, x, y):
        """The pole nearest to screen position (x, y) within PICK_RADIUS pixels, or None."""
        best, best_distance = None, PICK_RADIUS
        for i, p in enumerate(self.poles()):
            sx, sy = self.view.getPointOnScreen(p)
            distance = ((sx - x) ** 2 + (sy - y) ** 2) ** 0.5
            if distance <= best_distance:
                best, best_distance = i, distance
        return best

    def drag_plane(self, index):
        """(point, normal) of the plane a pole moves in: the curve's plane, or the screen's."""
        point = self.poles()[index]
        normal = None
        try:
            source, subs = self.obj.Source
            plane = source_edge(source, subs[0] if subs else "").findPlane()
            if plane is not None:
                normal = FreeCAD.Vector(plane.Axis)
        except Exception:
            normal = None
        view_direction = FreeCAD.Vector(self.view.getViewDirection())
        if normal is None or abs(normal.normalize().dot(view_direction.normalize())) < 1e-3:
            normal = view_direction
        return point, normal.normalize()

    def screen_to_plane(self, x, y, point, normal):
        """The point of the plane (point, normal) under screen position (x, y)."""
        on_focal_plane = FreeCAD.Vector(self.view.getPointOnFocalPlane(int(x), int(y)))
        if self.view.getCameraType() == "Perspective":
            origin = FreeCAD.Vector(*self.view.getCameraNode().position.getValue().getValue())
            direction = on_focal_plane - origin
        else:
            origin, direction = on_focal_plane, FreeCAD.Vector(self.view.getViewDirection())
        denominator = normal.dot(direction)
        if abs(denominator) < 1e-12:
            return on_focal_plane
        return origin + direction * (normal.dot(point - origin) / denominator)

    def press(self, x, y):
        """Start dragging the pole at (x, y); True if there was one."""
        index = self.pick(x, y)
        if index is None:
            return False
        self.select(index)
        point, normal = self.drag_plane(index)
        grab = self.screen_to_plane(x, y, point, normal)
        self.dragging = (index, point, normal, point - grab)
        return True

    def drag(self, x, y):
        if self.dragging is None:
            return False
        index, point, normal, offset = self.dragging
        self.move_pole(index, self.screen_to_plane(x, y, point, normal) + offset)
        return True

    def release(self):
        was = self.dragging is not None
        self.dragging = None
        return was

    def _on_button(self, event_callback):
        from pivy import coin

        event = event_callback.getEvent()
        if event.getButton() != coin.SoMouseButtonEvent.BUTTON1:
            return
        x, y = event_position(event)
        if event.getState() == coin.SoButtonEvent.DOWN:
            if self.press(x, y):
                event_callback.setHandled()
        elif event.getState() == coin.SoButtonEvent.UP and self.release():
            event_callback.setHandled()

    def _on_move(self, event_callback):
        if self.dragging is None:
            return
        x, y = event_position(event_callback.getEvent())
        self.drag(x, y)
        event_callback.setHandled()

    # --- task dialog -----------------------------------------------------------------

    def finish(self):
        """Remove the overlay and the mouse callbacks."""
        if self.view is not None:
            for type_id, callback in self._callbacks:
                try:
                    self.view.removeEventCallbackPivy(type_id, callback)
                except Exception:
                    pass
        self._callbacks = []
        self.overlay.detach()
