"""The README's blending picture (issue 32): a profile designed with basic curves (a line, a
circle arc and an ellipse arc in a sketch, joined by a Design spline: each conic kept exact),
revolved exactly and blended C2 into a free-form ring (a bicubic B-spline face picked as the
free-form side) by a Blend basic shape, in zebra
shading, with the Blend basic shape panel open (its Profile picked from the Design spline).
The whole main window at its default layout. Run under a virtual display:

    xvfb-run -a -s "-screen 0 1600x1000x24" /usr/bin/python3 tools/revolution_zebra.py [OUT_DIR]

OUT_DIR defaults to docs (docs/revolution_zebra.png). Look at the picture before committing it."""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from gui_screenshots import REPO, edit, grab, new_doc, settle, start_gui  # noqa: E402

import FreeCAD  # noqa: E402


def revolved_design(doc):
    """(sketch, design, blend): the profile in the XZ plane (sketch x = radius, y = height),
    designed, revolved and blended into the default ring above it."""
    import Part
    import Sketcher  # noqa: F401

    from freecad_workbench.features.blend_shape import make_blend_shape
    from freecad_workbench.features.design_spline import make_design_spline

    V = FreeCAD.Vector
    sketch = doc.addObject("Sketcher::SketchObject", "Profile")
    sketch.Placement = FreeCAD.Placement(V(), FreeCAD.Rotation(V(1, 0, 0), 90))  # (x, y) -> (x, 0, y)
    # From the bottom up: a bulge (an ellipse arc, semi-axes 4 up and 2 across), a fillet (a
    # quarter circle) into a neck (a line), which the ring continues.
    sketch.addGeometry(Part.LineSegment(V(4, 6, 0), V(4, 9, 0)))  # the neck
    sketch.addGeometry(Part.ArcOfCircle(Part.Circle(V(6, 6, 0), V(0, 0, 1), 2), math.pi, 1.5 * math.pi))
    ellipse = Part.Ellipse(V(6, 4, 0), V(4, 0, 0), V(6, 0, 0))  # centre (6, 0), major axis up
    sketch.addGeometry(Part.ArcOfEllipse(ellipse, -math.pi / 2, 0.0))  # from (8, 0) up to (6, 4)
    doc.recompute()
    design = make_design_spline(doc, [((sketch, f"Edge{i}"), None) for i in (3, 2, 1)])  # ends with the neck
    ring = doc.addObject("Part::Feature", "Ring")  # a free-form ring above the neck: bicubic, periodic
    ring.Shape = Part.Face(free_form_ring(4.0, 10.0, 1.0))
    blend = make_blend_shape(doc, "Revolution", profile=design, freeform=(ring, "Face1"), AroundCount=8,
                             ProfileCount=6)
    for hidden in (sketch, ring):
        hidden.ViewObject.Visibility = False
    return sketch, design, blend


def free_form_ring(radius, z0, step, arcs=8):
    """A bicubic B-spline ring around the Z axis, periodic around it, 4 rows from z0 up by
    `step`: its surface at `radius` (the poles' polygon pushed out by the cubic's shrink)."""
    import Part

    shrink = (2 + math.cos(2 * math.pi / arcs)) / 3  # a periodic cubic of a regular polygon's poles, at a pole
    # pole i at the angle of arc i - 1: OCCT's periodic span [i, i + 1] then lies over arc i,
    # the shape's arc the strip joins it to
    rows = [[FreeCAD.Vector(radius / shrink * math.cos(a), radius / shrink * math.sin(a), z0 + step * j)
             for j in range(4)] for a in (2 * math.pi * (i - 1) / arcs for i in range(arcs))]
    surface = Part.BSplineSurface()
    surface.buildFromPolesMultsKnots(rows, [1] * (arcs + 1), [4, 4], [float(k) for k in range(arcs + 1)],
                                     [0.0, 1.0], True, False, 3, 3)
    return surface


def main(out):
    import FreeCADGui

    os.makedirs(out, exist_ok=True)
    start_gui()
    doc = new_doc("Revolution")
    sketch, design, blend = revolved_design(doc)
    assert design.Status == "ok", design.Status
    assert blend.Status == "ok", blend.Status
    FreeCADGui.Selection.clearSelection()
    edit(blend)
    view = FreeCADGui.ActiveDocument.ActiveView
    # from the side, a little above: the stem, the fillet, the bowl and the ring beyond it
    view.setCameraOrientation(FreeCAD.Rotation(FreeCAD.Vector(0, 0, 1), 25).multiply(
        FreeCAD.Rotation(FreeCAD.Vector(1, 0, 0), 68)))
    FreeCADGui.getMainWindow().statusBar().clearMessage()
    settle()
    grab(out, "revolution_zebra", "fitAll")
    FreeCAD.closeDocument(doc.Name)
    settle()


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else os.path.join(REPO, "docs"))
    sys.stdout.flush()
    os._exit(0)  # leave without tearing down Qt from Python (Shiboken crashes at exit otherwise)
