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
    """The shape itself when it is one of SphereZone, Cylinder, Cone, Torus (what the blends
    take); InputError naming what it is otherwise."""
    if not isinstance(shape, _Shape):
        raise InputError("shape must be one of fw.shapes.SphereZone, Cylinder, Cone, Torus, "
                         f"not {type(shape).__name__}")
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


# What the blends take (fw.blend_basic_shape, fw.join_basic_shapes).
BasicShape = Union[SphereZone, Cylinder, Cone, Torus]

__all__ = ["SphereZone", "Cylinder", "Cone", "Torus"]
