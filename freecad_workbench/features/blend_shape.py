"""Blend basic shape (blending paper, Section 4.2): a basic shape of revolution (sphere zone,
cylinder, cone or torus) kept exact and joined at the end of its profile to a default
free-form ring by a C2 transition strip (`fw.blend_basic_shape`), or by the naive strip of
Fig. 2a (`fw.blend_naive`, for comparison). Headless; in the GUI the shell is shown with
zebra shading so that the seams can be judged (gui/blend_commands.py).

    from freecad_workbench.features.blend_shape import make_blend_shape
    blend = make_blend_shape(doc, "Torus", MajorRadius=20, MinorRadius=5)
    vase = make_blend_shape(doc, "Revolution", profile=sketch)   # a sketch's edges revolved

The shape lies around the Z axis of the object's Placement. A Revolution revolves its
`Profile` (a sketch, a Design spline, any edges in a plane through that axis; empty: a
parabola), the part of it between the first and last `ProfileFractions` of its parameter
range, split at the others (Uniform: `ProfileCount` equal pieces from the fraction
`ProfileStart` to `ProfileEnd`). Angles are in degrees: around
the axis a full turn or part of one (the partition may be non-uniform), along the profile latitudes
(sphere zone) or tube angles (torus); heights (cylinder, cone) are lengths. With `Uniform`
on, the lists are generated from `AroundCount` arcs over the full turn and `ProfileCount`
pieces from `ProfileStart` to `ProfileEnd`; off, the kind's lists are used as they are.
`JoinTo` links another Blend basic shape to join instead of a ring (Figs. 9-12: the end
of this profile to the start of that one's, with one C2 strip; hide the other object's own
blend). `Continuity` C1 builds Section 5 instead: the shape as a G1 biquadratic spline (arcs below
180°), a (4,2) double strip, a biquadratic ring. `FreeForm` links a B-spline face to join
instead of the default ring (bicubic, periodic
around the axis, clamped along it: any knots, they are merged with the shape's); it moves
with its object. `Interface` picks the end of the profile the free-form side joins (Auto:
the end, or the start where the end is a pole, as for a dome, or where the start leaves the
default ring more room), or "Both ends" (a ball joint's band, a cylinder joined at both
ends: `FreeForm` at the end, `FreeFormStart` at the start, default rings where empty;
`fw.blend_chain`). With `JoinTo`, Start adds free-form below this shape, End beyond the
joined one, Both ends both, all in one C2 complex. `Patches` counts the patches per role. Bad input (angles that do
not increase, a radius that is not positive, an end with no room for the default ring, a
face that is not a matching B-spline ring) keeps the last
good shape and puts the reason in `Status`.
"""
import math

import FreeCAD
import Part

from .. import blend, shapes
from ..errors import InputError
from .base import FeatureProxy, attach_view_provider, set_if_changed
from .undo import undo_step

QT_TRANSLATE_NOOP = FreeCAD.Qt.QT_TRANSLATE_NOOP  # marks a name for translation, returns it unchanged
KINDS = (
    QT_TRANSLATE_NOOP("FairSplines", "Sphere zone"),
    QT_TRANSLATE_NOOP("FairSplines", "Cylinder"),
    QT_TRANSLATE_NOOP("FairSplines", "Cone"),
    QT_TRANSLATE_NOOP("FairSplines", "Torus"),
    QT_TRANSLATE_NOOP("FairSplines", "Revolution"),
)
METHODS = ("rho", "sigma", "mixed")
INTERFACES = (
    QT_TRANSLATE_NOOP("FairSplines", "Auto"),
    QT_TRANSLATE_NOOP("FairSplines", "End"),
    QT_TRANSLATE_NOOP("FairSplines", "Start"),
    QT_TRANSLATE_NOOP("FairSplines", "Both ends"),
)
CONTINUITIES = ("C2", "C1")

# The dimensions of each kind: the lengths, then (around list, profile list).
KIND_LENGTHS = {
    "Sphere zone": ("Radius",),
    "Cylinder": ("Radius",),
    "Cone": ("Radius0", "Slope"),
    "Torus": ("MajorRadius", "MinorRadius"),
    "Revolution": (),
}
KIND_LISTS = {
    "Sphere zone": ("Longitudes", "Latitudes"),
    "Cylinder": ("Angles", "Heights"),
    "Cone": ("Angles", "Heights"),
    "Torus": ("AnglesU", "AnglesV"),
    "Revolution": ("Angles", "ProfileFractions"),
}
# Whether the profile list of a kind holds angles (degrees) rather than lengths (a
# Revolution's: fractions of its profile's parameter range).
PROFILE_IN_DEGREES = {"Sphere zone": True, "Cylinder": False, "Cone": False, "Torus": True, "Revolution": False}
UNIFORM_PROPERTIES = ("AroundCount", "ProfileCount", "ProfileStart", "ProfileEnd")
KIND_PROPERTIES = {k: KIND_LENGTHS[k] + KIND_LISTS[k] + UNIFORM_PROPERTIES for k in KINDS}


def _uniform(start, end, count):
    return [start + (end - start) * i / count for i in range(count + 1)]


# A pleasant default of each kind (model units, degrees): uniform, and the same lists spelled out.
KIND_DEFAULTS = {
    "Sphere zone": dict(Radius=10.0, Longitudes=_uniform(0.0, 360.0, 6), Latitudes=[-40.0, -10.0, 20.0, 45.0],
                        ProfileStart=-40.0, ProfileEnd=45.0),
    "Cylinder": dict(Radius=10.0, Angles=_uniform(0.0, 360.0, 6), Heights=[0.0, 5.0, 10.0, 15.0],
                     ProfileStart=0.0, ProfileEnd=15.0),
    "Cone": dict(Radius0=10.0, Slope=-0.3, Angles=_uniform(0.0, 360.0, 6), Heights=[0.0, 4.0, 8.0, 12.0],
                 ProfileStart=0.0, ProfileEnd=12.0),
    "Torus": dict(MajorRadius=20.0, MinorRadius=5.0, AnglesU=_uniform(0.0, 360.0, 6),
                  AnglesV=[-90.0, -30.0, 30.0, 90.0], ProfileStart=-90.0, ProfileEnd=90.0),
    "Revolution": dict(Angles=_uniform(0.0, 360.0, 6), ProfileFractions=[0.0, 1.0 / 3, 2.0 / 3, 1.0],
                       ProfileStart=0.0, ProfileEnd=1.0),
}
for _values in KIND_DEFAULTS.values():
    _values.update(AroundCount=6, ProfileCount=3)

_PROPERTIES = (
    ("App::PropertyEnumeration", "Kind", "Which basic shape", None, 0),
    ("App::PropertyLength", "Radius", "Sphere zone, cylinder: radius", None, 0),
    ("App::PropertyLength", "Radius0", "Cone: radius at height 0", None, 0),
    ("App::PropertyFloat", "Slope", "Cone: radius = Radius0 + Slope * height", None, 0),
    ("App::PropertyLength", "MajorRadius", "Torus: distance of the tube's centre from the axis", None, 0),
    ("App::PropertyLength", "MinorRadius", "Torus: radius of the tube", None, 0),
    ("App::PropertyFloatList", "Longitudes", "Sphere zone: increasing angles around the axis, a full turn or part "
     "of one (degrees)", None, 0),
    ("App::PropertyFloatList", "Latitudes", "Sphere zone: increasing latitudes in [-90, 90] (degrees); the ring "
     "joins at the last", None, 0),
    ("App::PropertyFloatList", "Angles", "Cylinder, cone: increasing angles around the axis, a full turn or part "
     "of one (degrees)", None, 0),
    ("App::PropertyFloatList", "Heights", "Cylinder, cone: increasing heights along the axis; the ring joins "
     "at the last", None, 0),
    ("App::PropertyFloatList", "AnglesU", "Torus: increasing angles around the axis, a full turn or part of one "
     "(degrees)", None, 0),
    ("App::PropertyFloatList", "AnglesV", "Torus: increasing angles around the tube, 0 = outer equator, less "
     "than a full turn (degrees); the ring joins at the last", None, 0),
    ("App::PropertyLinkSub", "Profile", "Revolution: the profile, a sketch (its edges, joined end to end), a Design "
     "spline or any edge, in a plane through the Z axis of the Placement and off it (empty: a parabola "
     "z = r^2 / 40 from r = 4 to 12)", None, 0),
    ("App::PropertyFloatList", "ProfileFractions", "Revolution: increasing fractions of the profile's parameter "
     "range (0 its start, 1 its end): the part revolved, split into rows there too", None, 0),
    ("App::PropertyBool", "Uniform", "Generate the lists: AroundCount equal arcs around, ProfileCount equal "
     "pieces from ProfileStart to ProfileEnd", True, 0),
    ("App::PropertyInteger", "AroundCount", "Uniform: number of arcs around the axis", 6, 0),
    ("App::PropertyInteger", "ProfileCount", "Uniform: number of pieces along the profile", 3, 0),
    ("App::PropertyFloat", "ProfileStart", "Uniform: start of the profile (degrees, or a height; Revolution: a "
     "fraction of its parameter range)", None, 0),
    ("App::PropertyFloat", "ProfileEnd", "Uniform: end of the profile, where the ring joins (degrees, or a "
     "height; Revolution: a fraction of its parameter range)", None, 0),
    ("App::PropertyEnumeration", "Method", "Reparameterization of the transition (Section 3): rho, sigma or "
     "mixed", "rho", 0),
    ("App::PropertyEnumeration", "Continuity", "C2: the (6,5) strip of Section 4.2 to bicubic NURBS; C1: the (4,2) "
     "double strip of Section 5 to biquadratic NURBS", "C2", 0),
    ("App::PropertyLinkSub", "FreeForm", "A B-spline face to join instead of the default ring: bicubic, periodic "
     "around the axis (in u), clamped along it, its first row near the interface", None, 0),
    ("App::PropertyEnumeration", "Interface", "Where free-form joins the profile: Auto (its end, or its start where "
     "the end is a pole), End, Start, or Both ends (FreeForm at the end, FreeFormStart at the start). With JoinTo "
     "the ends are those of the pair: Start below this shape, End beyond the joined one, Auto neither", "Auto", 0),
    ("App::PropertyLinkSub", "FreeFormStart", "Both ends: a B-spline face to join at the start of the profile "
     "instead of the default ring (as FreeForm, its first row near the start)", None, 0),
    ("App::PropertyLink", "JoinTo", "Another Blend basic shape joined instead of a free-form ring (Figs. 9-12): "
     "the end of this profile to the start of that one's, both kept exact; same number of arcs around", None, 0),
    ("App::PropertyBool", "Naive", "Build the naive blend of Fig. 2a instead (not C2), for comparison", False, 0),
    ("App::PropertyString", "Patches", "Number of patches per role (basic, transition, freeform)", "", 1),
    ("App::PropertyString", "Status", "'ok', or why the last recompute failed", "ok", 1),
    ("App::PropertyInteger", "Version", "Version of this object's properties", 0, 2),
)
_DIMENSIONS = tuple(sorted({p for props in KIND_PROPERTIES.values() for p in props}))


class BlendShape(FeatureProxy):
    """Proxy of a Part::FeaturePython: a basic shape blended into a free-form ring, as a
    shell whose patches share their edges."""

    Type = "BlendShape"
    VERSION = 3  # 2: FreeForm, Interface, JoinTo, Continuity; 3: Interface "Both ends", FreeFormStart
    GROUP = "Blend basic shape"
    PROPERTIES = _PROPERTIES
    ENUMERATIONS = {"Kind": KINDS, "Method": METHODS, "Interface": INTERFACES, "Continuity": CONTINUITIES}
    OUTPUTS = ("Status", "Patches")
    VERDICTS = ("Patches",)

    def ensure_properties(self, obj):
        super().ensure_properties(obj)
        show_kind_properties(obj)

    def onChanged(self, obj, prop):
        if prop in ("Kind", "Uniform"):
            show_kind_properties(obj)

    def build(self, obj):
        result = blend_result(obj)
        counts = {role: 0 for role in ("basic", "transition", "freeform")}
        for role, _ in result.patches:
            counts[role] = counts.get(role, 0) + 1
        set_if_changed(obj, "Patches", ", ".join(f"{role} {n}" for role, n in counts.items()))
        shape = result.shell
        shape.Placement = obj.Placement
        return shape


def show_kind_properties(obj):
    """Show the dimensions of obj's kind (the lists, or the uniform counts and range) in the
    property editor, hide the others."""
    if "Kind" not in obj.PropertiesList or "Uniform" not in obj.PropertiesList:
        return
    used = set(KIND_LENGTHS.get(obj.Kind, ()))
    used |= set(UNIFORM_PROPERTIES) if obj.Uniform else set(KIND_LISTS.get(obj.Kind, ()))
    if "Profile" in obj.PropertiesList:
        obj.setEditorMode("Profile", 0 if obj.Kind == "Revolution" else 2)
    for name in _DIMENSIONS:
        if name in obj.PropertiesList:
            obj.setEditorMode(name, 0 if name in used else 2)


def _length(value):
    return float(getattr(value, "Value", value))


def angle_lists(obj):
    """(around, profile) as the object uses them, in degrees (profile: lengths for a
    cylinder or cone): generated when Uniform is on, else the kind's lists."""
    if obj.Uniform:
        if obj.AroundCount < 1 or obj.ProfileCount < 1:
            raise InputError("the counts must be at least 1")
        start, end = float(obj.ProfileStart), float(obj.ProfileEnd)
        if not (math.isfinite(start) and math.isfinite(end)):
            raise InputError("ProfileStart and ProfileEnd must be finite")
        if not end > start:
            raise InputError(f"ProfileEnd ({end:g}) must be greater than ProfileStart ({start:g})")
        return (_uniform(0.0, 360.0, obj.AroundCount),
                _uniform(float(obj.ProfileStart), float(obj.ProfileEnd), obj.ProfileCount))
    around, profile = KIND_LISTS[obj.Kind]
    return list(getattr(obj, around)), list(getattr(obj, profile))


def basic_shape(obj, placement=None, trial_profile=None):
    """The fw.shapes object of obj, about the Z axis through the origin (local coordinates),
    or moved by `placement` (a FreeCAD.Placement). trial_profile: a Revolution's profile link to
    try instead of obj's Profile ((object, [edge names]), as profile_link returns)."""
    around_deg, profile = angle_lists(obj)
    if len(around_deg) < 2 or len(profile) < 2:
        raise InputError("each list needs at least 2 values")
    # Checked here, in the units the designer typed (the kernel would quote radians).
    around_name, profile_name = ("AroundCount", "ProfileCount") if obj.Uniform else KIND_LISTS[obj.Kind]
    unit = "°" if PROFILE_IN_DEGREES[obj.Kind] else ""
    for name, values, suffix in ((around_name, around_deg, "°"), (profile_name, profile, unit)):
        for i in range(1, len(values)):
            if not values[i] > values[i - 1]:
                raise InputError(f"{name}: value {i} ({values[i]:g}{suffix}) must be greater than "
                                 f"value {i - 1} ({values[i - 1]:g}{suffix})")
    around = [math.radians(a) for a in around_deg]
    if PROFILE_IN_DEGREES[obj.Kind]:
        profile = [math.radians(a) for a in profile]
    placement = placement or FreeCAD.Placement()
    frame = dict(axis=tuple(placement.Rotation.multVec(FreeCAD.Vector(0, 0, 1))),
                 x_axis=tuple(placement.Rotation.multVec(FreeCAD.Vector(1, 0, 0))))
    center = tuple(placement.Base)
    if obj.Kind == "Revolution":
        curve, splits = _profile_part(obj, profile, placement, link=trial_profile)
        return shapes.Revolution(curve, center, frame["axis"], around, splits)
    if obj.Kind == "Sphere zone":
        return shapes.SphereZone(center, _length(obj.Radius), around, profile, **frame)
    if obj.Kind == "Cylinder":
        return shapes.Cylinder(center, _length(obj.Radius), around, profile, **frame)
    if obj.Kind == "Cone":
        return shapes.Cone(center, _length(obj.Radius0), float(obj.Slope), around, profile, **frame)
    return shapes.Torus(center, _length(obj.MajorRadius), _length(obj.MinorRadius), around, profile, **frame)


def _default_profile():
    """The parabola z = r^2 / 40 from r = 4 to 12 in the XZ plane: the Revolution's profile
    while none is linked."""
    curve = Part.BSplineCurve()
    poles = [FreeCAD.Vector(4, 0, 0.4), FreeCAD.Vector(8, 0, 1.2), FreeCAD.Vector(12, 0, 3.6)]
    curve.buildFromPolesMultsKnots(poles, [3, 3], [0.0, 1.0], False, 2)
    return curve


def profile_link(source, subs=()):
    """The Profile link of a selection: `source` (a sketch, a Design spline, any object with
    edges and no faces) and the names of its selected sub-elements, which must be edges.
    Returns (source, [edge names]) (no names: all its edges); InputError names what is wrong."""
    label = getattr(source, "Label", repr(source))
    if not isinstance(source, FreeCAD.DocumentObject):
        raise InputError(f"{label} is not a document object")
    if is_blend_shape(source):
        raise InputError(f"{label} is a Blend basic shape: pick a sketch, a Design spline or edges")
    shape = getattr(source, "Shape", None)
    if shape is None or shape.isNull() or not shape.Edges:
        raise InputError(f"{label} has no edges: pick a sketch, a Design spline or edges")
    subs = [s for s in subs if s]
    for sub in subs:
        if not sub.startswith("Edge"):
            what = "a face" if sub.startswith("Face") else "a vertex" if sub.startswith("Vertex") else "not an edge"
            raise InputError(f"{label}.{sub} is {what}: pick a sketch, a Design spline or edges")
    if not subs and shape.Faces:
        raise InputError(f"{label} has faces: pick some of its edges, a sketch or a Design spline")
    return (source, subs)


def _profile_part(obj, fractions, placement, link=None):
    """(the Part curve or shape of obj's profile (or of `link` instead) in the coordinates of
    `placement` (None: obj's local ones), trimmed to the first and last fraction of its
    parameter range, and the inner fractions as parameters to split at)."""
    link = obj.Profile if link is None else link
    if link is None or link[0] is None:
        profile = _default_profile()
    else:
        source, subs = link
        shape = getattr(source, "Shape", None)
        if shape is None or shape.isNull():
            raise InputError(f"Profile {source.Label} has no shape")
        edges = [shape.getElement(sub) for sub in subs if sub] if subs and any(subs) else shape.Edges
        if not edges:
            raise InputError(f"Profile {source.Label} has no edges")
        moved = Part.Compound(edges).copy()
        to_local = obj.Placement.inverse()
        if placement is not None:
            to_local = placement.multiply(to_local)
        moved.transformShape(to_local.toMatrix())
        profile = shapes.joined_profile(moved)
    for f in fractions:
        if not 0.0 <= f <= 1.0:
            raise InputError(f"ProfileFractions: {f:g} is not in [0, 1] (fractions of the profile's parameter range)")
    if link is None or link[0] is None:
        if placement is not None:
            profile = profile.copy()
            profile.transform(placement.toMatrix())
    a, b = profile.FirstParameter, profile.LastParameter
    t = [a + f * (b - a) for f in fractions]
    # A fraction a rounding error from a knot is that knot (no row or end piece of no length).
    knots = profile.getKnots() if hasattr(profile, "getKnots") else []
    t = [min(knots, key=lambda k: abs(k - x)) if knots and min(abs(k - x) for k in knots) <= 1e-9 * (b - a) else x
         for x in t]
    if t[0] > a or t[-1] < b:
        profile = profile.copy()
        profile.segment(t[0], t[-1])
    return profile, t[1:-1]


def freeform_surface(obj, name="FreeForm"):
    """The Part.BSplineSurface of obj's FreeForm (or FreeFormStart) face in obj's local
    coordinates, or None (the default ring). InputError if the link is not a B-spline face."""
    link = getattr(obj, name)
    if link is None or link[0] is None:
        return None
    source, subs = link
    sub = subs[0] if subs else ""
    origin = f"{source.Label}.{sub}" if sub else source.Label
    shape = getattr(source, "Shape", None)
    if shape is None or shape.isNull():
        raise InputError(f"{name} {origin} has no shape")
    if sub:
        try:
            face = shape.getElement(sub)
        except Exception:  # noqa: BLE001 (FreeCAD raises plain exceptions for a bad name)
            raise InputError(f"{name} {origin} does not exist") from None
    elif len(shape.Faces) == 1:
        face = shape.Faces[0]
    else:
        raise InputError(f"{name} {origin} has {len(shape.Faces)} faces: pick one")
    if not isinstance(face, Part.Face):
        raise InputError(f"{name} {origin} is not a face")
    surface = face.Surface
    if not isinstance(surface, Part.BSplineSurface):
        raise InputError(f"{name} {origin} is a {type(surface).__name__}, not a B-spline surface")
    surface = surface.copy()
    surface.transform(obj.Placement.inverse().toMatrix())
    return surface


def blend_result(obj):
    """fw.BlendResult of obj (local coordinates): the C2 blend, or the naive one; joined to
    another Blend basic shape where JoinTo is set."""
    shape = basic_shape(obj)
    other = obj.JoinTo
    if other is not None:
        if not is_blend_shape(other):
            raise InputError(f"JoinTo {other.Label} is not a Blend basic shape")
        if other == obj or getattr(other, "JoinTo", None) == obj:
            raise InputError(f"JoinTo {other.Label} joins back to this shape")
        # the other shape in this object's local coordinates
        relative = obj.Placement.inverse().multiply(other.Placement)
        second = basic_shape(other, relative)
        if obj.Interface != "Auto":
            return _chain(obj, [shape, second])
        if obj.Naive:
            if obj.Continuity == "C1":
                raise InputError("the naive join has no C1 variant: use C2, or turn Naive off")
            return blend.join_naive(shape, second)
        return blend.join_basic_shapes(shape, second, continuity=obj.Continuity, method=obj.Method)
    if obj.Interface == "Both ends":
        return _chain(obj, [shape])
    ring = freeform_surface(obj)
    at = None if obj.Interface == "Auto" else obj.Interface.lower()
    if obj.Naive:
        return blend.blend_naive(shape, freeform=ring, continuity=obj.Continuity, at=at)
    return blend.blend_basic_shape(shape, freeform=ring, continuity=obj.Continuity, method=obj.Method, at=at)


def _chain(obj, shapes_):
    """Free-form at both ends of the profile, or a join with free-form beyond it
    (fw.blend_chain): C2 only, not naive."""
    if obj.Continuity == "C1":
        raise InputError(f"C1 joins free-form at one end of the profile: set Interface to Auto, End or Start "
                         f"(not {obj.Interface}), or use C2")
    if obj.Naive:
        raise InputError(f"the naive blend joins at one end: turn Naive off for Interface {obj.Interface}")
    both = obj.Interface == "Both ends"
    start = end = None
    if obj.Interface in ("Start", "Both ends"):
        start = (freeform_surface(obj, "FreeFormStart") if both else freeform_surface(obj)) or "default"
    if obj.Interface in ("End", "Both ends"):
        end = freeform_surface(obj) or "default"
    return blend.blend_chain(shapes_, start=start, end=end, method=obj.Method)


def is_blend_shape(obj):
    return isinstance(getattr(obj, "Proxy", None), BlendShape)


def _face_link(freeform, name):
    source, sub = freeform if isinstance(freeform, (tuple, list)) else (freeform, "")
    if not isinstance(source, FreeCAD.DocumentObject):
        raise InputError(f"{name} is not a document object: {source!r}")
    return (source, [sub]) if sub else source


def make_blend_shape(doc, kind="Sphere zone", name=None, placement=None, method="rho", naive=False, freeform=None,
                     interface="Auto", join_to=None, continuity="C2", freeform_start=None, profile=None,
                     **dimensions):
    """Create a Blend basic shape of the given kind in `doc` and recompute, as one undoable
    step. Dimensions not given take the kind's defaults (KIND_DEFAULTS): lengths in model
    units, angle lists in degrees. Giving any of the kind's lists turns Uniform off unless
    Uniform is given. freeform: a B-spline face to join, as (object, "FaceN") or an object
    with one face (None: the default ring); interface: "Auto", "End", "Start" or "Both ends"
    (freeform_start: the face at the start for "Both ends"). Bad
    dimensions leave the object with the message in its Status; unknown kinds, methods,
    interfaces or dimensions raise InputError. join_to: another Blend basic shape to join
    (its basic shape instead of a ring; its own view is hidden in the GUI). profile: a
    Revolution's profile, an object (a sketch, a Design spline) or (object, "EdgeN")."""
    if kind not in KINDS:
        raise InputError(f"unknown kind {kind!r}: use one of {', '.join(KINDS)}")
    if method not in METHODS:
        raise InputError(f"unknown method {method!r}: use one of {', '.join(METHODS)}")
    if continuity not in CONTINUITIES:
        raise InputError(f"unknown continuity {continuity!r}: use one of {', '.join(CONTINUITIES)}")
    if interface not in INTERFACES:
        raise InputError(f"unknown interface {interface!r}: use one of {', '.join(INTERFACES)}")
    link = None if freeform is None else _face_link(freeform, "freeform")
    if join_to is not None and not is_blend_shape(join_to):
        raise InputError(f"join_to is not a Blend basic shape: {join_to!r}")
    allowed = set(KIND_PROPERTIES[kind]) | {"Uniform"}
    unknown = sorted(set(dimensions) - allowed)
    if unknown:
        raise InputError(f"{kind} has no dimension {', '.join(unknown)}: it has {', '.join(sorted(allowed))}")
    values = dict(KIND_DEFAULTS[kind], **dimensions)
    if "Uniform" not in dimensions:
        values["Uniform"] = not any(p in dimensions for p in KIND_LISTS[kind])
    link_start = None if freeform_start is None else _face_link(freeform_start, "freeform_start")
    profile_link = None if profile is None else _face_link(profile, "profile")
    with undo_step(doc, "Create blend basic shape"):
        obj = doc.addObject("Part::FeaturePython", name or "BlendShape")
        BlendShape(obj)
        obj.Kind = kind
        obj.Method = method
        obj.Naive = bool(naive)
        obj.Interface = interface
        obj.Continuity = continuity
        if link is not None:
            obj.FreeForm = link
        if link_start is not None:
            obj.FreeFormStart = link_start
        if profile_link is not None:
            obj.Profile = profile_link
        if join_to is not None:
            obj.JoinTo = join_to
            if FreeCAD.GuiUp:
                join_to.ViewObject.Visibility = False
        for key, value in values.items():
            setattr(obj, key, [float(v) for v in value] if isinstance(value, (list, tuple)) else value)
        if placement is not None:
            obj.Placement = placement
        attach_view_provider(obj, "ViewProviderBlendShape")
        doc.recompute()
    return obj
