"""Basic shapes as G2 rational bicubic splines (blending paper, Section 2): tensor
products of the circle pieces of eq. (2) around an axis with a profile, for arbitrary,
non-uniform angle partitions (radians). Each shape gives its exact patches as
Part.BSplineSurface objects and feeds fw.blend_basic_shape.

    import math, freecad_workbench as fw
    zone = fw.shapes.SphereZone((0, 0, 0), 10, [0, 1, 2.5, 4, 2 * math.pi], [-0.5, 0.2, 0.7])
    faces = [Part.Face(s) for s in zone.patches()]
"""
from __future__ import annotations

from typing import TYPE_CHECKING, Any, Optional, Sequence, Union

import numpy as np

from . import kernel
from .basic import _frame, _vector3
from .errors import InputError
from .kernel import VectorLike, as_choice, as_real, surface_to_part

if TYPE_CHECKING:
    import Part


def _angles(values, name):
    try:
        a = np.ascontiguousarray([float(v) for v in values], dtype=float)
    except (TypeError, ValueError):
        raise InputError(f"{name} must be a list of numbers (radians)") from None
    return a


# The most patches a shape's partition may have: 10,000 took 0.05 s here; 25 million (5000
# angles each way) ran out of memory.
MAX_SHAPE_PATCHES = 100_000


def _check_partition(around, along):
    patches = max(len(around) - 1, 0) * max(len(along) - 1, 0)
    if patches > MAX_SHAPE_PATCHES:
        raise InputError(f"the partition has {len(around)} by {len(along)} angles or heights: {patches} patches, "
                         f"more than {MAX_SHAPE_PATCHES}; use fewer")


def require_shape(shape: Any) -> BasicShape:
    """The shape itself when it is one of SphereZone, Cylinder, Cone, Torus, Revolution,
    AffineImage (what the blends take); InputError naming what it is otherwise."""
    if not isinstance(shape, _Shape):
        raise InputError("shape must be one of fw.shapes.SphereZone, Cylinder, Cone, Torus, Revolution, "
                         f"AffineImage, not {type(shape).__name__}")
    return shape


class _Shape:
    """A basic shape about an axis through `center` (frame: x_axis, axis)."""

    def __init__(self, center: VectorLike, axis: VectorLike, x_axis: Optional[VectorLike]) -> None:
        self._control = None  # the edited G2 control structure, once set_control was called
        self.center = _vector3(center, "center")
        self.axis = _vector3(axis, "axis")
        self.x_axis, self.y_axis = _frame(self.axis, x_axis)
        self.axis = np.cross(self.x_axis, self.y_axis)

    def _frame_args(self):
        return self.center, self.x_axis, self.y_axis

    def g2(self) -> kernel.G2Surface:
        """The kernel's G2 control structure (homogeneous Bézier points, weights, scalars)."""
        raise NotImplementedError

    def _revolution(self):
        """The kernel's description for the shape-to-shape join."""
        raise NotImplementedError

    def pole_at(self, end: str) -> bool:
        """True where the profile's `end` ('start' or 'end') lies on the axis (a dome's pole):
        nothing can be joined there."""
        as_choice(end, "end", ("start", "end"))
        return False

    @property
    def edited(self) -> bool:
        """True once a control point was changed with set_control."""
        return self._control is not None

    def control(self) -> kernel.G2Surface:
        """The control structure in use: the edited one, or the shape's own (g2())."""
        return self._control if self._control is not None else self.g2()

    def control_point(self, i: int, j: int, r: int, s: int) -> tuple[tuple[float, float, float], float]:
        """(point, weight) of Bézier point b_rs of patch (i, j) (i around the axis, j along
        the profile; r, s in 0..3) of the control structure in use."""
        control = self.control()
        for name, value, count in (("i", i, control.nu), ("j", j, control.nv), ("r", r, 4), ("s", s, 4)):
            if isinstance(value, bool) or not isinstance(value, (int, np.integer)):
                raise InputError(f"control_point: {name} must be an integer, got {value!r}")
            if not 0 <= value < count:
                raise InputError(f"control_point: {name} = {value} is out of range 0..{count - 1}")
        h = control.bezier[(i * control.nv + j) * 16 + 4 * r + s]
        return tuple(h[:3] / h[3]), float(h[3])

    def set_control(self, i: int, j: int, r: int, s: int, point: VectorLike, weight: Optional[float] = None) -> None:
        """Edit the control structure (the paper's Fig. 1c/d, 4a): move Bézier point b_rs of
        patch (i, j) to `point`, optionally with a new positive weight. The patches then
        leave the shape where edited; fw.blend_basic_shape joins the edited structure (C2
        along the interface, arc joins next to an edit adjusted by eq. (11))."""
        current = self.control_point(i, j, r, s)  # checks the indices
        weight = current[1] if weight is None else as_real(weight, "weight", finite=False)
        point = _vector3(point, "point")
        if self._control is None:
            self._control = self.g2()
        try:
            self._control.set_control(int(i), int(j), int(r), int(s), point, weight)
        except (TypeError, IndexError) as exc:
            raise InputError(f"set_control: {exc}") from None

    def reset_control(self) -> None:
        """Drop the edits: the exact shape again."""
        self._control = None

    def patches(self) -> list[Part.BSplineSurface]:
        """The shape's rational bicubic patches (edited ones included) as Part.BSplineSurface
        objects, row by row (u around the axis, v along the profile)."""
        g2 = self.control()
        return [surface_to_part(g2.patch(i, j)) for i in range(g2.nu) for j in range(g2.nv)]


class SphereZone(_Shape):
    """Sphere zone (or dome, with a latitude of pi/2): longitudes around the axis,
    latitudes in [-pi/2, pi/2], both increasing."""

    def __init__(self, center: VectorLike, radius: float, longitudes: Sequence[float], latitudes: Sequence[float],
                 axis: VectorLike = (0, 0, 1), x_axis: Optional[VectorLike] = None) -> None:
        super().__init__(center, axis, x_axis)
        self.radius = as_real(radius, "radius", finite=False)
        self.longitudes = _angles(longitudes, "longitudes")
        self.latitudes = _angles(latitudes, "latitudes")
        _check_partition(self.longitudes, self.latitudes)
        self.g2()  # validate now: InputError names the problem

    @property
    def around(self) -> np.ndarray:
        """The angles around the axis."""
        return self.longitudes

    def g2(self) -> kernel.G2Surface:
        return kernel.sphere_zone(*self._frame_args(), self.radius, self.longitudes, self.latitudes)

    def _revolution(self):
        return kernel.ShapeOfRevolution("sphere", *self._frame_args(), self.radius, 0.0, self.longitudes,
                                        self.latitudes)

    def pole_at(self, end: str) -> bool:
        latitude = self.latitudes[-1] if as_choice(end, "end", ("start", "end")) == "end" else self.latitudes[0]
        return abs(abs(latitude) - np.pi / 2) < 1e-9


class Cylinder(_Shape):
    """Circular cylinder: angles around the axis, increasing heights along it."""

    def __init__(self, center: VectorLike, radius: float, angles: Sequence[float], heights: Sequence[float],
                 axis: VectorLike = (0, 0, 1), x_axis: Optional[VectorLike] = None) -> None:
        super().__init__(center, axis, x_axis)
        self.radius = as_real(radius, "radius", finite=False)
        self.angles = _angles(angles, "angles")
        self.heights = _angles(heights, "heights")
        _check_partition(self.angles, self.heights)
        self.g2()

    @property
    def around(self) -> np.ndarray:
        return self.angles

    def g2(self) -> kernel.G2Surface:
        return kernel.cylinder(*self._frame_args(), self.radius, self.angles, self.heights)

    def _revolution(self):
        return kernel.ShapeOfRevolution("cone", *self._frame_args(), self.radius, 0.0, self.angles, self.heights)


class Cone(_Shape):
    """Cone with radius radius0 + slope * z at height z along the axis (apex excluded)."""

    def __init__(self, center: VectorLike, radius0: float, slope: float, angles: Sequence[float],
                 heights: Sequence[float], axis: VectorLike = (0, 0, 1), x_axis: Optional[VectorLike] = None) -> None:
        super().__init__(center, axis, x_axis)
        self.radius0, self.slope = as_real(radius0, "radius0", finite=False), as_real(slope, "slope", finite=False)
        self.angles = _angles(angles, "angles")
        self.heights = _angles(heights, "heights")
        _check_partition(self.angles, self.heights)
        self.g2()

    @property
    def around(self) -> np.ndarray:
        return self.angles

    def g2(self) -> kernel.G2Surface:
        return kernel.cone(*self._frame_args(), self.radius0, self.slope, self.angles, self.heights)

    def _revolution(self):
        return kernel.ShapeOfRevolution("cone", *self._frame_args(), self.radius0, self.slope, self.angles,
                                        self.heights)


class Torus(_Shape):
    """Torus with 0 < minor_radius < major_radius: angles_u around the axis, angles_v
    around the tube (0 = outer equator)."""

    def __init__(self, center: VectorLike, major_radius: float, minor_radius: float, angles_u: Sequence[float],
                 angles_v: Sequence[float], axis: VectorLike = (0, 0, 1), x_axis: Optional[VectorLike] = None) -> None:
        super().__init__(center, axis, x_axis)
        self.major_radius = as_real(major_radius, "major_radius", finite=False)
        self.minor_radius = as_real(minor_radius, "minor_radius", finite=False)
        self.angles_u = _angles(angles_u, "angles_u")
        self.angles_v = _angles(angles_v, "angles_v")
        _check_partition(self.angles_u, self.angles_v)
        self.g2()

    @property
    def around(self) -> np.ndarray:
        return self.angles_u

    def g2(self) -> kernel.G2Surface:
        return kernel.torus(*self._frame_args(), self.major_radius, self.minor_radius, self.angles_u, self.angles_v)

    def _revolution(self):
        return kernel.ShapeOfRevolution("torus", *self._frame_args(), self.major_radius, self.minor_radius,
                                        self.angles_u, self.angles_v)


def _profile_curve(profile):
    """A kernel BSplineCurve from a kernel one, a Part curve or edge (exact B-spline form), or
    a shape or document object of several connected edges (a sketch, a Design spline object):
    their exact B-splines joined end to end in the order of their wire (the joins keep the
    continuity the edges have: a multiple knot, treated by eq. (11) in the C2 blend)."""
    if isinstance(profile, kernel.BSplineCurve):
        return profile
    if isinstance(profile, _Shape):
        raise InputError(f"profile must be a curve, not a {type(profile).__name__}")
    try:
        import Part
    except ImportError:
        raise InputError("profile must be a Part curve or edge (FreeCAD's Part module is needed) "
                         "or a kernel BSplineCurve") from None
    if not isinstance(profile, (Part.Shape, Part.Curve if hasattr(Part, "Curve") else ())) and hasattr(profile,
                                                                                                       "Shape"):
        profile = profile.Shape  # a document object: a sketch, a Design spline
    if isinstance(profile, Part.Shape) and len(profile.Edges) > 1:
        profile = joined_profile(profile)
    return kernel.from_part(profile)


def _new_splits(curve, splits):
    """The splits that are not a knot of the profile already (a row boundary): a split a
    rounding error (1e-9 of the parameter range) from a knot would make a row of no length,
    e.g. a third of a Design spline's range, 1.0 against its knot 0.9999999999999999."""
    knots = np.asarray(curve.knots, dtype=float)
    if len(splits) == 0 or len(knots) == 0:
        return splits
    tolerance = 1e-9 * max(knots[-1] - knots[0], 1e-300)
    return np.array([t for t in splits if np.abs(knots - t).min() > tolerance], dtype=float)


def joined_profile(shape: Any) -> Any:
    """The Part.BSplineCurve of a shape's edges joined end to end in the order of their wire
    (one edge: its exact B-spline). InputError if they do not form one connected wire."""
    import Part

    edges = shape.Edges
    if len(edges) == 1:
        return kernel.edge_bspline(edges[0])
    try:
        wire = Part.Wire(Part.__sortEdges__(edges))
    except Part.OCCError:
        raise InputError("the profile's edges do not form one connected wire") from None
    if len(wire.OrderedEdges) != len(edges):
        raise InputError("the profile's edges do not form one connected wire")
    curve = None
    for edge in wire.OrderedEdges:
        piece = kernel.edge_bspline(edge)
        if curve is None:
            curve = piece.copy()
        elif not curve.join(piece):
            raise InputError("the profile's edges could not be joined into one B-spline")
    return curve


class Revolution(_Shape):
    """Surface of revolution of a designed profile (issue 32): a rational cubic spline (a
    Part.BSplineCurve of degree <= 3, rational or not, e.g. fw.design_spline's output with its
    exact conic pieces; a conic arc; a quadratic spline, raised to cubic), in a plane through
    the axis and off it, revolved exactly by the circle pieces of eq. (2) over `angles`
    (radians, from the profile's half-plane). Along the profile the patches are the curve's
    Bézier pieces (between its knots, or the parameters `splits` inserted as knots).

        profile = fw.design_spline([(line, []), (arc, []), (ellipse_arc, [])])
        vase = fw.shapes.Revolution(profile, (0, 0, 0), (0, 0, 1), [0, 2, 4, 2 * math.pi])
    """

    def __init__(self, profile: Any, center: VectorLike, axis: VectorLike, angles: Sequence[float],
                 splits: Optional[Sequence[float]] = None) -> None:
        self._control = None
        splits = np.zeros(0) if splits is None else _angles(splits, "splits")
        curve = _profile_curve(profile)
        splits = _new_splits(curve, splits)
        self.profile = kernel.revolution_profile(curve, _vector3(center, "center"),
                                                 _vector3(axis, "axis"), splits)
        self.center = np.array(self.profile.origin, dtype=float)
        self.x_axis, self.y_axis = np.array(self.profile.x, dtype=float), np.array(self.profile.y, dtype=float)
        self.axis = np.array(self.profile.z, dtype=float)
        self.angles = _angles(angles, "angles")
        _check_partition(self.angles, self.profile.knots)
        self.g2()

    @property
    def around(self) -> np.ndarray:
        return self.angles

    def g2(self) -> kernel.G2Surface:
        return kernel.revolution(self.profile, self.angles)

    def _revolution(self):
        return kernel.shape_of_revolution(self.profile, self.angles)


def _rational_profile(center, axis, x_axis, points, weights, values, coordinate):
    """A conic arc in the (rho, z) half-plane about the axis as one rational quadratic Bézier
    (points: 3 (rho, z) pairs, weights 1, w, 1), split at the parameters where
    `coordinate` (0: rho, 1: z) takes the inner `values` (bisection: the arc is monotone in
    it). One polynomial in homogeneous space, so every split joins C-infinity."""
    center = _vector3(center, "center")
    n = _vector3(axis, "axis")
    x, _ = _frame(n, x_axis)
    n = n / np.linalg.norm(n)
    p = np.asarray(points, dtype=float)
    w = np.asarray(weights, dtype=float)
    if not (np.all(np.isfinite(p)) and np.all(np.isfinite(w))):
        raise InputError("the quadric's profile overflows at these sizes: its points or weights are not finite "
                         f"({p.tolist()}, weights {w.tolist()})")

    def at(s):
        b = np.array([(1 - s) ** 2, 2 * s * (1 - s), s * s]) * w
        return (b @ p) / b.sum()

    increasing = at(1.0)[coordinate] > at(0.0)[coordinate]
    splits = []
    for v in values[1:-1]:
        lo, hi = 0.0, 1.0
        for _ in range(60):
            mid = (lo + hi) / 2
            if (at(mid)[coordinate] < v) == increasing:
                lo = mid
            else:
                hi = mid
        splits.append((lo + hi) / 2)
    poles = np.array([center + r * x + z * n for r, z in p])
    curve = kernel.BSplineCurve(poles, np.array([0.0, 1.0]), np.array([3, 3], dtype=np.int32), 2, False, w)
    return curve, np.array(splits), center, n


def _increasing(values, name, minimum=None):
    v = _angles(values, name)
    if v.size < 2 or not np.all(np.isfinite(v)) or np.any(np.diff(v) <= 0):
        raise InputError(f"{name} must be at least two finite, increasing numbers")
    if minimum is not None and not v[0] > minimum:
        raise InputError(f"{name} must all be greater than {minimum:g} ({name} 0 is {v[0]:g})")
    return v


def _positive(value, name):
    v = as_real(value, name)
    if not v > 0:
        raise InputError(f"a degenerate quadric: {name} must be positive, got {v:g}")
    return v


def Paraboloid(center: VectorLike, focal: float, radii: Sequence[float], angles: Sequence[float],
               axis: VectorLike = (0, 0, 1), x_axis: Optional[VectorLike] = None) -> Revolution:
    """Zone of the paraboloid of revolution z = r^2 / (4 focal) (frame at its vertex `center`)
    between the increasing distances from the axis `radii` (> 0; the profile is split there),
    through Revolution: the profile is one parabola arc (a quadratic polynomial), so the
    patches lie exactly on the paraboloid."""
    f = _positive(focal, "focal")
    r = _increasing(radii, "radii", 0.0)
    with np.errstate(over="ignore", invalid="ignore"):  # _rational_profile names a profile that overflows
        pts = [(r[0], r[0] ** 2 / (4 * f)), ((r[0] + r[-1]) / 2, r[0] * r[-1] / (4 * f)),
               (r[-1], r[-1] ** 2 / (4 * f))]
    curve, splits, c, n = _rational_profile(center, axis, x_axis, pts, [1.0, 1.0, 1.0], r, 0)
    return Revolution(curve, c, n, angles, splits)


def Hyperboloid(center: VectorLike, a: float, c: float, heights: Sequence[float], angles: Sequence[float],
                sheets: int = 1, axis: VectorLike = (0, 0, 1), x_axis: Optional[VectorLike] = None) -> Revolution:
    """Zone of a hyperboloid of revolution about `axis` through `center`, between increasing
    `heights` z (the profile is split there), through Revolution. sheets=1:
    r^2/a^2 - z^2/c^2 = 1; sheets=2: z^2/c^2 - r^2/a^2 = 1 on the sheet z > 0 (heights above c:
    the vertex lies on the axis). The profile is one hyperbola arc r = a cosh t, z = c sinh t
    (two sheets: z = c cosh t, r = a sinh t), the rational quadratic with middle weight
    cosh((t1 - t0) / 2): exact."""
    a, c = _positive(a, "a"), _positive(c, "c")
    if sheets not in (1, 2):
        raise InputError(f"sheets must be 1 or 2, not {sheets!r}")
    z = _increasing(heights, "heights", c if sheets == 2 else None)
    with np.errstate(over="ignore", invalid="ignore"):  # _rational_profile names a profile that overflows
        if sheets == 1:
            t0, t1 = np.arcsinh(z[0] / c), np.arcsinh(z[-1] / c)
            point = lambda t: (a * np.cosh(t), c * np.sinh(t))  # noqa: E731
        else:
            t0, t1 = np.arccosh(z[0] / c), np.arccosh(z[-1] / c)
            point = lambda t: (a * np.sinh(t), c * np.cosh(t))  # noqa: E731
        half = (t1 - t0) / 2
        # The tangents' intersection: the middle point of the arc's parameter divided by cosh(half).
        mid = np.array(point((t0 + t1) / 2)) / np.cosh(half)
        pts = [point(t0), tuple(mid), point(t1)]
    curve, splits, cc, n = _rational_profile(center, axis, x_axis, pts, [1.0, np.cosh(half), 1.0], z, 1)
    return Revolution(curve, cc, n, angles, splits)


class AffineImage(_Shape):
    """The image of a basic shape under the affine map p -> matrix p + translation. The blends
    are linear in homogeneous coordinates, so they commute with the map: the blend of the
    image is the image of the blend (of the shape with the ring mapped back). An ellipsoid is
    the image of a sphere zone, an elliptic paraboloid that of a paraboloid of revolution."""

    def __init__(self, shape: Any, matrix: Any, translation: VectorLike = (0, 0, 0)) -> None:
        try:
            A = np.array(matrix, dtype=float).reshape(3, 3)
        except (TypeError, ValueError):
            raise InputError("matrix must be 3 x 3 numbers") from None
        M = np.eye(4)
        M[:3, :3], M[:3, 3] = A, _vector3(translation, "translation")
        self._set(shape, M)

    def _set(self, shape, M):
        self._control = None
        self.base = require_shape(shape)
        if isinstance(shape, AffineImage):
            raise InputError("map the base shape once: compose the two maps")
        if not np.all(np.isfinite(M)) or abs(np.linalg.det(M)) <= 1e-12 * max(np.abs(M).max(), 1e-300) ** 4:
            raise InputError("the map is degenerate (determinant 0) or not finite")
        self.map, self.inverse = M, np.linalg.inv(M)
        self.axis, self.x_axis, self.y_axis = self.base.axis, self.base.x_axis, self.base.y_axis
        h = M @ np.append(self.base.center, 1.0)
        self.center = h[:3] / h[3] if h[3] > 0 else self.base.center
        self.g2()  # validate now: InputError names the problem

    @property
    def around(self) -> np.ndarray:
        return self.base.around

    def pole_at(self, end: str) -> bool:
        return self.base.pole_at(end)

    def g2(self) -> kernel.G2Surface:
        return kernel.image_g2(self.base.g2(), self.map)

    def _revolution(self):
        raise InputError("an affine image is joined through its base shape (fw.blend maps it)")

    def _base_for_blend(self) -> BasicShape:
        """The base shape, carrying this image's edits mapped back (the blends run on it)."""
        if self._control is None:
            return self.base
        import copy

        base = copy.copy(self.base)
        base._control = kernel.image_g2(self._control, self.inverse)
        return base

    def _map_complex(self, complex_: kernel.BlendComplex) -> kernel.BlendComplex:
        """The blend complex of the base shape under this map."""
        return kernel.image_complex(complex_, self.map)


class ProjectiveImage(AffineImage):
    """The image of a basic shape under the projective map (w p, w) -> matrix (w p, w)
    (4 x 4): linear in homogeneous space, so the blends commute with it as with affine maps,
    wherever its weights stay positive (InputError otherwise)."""

    def __init__(self, shape: Any, matrix: Any) -> None:
        try:
            M = np.array(matrix, dtype=float).reshape(4, 4)
        except (TypeError, ValueError):
            raise InputError("matrix must be 4 x 4 numbers") from None
        self._set(shape, M)


def HyperbolicCylinder(center: VectorLike, a: float, b: float, angles: Sequence[float], heights: Sequence[float],
                       axis: VectorLike = (0, 0, 1), x_axis: Optional[VectorLike] = None) -> ProjectiveImage:
    """The hyperbolic cylinder x^2/a^2 - y^2/b^2 = 1 (x > 0; x along x_axis, heights along
    `axis`), the hyperbola (a sec t, b tan t) over the increasing angles t in (-pi/2, pi/2)
    extruded (Fig. 9). Exact: the paper's recipe turns (a, b sin t | cos t) into rational
    form with the circle pieces of eq. (2), i.e. the image of a circular cylinder's partial
    turn under (X, Y, Z, W) -> (a W, b Y, Z, X) in the frame."""
    a, b = _positive(a, "a"), _positive(b, "b")
    t = _increasing(angles, "angles")
    if not (t[0] > -np.pi / 2 and t[-1] < np.pi / 2):
        raise InputError("a hyperbolic cylinder's angles must lie in (-pi/2, pi/2) (the branch x > 0)")
    cylinder = Cylinder(center, 1.0, t, heights, axis, x_axis)
    F = np.eye(4)
    F[:3, 0], F[:3, 1], F[:3, 2], F[:3, 3] = cylinder.x_axis, cylinder.y_axis, cylinder.axis, cylinder.center
    P = np.array([[0, 0, 0, a], [0, b, 0, 0], [0, 0, 1, 0], [1, 0, 0, 0]], dtype=float)
    return ProjectiveImage(cylinder, F @ P @ np.linalg.inv(F))


def Ellipsoid(center: VectorLike, radii: Sequence[float], longitudes: Sequence[float], latitudes: Sequence[float],
              axis: VectorLike = (0, 0, 1), x_axis: Optional[VectorLike] = None) -> AffineImage:
    """Zone of the ellipsoid x^2/a^2 + y^2/b^2 + z^2/c^2 = 1 (radii (a, b, c) along x_axis,
    axis x x_axis and axis) about `center`: the affine image of the unit sphere zone over
    longitudes and latitudes (a latitude of pi/2: the pole), exact."""
    try:
        radii = list(radii)
    except TypeError:
        raise InputError("radii must be three numbers (a, b, c)") from None
    if len(radii) != 3:
        raise InputError(f"radii must be three numbers (a, b, c), got {len(radii)}")
    a, b, c = (_positive(r, name) for r, name in zip(radii, ("radius a", "radius b", "radius c")))
    n = _vector3(axis, "axis")
    x, y = _frame(n, x_axis)
    frame = np.column_stack([x, y, np.cross(x, y)])
    unit = SphereZone((0, 0, 0), 1.0, longitudes, latitudes)
    return AffineImage(unit, frame @ np.diag([a, b, c]), center)


class DupinCyclide(_Shape):
    """Dupin ring cyclide (the blending paper's "generalized tori"), c < mu < a, about
    `center` (x_axis, axis x x_axis, axis as its x, y, z):
    (x^2 + y^2 + z^2 - mu^2 + b^2)^2 = 4 (a x - c mu)^2 + 4 b^2 y^2, b^2 = a^2 - c^2 (c = 0:
    the torus of radii a and mu). Both families of curvature lines are circles, partitioned by
    angles_u and angles_v (radians, as a torus's): the G2 bicubic patches are exact.
    fw.blend_basic_shape(cyclide) joins it C2 at its last v angle to its default ring (a
    full turn of angles_u), and the naive baseline (fw.blend_naive, Fig. 2a) to the same ring;
    C1, user rings, joins and chains are not built for cyclides (docs/READINGS.md)."""

    def __init__(self, center: VectorLike, a: float, c: float, mu: float, angles_u: Sequence[float],
                 angles_v: Sequence[float], axis: VectorLike = (0, 0, 1), x_axis: Optional[VectorLike] = None) -> None:
        super().__init__(center, axis, x_axis)
        self.a, self.c, self.mu = (as_real(v, name, finite=False) for v, name in ((a, "a"), (c, "c"), (mu, "mu")))
        self.angles_u = _angles(angles_u, "angles_u")
        self.angles_v = _angles(angles_v, "angles_v")
        _check_partition(self.angles_u, self.angles_v)
        self.g2()

    @property
    def around(self) -> np.ndarray:
        return self.angles_u

    def g2(self) -> kernel.G2Surface:
        return kernel.dupin_cyclide(*self._frame_args(), self.a, self.c, self.mu, self.angles_u, self.angles_v)

    def _revolution(self):
        raise InputError("a Dupin cyclide is not a surface of revolution: it blends C2 to its default ring only "
                         "(fw.blend_basic_shape(cyclide), or fw.blend_naive(cyclide) to compare), not in joins, "
                         "chains, C1 or to a user's ring")


# What the blends take (fw.blend_basic_shape, fw.join_basic_shapes).
BasicShape = Union[SphereZone, Cylinder, Cone, Torus, Revolution, AffineImage, DupinCyclide]

__all__ = ["AffineImage", "Cone", "Cylinder", "DupinCyclide", "Ellipsoid", "HyperbolicCylinder", "Hyperboloid",
           "Paraboloid", "ProjectiveImage", "Revolution", "SphereZone", "Torus"]
