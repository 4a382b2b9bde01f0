"""The Fair blend: a parametric cubic B-spline whose curvature is monotone, proved by the
exact certificate, that bridges two edges' end points with their tangents (G1) and
curvatures (G2, the default), or two vertices with given directions (and curvatures). Planar
where the ends share a plane; where they do not, the fair blend in space
(fw.fair_blend_space_solution, issue 28), G2 to the edges' curvature vectors.
Headless; a view provider is attached only when FreeCAD.GuiUp.

    from freecad_workbench.features.fair_blend import make_fair_blend
    blend = make_fair_blend(doc, (line, "Edge1"), (arc, "Edge1"))               # two edges, G2
    blend = make_fair_blend(doc, (box, "Vertex1"), (box, "Vertex7"), continuity="G1",
                            start_direction=(1, 0, 0), end_direction=(0, 1, 0))

The ends, `Start` and `End`, are each an edge or a vertex (an element, or a whole object with
one edge or one vertex):
- an edge: the blend starts (ends) at one of its end points, chosen by `StartEnd` (`EndEnd`):
  "first", "last", or "auto", the end nearest to the other side. It leaves the start edge
  continuing it (tangent outwards) and runs on into the end edge (tangent inwards), so the
  joints are G1;
- a vertex: the blend starts (ends) there with the direction `StartDirection` (`EndDirection`).
- `Continuity`: G2 (default) also matches the edges' curvatures as OCCT evaluates them at the
  ends (at a vertex end: `StartCurvature`, `EndCurvature`, signed about the plane normal).
- `Method`: fair (default, fw.fair_blend_solution), or the monotone-curvature paper's
  Algorithm 2 (paper: its analytic centre; grid: its grid search), one short cubic, G1 only.
It follows its sources when they change. When the ends admit no monotone curve it shows the
fairest curve it found, with `Status` beginning "warning:" and the reason (also in the report
view). If a source is unusable, or the paper's method has no curve, it keeps its last good
shape, puts the reason in `Status`, and lets the rest of the document recompute.

Documents made with the Monotone blend (version 1, before fair blends) open and recompute
unchanged: they are migrated to Continuity G1 and Method paper (fairest, as it was called).
"""
import FreeCAD
import numpy as np
import Part

from ..errors import InputError
from ..fair_blend import (
    CONTINUITIES,
    METHODS,
    curvature_vector,
    edge_end,
    fair_blend_solution,
    fair_blend_space_solution,
)
from ..kernel import as_vector
from ..monotone import check_monotone_curvature, monotone_curvature_solution
from .base import FeatureProxy, attach_view_provider, set_if_changed
from .undo import undo_step

ENDS = ("auto", "first", "last")
WARNING = "warning: "

_PROPERTIES = (
    ("App::PropertyLinkSub", "Start", "Edge or vertex where the blend starts", None, 0),
    ("App::PropertyEnumeration", "StartEnd", "Which end of the start edge: auto (nearest), first or last", "auto", 0),
    ("App::PropertyVector", "StartDirection", "Tangent at the start when Start is a vertex", FreeCAD.Vector(1, 0, 0),
     0),
    ("App::PropertyLinkSub", "End", "Edge or vertex where the blend ends", None, 0),
    ("App::PropertyEnumeration", "EndEnd", "Which end of the end edge: auto (nearest), first or last", "auto", 0),
    ("App::PropertyVector", "EndDirection", "Tangent at the end when End is a vertex", FreeCAD.Vector(1, 0, 0), 0),
    ("App::PropertyFloat", "StartCurvature", "Curvature at the start when Start is a vertex and Continuity is G2 "
     "(1/mm, signed: positive turns counter-clockwise about the plane normal)", 0.0, 0),
    ("App::PropertyFloat", "EndCurvature", "Curvature at the end when End is a vertex and Continuity is G2 "
     "(1/mm, signed)", 0.0, 0),
    ("App::PropertyEnumeration", "Continuity", "G2: tangents and curvatures of the edges; G1: tangents only", "G2", 0),
    ("App::PropertyEnumeration", "Method", "fair: any ends; paper: the monotone-curvature paper's single cubic "
     "(Algorithm 2, G1); grid: its grid search", "fair", 0),
    ("App::PropertyString", "Curvature", "How the curvature runs (the certificate)", "", 1),
    ("App::PropertyString", "Status", "'ok', or why the last recompute failed", "ok", 1),
    ("App::PropertyInteger", "Version", "Version of this object's properties", 0, 2),
)


class FairBlend(FeatureProxy):
    """Proxy of a Part::FeaturePython holding a fair blend."""

    Type = "FairBlend"
    VERSION = 2  # 1: the Monotone blend (Algorithm 2 only)
    GROUP = "Fair blend"
    PROPERTIES = _PROPERTIES
    ENUMERATIONS = {"StartEnd": ENDS, "EndEnd": ENDS, "Continuity": CONTINUITIES, "Method": METHODS}
    OUTPUTS = ("Status", "Curvature")
    VERDICTS = ("Curvature",)

    def onDocumentRestored(self, obj):
        # Read what version 1 stored before the enumerations are brought up to date.
        old_method = obj.Method if "Method" in obj.PropertiesList else None
        old = "Version" not in obj.PropertiesList or obj.Version < 2
        super().onDocumentRestored(obj)
        if old:
            obj.Continuity = "G1"
            obj.Method = "grid" if old_method == "grid" else "paper"  # "fairest" was the paper's solver
        show_what_applies(obj)

    def build(self, obj):
        self._warning = None
        show_what_applies(obj)
        p0, t0, p1, t1, k0, k1, normal = blend_ends(obj)
        if obj.Method != "fair":
            if obj.Continuity == "G2":
                raise InputError("the paper's Algorithm 2 is G1 only: set Continuity to G1, or Method to fair")
            curve = monotone_curvature_solution(p0, t0, p1, t1, method=obj.Method).curve
            set_if_changed(obj, "Curvature", check_monotone_curvature(curve).summary)
            return curve.toShape()
        g2 = obj.Continuity == "G2"
        space = space_ends(obj, g2)
        if space is not None:  # the ends do not share a plane: the fair blend in space
            curve, report = fair_blend_space_solution(*space)
        else:
            curve, report = fair_blend_solution(p0, t0, p1, t1, k0 if g2 else None, k1 if g2 else None, normal)
        set_if_changed(obj, "Curvature", report.certificate.summary)
        if not report.monotone:
            # the kernel's why, then the verdict on the curve shown in a designer's words
            why = report.reason.split("; the fairest found instead")[0]
            self._warning = f"{why}; shown instead: the fairest curve found, which is {report.certificate.summary}"
        return curve.toShape()

    def execute(self, obj):
        super().execute(obj)
        warning = getattr(self, "_warning", None)
        if warning and obj.Status == "ok":  # a curve, but not a monotone one: say so, loudly
            set_if_changed(obj, "Status", WARNING + warning)
            FreeCAD.Console.PrintWarning(f"{obj.Label}: {warning}\n")


def show_what_applies(obj):
    """Directions and curvatures are used at vertex ends only (an edge gives its own tangent
    and curvature), curvatures only for G2: the others are hidden in the property editor."""
    for side in ("Start", "End"):
        try:
            vertex = _element(getattr(obj, side), side).ShapeType == "Vertex"
        except InputError:
            vertex = True  # not set yet, or unusable: show everything
        obj.setEditorMode(side + "Direction", 0 if vertex else 2)
        obj.setEditorMode(side + "Curvature", 0 if vertex and obj.Continuity == "G2" else 2)


def make_fair_blend(
    doc, start, end, start_end="auto", end_end="auto", start_direction=None, end_direction=None,
    continuity="G2", method="fair", start_curvature=0.0, end_curvature=0.0, name="FairBlend",
    _proxy=FairBlend, _label="Fair blend",
):
    """Create a Fair blend in `doc` and recompute, as one undoable step.

    start, end: ``(obj, "Edge2")``, ``(obj, "Vertex1")`` or a whole object with one edge or one
    vertex. start_end, end_end: "auto", "first" or "last" (for edges). start_direction,
    end_direction: tangents at vertex ends (FreeCAD.Vector or 3 numbers); start_curvature,
    end_curvature: their curvatures for G2. continuity: "G2" or "G1"; method: "fair", "paper"
    or "grid". Returns the new object; if no blend exists it is created with the reason in its
    Status.
    """
    for value, allowed, what in (
        (start_end, ENDS, "start_end"), (end_end, ENDS, "end_end"), (method, METHODS, "method"),
        (continuity, CONTINUITIES, "continuity"),
    ):
        if value not in allowed:
            raise InputError(f"unknown {what} {value!r}: use one of {', '.join(allowed)}")
    links = [_link(item, what) for item, what in ((start, "start"), (end, "end"))]
    with undo_step(doc, f"Create {_label.lower()}"):
        obj = doc.addObject("Part::FeaturePython", name)
        _proxy(obj)
        obj.Start, obj.End = links
        obj.StartEnd, obj.EndEnd, obj.Method, obj.Continuity = start_end, end_end, method, continuity
        obj.StartCurvature, obj.EndCurvature = float(start_curvature), float(end_curvature)
        if start_direction is not None:
            obj.StartDirection = FreeCAD.Vector(*as_vector(start_direction, "start_direction"))
        if end_direction is not None:
            obj.EndDirection = FreeCAD.Vector(*as_vector(end_direction, "end_direction"))
        attach_view_provider(obj, "ViewProviderFairBlend")
        doc.recompute()
    return obj


def _link(item, what):
    """An App::PropertyLinkSub value from (obj, "Edge1") or a whole object."""
    obj, sub = item if isinstance(item, (tuple, list)) else (item, "")
    if not isinstance(obj, FreeCAD.DocumentObject):
        raise InputError(f"the {what} is not a document object: {obj!r}")
    return (obj, [sub]) if sub else obj


def end_conditions(obj):
    """(p0, t0, p1, t1) of a Fair blend from its properties (FreeCAD.Vectors)."""
    return blend_ends(obj)[:4]


def blend_ends(obj):
    """(p0, t0, p1, t1, k0, k1, normal) of a Fair blend from its properties: points and
    tangents as FreeCAD.Vectors, curvatures signed about the plane normal (+Z in the XY plane,
    else the normal of the plane of the chord and the tangents; None where everything lies
    on one line, for the kernel to choose)."""
    p0, t0, p1, t1, ends = _blend_sides(obj)
    normal = _blend_normal(p0, t0, p1, t1)
    k0 = _curvature(ends[0], normal) if ends[0] else obj.StartCurvature
    k1 = _curvature(ends[1], normal) if ends[1] else obj.EndCurvature
    return p0, t0, p1, t1, k0, k1, normal


def space_ends(obj, g2):
    """(p0, t0, p1, t1[, K0, K1]) for fair_blend_space_solution where the ends do not lie in
    one plane (the chord and tangents, and for G2 the edges' curvature vectors, within 1e-9);
    None where they do (the planar blend, as before). A vertex end has no curvature vector:
    G2 in space needs edges at both ends."""
    p0, t0, p1, t1, ends = _blend_sides(obj)
    normal = _blend_normal(p0, t0, p1, t1)
    vectors = [np.array(p1 - p0), np.array(t0), np.array(t1)]
    if g2:
        vectors += [curvature_vector(e) for e in ends if e is not None]
    if normal is not None:
        n = np.array(normal)
        if all(abs(float(np.dot(v, n))) <= 1e-9 * max(np.linalg.norm(v), 1e-300) for v in vectors):
            return None
    elif not g2 or all(e is not None and np.linalg.norm(curvature_vector(e)) == 0.0 for e in ends):
        return None  # all on one line
    points = (np.array(p0), np.array(t0), np.array(p1), np.array(t1))
    if not g2:
        return points
    if ends[0] is None or ends[1] is None:
        raise InputError("these ends do not lie in one plane: a G2 blend in space needs edges at both ends "
                         "(a vertex end gives no curvature vector); use G1, or pick edges")
    return points + (curvature_vector(ends[0]), curvature_vector(ends[1]))


def _blend_sides(obj):
    """(p0, t0, p1, t1, [EdgeEnd or None, EdgeEnd or None]) of a Fair blend's properties."""
    start = _element(obj.Start, "Start")
    end = _element(obj.End, "End")
    # Where each side is, for "auto": a vertex is a point, an edge the nearer of its ends.
    start_points = _candidates(start, obj.StartEnd)
    end_points = _candidates(end, obj.EndEnd)
    (p0, which0), (p1, which1) = min(
        ((a, b) for a in start_points for b in end_points), key=lambda pair: (pair[0][0] - pair[1][0]).Length
    )
    t0 = end_tangent(start, which0, outwards=True) if which0 else obj.StartDirection
    t1 = end_tangent(end, which1, outwards=False) if which1 else obj.EndDirection
    ends = [edge_end(start, _END_NAME[which0], True, "Start") if which0 else None,
            edge_end(end, _END_NAME[which1], False, "End") if which1 else None]
    return p0, t0, p1, t1, ends


_END_NAME = {"first": "start", "last": "end"}


def _blend_normal(p0, t0, p1, t1):
    """+Z when the ends lie in a plane parallel to XY; else the normal of the plane of the
    chord and the tangents (or None: the kernel then picks the plane, G1 only)."""
    vectors = [np.array(p1 - p0), np.array(t0), np.array(t1)]
    scale = max(np.linalg.norm(v) for v in vectors)
    if all(abs(v[2]) <= 1e-12 * scale for v in vectors):
        return (0.0, 0.0, 1.0)
    u = vectors[0] / np.linalg.norm(vectors[0])
    n = max((np.cross(u, v / np.linalg.norm(v)) for v in vectors[1:]), key=np.linalg.norm)
    return tuple(n / np.linalg.norm(n)) if np.linalg.norm(n) > 1e-12 else None


def _curvature(end, normal):
    if normal is None:
        return 0.0  # straight ends along one line: the edges' curvature has no sign here
    return float(np.dot(np.cross(end.d1, end.d2), normal) / np.linalg.norm(end.d1) ** 3)


def _element(link, name):
    """The edge or vertex a LinkSub names."""
    if link is None or link[0] is None:
        raise InputError(f"{name} is not set: select an edge or a vertex")
    obj, subs = link
    try:
        return element_shape(obj, subs[0] if subs else "")
    except InputError as exc:
        raise InputError(f"{name}: {exc}") from None


def element_shape(obj, sub=""):
    """The edge or vertex `sub` of obj, or obj's single edge or vertex when sub is ''.
    Raises InputError otherwise."""
    origin = f"{obj.Label}.{sub}" if sub else obj.Label
    try:
        shape = Part.getShape(obj, sub, needSubElement=True) if sub else Part.getShape(obj)
    except Exception:
        shape = Part.Shape()
    if shape.isNull():
        raise InputError(f"{origin} not found")
    if shape.ShapeType in ("Edge", "Vertex"):
        return shape
    if len(shape.Edges) == 1:
        return shape.Edges[0]
    if not shape.Edges and len(shape.Vertexes) == 1:
        return shape.Vertexes[0]
    raise InputError(f"{origin} is not one edge or one vertex: select an edge or a vertex of it")


def _candidates(shape, choice):
    """[(point, "first"/"last"/None)] the side may use."""
    if shape.ShapeType == "Vertex":
        return [(shape.Point, None)]
    ends = {"first": shape.valueAt(shape.FirstParameter), "last": shape.valueAt(shape.LastParameter)}
    names = ("first", "last") if choice == "auto" else (choice,)
    return [(ends[n], n) for n in names]


def end_tangent(edge, which, outwards):
    """The edge's tangent at its `which` ("first" or "last") end, pointing out of the edge
    (outwards: a blend leaving it) or into it (a blend arriving)."""
    u = edge.FirstParameter if which == "first" else edge.LastParameter
    t = edge.derivative1At(u)
    leaving = which == "last"  # along the parameter, the last end is where the edge is left
    return t if leaving == outwards else -t
