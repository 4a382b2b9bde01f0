"""The README's blending picture (issue 32): a profile designed with basic curves (a line, a
circle arc and an ellipse arc in a sketch, joined by a Design spline: each conic kept exact),
revolved exactly and blended C2 into a free-form ring by a Blend basic shape, in zebra
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
    sketch.addGeometry(Part.LineSegment(V(4, 0, 0), V(4, 3, 0)))  # a stem
    sketch.addGeometry(Part.ArcOfCircle(Part.Circle(V(6, 3, 0), V(0, 0, 1), 2), math.pi / 2, math.pi))  # a fillet
    ellipse = Part.Ellipse(V(6, 6, 0), 3, 1)  # a flat bowl: semi-axes 3 across, 1 up
    sketch.addGeometry(Part.ArcOfEllipse(ellipse, -math.pi / 2, 0.0))
    doc.recompute()
    design = make_design_spline(doc, [((sketch, f"Edge{i}"), None) for i in (1, 2, 3)])
    blend = make_blend_shape(doc, "Revolution", profile=design, AroundCount=8, ProfileCount=6)
    sketch.ViewObject.Visibility = False
    return sketch, design, blend


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
    settle()
    grab(out, "revolution_zebra", "viewIsometric")
    FreeCAD.closeDocument(doc.Name)
    settle()


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else os.path.join(REPO, "docs"))
    sys.stdout.flush()
    os._exit(0)  # leave without tearing down Qt from Python (Shiboken crashes at exit otherwise)
