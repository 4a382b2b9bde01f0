"""The only module that talks to the compiled kernel (``_kernel``): arrays in, Part geometry out.

Every other module of the macro layer reaches the compiled functions through the names
below, grouped by the capability that calls them, and hands results over to FreeCAD with
to_part, surface_to_part, adopt and blend_result. ``_kernel.pyi`` types the compiled module.
"""
from __future__ import annotations

import math
import numbers
import sys
from collections import namedtuple
from typing import TYPE_CHECKING, Any, Sequence, Union

import numpy as np

if TYPE_CHECKING:  # names of the annotations only: FreeCAD and Part load when a function needs them
    import FreeCAD
    import Part

from fairsplines_setup import record as _record

# The kernel built for this FreeCAD: the package's own (make build) or the first-run build's
# in the user's data folder; KernelUnavailable (an ImportError) says what was found instead.
# BRIDGE_OFF: why the fast hand-over is off (the kernel's OpenCASCADE is not FreeCAD's).
BRIDGE_OFF = _record.activate(sys.modules[__package__].__path__)
try:
    from . import _kernel
except ImportError as exc:  # a module that matches the record but does not load (a missing library)
    raise _record.KernelUnavailable(
        _record.unavailable_message() + "\nImporting it failed: " + str(exc)
    ) from exc

# The exceptions of the macro API (errors.py re-exports them): the binding translates the
# kernel's typed exceptions into these.
InputError = _kernel.InputError
InputError.__module__ = "freecad_workbench"
InputError.__doc__ = "Bad input: the message names the problem (a subclass of ValueError)."
NoMonotoneSolution = _kernel.NoMonotoneSolution
NoMonotoneSolution.__module__ = "freecad_workbench"
NoMonotoneSolution.__doc__ = (
    "No monotone-curvature curve of the family meets the end conditions; the message says why "
    "(a subclass of InputError)."
)

# The argument types of the macro API, for its annotations (the as_* functions below check
# the values). FreeCAD 0.20 does not export Part's curve base class: a curve is Any there.
PointsLike = Union[np.ndarray, Sequence[Any]]  #: FreeCAD Vectors, Part Vertexes, tuples, an (N, 2)/(N, 3) array
VectorLike = Union["FreeCAD.Vector", "Part.Vertex", Sequence[float], np.ndarray]  #: one point or direction
CurveLike = Union["Part.Edge", "Part.Shape", "Part.BSplineCurve", Any]  #: a Part curve or edge
SurfaceLike = Union["Part.BSplineSurface", "Part.Face", "Part.Shape"]  #: a B-spline surface or a face on one

# The compiled functions and classes, by the capability (module) that calls them (the
# hand-over functions below call the kernel's curve and surface constructors themselves).
# csr fitting (csr.py).
EpsilonRule = _kernel.EpsilonRule
csr_spline = _kernel.csr_spline
csr_edge_capsule = _kernel.csr_edge_capsule
classic_interpolation = _kernel.classic_interpolation
quasi_interpolant = _kernel.quasi_interpolant
control_point_spline = _kernel.control_point_spline
quadratic_design = _kernel.quadratic_design
# Basic curves (basic.py).
BasicCurve = _kernel.BasicCurve
line_segment = _kernel.line_segment
CircleArc = _kernel.CircleArc
ellipse_arc = _kernel.ellipse_arc
parabola_arc = _kernel.parabola_arc
hyperbola_arc = _kernel.hyperbola_arc
RationalBezierCurve = _kernel.RationalBezierCurve
archimedean_spiral = _kernel.archimedean_spiral
circle_involute = _kernel.circle_involute
ParametricCurve = _kernel.ParametricCurve
# Design with basic curves (design.py; basic.py converts one piece the same way).
piece_polygon = _kernel.piece_polygon
merge_pieces = _kernel.merge_pieces
complete_marks = _kernel.complete_marks
quintic_pieces = _kernel.quintic_pieces
samples_polygon = _kernel.samples_polygon  # the sampled piece (basic.Samples)
revolve = _kernel.revolve
# Curve analysis (analysis.py).
curvature_profile = _kernel.curvature_profile
curvature_sign_changes = _kernel.curvature_sign_changes
curvature_extrema = _kernel.curvature_extrema
max_distance = _kernel.max_distance
# Monotonic-curvature B-splines (monotone.py).
analyze_end_conditions = _kernel.analyze_end_conditions
monotone_spline = _kernel.monotone_spline
design_monotone = _kernel.design_monotone
certify_monotone = _kernel.certify_monotone
certify_space_curvature = _kernel.certify_space_curvature
check_segments = _kernel.check_segments
curvature_variation = _kernel.curvature_variation
derivative_polygons = _kernel.derivative_polygons
# Fair blends (fair_blend.py).
fair_blend = _kernel.fair_blend
fair_blend_space = _kernel.fair_blend_space
# The fair fit (fair_fit.py).
fair_fit = _kernel.fair_fit
# Surface analysis (surface_analysis.py).
surface_curvature = _kernel.surface_curvature
edge_continuity = _kernel.edge_continuity
curvature_map = _kernel.curvature_map
# Face blends (face_blend.py).
blend_faces = _kernel.blend_faces
# Basic shapes (shapes.py).
sphere_zone = _kernel.sphere_zone
cylinder = _kernel.cylinder
cone = _kernel.cone
torus = _kernel.torus
ShapeOfRevolution = _kernel.ShapeOfRevolution
G2Surface = _kernel.G2Surface
BSplineCurve = _kernel.BSplineCurve  # a profile given as arrays (shapes.Revolution, the quadrics)
BSplineSurface = _kernel.BSplineSurface  # a ring mapped back for an affine image (blend.py)
RevolutionProfile = _kernel.RevolutionProfile
revolution_profile = _kernel.revolution_profile
revolution = _kernel.revolution
shape_of_revolution = _kernel.shape_of_revolution
image_g2 = _kernel.image_g2
dupin_cyclide = _kernel.dupin_cyclide
BlendComplex = _kernel.BlendComplex
# Basic shapes blended into NURBS, C2 (blend.py) and C1 (blend_c1.py).
ring_knots = _kernel.ring_knots
blend_sphere_zone = _kernel.blend_sphere_zone
blend_sphere_zone_naive = _kernel.blend_sphere_zone_naive
blend_cone = _kernel.blend_cone
blend_torus = _kernel.blend_torus
blend_chain = _kernel.blend_chain
blend_edited = _kernel.blend_edited
join_shapes = _kernel.join_shapes
blend_shape = _kernel.blend_shape
blend_cyclide = _kernel.blend_cyclide
blend_cyclide_naive = _kernel.blend_cyclide_naive
image_complex = _kernel.image_complex
ring_knots_c1 = _kernel.ring_knots_c1
blend_c1 = _kernel.blend_c1
join_shapes_c1 = _kernel.join_shapes_c1


def as_real(value, name, finite=True, minimum=None, positive=False):
    """One real number as a float; InputError naming the argument for anything else (None,
    strings, sequences, complex), for NaN and infinity (finite=False passes them on, for the
    kernel to name what they mean), below `minimum` or, when positive, not above 0."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (numbers.Real, np.ndarray)):
        raise InputError(f"{name} must be a number, got {value!r}")
    try:
        x = float(value)
    except (TypeError, ValueError):
        raise InputError(f"{name} must be a number, got {value!r}") from None
    if not finite:
        return x
    if not math.isfinite(x):
        raise InputError(f"{name} must be finite, got {x}")
    if minimum is not None and not x >= minimum:
        raise InputError(f"{name} must not be negative, got {x:g}" if minimum == 0 else
                         f"{name} must be at least {minimum:g}, got {x:g}")
    if positive and not x > 0:
        raise InputError(f"{name} must be positive, got {x:g}")
    return x


def as_count(value, name, minimum=0, maximum=None):
    """A whole number in [minimum, maximum] as an int (integral floats are accepted); the
    maximum bounds the work a count asks for, with a message instead of a long run."""
    if isinstance(value, (bool, np.bool_)):
        raise InputError(f"{name} must be a whole number, got {value!r}")
    if isinstance(value, numbers.Integral):
        n = int(value)
    elif isinstance(value, numbers.Real) and math.isfinite(value) and float(value).is_integer():
        n = int(value)
    else:
        raise InputError(f"{name} must be a whole number, got {value!r}")
    if n < minimum:
        raise InputError(f"{name} must be at least {minimum}, got {n}")
    if maximum is not None and n > maximum:
        raise InputError(f"{name} = {n} is more than {maximum}: the work it asks for is unbounded")
    return n


def as_flag(value, name):
    """A yes/no argument: bool (or 0 and 1); anything else (None, strings, 2) is an InputError."""
    if isinstance(value, (bool, np.bool_)):
        return bool(value)
    if isinstance(value, numbers.Integral) and value in (0, 1):
        return bool(value)
    raise InputError(f"{name} must be True or False, got {value!r}")


def as_choice(value, name, choices):
    """One of the strings `choices` (a tuple, or a dict whose keys are the choices)."""
    if not isinstance(value, str) or value not in choices:
        raise InputError(f"unknown {name} {value!r}: {name} must be one of {', '.join(map(repr, choices))}")
    return value


def as_reals(values, name):
    """A 1-D float64 array of numbers (a list, tuple or array); InputError naming the argument
    for strings, None, nested or ragged lists."""
    if isinstance(values, (str, bytes)) or values is None:
        raise InputError(f"{name} must be a list of numbers, got {values!r}")
    try:
        array = np.asarray(values, dtype=float)
    except (TypeError, ValueError):
        raise InputError(f"{name} must be a list of numbers, got {values!r}") from None
    if array.ndim != 1:
        raise InputError(f"{name} must be a flat list of numbers, got shape {array.shape}")
    return np.ascontiguousarray(array)


def as_points(points, name="points"):
    """Coerce FreeCAD Vectors, Part Vertexes, tuples or an (N,2)/(N,3) array to a
    C-contiguous float64 array of shape (N, 2) or (N, 3)."""
    if isinstance(points, np.ndarray):
        if (points.dtype == np.float64 and points.ndim == 2 and points.shape[1] in (2, 3)
                and points.flags.c_contiguous):
            return points  # already what the kernel reads (the common case: no numpy calls)
        if points.dtype.kind not in "iuf":  # complex, bool, object, strings: not coordinates
            raise InputError(f"{name} must be real numbers, got an array of {points.dtype}")
        array = points
    else:
        rows = []
        if isinstance(points, (str, bytes)) or not hasattr(points, "__iter__"):
            raise InputError(f"{name} must be a list of points, got {points!r}")
        for i, p in enumerate(points):
            if hasattr(p, "Point"):  # Part.Vertex
                p = p.Point
            if hasattr(p, "x") and hasattr(p, "y") and hasattr(p, "z"):  # FreeCAD.Vector
                rows.append((p.x, p.y, p.z))
            else:
                try:
                    rows.append(tuple(float(c) for c in p))
                except (TypeError, ValueError):
                    raise InputError(f"{name}[{i}] is not a point: {p!r}") from None
        if rows and len({len(r) for r in rows}) != 1:
            raise InputError(f"{name} mix 2D and 3D points")
        array = np.array(rows, dtype=float) if rows else np.zeros((0, 3))
    try:
        array = np.ascontiguousarray(array, dtype=np.float64)
    except (TypeError, ValueError):
        raise InputError(f"{name} must be numbers") from None
    if array.ndim != 2 or array.shape[1] not in (2, 3):
        raise InputError(f"{name} must have shape (N, 2) or (N, 3), got {array.shape}")
    return array


def as_vector(value, name="vector"):
    """One point or direction (FreeCAD.Vector, Part.Vertex, 2 or 3 numbers) as 3 floats
    (z = 0 for 2 numbers). The values themselves (NaN, zero length) are the kernel's to check."""
    if hasattr(value, "Point"):  # Part.Vertex
        value = value.Point
    try:
        v = [float(value.x), float(value.y), float(value.z)] if hasattr(value, "x") else [float(c) for c in value]
    except (TypeError, ValueError):
        raise InputError(f"{name} is not a point or vector: {value!r}") from None
    if len(v) not in (2, 3):
        raise InputError(f"{name} needs 2 or 3 coordinates, got {len(v)}")
    return np.array(v + [0.0] * (3 - len(v)))


def to_part(curve):
    """Exact hand-over of a kernel BSplineCurve to a FreeCAD Part.BSplineCurve.

    Fastest route first: the kernel builds the OCCT edge and FreeCAD adopts it through
    Part.__fromPythonOCC__ (no copy of the data in Python). Without the SWIG bridge the
    arrays go into buildFromPolesMultsKnots. Both are bit-for-bit exact."""
    if _BRIDGE is not None:
        return adopt(_kernel.edge_capsule(curve)).Edge1.Curve
    return to_part_arrays(curve)


def has_bridge():
    """Whether kernel-built edges reach FreeCAD without a copy (the SWIG bridge is built)."""
    return _BRIDGE is not None


def adopt(capsule):
    """The Part.Shape of a shape the kernel built (a ``*_capsule`` result), taking it over:
    the only caller of occ_bridge.adopt_shape. A capsule hands its shape over once (a
    second adoption is a TypeError); one never adopted frees its shape when collected.
    Only with the bridge (has_bridge())."""
    import Part

    return Part.__fromPythonOCC__(_BRIDGE.adopt_shape(capsule))


def to_part_arrays(curve):
    """The array route of to_part (buildFromPolesMultsKnots reads numpy arrays)."""
    import Part

    poles = curve.poles
    if poles.shape[1] == 2:
        poles = np.c_[poles, np.zeros(len(poles))]
    # FreeCAD reads integer arrays as 64-bit: an int32 array crashes it.
    mults = curve.mults.astype(np.int64)
    result = Part.BSplineCurve()
    if curve.rational:
        result.buildFromPolesMultsKnots(poles, mults, curve.knots, curve.periodic, curve.degree, curve.weights)
    else:
        result.buildFromPolesMultsKnots(poles, mults, curve.knots, curve.periodic, curve.degree)
    return result


def surface_to_part(surface):
    """Exact hand-over of a kernel BSplineSurface to a Part.BSplineSurface."""
    import Part

    if _BRIDGE is not None:
        return adopt(_kernel.face_capsule(surface)).Face1.Surface
    poles = surface.poles.reshape(surface.nu, surface.nv, 3)
    result = Part.BSplineSurface()
    weights = surface.weights.reshape(surface.nu, surface.nv) if surface.weights.size else None
    args = [poles.tolist(), surface.mults_u.tolist(), surface.mults_v.tolist(), surface.knots_u.tolist(),
            surface.knots_v.tolist(), False, False, surface.degree_u, surface.degree_v]
    if weights is not None:
        args.append(weights.tolist())
    result.buildFromPolesMultsKnots(*args)
    return result


def surface_from_part(surface, image=None):
    """A kernel BSplineSurface from a Part.BSplineSurface or a face on one (exact); with
    image = a 4 x 4 matrix M, its homogeneous poles under (w p, w) -> M (w p, w)."""
    import Part

    if isinstance(surface, Part.Shape):
        faces = surface.Faces
        if len(faces) != 1:
            raise InputError(f"expected one face, got a shape with {len(faces)} faces")
        surface = faces[0].Surface
    if not isinstance(surface, Part.BSplineSurface):
        raise InputError(f"expected a Part.BSplineSurface, got {type(surface).__name__}")
    poles = np.array([[(p.x, p.y, p.z) for p in row] for row in surface.getPoles()], dtype=float)
    nu, nv = poles.shape[0], poles.shape[1]
    weights = np.array(surface.getWeights(), dtype=float).reshape(nu * nv)
    if image is not None:
        h = np.hstack([poles.reshape(nu * nv, 3) * weights[:, None], weights[:, None]]) @ np.asarray(image).T
        if not np.all(h[:, 3] > 0):
            raise InputError("the ring reaches where the shape's map has no positive weight (to infinity)")
        weights = h[:, 3].copy()
        poles = (h[:, :3] / weights[:, None]).reshape(nu, nv, 3)
    return _kernel.make_bspline_surface(
        np.ascontiguousarray(poles.reshape(nu * nv, 3)), weights, np.array(surface.getUKnots(), dtype=float),
        np.array(surface.getVKnots(), dtype=float), np.array(surface.getUMultiplicities(), dtype=np.int32),
        np.array(surface.getVMultiplicities(), dtype=np.int32), surface.UDegree, surface.VDegree,
        surface.isUPeriodic(), surface.isVPeriodic(), nu, nv)


BlendResult = namedtuple("BlendResult", "patches shell surface")
BlendResult.__module__ = "freecad_workbench"
BlendResult.__doc__ = (
    "patches: [(role, Part.BSplineSurface)] with role 'basic', 'transition' or 'freeform'; "
    "shell: a Part.Shell with one face per patch (in the same order), neighbours sharing their edges; "
    "surface: one Part.BSplineSurface that OCCT "
    "reports C2, or None where the complex is not C2 (the naive baseline)."
)


def blend_result(complex_, single=True):
    """The BlendResult of a kernel BlendComplex (blend.py and blend_c1.py). With the bridge,
    in one hand-over: the kernel builds the shell from its grid (shared edges, no sewing) and
    the single surface, and FreeCAD adopts both as one compound; the patches are the shell's
    faces' surfaces (the same Part.BSplineSurface, bit for bit, as a hand-over of each patch).
    single=False: no single surface (.surface None)."""
    if has_bridge():
        parts = adopt(complex_.result_capsule(single)).childShapes()
        shell = parts[0]
        roles = complex_.roles()
        faces = shell.Faces
        if len(faces) != len(roles):
            raise InputError(f"the shell has {len(faces)} faces for {len(roles)} patches")
        patches = [(role, face.Surface) for role, face in zip(roles, faces)]
        return BlendResult(patches, shell, parts[1].Surface if len(parts) > 1 else None)
    return blend_result_arrays(complex_, single)


def blend_result_arrays(complex_, single=True):
    """blend_result without the bridge: every patch and the single surface through arrays,
    the shell sewn by Part from the patches' faces."""
    import Part

    patches = [(role, surface_to_part(s)) for role, _, _, s in complex_.patches()]
    surface = complex_.single_surface() if single else None
    shell = Part.Shell([Part.Face(s) for _, s in patches])
    shell.sewShape()
    return BlendResult(patches, shell, surface_to_part(surface) if surface is not None else None)


def _load_bridge(off=None):
    """The SWIG bridge, or None: not built, or `off` (default BRIDGE_OFF) says the kernel's
    OpenCASCADE may not be FreeCAD's (a shape passed by pointer needs the same OCCT)."""
    if not _record.bridge_allowed(BRIDGE_OFF if off is None else off):
        return None
    try:
        from . import occ_bridge
    except ImportError:
        return None
    return occ_bridge


_BRIDGE = _load_bridge()


def from_part(curve):
    """A kernel BSplineCurve from a Part edge or curve (converted to B-spline if needed)."""
    import Part

    if isinstance(curve, Part.Shape):
        edges = curve.Edges
        if len(edges) != 1:
            raise InputError(f"expected one edge, got a shape with {len(edges)} edges")
        require_bounded(edges[0].FirstParameter, edges[0].LastParameter, type(edges[0].Curve).__name__)
        curve = _edge_bspline(edges[0])
    elif not isinstance(curve, Part.BSplineCurve):
        if not hasattr(curve, "toShape"):
            raise InputError(f"not a curve or edge: {type(curve).__name__}")
        require_bounded(curve.FirstParameter, curve.LastParameter, type(curve).__name__)
        curve = _edge_bspline(curve.toShape())
    poles = np.array([(p.x, p.y, p.z) for p in curve.getPoles()], dtype=float)
    weights = np.array(curve.getWeights(), dtype=float) if curve.isRational() else np.zeros(0)
    return _kernel.BSplineCurve(
        poles,
        np.array(curve.getKnots(), dtype=float),
        np.array(curve.getMultiplicities(), dtype=np.int32),
        curve.Degree,
        curve.isPeriodic(),
        weights,
    )


# OCCT's Precision::Infinite(): the parameter range of an unbounded line, parabola or hyperbola.
_INFINITE = 2e100


def require_bounded(first, last, kind):
    """InputError for an unbounded parameter range (an untrimmed line or conic)."""
    if not (abs(first) < _INFINITE and abs(last) < _INFINITE):
        raise InputError(f"the {kind} is unbounded (parameters {first:g} to {last:g}): trim it first")


def edge_bspline(edge):
    """The edge's exact Part.BSplineCurve (rational where needed), restricted to the edge and
    running the way the edge does in its wire (reversed for a reversed edge)."""
    geom = _edge_bspline(edge)
    if edge.Orientation == "Reversed":
        geom = geom.copy()
        geom.reverse()
    return geom


def _edge_bspline(edge):
    """The edge's exact (rational where needed) B-spline, restricted to the edge."""
    import Part

    geom = edge.Curve
    if not isinstance(geom, Part.BSplineCurve):
        edge = edge.toNurbs().Edges[0]  # exact conversion (BRepBuilderAPI_NurbsConvert)
        geom = edge.Curve
        if not isinstance(geom, Part.BSplineCurve):  # a Bezier stays a Bezier there: convert it exactly
            geom = geom.toBSpline(geom.FirstParameter, geom.LastParameter)
    if not _spans_whole(edge, geom):
        geom = geom.copy()
        geom.segment(edge.FirstParameter, edge.LastParameter)
    return geom


def _spans_whole(edge, geom):
    span = geom.LastParameter - geom.FirstParameter
    return (
        math.isclose(edge.FirstParameter, geom.FirstParameter, abs_tol=1e-12 * span)
        and math.isclose(edge.LastParameter, geom.LastParameter, abs_tol=1e-12 * span)
    )
