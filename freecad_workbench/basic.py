"""Basic curves for design with basic curves (csr paper, Sections 3.2, 5 and 6).

Every basic curve is parameterised over u in [0, 1] and offers ``value(u)``,
``d1(u)``, ``d2(u)`` (FreeCAD Vectors), ``parameter_of(point)`` (eq. (4) for circle arcs,
eq. (5) for the others) and ``to_part()`` (FreeCAD geometry: the native conic arc where
FreeCAD has one, else a B-spline). Conics and rational cubics are converted exactly
(Section 6); spirals, involutes and user curves are approximated (Section 5).
``Samples(points)`` is the third kind of piece, data without a parameterization: its
part of a design is its csr-spline (Section 4; the unifying spline of Section 1, Fig. 1).

    import freecad_workbench as fw
    arc = fw.basic.CircleArc(center=(0, 0, 0), radius=1, start_angle=0, end_angle=math.pi)
    arc.parameter_of(arc.value(0.3))   # 0.3
"""
from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any, Callable, Optional, Sequence, Union

import numpy as np

from . import kernel
from .errors import InputError
from .kernel import CurveLike, PointsLike, VectorLike, as_real, as_reals, require_bounded, to_part

if TYPE_CHECKING:
    import FreeCAD
    import Part

__all__ = [
    "BasicCurve",
    "LineSegment",
    "CircleArc",
    "EllipseArc",
    "ParabolaArc",
    "HyperbolaArc",
    "RationalCubic",
    "ArchimedeanSpiral",
    "CircleInvolute",
    "ParametricCurve",
    "Samples",
    "from_edge",
]


def _vector3(value, name):
    if hasattr(value, "x") and hasattr(value, "y") and hasattr(value, "z"):
        value = (value.x, value.y, value.z)
    try:
        v = np.array([float(c) for c in value], dtype=float)
    except (TypeError, ValueError):
        raise InputError(f"{name} must be a point or vector, got {value!r}") from None
    if v.shape == (2,):
        v = np.r_[v, 0.0]
    if v.shape != (3,) or not np.all(np.isfinite(v)):
        raise InputError(f"{name} must be 2 or 3 finite numbers, got {value!r}")
    return v


def _frame(normal, x_axis):
    """Orthonormal (x, y) spanning the plane with the given normal; x is x_axis projected
    into the plane, or a fixed choice when x_axis is None."""
    n = _vector3(normal, "normal")
    if np.linalg.norm(n) < 1e-300:
        raise InputError("the normal must not be zero")
    n = n / np.linalg.norm(n)
    if x_axis is None:
        x_axis = (1.0, 0.0, 0.0) if abs(n[0]) < 0.9 else (0.0, 1.0, 0.0)
    x = _vector3(x_axis, "x_axis")
    x = x - n * np.dot(x, n)
    if np.linalg.norm(x) < 1e-12:
        raise InputError("the x axis must not be parallel to the normal")
    x = x / np.linalg.norm(x)
    return x, np.cross(n, x)


class BasicCurve:
    """Base of the basic curves: a kernel curve over u in [0, 1]."""

    exact = True  # Section 6 applies (rational of degree <= 3)

    def __init__(self, kernel_curve: kernel.BasicCurve) -> None:
        self._curve = kernel_curve
        if not math.isfinite(kernel_curve.size()):
            raise InputError(f"the {type(self).__name__}'s size is not finite: its numbers are too large, too small "
                             "or too close together")

    def _jet(self, which, u):
        """value, d1 or d2 at u as a FreeCAD Vector; InputError where it is not finite (far
        outside [0, 1] the extrapolation overflows)."""
        import FreeCAD

        v = getattr(self._curve, which)(as_real(u, "u"))
        if not np.all(np.isfinite(v)):
            raise InputError(f"{which}({u!r}) of the {type(self).__name__} is not finite: u is too far outside [0, 1]")
        return FreeCAD.Vector(*v)

    def value(self, u: float) -> FreeCAD.Vector:
        return self._jet("value", u)

    def d1(self, u: float) -> FreeCAD.Vector:
        return self._jet("d1", u)

    def d2(self, u: float) -> FreeCAD.Vector:
        return self._jet("d2", u)

    def parameter_of(self, point: VectorLike, tolerance: float = 1e-9) -> float:
        """u of a point on the curve; InputError if it is farther than tolerance x size."""
        return self._curve.parameter_of(_vector3(point, "point"), as_real(tolerance, "tolerance", minimum=0))

    def size(self) -> float:
        return self._curve.size()

    def to_part(self) -> Any:
        """FreeCAD geometry of the curve: an exact rational B-spline (subclasses with a
        native FreeCAD type return that instead)."""
        curve, _, _ = kernel.merge_pieces([kernel.piece_polygon(self._curve, np.zeros(0))], 0.0)
        return to_part(curve)

    def __repr__(self):
        return f"<{type(self).__name__} from {tuple(self.value(0))} to {tuple(self.value(1))}>"


class LineSegment(BasicCurve):
    def __init__(self, start: VectorLike, end: VectorLike) -> None:
        self.start, self.end = _vector3(start, "start"), _vector3(end, "end")
        super().__init__(kernel.line_segment(self.start, self.end))

    def to_part(self) -> Union[Part.LineSegment, Part.BSplineCurve]:
        """A Part.LineSegment; one longer than OCCT's lines hold (Precision::Infinite, 2e100)
        comes back as its exact degree-1 B-spline."""
        import FreeCAD
        import Part

        if self.size() >= 2e100:
            return super().to_part()
        return Part.LineSegment(FreeCAD.Vector(*self.start), FreeCAD.Vector(*self.end))


class CircleArc(BasicCurve):
    """Circle arc from start_angle to end_angle (radians, counter-clockwise about the
    normal when end > start, clockwise when end < start); angles from x_axis."""

    def __init__(self, center: VectorLike = (0, 0, 0), radius: float = 1.0, start_angle: float = 0.0,
                 end_angle: float = math.pi / 2, normal: VectorLike = (0, 0, 1),
                 x_axis: Optional[VectorLike] = None) -> None:
        self.center = _vector3(center, "center")
        self.x_axis, self.y_axis = _frame(normal, x_axis)
        self.radius = as_real(radius, "radius", finite=False)
        self.start_angle = as_real(start_angle, "start_angle", finite=False)
        self.end_angle = as_real(end_angle, "end_angle", finite=False)
        super().__init__(
            kernel.CircleArc(self.center, self.x_axis, self.y_axis, self.radius, self.start_angle,
                             self.end_angle - self.start_angle)
        )

    def to_part(self) -> Union[Part.ArcOfCircle, Part.BSplineCurve]:
        import FreeCAD
        import Part

        a0, a1 = sorted((self.start_angle, self.end_angle))
        normal = np.cross(self.x_axis, self.y_axis)
        circle = Part.Circle(FreeCAD.Vector(*self.center), FreeCAD.Vector(*normal), self.radius)
        # Align FreeCAD's x axis with ours so the angles mean the same.
        circle.XAxis = FreeCAD.Vector(*self.x_axis)
        arc = Part.ArcOfCircle(circle, a0, a1)
        return arc if self.end_angle > self.start_angle else _reversed(arc)


class EllipseArc(BasicCurve):
    """Ellipse arc x = a cos t, y = b sin t in the frame (x_axis = major axis), t from
    start to end."""

    def __init__(self, center: VectorLike = (0, 0, 0), major_radius: float = 2.0, minor_radius: float = 1.0,
                 start: float = 0.0, end: float = math.pi / 2, normal: VectorLike = (0, 0, 1),
                 x_axis: Optional[VectorLike] = None) -> None:
        self.center = _vector3(center, "center")
        self.x_axis, self.y_axis = _frame(normal, x_axis)
        self.a = as_real(major_radius, "major_radius", finite=False)
        self.b = as_real(minor_radius, "minor_radius", finite=False)
        self.start = as_real(start, "start", finite=False)
        self.end = as_real(end, "end", finite=False)
        super().__init__(kernel.ellipse_arc(self.center, self.x_axis, self.y_axis, self.a, self.b, self.start,
                                            self.end - self.start))


class ParabolaArc(BasicCurve):
    """Parabola arc x = t^2 / (4 focal), y = t (FreeCAD's convention), t in [t0, t1];
    vertex at `vertex`, x_axis along the axis of symmetry."""

    def __init__(self, vertex: VectorLike = (0, 0, 0), focal: float = 1.0, t0: float = -1.0, t1: float = 1.0,
                 normal: VectorLike = (0, 0, 1), x_axis: Optional[VectorLike] = None) -> None:
        self.vertex = _vector3(vertex, "vertex")
        self.x_axis, self.y_axis = _frame(normal, x_axis)
        self.focal = as_real(focal, "focal", finite=False)
        self.t0, self.t1 = as_real(t0, "t0", finite=False), as_real(t1, "t1", finite=False)
        super().__init__(kernel.parabola_arc(self.vertex, self.x_axis, self.y_axis, self.focal, self.t0, self.t1))


class HyperbolaArc(BasicCurve):
    """Hyperbola arc x = a cosh t, y = b sinh t, t in [t0, t1]."""

    def __init__(self, center: VectorLike = (0, 0, 0), major_radius: float = 1.0, minor_radius: float = 1.0,
                 t0: float = -1.0, t1: float = 1.0, normal: VectorLike = (0, 0, 1),
                 x_axis: Optional[VectorLike] = None) -> None:
        self.center = _vector3(center, "center")
        self.x_axis, self.y_axis = _frame(normal, x_axis)
        self.a = as_real(major_radius, "major_radius", finite=False)
        self.b = as_real(minor_radius, "minor_radius", finite=False)
        self.t0 = as_real(t0, "t0", finite=False)
        self.t1 = as_real(t1, "t1", finite=False)
        super().__init__(kernel.hyperbola_arc(self.center, self.x_axis, self.y_axis, self.a, self.b, self.t0, self.t1))


class RationalCubic(BasicCurve):
    """Rational Bézier curve of degree <= 3 from homogeneous control points (rows
    (w x, w y, w z, w)), or from poles and weights."""

    def __init__(self, poles: Optional[PointsLike] = None, weights: Optional[Sequence[float]] = None,
                 homogeneous: Optional[PointsLike] = None) -> None:
        if homogeneous is None:
            if poles is None:
                raise InputError("give poles (and weights) or homogeneous control points")
            if isinstance(poles, (str, bytes)) or not hasattr(poles, "__iter__"):
                raise InputError(f"poles must be a list of points, got {poles!r}")
            p = np.array([_vector3(q, f"pole {i}") for i, q in enumerate(poles)])
            w = np.ones(len(p)) if weights is None else as_reals(weights, "weights")
            if w.shape != (len(p),):
                raise InputError(f"expected {len(p)} weights, got {np.shape(w)}")
            homogeneous = np.c_[p * w[:, None], w]
        try:
            h = np.ascontiguousarray(homogeneous, dtype=float)
        except (TypeError, ValueError):
            raise InputError(f"homogeneous control points must be rows of 4 numbers, got {homogeneous!r}") from None
        if h.ndim != 2 or h.shape[1] != 4 or not 2 <= h.shape[0] <= 4:
            raise InputError(f"homogeneous control points must be 2 to 4 rows of 4 numbers, got shape {h.shape}")
        self.homogeneous = h
        super().__init__(kernel.RationalBezierCurve(h))


class _Transcendental(BasicCurve):
    exact = False  # Section 5 applies

    def to_part(self, tolerance: float = 1e-9) -> Part.BSplineCurve:
        """A cubic C2 B-spline within tolerance x size of the curve (Section 5 with marks
        doubled until the deviation at sampled parameters is below it)."""
        size = self.size()
        for m in (16, 32, 64, 128, 256, 512, 1024):
            marks = np.arange(1, m) / m
            curve, _, _ = kernel.merge_pieces([kernel.piece_polygon(self._curve, marks)], 0.0)
            part = to_part(curve)
            u = np.linspace(0, 1, 8 * m + 1)
            error = max((part.value(x) - self.value(x)).Length for x in u)
            if error <= tolerance * size:
                break
        return part


class ArchimedeanSpiral(_Transcendental):
    """Archimedean spiral r = a + b theta, theta in [theta0, theta1]."""

    def __init__(self, center: VectorLike = (0, 0, 0), a: float = 0.0, b: float = 1.0 / (2 * math.pi),
                 theta0: float = math.pi / 2, theta1: float = 2 * math.pi, normal: VectorLike = (0, 0, 1),
                 x_axis: Optional[VectorLike] = None) -> None:
        self.center = _vector3(center, "center")
        self.x_axis, self.y_axis = _frame(normal, x_axis)
        self.a = as_real(a, "a", finite=False)
        self.b = as_real(b, "b", finite=False)
        self.theta0 = as_real(theta0, "theta0", finite=False)
        self.theta1 = as_real(theta1, "theta1", finite=False)
        super().__init__(
            kernel.archimedean_spiral(self.center, self.x_axis, self.y_axis, self.a, self.b, self.theta0, self.theta1)
        )


class CircleInvolute(_Transcendental):
    """Involute of the circle of radius r: r (cos t + t sin t, sin t - t cos t), t in [t0, t1]."""

    def __init__(self, center: VectorLike = (0, 0, 0), radius: float = 1.0, t0: float = 0.0, t1: float = math.pi,
                 normal: VectorLike = (0, 0, 1), x_axis: Optional[VectorLike] = None) -> None:
        self.center = _vector3(center, "center")
        self.x_axis, self.y_axis = _frame(normal, x_axis)
        self.radius = as_real(radius, "radius", finite=False)
        self.t0, self.t1 = as_real(t0, "t0", finite=False), as_real(t1, "t1", finite=False)
        super().__init__(
            kernel.circle_involute(self.center, self.x_axis, self.y_axis, self.radius, self.t0, self.t1)
        )


class ParametricCurve(_Transcendental):
    """A curve given by a Python function f(s) -> point, s in [s0, s1]. Derivatives are
    taken from `derivative` / `second_derivative` when given, else by central differences.
    It goes through the Section 5 route."""

    def __init__(self, function: Callable[[float], VectorLike], s0: float = 0.0, s1: float = 1.0,
                 derivative: Optional[Callable[[float], VectorLike]] = None,
                 second_derivative: Optional[Callable[[float], VectorLike]] = None) -> None:
        if not callable(function):
            raise InputError("a parametric curve needs a function f(s) -> point")
        self.function, self.s0, self.s1 = function, as_real(s0, "s0"), as_real(s1, "s1")
        step = 1e-4 * (self.s1 - self.s0) if self.s1 > self.s0 else 1e-4

        def f(s):
            return _vector3(function(s), "f(s)")

        def df(s):
            if derivative is not None:
                return _vector3(derivative(s), "f'(s)")
            return (f(s + step) - f(s - step)) / (2 * step)

        def d2f(s):
            if second_derivative is not None:
                return _vector3(second_derivative(s), "f''(s)")
            return (f(s + step) - 2 * f(s) + f(s - step)) / (step * step)

        super().__init__(kernel.ParametricCurve(lambda s: (f(s), df(s), d2f(s)), self.s0, self.s1))


class Samples:
    """Sampled data as a piece of fw.design_spline: the unifying spline of the csr paper
    (Section 1, Fig. 1). Its part of the design is the csr-spline of the samples (Section 4,
    eq. (6)), a cubic C2 B-spline with a knot per sample at the samples' parameters
    (chordal by default); in the design its control points keep their beta_i and it joins
    its neighbours by Fig. 9 (agree, averaged, edge; beta := 1 at the new control points),
    see docs/READINGS.md, "The unifying spline".

    points: an (N,2)/(N,3) array-like, FreeCAD Vectors or Part Vertexes, or a Points object
        (Points.Points or a Points::Feature); N >= 3, in the order of traversal.
    parametrization, epsilon, epsilon_rule: as for fw.csr_spline.
    Raises InputError for fewer than 3 samples, samples that are not finite, consecutive
    samples that coincide, all samples coincident or wrong shapes.
    """

    exact = False

    def __init__(self, points: Any, parametrization: str = "chordal", epsilon: float = 1e-9,
                 epsilon_rule: str = "case") -> None:
        from .csr import EPSILON_RULES, PARAMETRIZATIONS
        from .kernel import as_choice, as_points

        as_choice(parametrization, "parametrization", PARAMETRIZATIONS)
        as_choice(epsilon_rule, "epsilon_rule", EPSILON_RULES)
        for _ in range(2):  # Points::Feature -> Points.Points -> [FreeCAD.Vector]
            if hasattr(points, "Points") and not isinstance(points, (list, tuple, np.ndarray)):
                points = points.Points
        q = as_points(points, "samples")
        if len(q) < 3:
            raise InputError(f"a sampled piece needs at least 3 samples, got {len(q)}")
        if q.shape[1] == 2:
            q = np.ascontiguousarray(np.c_[q, np.zeros(len(q))])
        self.points = q
        self.parametrization, self.epsilon_rule = parametrization, epsilon_rule
        self.epsilon = as_real(epsilon, "epsilon", finite=False)
        try:
            self._polygon = kernel.samples_polygon(q, parametrization, self.epsilon, EPSILON_RULES[epsilon_rule])
        except InputError as exc:
            raise InputError(f"samples: {exc}") from None

    def to_part(self) -> Part.BSplineCurve:
        """The piece alone: the csr-spline of the samples over u in [0, 1] (Part.BSplineCurve)."""
        curve, _, _ = kernel.merge_pieces([self._polygon], 0.0)
        return to_part(curve)

    def __repr__(self):
        return f"<Samples: {len(self.points)} from {tuple(self.points[0])} to {tuple(self.points[-1])}>"


def _reversed(geometry):
    """A B-spline of the geometry with the direction reversed."""
    b = geometry.toBSpline()
    b.reverse()
    return b


def from_edge(edge: CurveLike) -> BasicCurve:
    """The basic curve of a FreeCAD edge (Part or Sketcher): lines, circles, ellipses,
    parabolas, hyperbolas and their arcs, over the edge's parameter range."""
    import Part

    if not isinstance(edge, Part.Edge):
        if isinstance(edge, Part.Shape) and len(edge.Edges) == 1:
            edge = edge.Edges[0]
        elif hasattr(edge, "toShape"):
            edge = edge.toShape()
        else:
            raise InputError(f"not an edge: {type(edge).__name__}")
    curve, t0, t1 = edge.Curve, edge.FirstParameter, edge.LastParameter
    require_bounded(t0, t1, type(curve).__name__)
    if isinstance(curve, (Part.Line, Part.LineSegment)):
        return LineSegment(edge.valueAt(t0), edge.valueAt(t1))
    if isinstance(curve, Part.BSplineCurve) or isinstance(curve, Part.BezierCurve):
        raise InputError("a B-spline or Bézier edge is not a basic curve: use it as data for the csr fit")
    if isinstance(curve, (Part.Circle, Part.Ellipse)) and edge.isClosed():
        raise InputError(f"a full {type(curve).__name__.lower()} cannot be one piece: use two arcs of it")
    normal, x_axis = getattr(curve, "Axis", None), getattr(curve, "XAxis", None)
    if isinstance(curve, Part.Circle):
        return CircleArc(curve.Center, curve.Radius, t0, t1, normal, x_axis)
    if isinstance(curve, Part.Ellipse):
        return EllipseArc(curve.Center, curve.MajorRadius, curve.MinorRadius, t0, t1, normal, x_axis)
    if isinstance(curve, Part.Parabola):
        return ParabolaArc(curve.Location, curve.Focal, t0, t1, normal, x_axis)
    if isinstance(curve, Part.Hyperbola):
        return HyperbolaArc(curve.Center, curve.MajorRadius, curve.MinorRadius, t0, t1, normal, x_axis)
    raise InputError(f"{type(curve).__name__} edges are not basic curves (lines and conics are)")
