"""One undoable step around a factory's changes."""
from contextlib import contextmanager


@contextmanager
def undo_step(doc, name):
    """Run the block as one undo step named `name`: opened here unless the document has
    one pending (then the changes join it), aborted if the block raises.

    Without undo (UndoMode 0, e.g. documents made in freecadcmd or plain python) nothing is
    opened: FreeCAD 0.20 would leave an application-wide active transaction behind that
    then names the next undo step of whatever document changes next."""
    own = bool(doc.UndoMode) and not doc.HasPendingTransaction
    if own:
        doc.openTransaction(name)
    try:
        yield
    except BaseException:
        if own:
            doc.abortTransaction()
        raise
    if own:
        doc.commitTransaction()
