"""The G1/C1 variant of the blend (blending paper, Section 5, eta of Appendix 7.3):
`fw.blend_basic_shape(shape, freeform, continuity="C1")` lands here.

    zone = fw.shapes.SphereZone((0, 0, 0), 10, longitudes, latitudes)
    result = fw.blend_basic_shape(zone, continuity="C1")
    result.surface.Continuity      # 'C1' (or better)
    knots = fw.freeform_knots(zone, continuity="C1")   # u knots of a matching ring

The basic shape is a G1 rational biquadratic spline (rational quadratic circle arcs, each
below pi); around the axis every arc becomes two C1 quartics (eq. (12)), so the basic
patches are of degree (4,2) ((4,4) here, the profile converted too, so that one C1 surface
exists) and stay exactly on the shape. The free-form side is a biquadratic C1 ring:
periodic in u on the knots of freeform_knots(shape, continuity="C1"), clamped in v, its
first row where the transition ends. A double strip of degree (4,2) joins them C1.
"""
from . import _kernel
from .errors import InputError
from .kernel import surface_from_part
from .shapes import Cone, Cylinder, SphereZone, Torus


def _checked(shape):
    if not isinstance(shape, (SphereZone, Cylinder, Cone, Torus)):
        raise InputError(f"shape must be one of fw.shapes.SphereZone, Cylinder, Cone, Torus, not {type(shape).__name__}")
    return shape


def freeform_knots_c1(shape):
    """The u knots (one period) a biquadratic ring must have to join `shape` with C1: the
    arc knots of eq. (12), intervals in the ratios beta = sin(alpha_i/2)/sin(alpha_{i-1}/2)."""
    return _kernel.ring_knots_c1(_checked(shape).around)


def complex_c1(shape, freeform=None):
    """The kernel's BlendComplex of Section 5 (smoothness 1) for `shape` and a biquadratic
    Part.BSplineSurface ring (or None for the default ring)."""
    _checked(shape)
    frame = (shape.center, shape.x_axis, shape.y_axis)
    ring = None if freeform is None else surface_from_part(freeform)
    if isinstance(shape, SphereZone):
        return _kernel.blend_sphere_zone_c1(*frame, shape.radius, shape.longitudes, shape.latitudes, ring)
    if isinstance(shape, (Cylinder, Cone)):
        radius0, slope = (shape.radius, 0.0) if isinstance(shape, Cylinder) else (shape.radius0, shape.slope)
        return _kernel.blend_cone_c1(*frame, radius0, slope, shape.angles, shape.heights, ring)
    return _kernel.blend_torus_c1(*frame, shape.major_radius, shape.minor_radius, shape.angles_u, shape.angles_v, ring)


def blend_basic_shape_c1(shape, freeform=None):
    """Section 5: `shape` joined at the end of its profile to a biquadratic C1 ring (or the
    default one) by a C1 (4,2) double strip. Returns a BlendResult (patches, shell, surface)."""
    from .blend import _result

    return _result(complex_c1(shape, freeform))


__all__ = ["blend_basic_shape_c1", "complex_c1", "freeform_knots_c1"]
