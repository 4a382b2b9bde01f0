"""What every FairSplines feature shares: properties added only when missing (old files load),
the error state (keep the last good shape, show the message), one undoable creation step,
and a proxy that keeps nothing outside its properties. Headless."""
from contextlib import contextmanager

import FreeCAD

OUTPUT = 8  # App::Property::Output: setting it does not touch the object


def ensure_properties(obj, properties, group, enumerations=None, outputs=("Status",)):
    """Add any missing property of `properties` ((type, name, tooltip, default, editor mode)
    tuples) with its default, keep the values of existing ones, and bring enumerations
    ({name: choices}) up to date, keeping a value that is still a choice."""
    enumerations = enumerations or {}
    for type_, name, tooltip, default, mode in properties:
        choices = list(enumerations.get(name, ()))
        if name not in obj.PropertiesList:
            obj.addProperty(type_, name, group, tooltip, OUTPUT if name in outputs else 0)
            if choices:
                setattr(obj, name, choices)
            if default is not None:
                setattr(obj, name, default)
        elif choices and list(obj.getEnumerationsOfProperty(name)) != choices:
            value = getattr(obj, name)
            setattr(obj, name, choices)
            setattr(obj, name, value if value in choices else default)
        obj.setEditorMode(name, mode)


def fail(obj, message):
    """Error state: keep the last good shape, show the message, let recompute go on."""
    if obj.Status != message:
        obj.Status = message
    FreeCAD.Console.PrintError(f"{obj.Label}: {message}\n")


def succeed(obj):
    """Leave the error state."""
    if obj.Status != "ok":
        obj.Status = "ok"


@contextmanager
def undoable(doc, title):
    """One undo step named `title`, unless a transaction is already open (then it is part of it)
    or the document keeps no undo (UndoMode 0, as headless documents by default: there an
    opened transaction would never close and would lend its name to the next one anywhere)."""
    own = bool(doc.UndoMode) and not doc.HasPendingTransaction
    if own:
        doc.openTransaction(title)
    try:
        yield
    except Exception:
        if own:
            doc.abortTransaction()
        raise
    if own:
        doc.commitTransaction()


class Proxy:
    """A feature proxy that keeps everything in properties. FreeCAD 0.20 stores a proxy with
    __getstate__/__setstate__, older versions with dumps/loads."""

    def __getstate__(self):
        return None

    def __setstate__(self, state):
        return None

    def dumps(self):
        return None

    def loads(self, state):
        return None
