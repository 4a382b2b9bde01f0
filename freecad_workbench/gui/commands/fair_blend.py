"""The monotone-curvature commands (GUI only). Each records a replayable macro line.

FairSplines_MonotoneBlend    Fair blend between two selected edges (their picked ends) or vertices (the
                             command kept its name, so toolbars people made keep it)
FairSplines_MonotoneDesign   Algorithm 1 in a task panel: control vectors kept in their fair locations
"""
import FreeCAD
import FreeCADGui
import Part

from ...errors import InputError
from ...features.fair_blend import element_shape, end_tangent
from ...features.monotone_design import MonotoneDesign
from .common import QT_TRANSLATE_NOOP, create, doc_code, link_code, resources, selected_links

NAME = "FairSplines_MonotoneBlend"  # Fair blend: the command kept its name, so toolbars people made keep it
DESIGN_NAME = "FairSplines_MonotoneDesign"
COMMANDS = (NAME, DESIGN_NAME)

# A new design: turning left, every C^2 already in its fair location (knots 0,0,0,0,1,2,2,2,2).
DEFAULT_DESIGN = ((10.0, 0.0), [(10.0, 5.0), (3.0, 4.5), (-133.0 / 12, -13.0 / 3)])


# --- Monotone blend -------------------------------------------------------------------------


def _side(obj, sub, picked):
    """(shape, end choice) of one selected side: an edge with the end nearest to where it was
    picked ("auto" when the pick is not on it), or a vertex (None)."""
    try:
        shape = element_shape(obj, sub)
    except InputError:
        return None
    if shape.ShapeType == "Vertex":
        return shape, None
    end = "auto"
    if picked is not None:
        first, last = shape.valueAt(shape.FirstParameter), shape.valueAt(shape.LastParameter)
        on_edge = shape.distToShape(Part.Vertex(picked))[0] <= 0.01 * max(shape.BoundBox.DiagonalLength, 1e-12)
        if on_edge:
            end = "first" if (picked - first).Length <= (picked - last).Length else "last"
    return shape, end


def blend_sides():
    """The selection as [(obj, sub, shape, end)] if it is two edges or vertices, else []."""
    sides = []
    doc = FreeCAD.ActiveDocument
    if doc is None:
        return []
    for sel in FreeCADGui.Selection.getSelectionEx(doc.Name):
        subs = list(sel.SubElementNames) or [""]
        picks = list(sel.PickedPoints) if sel.SubElementNames else []
        for k, sub in enumerate(subs):
            side = _side(sel.Object, sub, picks[k] if k < len(picks) else None)
            if side is None:
                return []
            sides.append((sel.Object, sub) + side)
    return sides if len(sides) == 2 else []


def _vertex_direction(obj, vertex, other, outwards):
    """A starting direction at a selected vertex: along an edge of the same object that ends
    there (continuing it), else towards (from) the other side."""
    for edge in Part.getShape(obj).Edges:
        for which, u in (("first", edge.FirstParameter), ("last", edge.LastParameter)):
            if edge.valueAt(u).isEqual(vertex.Point, 1e-7):
                return end_tangent(edge, which, outwards)
    chord = other - vertex.Point
    return chord if outwards else -chord


def _vector_code(v):
    return f"FreeCAD.Vector({v.x!r}, {v.y!r}, {v.z!r})"


class FairBlendCommand:
    def GetResources(self):
        return resources(
            NAME,
            QT_TRANSLATE_NOOP("FairSplines_MonotoneBlend", "Fair blend"),
            QT_TRANSLATE_NOOP(
                "FairSplines_MonotoneBlend",
                "Bridge two selected edges, at the ends you clicked near, with a curve whose curvature\n"
                "only rises or only falls, proved exactly. Matches the edges' tangents and curvatures\n"
                "(G2); set Continuity to G1 for tangents only. Or select two vertices and set the\n"
                "directions in the blend's properties.",
            ),
            "Fair blends (G1 and G2)",
            accel="F, B",
        )

    def IsActive(self):
        return bool(blend_sides())

    def Activated(self):
        sides = blend_sides()
        if not sides:
            return
        (o0, s0, shape0, end0), (o1, s1, shape1, end1) = sides
        args = []
        for obj, sub in ((o0, s0), (o1, s1)):
            args.append(link_code(obj, sub or None))
        if end0:
            args.append(f"start_end={end0!r}")
        else:
            other = shape1.Point if end1 is None else shape1.valueAt(shape1.FirstParameter)
            args.append(f"start_direction={_vector_code(_vertex_direction(o0, shape0, other, True))}")
        if end1:
            args.append(f"end_end={end1!r}")
        else:
            other = shape0.Point if end0 is None else shape0.valueAt(shape0.LastParameter)
            args.append(f"end_direction={_vector_code(_vertex_direction(o1, shape1, other, False))}")
        create(o0.Document, "fair_blend", "make_fair_blend", ", ".join(args))
        FreeCADGui.Selection.clearSelection()


# --- Monotone design (Algorithm 1) ----------------------------------------------------------


def _selected_design():
    for obj, _ in selected_links():
        if isinstance(getattr(obj, "Proxy", None), MonotoneDesign):
            return obj
    return None


class MonotoneDesignCommand:
    def GetResources(self):
        return resources(
            DESIGN_NAME,
            QT_TRANSLATE_NOOP("FairSplines_MonotoneDesign", "Monotone design"),
            QT_TRANSLATE_NOOP(
                "FairSplines_MonotoneDesign",
                "Design a cubic spline whose curvature only rises or only falls, from the steps between\n"
                "its control points. Edits the selected Monotone design, or creates one. A step that\n"
                "would break the monotone curvature is moved back to the nearest one that keeps it.",
            ),
            "Monotonic-curvature cubic B-splines",
        )

    def IsActive(self):
        return FreeCAD.ActiveDocument is not None and not FreeCADGui.Control.activeDialog()

    def Activated(self):
        obj = _selected_design()
        doc = FreeCAD.ActiveDocument
        FreeCADGui.doCommand("import FreeCAD, FreeCADGui")
        if obj is None:
            first, diffs = DEFAULT_DESIGN
            FreeCADGui.doCommand("from freecad_workbench.features.monotone_design import make_monotone_design")
            FreeCADGui.doCommand(
                f"_design = make_monotone_design({doc_code(doc)}, {first!r}, {diffs!r})"
            )
            FreeCADGui.doCommand(f"FreeCADGui.getDocument({doc.Name!r}).setEdit(_design.Name)")
        else:
            FreeCADGui.doCommand(f"FreeCADGui.getDocument({obj.Document.Name!r}).setEdit({obj.Name!r})")
        FreeCADGui.Selection.clearSelection()


def command_objects():
    return {NAME: FairBlendCommand(), DESIGN_NAME: MonotoneDesignCommand()}
