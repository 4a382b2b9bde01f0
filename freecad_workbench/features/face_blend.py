"""The face blend: a parametric fw.blend_faces between an edge of one face and an edge of
another (issue 29; docs/FACE_BLENDS.md). Headless; the GUI's command (FairSplines_BlendFaces), task
panel and zebra view provider attach when FreeCAD.GuiUp.

    from freecad_workbench.features.face_blend import make_face_blend
    blend = make_face_blend(doc, (box, "Face6"), (box, "Edge3"), (other, "Face1"), (other, "Edge1"))
    blend.Status   # "ok: G2, exact / exact, 13 of 13 sections monotone, gap 1.1e-16, ..."

It follows its sources: a recompute reads the faces and edges again. If they are bad (an edge
not on its face, faces that touch, a blend that would cross itself), the feature keeps its last
good shape and puts the message in Status.
"""
from ..errors import InputError
from ..face_blend import blend_faces
from .base import FeatureProxy, attach_view_provider, set_if_changed
from .undo import undo_step

# (type, name, tooltip, default, editor mode); defaults are set only when a property is new.
_PROPERTIES = (
    ("App::PropertyLinkSub", "FaceA", "The first face", None, 0),
    ("App::PropertyLinkSub", "EdgeA", "The edge of the first face the blend starts from", None, 0),
    ("App::PropertyLinkSub", "FaceB", "The second face", None, 0),
    ("App::PropertyLinkSub", "EdgeB", "The edge of the second face the blend ends on", None, 0),
    ("App::PropertyEnumeration", "ContinuityA",
     "How the blend meets the first face: G1 in position and tangent plane; G2 in curvature too", "G2", 0),
    ("App::PropertyEnumeration", "ContinuityB",
     "How the blend meets the second face: G1 in position and tangent plane; G2 in curvature too", "G2", 0),
    ("App::PropertyBool", "Flip", "Pair the start of the first edge with the end of the second", False, 0),
    ("App::PropertyFloat", "Start", "Where the blend starts along each edge, as a fraction (0 to 1)", 0.0, 0),
    ("App::PropertyFloat", "End", "Where the blend ends along each edge, as a fraction (0 to 1)", 1.0, 0),
    ("App::PropertyFloat", "ScaleA",
     "How far the blend runs along the first face's direction, as a multiple of the default; "
     "0: chosen for fair cross sections (derivative magnitude alpha)", 0.0, 0),
    ("App::PropertyFloat", "ScaleB", "The same for the second face; 0: chosen for fair cross sections", 0.0, 0),
    ("App::PropertyString", "Status",
     "'ok' with the method per side, the sections certified monotone and the measured errors, "
     "or why the last recompute failed", "ok", 1),
    ("App::PropertyInteger", "Version", "Version of this object's properties", 0, 2),
)


def _element(link, what):
    if not link:
        raise InputError(f"{what} is not set")
    obj, subs = link
    names = [subs] if isinstance(subs, str) else list(subs)
    if len(names) != 1:
        raise InputError(f"{what} must name one element of {obj.Label}, got {names}")
    try:
        return obj.Shape.getElement(names[0])
    except Exception:
        raise InputError(f"{what}: {obj.Label} has no {names[0]}") from None


class FaceBlend(FeatureProxy):
    """Proxy of a Part::FeaturePython holding the G1/G2 blend of two faces along two edges."""

    Type = "FaceBlend"
    VERSION = 2
    GROUP = "Face blend"
    PROPERTIES = _PROPERTIES
    ENUMERATIONS = {"ContinuityA": ("G1", "G2"), "ContinuityB": ("G1", "G2")}

    def migrate(self, obj):
        # Version 1 had one Continuity for both sides.
        if obj.Version < 2 and "Continuity" in obj.PropertiesList:
            obj.ContinuityA = obj.ContinuityB = str(obj.Continuity)
            obj.removeProperty("Continuity")
        super().migrate(obj)

    def continuity_text(self, obj):
        """'G2', 'G1', or 'G2 / G1' when the sides differ."""
        a, b = str(obj.ContinuityA), str(obj.ContinuityB)
        return a if a == b else f"{a} / {b}"

    def build(self, obj):
        face_a, edge_a = _element(obj.FaceA, "FaceA"), _element(obj.EdgeA, "EdgeA")
        face_b, edge_b = _element(obj.FaceB, "FaceB"), _element(obj.EdgeB, "EdgeB")
        surface, report = blend_faces(face_a, edge_a, face_b, edge_b,
                                      continuity=(str(obj.ContinuityA), str(obj.ContinuityB)),
                                      flip=bool(obj.Flip), start=obj.Start, end=obj.End,
                                      scale_a=obj.ScaleA if obj.ScaleA > 0 else None,
                                      scale_b=obj.ScaleB if obj.ScaleB > 0 else None)
        self.report = report  # the last good build's report, for the task panel (not saved)
        monotone = sum(s["monotone"] for s in report.sections)
        errors = report.errors
        self._status = (f"ok: {self.continuity_text(obj)}, {report.sides[0]['method']} / {report.sides[1]['method']}, "
                        f"{monotone} of {len(report.sections)} sections monotone, "
                        f"gap {max(e['gap'] for e in errors):.1e}, angle {max(e['angle'] for e in errors):.1e} deg, "
                        f"curvature jump {max(e['curvature_jump'] for e in errors):.1e}")
        return surface.toShape()

    def execute(self, obj):
        self._status = "ok"
        super().execute(obj)  # raises on failure, keeping the last good shape
        set_if_changed(obj, "Status", self._status)


def make_face_blend(doc, face_a, edge_a, face_b, edge_b, continuity="G2", flip=False, start=0.0, end=1.0,
                    name="FaceBlend", scale_a=0.0, scale_b=0.0):
    """Create a face blend in `doc` and recompute, as one undoable step. Each of face_a, edge_a,
    face_b, edge_b is ``(obj, "Face1")`` / ``(obj, "Edge3")``; continuity "G1", "G2" or a pair
    (the first face's, the second's); scale_a, scale_b: 0 for fair
    (chosen), else multiples of the default magnitude. Returns the new object; if the sources are
    bad it exists with the message in its Status."""
    with undo_step(doc, "Create face blend"):
        obj = doc.addObject("Part::FeaturePython", name)
        FaceBlend(obj)
        obj.FaceA, obj.EdgeA, obj.FaceB, obj.EdgeB = face_a, edge_a, face_b, edge_b
        obj.ContinuityA, obj.ContinuityB = (tuple(continuity) if isinstance(continuity, (tuple, list))
                                            else (continuity, continuity))
        obj.Flip = bool(flip)
        obj.Start, obj.End = float(start), float(end)
        obj.ScaleA, obj.ScaleB = float(scale_a), float(scale_b)
        attach_view_provider(obj, "ViewProviderFaceBlend")
        doc.recompute()
    return obj
