"""The blending command (GUI only); it records a replayable macro line.

FairSplines_BlendBasicShape   a sphere zone, cylinder, cone or torus joined C2 (Section 4.2) or
                              C1 (Section 5) to a free-form ring, a selected B-spline face or
                              another Blend basic shape (blending paper); its panel opens and
                              previews live; the shell is shown with zebra shading
"""
import FreeCAD
import FreeCADGui

from .common import QT_TRANSLATE_NOOP, create, edit_later, resources

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
        obj = create(FreeCAD.ActiveDocument, "blend_shape", "make_blend_shape", "'Sphere zone'")
        if obj is not None:
            edit_later(obj)


def command_objects():
    return {NAME: BlendBasicShapeCommand()}
