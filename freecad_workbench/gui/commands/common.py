"""What the commands share: reading the selection, writing the macro line that replays a
command, and opening a new object's task panel once the command has returned."""
import os

import FreeCAD
import FreeCADGui

from .. import ICON_DIR, icon_path
from ..comb import edges_of

ROOT = os.path.dirname(ICON_DIR)
README = os.path.join(ROOT, "README.md")
QT_TRANSLATE_NOOP = FreeCAD.Qt.QT_TRANSLATE_NOOP
_HELP_FILES = {}  # section heading -> the documentation file that holds it


def help_file(section):
    """The documentation file (README.md, or one in docs/) with a heading `section`."""
    if not _HELP_FILES:
        docs = os.path.join(ROOT, "docs")
        for path in [README] + sorted(os.path.join(docs, f) for f in os.listdir(docs) if f.endswith(".md")):
            with open(path, encoding="utf-8") as f:
                for line in f:
                    if line.startswith("#"):
                        _HELP_FILES.setdefault(line.lstrip("#").strip(), path)
    return _HELP_FILES.get(section, README)


def resources(name, menu_text, tool_tip, section, icon=None, accel=None):
    """GetResources of a command: its icon (named after the command), menu text and tool
    tip (translated in the command's context), and What's This help that points to the
    documentation section (README.md or docs/) describing it."""
    more = FreeCAD.Qt.translate("FairSplines", "More in FairSplines' documentation, section \u201c{}\u201d:\n{}")
    result = {
        "Pixmap": icon_path(icon or name),
        "MenuText": menu_text,
        "ToolTip": tool_tip,
        "WhatsThis": f"{FreeCAD.Qt.translate(name, tool_tip)}\n\n{more.format(section, help_file(section))}",
    }
    if accel:
        result["Accel"] = accel
    return result


def selected_links(doc=None):
    """The selection in the active document as [(obj, subname)] in pick order (a whole
    object has subname '')."""
    doc = doc or FreeCAD.ActiveDocument
    if doc is None:
        return []
    links = []
    for sel in FreeCADGui.Selection.getCompleteSelection():
        obj = sel.Object
        if obj.Document.Name != doc.Name:
            continue
        subs = sel.SubElementNames or ("",)
        links.extend((obj, sub) for sub in subs)
    return links


def element(sub):
    """The element name at the end of a subname ('Edge3' of 'Body.Sketch.Edge3')."""
    return sub.rsplit(".", 1)[-1] if sub else ""


def edge_links(links):
    """The links that hold edges: an EdgeN element, or a whole object with edges."""
    result = []
    for obj, sub in links:
        name = element(sub)
        if name:
            if name.startswith("Edge"):
                result.append((obj, sub))
        elif edges_of(obj):
            result.append((obj, sub))
    return result


def one_edge(obj, sub):
    """Whether (obj, sub) names one edge: an EdgeN, or a whole object with one edge."""
    name = element(sub)
    if name:
        return name.startswith("Edge")
    shape = getattr(obj, "Shape", None)
    return shape is not None and not shape.isNull() and len(shape.Edges) == 1


def link_code(obj, sub=None):
    """Python source naming obj (and (obj, sub) when sub is given), for the macro recording."""
    ref = f"FreeCAD.getDocument({obj.Document.Name!r}).getObject({obj.Name!r})"
    return ref if sub is None else f"({ref}, {sub!r})"


def links_code(links):
    """Python source of a links list, for the macro recording."""
    return "[" + ", ".join(link_code(obj, sub) for obj, sub in links) + "]"


def run_on_selected_edges(module, function):
    """Call module.function(links) on the selected edges, recorded as a macro line."""
    links = edge_links(selected_links())
    if not links:
        return
    FreeCADGui.doCommand("import FreeCAD")
    FreeCADGui.doCommand(f"import {module}")
    FreeCADGui.doCommand(f"{module}.{function}({links_code(links)})")


def doc_code(doc):
    return f"FreeCAD.getDocument({doc.Name!r})"


def create(doc, module, maker, args=""):
    """Make an object with freecad_workbench.features.<module>.<maker>(doc, args) through the
    macro recorder (the lines a macro replays) and return it, or None if nothing was made."""
    before = {o.Name for o in doc.Objects}
    FreeCADGui.doCommand("import FreeCAD")
    FreeCADGui.doCommand(f"from freecad_workbench.features.{module} import {maker}")
    FreeCADGui.doCommand(f"{maker}({', '.join([doc_code(doc)] + ([args] if args else []))})")
    return new_object(doc, before)


def new_object(doc, before):
    """The object a command added to doc (names `before` were there already), or None."""
    created = [o for o in doc.Objects if o.Name not in before]
    return created[-1] if created else None


def edit(obj):
    """Open obj's task panel (recorded in the macro)."""
    FreeCADGui.doCommand("import FreeCADGui")
    FreeCADGui.doCommand(f"FreeCADGui.getDocument({obj.Document.Name!r}).setEdit({obj.Name!r}, 0)")


def edit_later(obj):
    """Open obj's task panel once the command has returned: FreeCAD closes the command's
    own undo step then, so the panel's changes become an undo step of their own."""
    from ..qt import QtCore

    doc_name, name = obj.Document.Name, obj.Name

    def later():
        doc = FreeCAD.listDocuments().get(doc_name)
        target = doc.getObject(name) if doc is not None else None
        if target is not None and not FreeCADGui.Control.activeDialog():
            edit(target)

    QtCore.QTimer.singleShot(0, later)
