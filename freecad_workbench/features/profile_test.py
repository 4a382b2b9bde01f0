"""Profile test (csr paper, Section 6, Fig. 14): revolve a profile curve into its exact
surface of revolution (`fw.revolve_profile`) to inspect the profile's curvature in the
surface's highlight lines. Headless; in the GUI the surface is shown with zebra
(reflection-line) shading, see gui/zebra.py.

    from freecad_workbench.features.profile_test import make_profile_test
    test = make_profile_test(doc, design)   # axis: the sketch's vertical axis, or Z

The profile is an edge of any object (``(obj, "EdgeN")``) or a whole object with one
edge (a Design spline, an Edit polygon, a csr fit). The axis (`AxisPoint`,
`AxisDirection`) is chosen when the test is made, unless given: for an edge of a sketch,
the sketch's vertical (V) axis; otherwise the Z axis through the origin, or, when the
profile lies in a plane across Z, the in-plane direction nearest to Y through the origin.
A bad profile or axis keeps the last good shape with the message in `Status`.
"""
import FreeCAD

from ..design import revolve_profile
from ..errors import InputError
from .basic_curve import global_placement
from .edit_polygon import source_edge
from .base import FeatureProxy, attach_view_provider
from .undo import undo_step

_PROPERTIES = (
    ("App::PropertyLinkSub", "Profile", "The profile curve (an object with one edge, or one edge of an object)",
     None, 0),
    ("App::PropertyVectorDistance", "AxisPoint", "A point of the axis of revolution", None, 0),
    ("App::PropertyVector", "AxisDirection", "Direction of the axis of revolution", FreeCAD.Vector(0, 0, 1), 0),
    ("App::PropertyString", "Status", "'ok', or why the last recompute failed", "ok", 1),
    ("App::PropertyInteger", "Version", "Version of this object's properties", 0, 2),
)


class ProfileTest(FeatureProxy):
    """Proxy of a Part::FeaturePython: the exact surface of revolution of its profile."""

    Type = "ProfileTest"
    VERSION = 1
    GROUP = "Profile test"
    PROPERTIES = _PROPERTIES

    def build(self, obj):
        return profile_surface(obj).toShape()


def is_profile_test(obj):
    return isinstance(getattr(obj, "Proxy", None), ProfileTest)


def _profile_link(obj):
    if obj.Profile is None:
        raise InputError("no profile")
    source, subs = obj.Profile
    return source, (subs[0] if subs else "")


def profile_edge(obj):
    return source_edge(*_profile_link(obj))


def profile_surface(obj):
    """The exact Part.BSplineSurface of revolution of obj's profile about its axis."""
    edge = profile_edge(obj)
    direction = FreeCAD.Vector(obj.AxisDirection)
    if direction.Length <= 1e-12:
        raise InputError("the axis direction must not be zero")
    return revolve_profile(edge, FreeCAD.Vector(obj.AxisPoint), direction)


def default_axis(source, sub, edge):
    """(point, direction) of the default axis (see the module docstring)."""
    if sub and source is not None and source.isDerivedFrom("Sketcher::SketchObject"):
        placement = global_placement(source)
        return placement.Base, placement.Rotation.multVec(FreeCAD.Vector(0, 1, 0))
    z = FreeCAD.Vector(0, 0, 1)
    normal = _plane_normal(edge)
    if normal is None or abs(normal.dot(z)) <= 1e-9:
        return FreeCAD.Vector(), z
    y = FreeCAD.Vector(0, 1, 0)
    direction = y - normal * normal.dot(y)
    if direction.Length <= 1e-9:
        direction = FreeCAD.Vector(1, 0, 0) - normal * normal.x
    return FreeCAD.Vector(), direction.normalize()


def _plane_normal(edge):
    """The normal of the plane the edge lies in, or None (a line, a space curve)."""
    try:
        plane = edge.findPlane()
    except Exception:
        plane = None
    if plane is None:
        return None
    return FreeCAD.Vector(plane.Axis).normalize()


def make_profile_test(doc, profile, axis_point=None, axis_direction=None, name="ProfileTest"):
    """Create a Profile test of `profile` (an object with one edge, or (object, "EdgeN"))
    in `doc` and recompute, as one undoable step. Axis default: see the module docstring."""
    if isinstance(profile, (tuple, list)):
        source, sub = profile
    else:
        source, sub = profile, ""
    if not isinstance(source, FreeCAD.DocumentObject):
        raise InputError(f"not a document object: {source!r}")
    if axis_point is None or axis_direction is None:
        point, direction = default_axis(source, sub, source_edge(source, sub))
        axis_point = point if axis_point is None else axis_point
        axis_direction = direction if axis_direction is None else axis_direction
    with undo_step(doc, "Create profile test"):
        obj = doc.addObject("Part::FeaturePython", name)
        ProfileTest(obj)
        obj.Profile = (source, [sub] if sub else [])
        obj.AxisPoint = FreeCAD.Vector(*axis_point)
        obj.AxisDirection = FreeCAD.Vector(*axis_direction)
        attach_view_provider(obj, "ViewProviderProfileTest")
        doc.recompute()
    return obj
