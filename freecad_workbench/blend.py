"""Basic shapes blended into NURBS with a curvature-continuous (6,5) transition (blending
paper, Section 4.2), and the naive baseline of Fig. 2a.

    zone = fw.shapes.SphereZone((0, 0, 0), 10, longitudes, latitudes)
    result = fw.blend_basic_shape(zone)          # default free-form ring
    result.patches   # [(role, Part.BSplineSurface)], role 'basic', 'transition', 'freeform'
    result.shell     # Part.Shell of all patches, sharing their edges (STEP-ready)
    result.surface   # one C2 Part.BSplineSurface of the complex (or None)

Shapes of revolution over a full turn around their axis or part of one, joined at the end
of their profile: SphereZone (top latitude), Cylinder and Cone (top height), Torus (last
tube angle of an open range); or at its start (at="start"; chosen by itself for a dome,
whose end is the pole).

    dome = fw.shapes.SphereZone((0, 0, 3), 1, longitudes, [0.2, 0.9, math.pi / 2])
    post = fw.shapes.Cylinder((0, 0, 0), 1, longitudes, [0, 1, 2])
    joined = fw.join_basic_shapes(post, dome)   # Figs. 9-12: basic shape to basic shape
"""
from __future__ import annotations

from typing import Optional, Sequence, Union

import numpy as np

from . import kernel
from .blend_c1 import blend_basic_shape_c1, blend_naive_c1, complex_c1, freeform_knots_c1
from .errors import InputError
from .kernel import BlendResult, SurfaceLike, as_choice, blend_result, surface_from_part
from .shapes import AffineImage, BasicShape, Cone, Cylinder, DupinCyclide, Revolution, SphereZone, require_shape

_METHODS = ("rho", "sigma", "mixed")


def _check(shape, continuity, method):
    as_choice(continuity, "continuity", ("C2", "C1"))
    as_choice(method, "method", _METHODS)
    check_cost(require_shape(shape))


def _revolving(shape):
    """InputError for a Dupin cyclide (or an image of one) where only shapes of revolution go."""
    base = shape.base if isinstance(shape, AffineImage) else shape
    if isinstance(base, DupinCyclide):
        base._revolution()  # raises the InputError that says what a cyclide blends with


# The most patches of a shape a blend takes: 400 arcs x 2 pieces (800 patches, the ring's
# and the strip's besides) took 4.4 s here, most of it sewing the shell.
MAX_PATCHES = 2048


def check_cost(shape):
    """Say the cost up front: a partition of more than MAX_PATCHES patches is refused with
    its size, before any work (blends grow with arcs around x pieces along the profile)."""
    g2 = shape.control()
    patches = g2.nu * g2.nv
    if patches > MAX_PATCHES:
        raise InputError(f"this partition has {g2.nu} arcs around and {g2.nv} pieces along the profile: "
                         f"{patches} patches, more than {MAX_PATCHES}; use fewer, longer arcs")


def _ring(shape, freeform):
    return None if freeform is None else surface_from_part(freeform)


def _through_base(shape, freeform):
    """(the shape the blend runs on, its ring, the map of the result): an AffineImage is
    blended as its base shape with the ring mapped back, and the complex mapped forward (the
    construction commutes with affine maps, docs/BLENDING.md); other shapes as they are."""
    if not isinstance(shape, AffineImage):
        return shape, freeform, None
    ring = None
    if freeform is not None:
        ring = surface_from_part(freeform, shape.inverse)
    return shape._base_for_blend(), ring, shape


def _mapped(image, complex_):
    return complex_ if image is None else image._map_complex(complex_)


def _common_image(shapes):
    """The one affine map of a join or chain (None: no AffineImage); InputError where the
    shapes are not all images under the same map."""
    images = [s for s in shapes if isinstance(s, AffineImage)]
    if not images:
        return None
    first = images[0]

    def same(s):
        return isinstance(s, AffineImage) and np.allclose(s.map, first.map, rtol=1e-12, atol=0)

    for s in shapes:
        if not same(s):
            raise InputError("shapes joined in one complex must all be affine images under the same map "
                             "(or none of them)")
    return first


def freeform_knots(shape: BasicShape, method: str = "rho", continuity: str = "C2") -> np.ndarray:
    """The u knots (one period) a free-form ring must have to join `shape` at its top: the
    arc knots of the C2 circle, intervals in the ratios beta of the longitudes (continuity
    "C1": those of eq. (12) for a biquadratic ring, blend_c1.py)."""
    as_choice(continuity, "continuity", ("C2", "C1"))
    if continuity == "C1":
        return freeform_knots_c1(shape)
    _check(shape, "C2", method)
    return kernel.ring_knots(shape.around, method)


def _interface(shape, at):
    """'end' or 'start'; None chooses the end unless it is a pole (a dome)."""
    if at is None:
        return "start" if shape.pole_at("end") and not shape.pole_at("start") else "end"
    as_choice(at, "at", ("end", "start"))
    return at


def _interface_or_auto(shape, at):
    """As _interface, but None is the kernel's 'auto': the end unless it is a pole or, for the
    default ring, the start has more room for it (issue 15)."""
    return "auto" if at is None else _interface(shape, at)


def _complex(shape, freeform, method, naive, at):
    frame = (shape.center, shape.x_axis, shape.y_axis)
    ring = freeform if freeform is None or isinstance(freeform, kernel.BSplineSurface) else _ring(shape, freeform)
    if isinstance(shape, Revolution):
        return kernel.blend_shape(shape._revolution(), method, ring, True, naive, at)
    if isinstance(shape, SphereZone):
        if naive:
            return kernel.blend_sphere_zone_naive(*frame, shape.radius, shape.longitudes, shape.latitudes, ring, at)
        return kernel.blend_sphere_zone(*frame, shape.radius, shape.longitudes, shape.latitudes, method, ring, True, at)
    if isinstance(shape, (Cylinder, Cone)):
        radius0, slope = (shape.radius, 0.0) if isinstance(shape, Cylinder) else (shape.radius0, shape.slope)
        return kernel.blend_cone(*frame, radius0, slope, shape.angles, shape.heights, method, ring, True, naive, at)
    return kernel.blend_torus(*frame, shape.major_radius, shape.minor_radius, shape.angles_u, shape.angles_v, method,
                              ring, True, naive, at)


def blend_basic_shape(shape: BasicShape, freeform: Optional[SurfaceLike] = None, continuity: str = "C2",
                      method: str = "rho", at: Optional[str] = None) -> BlendResult:
    """Join a basic shape (at the end of its profile) to a bicubic free-form ring (a
    periodic-in-u, clamped-in-v Part.BSplineSurface going once around the axis, its
    first row near the interface, on any knots: they are merged with the shape's), or to
    a default ring that continues the shape, with a C2 transition strip of degree (6,5).
    The basic shape stays exact. method: 'rho', 'sigma' or 'mixed' (Section 3). at:
    'end' or 'start' of the profile (None: the end, or the start where the end is a
    pole). A shape edited with shape.set_control (Fig. 1c/d) is joined as edited: C2
    along the interface and across the strip, the rows across the profile G2 (its
    .surface is then None). continuity "C1": Section 5, a biquadratic ring and a (4,2)
    double strip (blend_c1.py; method unused)."""
    as_choice(continuity, "continuity", ("C2", "C1"))
    _check(shape, continuity, method)
    shape, freeform, image = _through_base(shape, freeform)
    if isinstance(shape, DupinCyclide) and continuity == "C2" and freeform is None and not shape.edited \
            and at in (None, "end"):
        return blend_result(_mapped(image, kernel.blend_cyclide(*shape._frame_args(), shape.a, shape.c, shape.mu,
                                                                shape.angles_u, shape.angles_v, method)))
    _revolving(shape)
    if continuity == "C1":
        if shape.edited:
            raise InputError("the C1 variant joins the unedited shape (call shape.reset_control())")
        if image is not None:
            return blend_result(image._map_complex(complex_c1(shape, freeform, at=_interface(shape, at))))
        return blend_basic_shape_c1(shape, freeform, at=_interface(shape, at))
    if shape.edited:
        if _interface(shape, at) != "end":
            raise InputError("an edited control structure joins at the end of its profile")
        ring = freeform if freeform is None or isinstance(freeform, kernel.BSplineSurface) else _ring(shape, freeform)
        return blend_result(_mapped(image, kernel.blend_edited(shape._revolution(), shape.control(), method, ring)))
    return blend_result(_mapped(image, _complex(shape, freeform, method, False, _interface_or_auto(shape, at))))


def blend_naive(shape: BasicShape, freeform: Optional[SurfaceLike] = None, continuity: str = "C2",
                at: Optional[str] = None) -> BlendResult:
    """The naive baseline of Fig. 2a: direct second-order Hermite interpolation of the G2
    shape and the ring, without reparameterization (strip of degree (3,5)). Not C2 where
    the partition's beta do not match: its .surface is None. continuity "C1": the G1
    shape's arcs split and degree-raised without eta, the same (4,2) double strip."""
    _check(shape, continuity, "rho")
    if shape.edited:
        raise InputError("the naive baseline takes the unedited shape (call shape.reset_control())")
    shape, freeform, image = _through_base(shape, freeform)
    if isinstance(shape, DupinCyclide) and continuity == "C2" and freeform is None and at in (None, "end"):
        return blend_result(_mapped(image, kernel.blend_cyclide_naive(*shape._frame_args(), shape.a, shape.c,
                                                                      shape.mu, shape.angles_u, shape.angles_v)),
                            single=False)
    _revolving(shape)
    if continuity == "C1":
        if image is not None:
            complex_ = complex_c1(shape, freeform, None, naive=True, at=_interface(shape, at))
            return blend_result(image._map_complex(complex_), single=False)
        return blend_naive_c1(shape, freeform, at=_interface(shape, at))
    return blend_result(_mapped(image, _complex(shape, freeform, "rho", True, _interface_or_auto(shape, at))),
                        single=False)


def join_basic_shapes(shape_a: BasicShape, shape_b: BasicShape, continuity: str = "C2",
                      method: str = "rho") -> BlendResult:
    """Basic shape to basic shape (Figs. 9, 11, 12): the end of shape_a's profile joined to
    the start of shape_b's by one C2 transition row of degree (6,5) (C1: a (4,2) double
    strip); both stay exact. Both need a full turn around their axis (or both a partial
    one) with the same number of arcs (the angles may differ: the scalars are averaged,
    beta~ = sqrt(beta_a beta_b)). Returns a BlendResult; the
    patches of both shapes are tagged 'basic'. shape_b should continue shape_a (its start
    beyond shape_a's end along the axis), else the strip folds back."""
    _check(shape_a, continuity, method)
    _check(shape_b, continuity, method)
    _revolving(shape_a)
    _revolving(shape_b)
    if shape_a.edited or shape_b.edited:
        raise InputError("join_basic_shapes takes unedited shapes (call reset_control())")
    image = _common_image([shape_a, shape_b])
    a, b = (s.base if image is not None else s for s in (shape_a, shape_b))
    if continuity == "C1":
        return blend_result(_mapped(image, kernel.join_shapes_c1(a._revolution(), b._revolution(), True)))
    return blend_result(_mapped(image, kernel.join_shapes(a._revolution(), b._revolution(), method, True, False)))


def _chain_end(end, name, back=None):
    """(ring?, net) of one end of a chain: None (open), "default" (the default ring) or a ring
    (mapped by `back`, (matrix, translation), for a chain of affine images)."""
    if end is None:
        return False, None
    if isinstance(end, str):
        as_choice(end, name, ("default",))
        return True, None
    return True, surface_from_part(end, back)


def blend_chain(shapes: Union[BasicShape, Sequence[BasicShape]], start: Optional[Union[str, SurfaceLike]] = None,
                end: Optional[Union[str, SurfaceLike]] = None, method: str = "rho") -> BlendResult:
    """Several interfaces on one C2 complex: shapes of revolution in order, the end of each
    joined to the start of the next (as join_basic_shapes, Figs. 9-12), and a free-form ring
    at the first shape's start and/or the last one's end (as blend_basic_shape). start, end:
    None (that end stays open), "default" (the default ring continuing the shape) or a
    bicubic ring (periodic in u for a full turn, clamped in v, its first row at the shape's
    end, running away from it).

        band = fw.shapes.SphereZone(c, 2.5, longitudes, latitudes)
        ball = fw.blend_chain(band, start="default", end="default")    # free-form both sides
        post_dome = fw.blend_chain([post, dome], start="default")      # free-form below the post

    One circle conversion serves every strip: the scalars around the axis are the geometric
    mean of the shapes' (Fig. 11's average for two). Shapes edited with set_control are
    joined as edited (G2 along their profile: .surface is None); else .surface is the one C2
    surface of the whole complex. Rows in v: the start ring, shapes and strips in order, the
    end ring."""
    shapes = list(shapes) if isinstance(shapes, (list, tuple)) else [shapes]
    if not shapes:
        raise InputError("blend_chain needs at least one shape")
    as_choice(method, "method", _METHODS)
    for shape in shapes:
        check_cost(require_shape(shape))
        _revolving(shape)
    image = _common_image(shapes)
    back = None if image is None else image.inverse
    start_ring, start_net = _chain_end(start, "start", back)
    end_ring, end_net = _chain_end(end, "end", back)
    if image is not None:
        shapes = [shape._base_for_blend() for shape in shapes]
    edited = [shape.control() if shape.edited else None for shape in shapes]
    complex_ = kernel.blend_chain([shape._revolution() for shape in shapes], edited, start_ring, end_ring, start_net,
                                  end_net, method, True)
    return blend_result(_mapped(image, complex_), single=not any(e is not None for e in edited))


def join_naive(shape_a: BasicShape, shape_b: BasicShape) -> BlendResult:
    """The Fig. 2a baseline between two basic shapes: the G2 patches as they are and a (3,5)
    Hermite strip without reparameterization (its .surface is None: not C2)."""
    _check(shape_a, "C2", "rho")
    _check(shape_b, "C2", "rho")
    _revolving(shape_a)
    _revolving(shape_b)
    image = _common_image([shape_a, shape_b])
    a, b = (s.base if image is not None else s for s in (shape_a, shape_b))
    complex_ = kernel.join_shapes(a._revolution(), b._revolution(), "rho", False, True)
    return blend_result(_mapped(image, complex_), single=False)


__all__ = ["BlendResult", "blend_basic_shape", "blend_chain", "blend_naive", "freeform_knots", "join_basic_shapes",
           "join_naive"]
