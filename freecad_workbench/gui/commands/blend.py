"""The blending command (GUI only); it records a replayable macro line.

FairSplines_BlendBasicShape   a sphere zone, cylinder, cone or torus joined C2 (Section 4.2) or
                              C1 (Section 5) to a free-form ring, a selected B-spline face or
                              another Blend basic shape (blending paper); its panel opens and
                              previews live; the shell is shown with zebra shading
"""
import FreeCAD
import FreeCADGui

from .common import QT_TRANSLATE_NOOP, doc_code, edit_later, new_object, resources

NAME = "FairSplines_BlendBasicShape"


class BlendBasicShapeCommand:
    def GetResources(self):
        return resources(
            NAME,
            QT_TRANSLATE_NOOP(NAME, "Blend basic shape"),
            QT_TRANSLATE_NOOP(
                NAME,
                "A sphere zone, cylinder, cone or torus kept exact and joined smoothly (C2, or C1) to a\n"
                "free-form ring, a selected B-spline face or another basic shape.\n"
                "Set it up in the panel; zebra stripes show the seams.",
            ),
            "Basic shapes blended into NURBS",
        )

    def IsActive(self):
        return FreeCAD.ActiveDocument is not None and not FreeCADGui.Control.activeDialog()

    def Activated(self):
        doc = FreeCAD.ActiveDocument
        before = {o.Name for o in doc.Objects}
        FreeCADGui.doCommand("import FreeCAD")
        FreeCADGui.doCommand("from freecad_workbench.features.blend_shape import make_blend_shape")
        FreeCADGui.doCommand(f"make_blend_shape({doc_code(doc)}, 'Sphere zone')")
        obj = new_object(doc, before)
        if obj is not None:
            edit_later(obj)


def command_objects():
    return {NAME: BlendBasicShapeCommand()}
