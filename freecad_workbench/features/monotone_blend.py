"""The Monotone blend: a parametric cubic B-spline with monotone curvature (Algorithm 2 of
Wang et al.) that bridges two edges' end points with their tangents, or two vertices with
given directions. Headless; a view provider is attached only when FreeCAD.GuiUp.

    from freecad_workbench.features.monotone_blend import make_monotone_blend
    blend = make_monotone_blend(doc, (line, "Edge1"), (arc, "Edge1"))          # two edges
    blend = make_monotone_blend(doc, (box, "Vertex1"), (box, "Vertex7"),
                                start_direction=(1, 0, 0), end_direction=(0, 1, 0))

The ends, `Start` and `End`, are each an edge or a vertex (an element, or a whole object with
one edge or one vertex):
- an edge: the blend starts (ends) at one of its end points, chosen by `StartEnd` (`EndEnd`):
  "first", "last", or "auto", the end nearest to the other side. It leaves the start edge
  continuing it (tangent outwards) and runs on into the end edge (tangent inwards), so the
  joints are G1;
- a vertex: the blend starts (ends) there with the direction `StartDirection` (`EndDirection`).
It follows its sources when they change. If no curve of the family meets the end conditions
(fw.NoMonotoneSolution) or a source is unusable, it keeps its last good shape, puts the reason
in `Status`, prints it to the report view, and lets the rest of the document recompute.
"""
import FreeCAD
import Part

from ..errors import InputError
from ..kernel import as_vector
from ..monotone import METHODS, check_monotone_curvature, monotone_curvature_solution
from .base import FeatureProxy, set_if_changed
from .undo import undo_step

ENDS = ("auto", "first", "last")

_PROPERTIES = (
    ("App::PropertyLinkSub", "Start", "Edge or vertex where the blend starts", None, 0),
    ("App::PropertyEnumeration", "StartEnd", "Which end of the start edge: auto (nearest), first or last", "auto", 0),
    ("App::PropertyVector", "StartDirection", "Tangent at the start when Start is a vertex", FreeCAD.Vector(1, 0, 0), 0),
    ("App::PropertyLinkSub", "End", "Edge or vertex where the blend ends", None, 0),
    ("App::PropertyEnumeration", "EndEnd", "Which end of the end edge: auto (nearest), first or last", "auto", 0),
    ("App::PropertyVector", "EndDirection", "Tangent at the end when End is a vertex", FreeCAD.Vector(1, 0, 0), 0),
    ("App::PropertyEnumeration", "Method", "fairest: the analytic centre; grid: the paper's first hit", "fairest", 0),
    ("App::PropertyString", "Curvature", "How the curvature runs (the certificate)", "", 1),
    ("App::PropertyString", "Status", "'ok', or why the last recompute failed", "ok", 1),
    ("App::PropertyInteger", "Version", "Version of this object's properties", 0, 2),
)
class MonotoneBlend(FeatureProxy):
    """Proxy of a Part::FeaturePython holding a monotone-curvature blend."""

    Type = "MonotoneBlend"
    VERSION = 1
    GROUP = "Monotone blend"
    PROPERTIES = _PROPERTIES
    ENUMERATIONS = {"StartEnd": ENDS, "EndEnd": ENDS, "Method": METHODS}
    OUTPUTS = ("Status", "Curvature")

    def build(self, obj):
        p0, t0, p1, t1 = end_conditions(obj)
        solution = monotone_curvature_solution(p0, t0, p1, t1, method=obj.Method)
        set_if_changed(obj, "Curvature", check_monotone_curvature(solution.curve).reason)
        return solution.curve.toShape()


def make_monotone_blend(
    doc, start, end, start_end="auto", end_end="auto", start_direction=None, end_direction=None,
    method="fairest", name="MonotoneBlend",
):
    """Create a Monotone blend in `doc` and recompute, as one undoable step.

    start, end: ``(obj, "Edge2")``, ``(obj, "Vertex1")`` or a whole object with one edge or one
    vertex. start_end, end_end: "auto", "first" or "last" (for edges). start_direction,
    end_direction: tangents at vertex ends (FreeCAD.Vector or 3 numbers). Returns the new
    object; if no blend exists it is created with the reason in its Status.
    """
    for value, allowed, what in ((start_end, ENDS, "start_end"), (end_end, ENDS, "end_end"), (method, METHODS, "method")):
        if value not in allowed:
            raise InputError(f"unknown {what} {value!r}: use one of {', '.join(allowed)}")
    links = [_link(item, what) for item, what in ((start, "start"), (end, "end"))]
    with undo_step(doc, "Create monotone blend"):
        obj = doc.addObject("Part::FeaturePython", name)
        MonotoneBlend(obj)
        obj.Start, obj.End = links
        obj.StartEnd, obj.EndEnd, obj.Method = start_end, end_end, method
        if start_direction is not None:
            obj.StartDirection = FreeCAD.Vector(*as_vector(start_direction, "start_direction"))
        if end_direction is not None:
            obj.EndDirection = FreeCAD.Vector(*as_vector(end_direction, "end_direction"))
        if FreeCAD.GuiUp:
            from ..gui.view_providers import ViewProviderMonotoneBlend

            ViewProviderMonotoneBlend(obj.ViewObject)
        doc.recompute()
    return obj


def _link(item, what):
    """An App::PropertyLinkSub value from (obj, "Edge1") or a whole object."""
    obj, sub = item if isinstance(item, (tuple, list)) else (item, "")
    if not isinstance(obj, FreeCAD.DocumentObject):
        raise InputError(f"the {what} is not a document object: {obj!r}")
    return (obj, [sub]) if sub else obj


def end_conditions(obj):
    """(p0, t0, p1, t1) of a Monotone blend from its properties (FreeCAD.Vectors)."""
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
    return p0, t0, p1, t1


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
