"""Curvature combs on a face's isolines and planar cross sections (issue 27), drawn with
gui/comb.py's comb (comb_lines, auto_scale, _CombNode): the curves are made for the
drawing only, nothing is added to the document.

    show([(obj, "Face2")], lines="U", count=5)        # 5 U isolines, evenly spaced
    show([(obj, "")], lines="Z", count=8)             # 8 cross sections normal to Z
    hide()

lines: "U", "V", "UV" (both), or "X", "Y", "Z" (sections by planes normal to that axis,
evenly spaced through the faces' bounding box, ends excluded).
"""
import FreeCAD

from . import comb

LINES = ("U", "V", "UV", "X", "Y", "Z")
SAMPLES = 60  # teeth per curve


def _element(sub):
    return sub.rsplit(".", 1)[-1] if sub else ""


def faces_of(links):
    """The faces (global coordinates) of selection-style links: FaceN, or every face."""
    import Part

    faces = []
    for obj, sub in links:
        name = _element(sub)
        if name.startswith("Face"):
            faces.append(Part.getShape(obj, sub, needSubElement=True))
        elif not name:
            faces.extend(Part.getShape(obj).Faces)
    return faces


def _isolines(face, direction, count):
    """Isolines of one face, trimmed to it."""
    u0, u1, v0, v1 = face.ParameterRange
    edges = []
    for i in range(1, count + 1):
        t = i / (count + 1)
        try:
            if direction == "U":
                curve, first, last = face.Surface.uIso(u0 + (u1 - u0) * t), v0, v1
            else:
                curve, first, last = face.Surface.vIso(v0 + (v1 - v0) * t), u0, u1
            edge = curve.toShape(first, last)
            inside = edge.common(face)
            edges.extend(inside.Edges if inside.Edges else [edge])
        except Exception:  # a degenerate isoline (a pole)
            continue
    return [e for e in edges if e.Length > 1e-9]


def _sections(faces, axis, count):
    box = faces[0].BoundBox
    for face in faces[1:]:
        box.add(face.BoundBox)
    k = "XYZ".index(axis)
    low, high = (box.XMin, box.YMin, box.ZMin)[k], (box.XMax, box.YMax, box.ZMax)[k]
    normal = FreeCAD.Vector(*[1.0 if j == k else 0.0 for j in range(3)])
    edges = []
    for i in range(1, count + 1):
        d = low + (high - low) * i / (count + 1)
        for face in faces:
            try:
                for wire in face.slice(normal, d):
                    edges.extend(wire.Edges)
            except Exception:  # the plane misses the face
                continue
    return [e for e in edges if e.Length > 1e-9]


def curves(links, lines="UV", count=5):
    """The edges the combs are drawn on."""
    faces = faces_of(links)
    if not faces:
        return []
    if lines in ("X", "Y", "Z"):
        return _sections(faces, lines, count)
    edges = []
    for face in faces:
        for direction in ("U", "V"):
            if direction in lines:
                edges.extend(_isolines(face, direction, count))
    return edges


_shown = []  # [(node, links, lines, count, scale)]


def show(links, lines="UV", count=5, scale=1.0):
    """Combs on the isolines or sections of the linked faces (replaces those shown)."""
    from .overlay import active_view

    if lines not in LINES:
        raise ValueError(f"lines must be one of {', '.join(LINES)}, got {lines!r}")
    hide()
    links = list(links)
    edges = curves(links, lines, int(count))
    node = comb._CombNode(("iso",))
    node.root.setName("FairSplinesIsoCombs")
    if edges:
        factor = scale * comb.auto_scale(edges, SAMPLES)
        node.update([comb.comb_lines(edge, factor, SAMPLES) for edge in edges])
    view = active_view(links[0][0].Document) if links else None
    if view is not None:
        node.attach([view])
    _shown.append((node, links, lines, int(count), float(scale), edges))
    return edges


def current():
    return _shown[-1] if _shown else None


def hide():
    while _shown:
        _shown.pop()[0].detach()
