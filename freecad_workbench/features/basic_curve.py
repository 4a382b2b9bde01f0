"""The basic curve feature: a parametric basic curve (csr paper, Sections 5 and 6) with its
dimensions as properties, for design with basic curves. Headless; a view provider is
attached only when FreeCAD.GuiUp.

    from freecad_workbench.features.basic_curve import make_basic_curve
    arc = make_basic_curve(doc, "Circle arc", Radius=10, StartAngle=0, EndAngle=90)

The curve lies in the XY plane of the object's Placement (centre, vertex or spiral pole at
its origin, the X axis as reference direction). Angles are in degrees. Its shape is the
curve's FreeCAD geometry (`to_part()`: the native line or circle arc, an exact rational
B-spline for the other conics, a B-spline within 1e-9 of the size for spirals and
involutes). A Design spline that links to this object uses the exact basic curve, not
its shape.

Kinds and their dimensions:
- Line segment: Start, End (points in the placement's coordinates);
- Circle arc: Radius, StartAngle, EndAngle (clockwise when EndAngle < StartAngle);
- Ellipse arc: MajorRadius (along X), MinorRadius, StartAngle, EndAngle (the
  parameter t of (a cos t, b sin t));
- Parabola arc: Focal (vertex to focus, along X), StartY, EndY (y of the end points;
  x = y^2 / (4 Focal));
- Hyperbola arc: MajorRadius, MinorRadius, StartParameter, EndParameter (t of
  (a cosh t, b sinh t));
- Archimedean spiral: Radius (r at angle 0), Pitch (growth of r per turn), StartAngle,
  Turns (r = Radius + Pitch * angle / 360 deg, angle from StartAngle over Turns turns);
- Circle involute: Radius (of the base circle), StartAngle, EndAngle (roll angles, >= 0);
- Rational cubic: Poles (2 to 4) and Weights (one per pole, positive), a rational Bezier
  curve of degree <= 3 (this covers every conic arc).

If the dimensions are bad (a zero radius, an empty range) the feature keeps its last good
shape, puts the message in `Status`, prints it to the report view, and lets the rest of
the document recompute.
"""
import math

import FreeCAD

from .. import basic
from ..errors import InputError
from .base import FeatureProxy, attach_view_provider
from .undo import undo_step

QT_TRANSLATE_NOOP = FreeCAD.Qt.QT_TRANSLATE_NOOP  # marks a name for translation, returns it unchanged
KINDS = (
    QT_TRANSLATE_NOOP("FairSplines", "Line segment"),
    QT_TRANSLATE_NOOP("FairSplines", "Circle arc"),
    QT_TRANSLATE_NOOP("FairSplines", "Ellipse arc"),
    QT_TRANSLATE_NOOP("FairSplines", "Parabola arc"),
    QT_TRANSLATE_NOOP("FairSplines", "Hyperbola arc"),
    QT_TRANSLATE_NOOP("FairSplines", "Archimedean spiral"),
    QT_TRANSLATE_NOOP("FairSplines", "Circle involute"),
    QT_TRANSLATE_NOOP("FairSplines", "Rational cubic"),
)

# The dimensions each kind uses, in the order the task panel shows them.
KIND_PROPERTIES = {
    "Line segment": ("Start", "End"),
    "Circle arc": ("Radius", "StartAngle", "EndAngle"),
    "Ellipse arc": ("MajorRadius", "MinorRadius", "StartAngle", "EndAngle"),
    "Parabola arc": ("Focal", "StartY", "EndY"),
    "Hyperbola arc": ("MajorRadius", "MinorRadius", "StartParameter", "EndParameter"),
    "Archimedean spiral": ("Radius", "Pitch", "StartAngle", "Turns"),
    "Circle involute": ("Radius", "StartAngle", "EndAngle"),
    "Rational cubic": ("Poles", "Weights"),
}

# A pleasant default shape of each kind (model units, degrees).
KIND_DEFAULTS = {
    "Line segment": dict(Start=FreeCAD.Vector(0, 0, 0), End=FreeCAD.Vector(20, 0, 0)),
    "Circle arc": dict(Radius=10.0, StartAngle=0.0, EndAngle=90.0),
    "Ellipse arc": dict(MajorRadius=20.0, MinorRadius=10.0, StartAngle=0.0, EndAngle=90.0),
    "Parabola arc": dict(Focal=5.0, StartY=-10.0, EndY=10.0),
    "Hyperbola arc": dict(MajorRadius=10.0, MinorRadius=10.0, StartParameter=-1.0, EndParameter=1.0),
    "Archimedean spiral": dict(Radius=0.0, Pitch=10.0, StartAngle=90.0, Turns=1.75),
    "Circle involute": dict(Radius=10.0, StartAngle=0.0, EndAngle=180.0),
    "Rational cubic": dict(
        Poles=[FreeCAD.Vector(0, 0, 0), FreeCAD.Vector(10, 10, 0), FreeCAD.Vector(20, 10, 0), FreeCAD.Vector(30, 0, 0)],
        Weights=[1.0, 1.0, 1.0, 1.0],
    ),
}

# (type, name, tooltip, default, editor mode); defaults are set only when a property is new.
_PROPERTIES = (
    ("App::PropertyEnumeration", "Kind", "Which basic curve", None, 0),
    ("App::PropertyVectorDistance", "Start", "Line segment: start point (placement coordinates)", None, 0),
    ("App::PropertyVectorDistance", "End", "Line segment: end point (placement coordinates)", None, 0),
    ("App::PropertyLength", "Radius", "Circle arc, involute: radius; spiral: radius at angle 0", None, 0),
    ("App::PropertyLength", "MajorRadius", "Ellipse, hyperbola: semi-axis along X", None, 0),
    ("App::PropertyLength", "MinorRadius", "Ellipse, hyperbola: semi-axis along Y", None, 0),
    ("App::PropertyAngle", "StartAngle", "Angle (from X) where the curve starts", None, 0),
    ("App::PropertyAngle", "EndAngle", "Angle (from X) where the curve ends", None, 0),
    ("App::PropertyLength", "Focal", "Parabola: distance from vertex to focus", None, 0),
    ("App::PropertyDistance", "StartY", "Parabola: y of the start point", None, 0),
    ("App::PropertyDistance", "EndY", "Parabola: y of the end point", None, 0),
    ("App::PropertyFloat", "StartParameter", "Hyperbola: t of the start point (a cosh t, b sinh t)", None, 0),
    ("App::PropertyFloat", "EndParameter", "Hyperbola: t of the end point", None, 0),
    ("App::PropertyLength", "Pitch", "Spiral: growth of the radius per turn", None, 0),
    ("App::PropertyFloat", "Turns", "Spiral: number of turns from StartAngle", None, 0),
    ("App::PropertyVectorList", "Poles", "Rational cubic: 2 to 4 control points (placement coordinates)", None, 0),
    ("App::PropertyFloatList", "Weights", "Rational cubic: one positive weight per pole", None, 0),
    ("App::PropertyString", "Status", "'ok', or why the last recompute failed", "ok", 1),
    ("App::PropertyInteger", "Version", "Version of this object's properties", 0, 2),
)
_DIMENSIONS = tuple(name for _, name, *_ in _PROPERTIES if name not in ("Kind", "Status", "Version"))


class BasicCurveFeature(FeatureProxy):
    """Proxy of a Part::FeaturePython holding one basic curve built from its dimensions."""

    Type = "BasicCurve"
    VERSION = 1
    GROUP = "Basic curve"
    PROPERTIES = _PROPERTIES
    ENUMERATIONS = {"Kind": KINDS}

    def ensure_properties(self, obj):
        super().ensure_properties(obj)
        show_kind_properties(obj)

    def onChanged(self, obj, prop):
        if prop == "Kind":
            show_kind_properties(obj)

    def build(self, obj):
        shape = local_curve(obj).to_part().toShape()
        shape.Placement = obj.Placement
        return shape

    def basic_curve(self, obj, placement=None):
        """The exact fw.basic curve of obj, placed by `placement` (default: where the
        object's shape is in the document, containers included)."""
        if placement is None:
            placement = global_placement(obj)
        return build_curve(obj, placement)


def show_kind_properties(obj):
    """Show the dimensions of obj's kind in the property editor, hide the others."""
    if "Kind" not in obj.PropertiesList:
        return
    used = KIND_PROPERTIES.get(obj.Kind, ())
    for name in _DIMENSIONS:
        if name in obj.PropertiesList:
            obj.setEditorMode(name, 0 if name in used else 2)


def _value(obj, name):
    """A dimension as a float (lengths in mm, angles in degrees)."""
    value = getattr(obj, name)
    return float(value.Value) if hasattr(value, "Value") else float(value)


def build_curve(obj, placement):
    """The fw.basic curve of a BasicCurve object's dimensions, placed by `placement`."""
    kind = obj.Kind
    rotation = placement.Rotation
    origin = placement.Base
    normal = rotation.multVec(FreeCAD.Vector(0, 0, 1))
    x_axis = rotation.multVec(FreeCAD.Vector(1, 0, 0))
    frame = dict(normal=normal, x_axis=x_axis)
    angle = lambda name: math.radians(_value(obj, name))  # noqa: E731
    if kind == "Line segment":
        start, end = placement.multVec(obj.Start), placement.multVec(obj.End)
        if (end - start).Length <= 1e-12 * max(1.0, start.Length, end.Length):
            raise InputError("degenerate line segment: Start and End coincide")
        return basic.LineSegment(start, end)
    if kind == "Circle arc":
        return basic.CircleArc(origin, _value(obj, "Radius"), angle("StartAngle"), angle("EndAngle"), **frame)
    if kind == "Ellipse arc":
        return basic.EllipseArc(origin, _value(obj, "MajorRadius"), _value(obj, "MinorRadius"), angle("StartAngle"),
                                angle("EndAngle"), **frame)
    if kind == "Parabola arc":
        return basic.ParabolaArc(origin, _value(obj, "Focal"), _value(obj, "StartY"), _value(obj, "EndY"), **frame)
    if kind == "Hyperbola arc":
        return basic.HyperbolaArc(origin, _value(obj, "MajorRadius"), _value(obj, "MinorRadius"),
                                  _value(obj, "StartParameter"), _value(obj, "EndParameter"), **frame)
    if kind == "Archimedean spiral":
        turns = _value(obj, "Turns")
        if not turns > 0:
            raise InputError(f"degenerate spiral: Turns must be positive, got {turns:g}")
        pitch = _value(obj, "Pitch")
        if not pitch > 0:
            raise InputError("degenerate spiral: Pitch must be positive")
        theta0 = angle("StartAngle")
        return basic.ArchimedeanSpiral(origin, _value(obj, "Radius"), pitch / (2 * math.pi), theta0,
                                       theta0 + 2 * math.pi * turns, **frame)
    if kind == "Circle involute":
        return basic.CircleInvolute(origin, _value(obj, "Radius"), angle("StartAngle"), angle("EndAngle"), **frame)
    if kind == "Rational cubic":
        poles = [placement.multVec(p) for p in obj.Poles]
        weights = list(obj.Weights)
        if len(weights) != len(poles):
            raise InputError(f"a rational cubic needs one weight per pole: {len(poles)} poles, {len(weights)} weights")
        if any(not w > 0 for w in weights):
            raise InputError("the weights of a rational cubic must be positive")
        return basic.RationalCubic(poles, weights)
    raise InputError(f"unknown kind {kind!r}")


def local_curve(obj):
    """The basic curve in the placement's own coordinates (identity placement)."""
    return build_curve(obj, FreeCAD.Placement())


def global_placement(obj):
    """Where obj is placed in the document: its Placement, times those of the groups with
    a placement (App::Part, Body) it is in."""
    placement = obj.Placement
    parent = obj.getParentGeoFeatureGroup()
    while parent is not None:
        placement = parent.Placement.multiply(placement)
        parent = parent.getParentGeoFeatureGroup()
    return placement


def is_basic_curve(obj):
    """Whether obj is a BasicCurve feature."""
    return isinstance(getattr(obj, "Proxy", None), BasicCurveFeature)


def make_basic_curve(doc, kind="Circle arc", placement=None, name=None, **dimensions):
    """Create a basic curve of the given kind in `doc` and recompute, as one undoable step.

    Dimensions not given take the kind's defaults (KIND_DEFAULTS); lengths in model units,
    angles in degrees. Returns the new object; bad dimensions leave it with the message
    in its Status (see the module docstring). Unknown kinds or dimensions raise InputError.
    """
    if kind not in KINDS:
        raise InputError(f"unknown kind {kind!r}: use one of {', '.join(KINDS)}")
    unknown = sorted(set(dimensions) - set(KIND_PROPERTIES[kind]))
    if unknown:
        raise InputError(f"{kind} has no dimension {', '.join(unknown)}: it has {', '.join(KIND_PROPERTIES[kind])}")
    values = dict(KIND_DEFAULTS[kind], **dimensions)
    with undo_step(doc, "Create basic curve"):
        obj = doc.addObject("Part::FeaturePython", name or kind.title().replace(" ", ""))
        BasicCurveFeature(obj)
        obj.Kind = kind
        for key, value in values.items():
            setattr(obj, key, value)
        if placement is not None:
            obj.Placement = placement
        attach_view_provider(obj, "ViewProviderBasicCurve")
        doc.recompute()
    return obj
