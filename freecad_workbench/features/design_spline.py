"""The Design spline: a parametric design with basic curves (csr paper, Sections 5, 6 and
Fig. 9). Pieces of basic curves, each with marked points, become one cubic C2 NURBS that
keeps the pieces exact between the marks and rounds off the transitions
(`fw.design_spline`). Headless; a view provider is attached only when FreeCAD.GuiUp.

    from freecad_workbench.features.design_spline import make_design_spline
    spline = make_design_spline(doc, [((sketch, "Edge1"), [0.2, 0.5, 0.8]), (arc_object, [0.3, 0.7])])

Pieces (`Pieces`, in order) are links to
- an edge of any object (``(sketch, "Edge3")``, ``(part_feature, "Edge1")``): lines,
  circles, ellipses, parabolas, hyperbolas and their arcs, over the edge's range, where
  the edge is in the document (placements of the object and its containers applied);
- a BasicCurve object (whole, or its ``"Edge1"``): its exact basic curve, spirals and
  involutes included;
- any other whole object with exactly one such edge;
- sampled data (the unifying spline, csr paper Fig. 1): a whole Points object, a whole
  sketch whose geometry is points only, or any other whole object with vertices and no
  edges. Its points, in their stored order, become a `fw.basic.Samples` piece: its part of
  the curve is their csr-spline (Section 4). A sampled piece has no marks (its samples are
  its knots); its MarkCounts entry is 0.

Marks are parameters in [0, 1] of each piece, strictly increasing, in the piece's
direction of travel in the design. They are stored flat in `Marks`, `MarkCounts` giving
how many belong to each piece (a plain float list: saved in binary, so a reopened file
recomputes to identical poles). `Reversed` runs a piece from its end to its start;
`make_design_spline` sets it so that consecutive pieces meet end to start. Pieces that
MarkCounts or Reversed do not cover have no marks and are not reversed.

Outputs (read-only): `Joins` (per pair of consecutive pieces: agree, averaged or edge),
`MarksAdded` (per piece, marks the kernel added to keep the weights of a wide arc
positive), `Status`. On bad input (marks outside [0, 1] or not increasing, an edge that
is not a basic curve, a deleted source) the feature keeps its last good shape, puts the
message in `Status` (naming the piece and its source), prints it to the report view and
lets the rest of the document recompute.
"""
import re

import numpy as np

import FreeCAD
import Part

from .. import basic, preferences
from ..design import design_spline, piece_marks
from ..errors import InputError
from .basic_curve import is_basic_curve
from .csr_fit import _object_points
from .base import FeatureProxy, attach_view_provider, set_if_changed
from .undo import undo_step

# Marks a new piece gets when none are given: with m = 5 intervals a conic stays exact on
# [u_2, u_3] even between two other pieces, and there are enough sliders to shape the ends.
DEFAULT_MARKS = (0.2, 0.4, 0.6, 0.8)
DEFAULT_JOIN_TOLERANCE = 1e-6

_PROPERTIES = (
    ("App::PropertyLinkSubList", "Pieces",
     "Basic curves in order: edges (lines, arcs, conics) of sketches or Part objects, or BasicCurve objects; "
     "Points objects or sketches of points as sampled pieces",
     None, 0),
    ("App::PropertyFloatList", "Marks",
     "Mark parameters in [0, 1], piece after piece (MarkCounts says how many belong to each)", None, 0),
    ("App::PropertyIntegerList", "MarkCounts", "Number of marks on each piece", None, 0),
    ("App::PropertyBoolList", "Reversed", "Per piece: run it from its end to its start", None, 0),
    ("App::PropertyLength", "JoinTolerance",
     "End points of consecutive pieces closer than this are averaged into one; farther apart they are joined "
     "by an edge", DEFAULT_JOIN_TOLERANCE, 0),
    ("App::PropertyStringList", "Joins",
     "How consecutive pieces were joined: agree (same end point), averaged, or edge", None, 1),
    ("App::PropertyIntegerList", "MarksAdded", "Marks added on each piece to keep its weights positive", None, 1),
    ("App::PropertyString", "Status", "'ok', or why the last recompute failed", "ok", 1),
    ("App::PropertyInteger", "Version", "Version of this object's properties", 0, 2),
)


class DesignSpline(FeatureProxy):
    """Proxy of a Part::FeaturePython holding fw.design_spline of its pieces and marks."""

    Type = "DesignSpline"
    VERSION = 1
    GROUP = "Design spline"
    PROPERTIES = _PROPERTIES
    OUTPUTS = ("Joins", "MarksAdded", "Status")
    VERDICTS = ("Joins", "MarksAdded")

    def build(self, obj):
        labels = [piece_label(source, sub) for source, sub in piece_links(obj)]
        try:
            pieces, _ = design_inputs(obj)
            result = design_spline(pieces, join_tolerance=float(obj.JoinTolerance), details=True)
        except Exception as exc:
            raise InputError(_describe(exc, labels)) from exc
        set_if_changed(obj, "Joins", [str(j) for j in result.joins])
        set_if_changed(obj, "MarksAdded", [int(a) for a in result.marks_added])
        return result.curve.toShape()


def is_design_spline(obj):
    return isinstance(getattr(obj, "Proxy", None), DesignSpline)


# --- pieces ------------------------------------------------------------------------


def piece_links(obj):
    """The pieces of a Design spline as a flat [(object, subname)] in order (FreeCAD
    groups consecutive subnames of one object in one entry)."""
    links = []
    for source, subs in obj.Pieces:
        for sub in subs or ("",):
            links.append((source, sub))
    return links


def piece_label(source, sub):
    if source is None:
        return "a deleted object"
    return f"{source.Label}.{sub}" if sub else source.Label


def resolve_piece(source, sub=""):
    """The fw.basic curve of a piece link, in document coordinates."""
    label = piece_label(source, sub)
    if source is None:
        raise InputError("a piece's object was deleted")
    element = sub.rsplit(".", 1)[-1] if sub else ""
    if is_basic_curve(source) and element in ("", "Edge1"):
        return source.Proxy.basic_curve(source)
    if not element and is_samples_source(source):
        points, _, _ = _object_points(source, 2)
        try:
            return basic.Samples(points)
        except InputError as exc:
            raise InputError(f"{label}: {exc}") from None
    if element:
        try:
            shape = Part.getShape(source, sub, needSubElement=True)
        except Exception:
            shape = Part.Shape()
        if shape.isNull():
            raise InputError(f"{label} not found")
        if shape.ShapeType != "Edge":
            raise InputError(f"{label} is a {shape.ShapeType.lower()}: pick an edge")
        edge = shape
    else:
        shape = Part.getShape(source)
        if shape.isNull():
            raise InputError(f"{label} has no shape")
        if len(shape.Edges) != 1:
            raise InputError(f"{label} has {len(shape.Edges)} edges: pick one of them ({label}.EdgeN)")
        edge = shape.Edges[0]
    return basic.from_edge(edge)


def is_samples_source(source):
    """Whether a whole object gives a sampled piece: a Points object, a sketch of points
    only, or a shape with vertices and no edges."""
    if source.isDerivedFrom("Points::Feature"):
        return True
    if source.isDerivedFrom("Sketcher::SketchObject"):
        geometry = list(source.Geometry)
        return bool(geometry) and all(isinstance(g, Part.Point) for g in geometry)
    shape = getattr(source, "Shape", None)
    return isinstance(shape, Part.Shape) and not shape.isNull() and not shape.Edges and bool(shape.Vertexes)


def curve_ends(curve):
    """The start and end point of a piece (a basic curve or samples) as arrays."""
    if isinstance(curve, basic.Samples):
        return curve.points[0], curve.points[-1]
    return np.asarray(curve.value(0)), np.asarray(curve.value(1))


def reversed_curve(curve):
    """The basic curve run backwards: u -> 1 - u (exact for lines, conics and rational
    cubics; spirals, involutes and user curves keep their Section 5 route); samples in
    the opposite order."""
    if isinstance(curve, basic.Samples):
        return basic.Samples(curve.points[::-1], curve.parametrization, curve.epsilon, curve.epsilon_rule)
    n = np.cross(getattr(curve, "x_axis", np.zeros(3)), getattr(curve, "y_axis", np.zeros(3)))
    if isinstance(curve, basic.LineSegment):
        return basic.LineSegment(curve.end, curve.start)
    if isinstance(curve, basic.CircleArc):
        return basic.CircleArc(curve.center, curve.radius, curve.end_angle, curve.start_angle, n, curve.x_axis)
    if isinstance(curve, basic.EllipseArc):
        return basic.EllipseArc(curve.center, curve.a, curve.b, curve.end, curve.start, n, curve.x_axis)
    # Parabola and hyperbola: t -> -t with the y axis flipped (the normal turned over).
    if isinstance(curve, basic.ParabolaArc):
        return basic.ParabolaArc(curve.vertex, curve.focal, -curve.t1, -curve.t0, -n, curve.x_axis)
    if isinstance(curve, basic.HyperbolaArc):
        return basic.HyperbolaArc(curve.center, curve.a, curve.b, -curve.t1, -curve.t0, -n, curve.x_axis)
    if isinstance(curve, basic.RationalCubic):
        return basic.RationalCubic(homogeneous=curve.homogeneous[::-1].copy())
    kernel = curve._curve
    return basic.ParametricCurve(
        lambda s: kernel.value(1.0 - s), 0.0, 1.0,
        derivative=lambda s: -np.asarray(kernel.d1(1.0 - s)),
        second_derivative=lambda s: kernel.d2(1.0 - s),
    )


def auto_reversed(curves):
    """Per curve, whether to reverse it so that each starts where the previous ends: the
    first is turned to face the second, each next one to start at the nearer end."""
    if len(curves) < 2:
        return [False] * len(curves)
    ends = [curve_ends(c) for c in curves]

    def gap(p, *others):
        return min(float(np.linalg.norm(p - q)) for q in others)

    flags = [gap(ends[0][0], *ends[1]) < gap(ends[0][1], *ends[1])]
    last = ends[0][0] if flags[0] else ends[0][1]
    for start, end in ends[1:]:
        flip = gap(end, last) < gap(start, last)
        flags.append(flip)
        last = start if flip else end
    return flags


def get_marks(obj):
    """Per piece, its list of marks (pieces beyond MarkCounts have none)."""
    counts = list(obj.MarkCounts)
    marks = list(obj.Marks)
    if any(c < 0 for c in counts) or sum(counts) != len(marks):
        raise InputError(f"MarkCounts {counts} do not add up to the {len(marks)} Marks")
    result, i = [], 0
    for count in counts:
        result.append(marks[i:i + count])
        i += count
    n = len(piece_links(obj))
    return (result + [[] for _ in range(n - len(result))])[:max(n, len(result))]


def set_marks(obj, marks_per_piece):
    """Store per-piece marks (lists of parameters) in Marks and MarkCounts."""
    flat = [float(u) for marks in marks_per_piece for u in marks]
    counts = [len(marks) for marks in marks_per_piece]
    if list(obj.Marks) != flat:
        obj.Marks = flat
    if list(obj.MarkCounts) != counts:
        obj.MarkCounts = counts


def piece_curves(obj):
    """Per piece: (label, basic curve in the design's direction, or None, error or None)."""
    links = piece_links(obj)
    flags = list(obj.Reversed) + [False] * len(links)
    result = []
    for index, (source, sub) in enumerate(links):
        label = piece_label(source, sub)
        try:
            curve = resolve_piece(source, sub)
            result.append((label, reversed_curve(curve) if flags[index] else curve, None))
        except Exception as exc:
            result.append((label, None, str(exc)))
    return result


def design_inputs(obj):
    """The (basic curve, marks) pieces for fw.design_spline, and a label per piece."""
    links = piece_links(obj)
    labels = [piece_label(source, sub) for source, sub in links]
    if not links:
        raise InputError("a design needs at least one piece")
    marks = get_marks(obj)
    if len(marks) > len(links):
        raise InputError(f"MarkCounts has {len(obj.MarkCounts)} entries for {len(links)} pieces")
    flags = list(obj.Reversed) + [False] * len(links)
    pieces = []
    for index, (source, sub) in enumerate(links):
        try:
            curve = resolve_piece(source, sub)
        except InputError as exc:
            raise InputError(f"piece {index}: {exc}") from None
        if flags[index]:
            curve = reversed_curve(curve)
        if isinstance(curve, basic.Samples) and not marks[index]:
            pieces.append(curve)
        else:
            pieces.append((curve, marks[index]))
    return pieces, labels


def normalize_pieces(pieces):
    """[(link, marks)] with link an object or (object, "EdgeN") -> [(object, sub)], [marks]."""
    links, marks = [], []
    for index, item in enumerate(pieces):
        try:
            link, piece_marks_ = item
        except (TypeError, ValueError):
            raise InputError(f"piece {index} must be a pair (link, marks)") from None
        if isinstance(link, (tuple, list)):
            if len(link) != 2 or not isinstance(link[1], str):
                raise InputError(f"piece {index}: a link is an object or (object, 'EdgeN'), got {link!r}")
            source, sub = link
        else:
            source, sub = link, ""
        if not isinstance(source, FreeCAD.DocumentObject):
            raise InputError(f"piece {index}: not a document object: {source!r}")
        links.append((source, sub))
        marks.append(None if piece_marks_ is None else list(piece_marks_))
    return links, marks


def make_design_spline(doc, pieces, join_tolerance=None, name="DesignSpline", reversed=None):
    """Create a Design spline in `doc` and recompute, as one undoable step.

    pieces: [(link, marks)], link an object (a BasicCurve, or an object with one edge) or
        (object, "EdgeN"); marks a list of parameters in [0, 1] or points on the curve,
        in the piece's direction in the design; None gives DEFAULT_MARKS.
    reversed: per piece whether to run it backwards; None chooses so that consecutive
        pieces meet end to start (auto_reversed).
    join_tolerance: None takes the JoinTolerance preference (freecad_workbench/preferences.py).
    Returns the new object; bad marks or pieces leave it with the message in its Status.
    Raises InputError only for input that cannot be stored (not document objects).
    """
    links, marks = normalize_pieces(pieces)
    if not links:
        raise InputError("a design needs at least one piece")
    curves = []
    for source, sub in links:
        try:
            curves.append(resolve_piece(source, sub))
        except InputError:
            curves.append(None)
    if reversed is None:
        usable = all(c is not None for c in curves)
        reversed = auto_reversed(curves) if usable else [False] * len(links)
    reversed = [bool(r) for r in reversed]
    if len(reversed) != len(links):
        raise InputError(f"reversed has {len(reversed)} entries for {len(links)} pieces")
    parameters = []
    for index, piece in enumerate(marks):
        if piece is None:
            parameters.append([] if isinstance(curves[index], basic.Samples) else list(DEFAULT_MARKS))
        elif all(isinstance(m, (int, float)) for m in piece):
            parameters.append([float(m) for m in piece])
        else:
            if curves[index] is None:
                raise InputError(f"piece {index}: marks given as points need a usable curve")
            curve = reversed_curve(curves[index]) if reversed[index] else curves[index]
            try:
                parameters.append([float(u) for u in piece_marks(curve, piece)])
            except InputError as exc:
                raise InputError(f"piece {index}: {exc}") from None
    with undo_step(doc, "Create design spline"):
        obj = doc.addObject("Part::FeaturePython", name)
        DesignSpline(obj)
        obj.Pieces = links
        set_marks(obj, parameters)
        obj.Reversed = reversed
        obj.JoinTolerance = float(preferences.get("JoinTolerance") if join_tolerance is None else join_tolerance)
        attach_view_provider(obj, "ViewProviderDesignSpline")
        doc.recompute()
    return obj


_PIECE_INDEX = re.compile(r"\bpiece (\d+)")
_MARK_INDEX = re.compile(r"\bmark (\d+)")


def _describe(exc, labels):
    """The exception's message for the Status a designer reads: pieces numbered from 1 (the
    kernel counts from 0), and where it names a piece, which source that is."""
    message = str(exc).strip() or type(exc).__name__
    match = _PIECE_INDEX.search(message)
    message = _PIECE_INDEX.sub(lambda m: f"piece {int(m.group(1)) + 1}", message)
    message = _MARK_INDEX.sub(lambda m: f"mark {int(m.group(1)) + 1}", message)
    if match and labels:
        index = int(match.group(1))
        if index < len(labels) and labels[index] not in message:
            message += f" (piece {index + 1} is {labels[index]})"
    return message
