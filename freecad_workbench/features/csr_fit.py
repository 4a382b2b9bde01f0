"""The csr fit: a parametric csr-spline (Section 4, eq. (6)) through points taken from
other objects. Headless; a view provider is attached only when FreeCAD.GuiUp.

    from freecad_workbench.features.csr_fit import make_csr_fit
    fit = make_csr_fit(doc, [(polyline, "Vertex1"), (polyline, "Vertex2"), point_cloud])

Where the points come from, in the order of the `Sources` entries:
- a vertex (``(obj, "Vertex3")``): its position;
- an edge (``(obj, "Edge2")``): `Samples` points equally spaced in arc length
  (``edge.discretize(Number=Samples)``). Where an edge touches the previous points it
  is turned to continue them and the shared point is taken once;
- a whole Points object: its points (``obj.Points.Points``), in their stored order;
- a whole sketch: its point geometries (``Part.Point``, construction or not), in
  geometry order, placed by the sketch's Placement. Select a sketch's vertices or edges
  to use anything else;
- any other whole object: its vertices if the shape has no edges, else its one wire
  (or edge), sampled like an edge.
For a closed fit, a last point equal to the first is left out.

If the data is bad (too few points, coincident points, NaN, a missing source) the
feature keeps its last good shape, puts the message in `Status`, prints it to the
report view, and lets the rest of the document recompute.
"""
import re

import FreeCAD
import Part

from .. import preferences
from ..csr import PARAMETRIZATIONS, csr_spline
from ..errors import InputError
from .base import FeatureProxy, attach_view_provider, set_if_changed
from .undo import undo_step

# Points closer than this are one point when edges are joined (OCCT's Precision::Confusion).
JOIN_TOLERANCE = 1e-7

# (type, name, tooltip, default, editor mode); defaults are set only when a property is new.
_PROPERTIES = (
    ("App::PropertyLinkSubList", "Sources", "Vertices, edges, Points objects or sketches, in order", None, 0),
    ("App::PropertyEnumeration", "Parametrization", "Parameters of the data points", "chordal", 0),
    ("App::PropertyBool", "Closed", "Fit a closed (periodic) curve", False, 0),
    ("App::PropertyString", "CurvatureTolerance",
     "How closely the curve keeps circles and lines of the data, relative to its size (for example 1e-9): "
     "the csr-spline's epsilon of eq. (6). Shown as text, which keeps small values readable", None, 0),
    ("App::PropertyFloat", "Epsilon", "The curvature tolerance as a number (for macros; CurvatureTolerance "
     "shows it)", 1e-9, 2),
    ("App::PropertyInteger", "Samples", "Points taken from each source edge", 50, 0),
    ("App::PropertyString", "Status", "'ok', or why the last recompute failed", "ok", 1),
    ("App::PropertyInteger", "Version", "Version of this object's properties", 0, 2),
)


class CsrFit(FeatureProxy):
    """Proxy of a Part::FeaturePython holding a csr-spline fitted to its Sources."""

    Type = "CsrFit"
    VERSION = 2  # 2: CurvatureTolerance shows Epsilon (the property editor showed 1e-9 as 0.00)
    GROUP = "Csr fit"
    PROPERTIES = _PROPERTIES
    ENUMERATIONS = {"Parametrization": PARAMETRIZATIONS}

    def onChanged(self, obj, prop):
        """Epsilon and CurvatureTolerance are one value: the number and its text."""
        if "Restore" in obj.State or not {"Epsilon", "CurvatureTolerance"} <= set(obj.PropertiesList):
            return
        if prop == "Epsilon":
            set_if_changed(obj, "CurvatureTolerance", f"{obj.Epsilon:g}")
        elif prop == "CurvatureTolerance":
            try:
                value = float(obj.CurvatureTolerance)
            except ValueError:
                return  # build says so
            if value != obj.Epsilon:
                obj.Epsilon = value

    def migrate(self, obj):
        if obj.Version < 2:
            obj.CurvatureTolerance = f"{obj.Epsilon:g}"
        super().migrate(obj)

    def build(self, obj):
        origins = []
        obj.setEditorMode("Samples", 0 if uses_edges(obj.Sources) else 2)
        try:
            float(obj.CurvatureTolerance)
        except ValueError:
            raise InputError(f"CurvatureTolerance is not a number: {obj.CurvatureTolerance!r}") from None
        try:
            points, origins = collect_points(obj.Sources, obj.Samples, obj.Closed)
            curve = csr_spline(points, closed=obj.Closed, parametrization=obj.Parametrization, epsilon=obj.Epsilon)
        except Exception as exc:
            raise InputError(_describe(exc, origins)) from exc
        return curve.toShape()


def make_csr_fit(doc, sources, parametrization="chordal", closed=False, epsilon=None, samples=50, name="CsrFit"):
    """Create a csr fit in `doc` and recompute, as one undoable step.

    sources: a list whose items are a document object (taken whole), ``(obj, "Vertex1")``
    or ``(obj, ["Edge1", "Edge2"])``. Returns the new object; if the data is bad it exists
    with the message in its Status (see the module docstring). epsilon None takes the
    CsrEpsilon preference (freecad_workbench/preferences.py).
    """
    links = normalize_sources(sources)
    if parametrization not in PARAMETRIZATIONS:
        raise InputError(f"unknown parametrization {parametrization!r}: use one of {', '.join(PARAMETRIZATIONS)}")
    with undo_step(doc, "Create csr fit"):
        obj = doc.addObject("Part::FeaturePython", name)
        CsrFit(obj)
        obj.Sources = links
        obj.Parametrization = parametrization
        obj.Closed = bool(closed)
        obj.Epsilon = float(preferences.get("CsrEpsilon") if epsilon is None else epsilon)
        obj.Samples = int(samples)
        attach_view_provider(obj, "ViewProviderCsrFit")
        doc.recompute()
    return obj


def normalize_sources(sources):
    """Sources as [(obj, subname)] for App::PropertyLinkSubList, in the given order."""
    links = []
    for item in sources:
        if isinstance(item, (tuple, list)):
            if len(item) != 2:
                raise InputError(f"a source is an object or (object, subnames), got {item!r}")
            obj, subs = item
            subs = [subs] if isinstance(subs, str) else list(subs) or [""]
        else:
            obj, subs = item, [""]
        if not isinstance(obj, FreeCAD.DocumentObject):
            raise InputError(f"not a document object: {obj!r}")
        links.extend((obj, sub) for sub in subs)
    return links


def collect_points(sources, samples=50, closed=False):
    """Points from PropertyLinkSubList-style sources -> ([FreeCAD.Vector], [origin label]),
    one origin label per point, following the rules of the module docstring."""
    if samples < 2:
        raise InputError(f"Samples must be at least 2, got {samples}")
    runs = []  # (points, origin, is_edge)
    for obj, subs in sources:
        if obj is None:
            raise InputError("a source object was deleted")
        for sub in subs or ("",):
            if sub:
                runs.append(_element_points(obj, sub, samples))
            else:
                runs.append(_object_points(obj, samples))
    points, origins = _join(runs)
    if closed and len(points) > 2 and points[-1].isEqual(points[0], JOIN_TOLERANCE):
        points.pop()
        origins.pop()
    return points, origins


def uses_edges(sources):
    """Whether any of the sources is sampled as an edge (then Samples applies)."""
    for obj, subs in sources:
        if obj is None:
            continue
        for sub in subs or ("",):
            element = sub.rsplit(".", 1)[-1]
            if element:
                if element.startswith("Edge"):
                    return True
            elif not obj.isDerivedFrom("Points::Feature") and not obj.isDerivedFrom("Sketcher::SketchObject"):
                shape = getattr(obj, "Shape", None)
                if isinstance(shape, Part.Shape) and not shape.isNull() and shape.Edges:
                    return True
    return False


def usable_source(obj, sub=""):
    """Whether (obj, sub) can give points by the rules above (a quick check for the GUI;
    it reads no point data)."""
    element = sub.rsplit(".", 1)[-1]
    if element:
        return element.startswith(("Vertex", "Edge"))
    if obj.isDerivedFrom("Points::Feature"):
        return True
    if obj.isDerivedFrom("Sketcher::SketchObject"):
        return any(isinstance(g, Part.Point) for g in obj.Geometry)
    shape = getattr(obj, "Shape", None)
    if not isinstance(shape, Part.Shape) or shape.isNull():
        return False
    if not shape.Edges:
        return bool(shape.Vertexes)
    wires = shape.Wires
    return len(shape.Edges) == 1 or (len(wires) == 1 and len(wires[0].Edges) == len(shape.Edges))


def _element_points(obj, sub, samples):
    origin = f"{obj.Label}.{sub}"
    try:
        shape = Part.getShape(obj, sub, needSubElement=True)
    except Exception:
        shape = Part.Shape()
    if shape.isNull():
        raise InputError(f"{origin} not found")
    if shape.ShapeType == "Vertex":
        return [shape.Point], origin, False
    if shape.ShapeType == "Edge":
        return shape.discretize(Number=samples), origin, True
    raise InputError(f"{origin}: select vertices or edges, not a {shape.ShapeType.lower()}")


def _object_points(obj, samples):
    origin = obj.Label
    if obj.isDerivedFrom("Points::Feature"):
        return list(obj.Points.Points), origin, False
    if obj.isDerivedFrom("Sketcher::SketchObject"):
        placement = obj.Placement
        points = [placement.multVec(FreeCAD.Vector(g.X, g.Y, g.Z)) for g in obj.Geometry if isinstance(g, Part.Point)]
        if not points:
            raise InputError(f"{origin} has no points: add points, or select its vertices or edges")
        return points, origin, False
    shape = Part.getShape(obj)
    if shape.isNull():
        raise InputError(f"{origin} has no shape")
    if not shape.Edges:
        return [v.Point for v in shape.Vertexes], origin, False
    if len(shape.Edges) == 1:
        return shape.Edges[0].discretize(Number=samples), origin, True
    wires = shape.Wires
    if len(wires) == 1 and len(wires[0].Edges) == len(shape.Edges):
        return wires[0].discretize(Number=samples), origin, True
    raise InputError(f"{origin} has several wires: select its vertices or edges")


def _join(runs):
    """Concatenate point runs. An edge run is turned to start where the points so far end
    (or, for the first two runs, the first is turned to meet the second) and the shared
    point is taken once."""
    points, origins = [], []
    first_is_edge = False
    for index, (run, origin, is_edge) in enumerate(runs):
        run = list(run)
        if points and is_edge and len(run) > 1:
            last = points[-1]
            if index == 1 and first_is_edge and not _touches(run, last) and _touches(run, points[0]):
                points.reverse()
                origins.reverse()
                last = points[-1]
            if run[-1].isEqual(last, JOIN_TOLERANCE) and not run[0].isEqual(last, JOIN_TOLERANCE):
                run.reverse()
            if run[0].isEqual(last, JOIN_TOLERANCE):
                run = run[1:]
        if index == 0:
            first_is_edge = is_edge
        points.extend(run)
        origins.extend([origin] * len(run))
    return points, origins


def _touches(run, point):
    return run[0].isEqual(point, JOIN_TOLERANCE) or run[-1].isEqual(point, JOIN_TOLERANCE)


_POINT_INDEX = re.compile(r"\bpoints? (\d+)(?: and (\d+))?")


def _describe(exc, origins):
    """The exception's message; where it names point indices, add the sources they came from."""
    message = str(exc).strip() or type(exc).__name__
    match = _POINT_INDEX.search(message)
    if match and origins:
        indices = [int(g) for g in match.groups() if g is not None]
        if all(i < len(origins) for i in indices):
            names = list(dict.fromkeys(origins[i] for i in indices))
            message += f" (from {' and '.join(names)})"
    return message
