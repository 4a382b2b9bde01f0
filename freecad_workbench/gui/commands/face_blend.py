"""The face blend command (GUI only); it records a replayable macro line.

FairSplines_BlendFaces   a G2 (or G1) blend surface between an edge of one face and an edge of
                         another, both picked in the 3D view (issue 29, docs/FACE_BLENDS.md);
                         its panel opens and recomputes live; the blend shows with zebra
"""
import FreeCAD
import FreeCADGui
import Part

from .common import QT_TRANSLATE_NOOP, create, edit_later, element, link_code, resources

translate = FreeCAD.Qt.translate

NAME = "FairSplines_BlendFaces"


def _faces_of_edge(shape, edge):
    """The names ('Face2') of the faces of shape that hold edge."""
    return [f"Face{k + 1}" for k, face in enumerate(shape.Faces) if any(e.isSame(edge) for e in face.Edges)]


def blend_selection():
    """The selection as (((obj, 'FaceN'), (obj, 'EdgeM')) for side A, the same for side B), in
    pick order, or a message saying what to select. Two edges must be selected; each edge's
    face is the one selected with it (of the same object), else the only face it bounds."""
    doc = FreeCAD.ActiveDocument
    if doc is None:
        return translate("FairSplines", "Open a document first")
    edges, faces = [], []
    for sel in FreeCADGui.Selection.getSelectionEx(doc.Name):
        for sub in sel.SubElementNames:
            name = element(sub)
            if name.startswith("Edge"):
                edges.append((sel.Object, name))
            elif name.startswith("Face"):
                faces.append((sel.Object, name))
    if len(edges) != 2:
        return translate("FairSplines", "Select two edges, each on the face to blend from (Ctrl+click)")
    sides = []
    for obj, name in edges:
        shape = Part.getShape(obj)  # global coordinates, as the selection names them
        holders = _faces_of_edge(shape, shape.getElement(name))
        picked = [f for o, f in faces if o is obj and f in holders]
        if len(picked) == 1:
            face = picked[0]
        elif len(holders) == 1:
            face = holders[0]
        elif not holders:
            return translate("FairSplines", "{} of {} bounds no face").format(name, obj.Label)
        else:
            return translate("FairSplines", "{} of {} bounds {}: select the face to blend from too "
                                            "(Ctrl+click)").format(name, obj.Label, " and ".join(holders))
        sides.append(((obj, face), (obj, name)))
    return tuple(sides)


def _say(message):
    """A refusal in the status bar and the report view (no dialog to dismiss)."""
    from ..qt import main_window

    FreeCAD.Console.PrintWarning(f"{translate('FairSplines', 'Blend faces')}: {message}\n")
    main = main_window()
    if main is not None:
        main.statusBar().showMessage(message, 8000)


class BlendFacesCommand:
    def GetResources(self):
        return resources(
            NAME,
            QT_TRANSLATE_NOOP(NAME, "Blend faces"),
            QT_TRANSLATE_NOOP(
                NAME,
                "A smooth surface from an edge of one face to an edge of another: it meets both faces\n"
                "in curvature (G2) or in tangent (G1), exactly where the edge is a boundary of its face.\n"
                "Its cross sections are chosen for fair, monotone curvature (certified).\n"
                "Select two edges in the 3D view, with the face of each where an edge bounds two.\n"
                "Exact boundary derivatives from the face's poles; shows with zebra stripes.",
            ),
            "Face blends: G1 and G2 along the whole edge, fair across (issue 29)",
        )

    def IsActive(self):
        return FreeCAD.ActiveDocument is not None and not FreeCADGui.Control.activeDialog()

    def Activated(self):
        sides = blend_selection()
        if isinstance(sides, str):
            _say(sides)
            return
        (face_a, edge_a), (face_b, edge_b) = sides
        args = ", ".join(link_code(*link) for link in (face_a, edge_a, face_b, edge_b))
        obj = create(face_a[0].Document, "face_blend", "make_face_blend", args)
        FreeCADGui.Selection.clearSelection()
        if obj is not None:
            edit_later(obj)


def command_objects():
    return {NAME: BlendFacesCommand()}
