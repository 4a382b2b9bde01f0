"""Edit polygon: the designer moves control points of a designed spline (csr paper,
Fig. 10f, Fig. 11e), as a derived, parametric B-spline feature.

    from freecad_workbench.features.edit_polygon import make_edit_polygon, set_pole
    edited = make_edit_polygon(doc, design)      # follows the design
    set_pole(edited, 5, FreeCAD.Vector(3, 4, 0))  # pole 5 (from 0) moved there
    doc.recompute()

Why a derived feature and not a conversion to a Sketcher B-spline: the edited curve stays
linked to its design. It stores only the displacement of each pole (`PoleOffsets`), so
when the marks or the basic curves upstream change, the edits are re-applied to the new
polygon (as long as it has as many poles); knots and weights are never touched, so the
result stays a cubic C2 NURBS, the conic pieces stay exact wherever no pole of theirs was
moved, and moving one pole changes the curve only on the (at most) four spans that pole
supports. It works for curves in any plane and needs no solver. A Sketcher copy would be
a dead end: one-way (a change of the design is lost), planar in the sketch, and in
FreeCAD 0.20 its solver treats weights through control-circle radii and may move other
poles when one is dragged.

The source is any object with one B-spline edge (a Design spline, a csr fit, a Part
B-spline) or an edge of an object. If the source gets a different number of poles, or
breaks, the feature keeps its last good shape and names the problem in `Status`; set
`PoleOffsets` to an empty list to start over.
"""
import math

import FreeCAD
import Part

from ..errors import InputError
from .base import FeatureProxy, attach_view_provider
from .undo import undo_step

_PROPERTIES = (
    ("App::PropertyLinkSub", "Source", "The spline whose control polygon is edited (an object or one of its edges)",
     None, 0),
    ("App::PropertyVectorList", "PoleOffsets",
     "Displacement of each pole from the source's pole (empty: none moved)", None, 0),
    ("App::PropertyVectorList", "Poles", "The edited poles", None, 1),
    ("App::PropertyString", "Status", "'ok', or why the last recompute failed", "ok", 1),
    ("App::PropertyInteger", "Version", "Version of this object's properties", 0, 2),
)


class EditPolygon(FeatureProxy):
    """Proxy of a Part::FeaturePython: the source spline with some poles moved."""

    Type = "EditPolygon"
    VERSION = 1
    GROUP = "Edit polygon"
    PROPERTIES = _PROPERTIES
    OUTPUTS = ("Poles", "Status")

    def build(self, obj):
        curve = edited_curve(obj)
        poles = curve.getPoles()
        if [tuple(p) for p in obj.Poles] != [tuple(p) for p in poles]:
            obj.Poles = poles
        return curve.toShape()


def is_edit_polygon(obj):
    return isinstance(getattr(obj, "Proxy", None), EditPolygon)


def edge_bspline(edge):
    """The Part.BSplineCurve of an edge over its range (a B-spline edge as it is)."""
    geom, first, last = edge.Curve, edge.FirstParameter, edge.LastParameter
    if isinstance(geom, Part.BSplineCurve):
        if abs(first - geom.FirstParameter) <= 1e-12 and abs(last - geom.LastParameter) <= 1e-12:
            return geom.copy()
        curve = geom.copy()
        curve.segment(first, last)
        return curve
    return geom.toBSpline(first, last)


def source_edge(source, sub=""):
    """The edge a source link names: (obj, "EdgeN"), or the one edge of obj."""
    if source is None:
        raise InputError("the source object was deleted")
    label = f"{source.Label}.{sub}" if sub else source.Label
    if sub:
        try:
            shape = Part.getShape(source, sub, needSubElement=True)
        except Exception:
            shape = Part.Shape()
        if shape.isNull() or shape.ShapeType != "Edge":
            raise InputError(f"{label} is not an edge")
        return shape
    shape = Part.getShape(source)
    if shape.isNull():
        raise InputError(f"{label} has no shape (yet)")
    if len(shape.Edges) != 1:
        raise InputError(f"{label} has {len(shape.Edges)} edges: pick one ({label}.EdgeN)")
    return shape.Edges[0]


def _source(obj):
    link = obj.Source
    if link is None:
        raise InputError("no source spline")
    source, subs = link
    return source, (subs[0] if subs else "")


def base_curve(obj):
    """The source spline as a Part.BSplineCurve (before the edits)."""
    source, sub = _source(obj)
    return edge_bspline(source_edge(source, sub))


def edited_curve(obj):
    """The source spline with PoleOffsets added to its poles (weights and knots kept)."""
    curve = base_curve(obj)
    offsets = list(obj.PoleOffsets)
    if offsets and len(offsets) != curve.NbPoles:
        raise InputError(
            f"the source now has {curve.NbPoles} poles, the edits were made on {len(offsets)}: "
            "restore the source, or clear PoleOffsets to start over"
        )
    for index, offset in enumerate(offsets, start=1):
        if not all(math.isfinite(c) for c in offset):
            raise InputError(f"PoleOffsets: the offset of pole {index} is not finite "
                             f"({offset.x}, {offset.y}, {offset.z})")
        if offset.Length > 0.0:
            curve.setPole(index, curve.getPole(index) + offset)
    return curve


def set_pole(obj, index, point):
    """Move pole `index` (from 0) of the edited curve to `point` (stored as an offset)."""
    base = base_curve(obj)
    if not 0 <= index < base.NbPoles:
        raise InputError(f"pole {index} does not exist: the curve has poles 0 to {base.NbPoles - 1}")
    offsets = list(obj.PoleOffsets) or [FreeCAD.Vector()] * base.NbPoles
    if len(offsets) != base.NbPoles:
        raise InputError(f"PoleOffsets has {len(offsets)} entries for {base.NbPoles} poles")
    offsets[index] = FreeCAD.Vector(point) - base.getPole(index + 1)
    obj.PoleOffsets = offsets


def reset_pole(obj, index):
    """Put pole `index` back where the source has it."""
    offsets = list(obj.PoleOffsets)
    if 0 <= index < len(offsets) and offsets[index].Length > 0:
        offsets[index] = FreeCAD.Vector()
        obj.PoleOffsets = offsets if any(o.Length > 0 for o in offsets) else []


def make_edit_polygon(doc, source, name="EditPolygon"):
    """Create an Edit polygon of `source` (an object with one B-spline edge, or
    (object, "EdgeN")) in `doc` and recompute, as one undoable step."""
    if isinstance(source, (tuple, list)):
        obj_, sub = source
    else:
        obj_, sub = source, ""
    if not isinstance(obj_, FreeCAD.DocumentObject):
        raise InputError(f"not a document object: {obj_!r}")
    with undo_step(doc, "Create edit polygon"):
        obj = doc.addObject("Part::FeaturePython", name)
        EditPolygon(obj)
        obj.Source = (obj_, [sub] if sub else [])
        attach_view_provider(obj, "ViewProviderEditPolygon")
        doc.recompute()
    return obj
