"""The Monotone design: a parametric cubic B-spline designed by Algorithm 1 of Wang et al. from
a first control vector and the differences of the following ones, each kept in its fair
location so that the curvature is monotone. Headless; a view provider is attached only when
FreeCAD.GuiUp. The Monotone design command edits it in a task panel.

    from freecad_workbench.features.monotone_design import make_monotone_design
    design = make_monotone_design(doc, (1, 0), [(1, 0.5), (0.3, 0.45), (-1.1, -0.43)])

Properties: `FirstVector` V_0 and `Differences` dV_i (in the XY plane of the object's
Placement), `Knots` (the full knot vector; empty: clamped, uniform inside). `Differences` hold
what was asked; `UsedDifferences` what Algorithm 1 used after moving each into its fair
location. Bad input (a zero first vector, too few differences, unusable knots) keeps the last
good shape and puts the reason in `Status`.
"""
import FreeCAD

from ..kernel import as_vector
from ..monotone import clamp_to_fair_locations, monotone_curvature_design
from .base import FeatureProxy, attach_view_provider, set_if_changed
from .undo import undo_step

_PROPERTIES = (
    ("App::PropertyVector", "FirstVector", "V_0 = C_1 - C_0, in the XY plane", FreeCAD.Vector(1, 0, 0), 0),
    ("App::PropertyVectorList", "Differences", "dV_i = V_(i+1) - V_i as asked, in the XY plane", None, 0),
    ("App::PropertyFloatList", "Knots", "Full knot vector t_0..t_(n+4); empty: clamped, uniform inside", None, 0),
    ("App::PropertyVectorList", "UsedDifferences", "The dV_i used: each in its fair location", None, 1),
    ("App::PropertyString", "Status", "'ok', or why the last recompute failed", "ok", 1),
    ("App::PropertyInteger", "Version", "Version of this object's properties", 0, 2),
)


class MonotoneDesign(FeatureProxy):
    """Proxy of a Part::FeaturePython holding an Algorithm 1 design."""

    Type = "MonotoneDesign"
    VERSION = 1
    GROUP = "Monotone design"
    PROPERTIES = _PROPERTIES
    OUTPUTS = ("Status", "UsedDifferences")

    def build(self, obj):
        differences = [(v.x, v.y, v.z) for v in obj.Differences]
        knots = list(obj.Knots) or None
        curve = monotone_curvature_design(obj.FirstVector, differences, knots)
        used, _ = clamp_to_fair_locations(obj.FirstVector, differences, knots)
        set_if_changed(obj, "UsedDifferences", [FreeCAD.Vector(x, y, 0) for x, y in used])
        shape = curve.toShape()
        shape.Placement = obj.Placement
        return shape


def make_monotone_design(doc, first_vector, differences, knots=None, name="MonotoneDesign"):
    """Create a Monotone design in `doc` and recompute, as one undoable step.

    first_vector: V_0 (2 or 3 numbers, z = 0, or a FreeCAD.Vector); differences: the dV_i;
    knots: the full knot vector, or None for clamped, uniform inside."""
    with undo_step(doc, "Create monotone design"):
        obj = doc.addObject("Part::FeaturePython", name)
        MonotoneDesign(obj)
        obj.FirstVector = FreeCAD.Vector(*as_vector(first_vector, "first_vector"))
        obj.Differences = [FreeCAD.Vector(*as_vector(d, f"dV_{i}")) for i, d in enumerate(differences)]
        obj.Knots = [float(t) for t in knots] if knots is not None else []
        attach_view_provider(obj, "ViewProviderMonotoneDesign")
        doc.recompute()
    return obj
