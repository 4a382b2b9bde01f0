"""Live editing of an object's properties from a task panel: every change is applied and
recomputed at once (the preview), inside one undo step; OK keeps it, Cancel restores the
values the panel opened with. GUI helper, but uses only App calls.

FreeCAD closes a transaction a command opened when the command returns, so the step is
opened lazily, at the first change. If another step was already open the changes join
it, and Cancel puts the properties back by assignment.
"""
import FreeCAD


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
        only when editing ends (no recompute per keystroke)."""
        from .qt import QtWidgets

        spin = QtWidgets.QDoubleSpinBox()
        spin.setRange(lower, upper)
        spin.setDecimals(decimals)
        spin.setSuffix(suffix)
        spin.setKeyboardTracking(False)
        return spin

    def getStandardButtons(self):
        from .qt import QtWidgets

        return int(QtWidgets.QDialogButtonBox.Ok | QtWidgets.QDialogButtonBox.Cancel)

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
