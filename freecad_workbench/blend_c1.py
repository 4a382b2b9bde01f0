"""The G1/C1 variant of the blend (blending paper, Section 5, eta of Appendix 7.3):
`fw.blend_basic_shape(shape, freeform, continuity="C1")` lands here (blend.py imports this
module; this module imports nothing of blend.py).

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
from __future__ import annotations

from typing import Optional, Sequence

import numpy as np

from . import kernel
from .errors import InputError
from .kernel import BlendResult, SurfaceLike, blend_result, surface_from_part
from .shapes import BasicShape, require_shape


def freeform_knots_c1(shape: BasicShape, beta_t: Optional[Sequence[float]] = None) -> np.ndarray:
    """The u knots (one period) a biquadratic ring must have to join `shape` with C1: the
    arc knots of eq. (12), intervals in the ratios beta = sin(alpha_i/2)/sin(alpha_{i-1}/2)
    (or beta_t)."""
    return kernel.ring_knots_c1(require_shape(shape).around, _beta_t(shape, beta_t))


def _beta_t(shape, beta_t):
    if beta_t is None:
        return np.zeros(0)
    try:
        values = np.ascontiguousarray([float(b) for b in beta_t], dtype=float)
    except (TypeError, ValueError):
        raise InputError("beta_t must be a list of numbers, one per arc around the axis") from None
    if values.size != len(shape.around) - 1:
        raise InputError(f"beta_t needs one scalar per arc around the axis ({len(shape.around) - 1}), "
                         f"not {values.size}")
    return values


def complex_c1(shape: BasicShape, freeform: Optional[SurfaceLike] = None, beta_t: Optional[Sequence[float]] = None,
               naive: bool = False, at: str = "end") -> kernel.BlendComplex:
    """The kernel's BlendComplex of Section 5 (smoothness 1) for `shape` and a biquadratic
    Part.BSplineSurface ring (or None for the default ring). beta_t: new continuity scalars
    around the axis (beta_t[i] between arcs i-1 and i, multiplying to 1), None for beta.
    naive: the arcs only split and degree-raised, without eta (the baseline; not C1).
    at: "end" or "start" of the profile (the start: the profile run backwards)."""
    require_shape(shape)
    ring = freeform if freeform is None or isinstance(freeform, kernel.BSplineSurface) else surface_from_part(freeform)
    return kernel.blend_c1(shape._revolution(), ring, _beta_t(shape, beta_t), True, naive, at)


def blend_basic_shape_c1(shape: BasicShape, freeform: Optional[SurfaceLike] = None,
                         beta_t: Optional[Sequence[float]] = None, at: str = "end") -> BlendResult:
    """Section 5: `shape` joined at the end of its profile to a biquadratic C1 ring (or the
    default one) by a C1 (4,2) double strip. Returns a BlendResult (patches, shell, surface).
    beta_t as for complex_c1 (a user ring then needs freeform_knots_c1(shape, beta_t))."""
    return blend_result(complex_c1(shape, freeform, beta_t, at=at))


def blend_naive_c1(shape: BasicShape, freeform: Optional[SurfaceLike] = None, at: str = "end") -> BlendResult:
    """The C1 baseline: the G1 shape's arcs split at their middle and degree-raised to 4
    without the eta reparameterization, the same (4,2) double strip. Its seams along the
    strip are not C1 in homogeneous space, so it has no single C1 surface (.surface None)."""
    return blend_result(complex_c1(shape, freeform, None, naive=True, at=at), single=False)


__all__ = ["blend_basic_shape_c1", "blend_naive_c1", "complex_c1", "freeform_knots_c1"]
