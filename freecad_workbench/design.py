"""Design with basic curves (csr paper, Sections 5, 6 and Fig. 9): basic curve pieces
with marks to one non-uniform cubic C2 NURBS that keeps the pieces exact between the
marks, rounds off the transitions, and whose control polygon can be edited freely."""
from __future__ import annotations

import math
import numbers
from collections import namedtuple
from typing import TYPE_CHECKING, Any, Sequence, Union

import numpy as np

from . import kernel
from .basic import BasicCurve, Samples, from_edge
from .errors import InputError
from .kernel import CurveLike, VectorLike, as_count, as_flag, as_real, from_part, to_part

if TYPE_CHECKING:
    import Part

DesignResult = namedtuple("DesignResult", "curve joins ranges marks marks_added")
DesignResult.__doc__ = (
    "design_spline(..., details=True): the Part.BSplineCurve; per join 'agree', 'averaged' or 'edge'; "
    "per piece (t0, scale) with the piece's u at the curve's t0 + scale * u; per piece the marks used "
    "(u_0 = 0 .. u_m = 1) and how many were added to keep the weights positive."
)


def piece_marks(curve, marks, tolerance=1e-9):
    """Marks as parameters in [0, 1]: numbers are taken as they are, points are located on
    the curve by eq. (4) / eq. (5) (InputError if off the curve beyond tolerance)."""
    if isinstance(marks, (str, bytes)) or not hasattr(marks, "__iter__"):
        raise InputError(f"marks must be a list of parameters or points, got {marks!r}")
    u = []
    for i, mark in enumerate(marks):
        if isinstance(mark, numbers.Real):
            u.append(float(mark))
        else:
            try:
                u.append(curve.parameter_of(mark, tolerance))
            except InputError as exc:
                raise InputError(f"mark {i}: {exc}") from None
    return np.array(u, dtype=float)


def _piece(item, index):
    if isinstance(item, Samples):
        return item, None
    try:
        curve, marks = item
    except (TypeError, ValueError):
        raise InputError(f"piece {index} must be a pair (basic curve, marks)") from None
    if isinstance(curve, Samples):
        if marks is not None and (isinstance(marks, (str, bytes)) or not hasattr(marks, "__len__") or len(marks)):
            raise InputError(f"piece {index}: a Samples piece takes no marks (its samples are its knots), "
                             f"got {marks!r}")
        return curve, None
    if not isinstance(curve, BasicCurve):
        curve = from_edge(curve)
    return curve, marks


def design_spline(pieces: Sequence[Union[Samples, tuple[Union[BasicCurve, Samples, Part.Edge], Sequence[Any]]]],
                  join_tolerance: float = 1e-6,
                  details: bool = False) -> Union[Part.BSplineCurve, DesignResult]:
    """One cubic C2 NURBS from basic curve pieces with marks.

    pieces: list of (basic_curve, marks); basic_curve is a fw.basic curve or a FreeCAD
        edge (lines and conics); marks are parameters in [0, 1] or points on the curve.
        A fw.basic.Samples piece stands alone (or as (samples, None)): its part of the
        curve is the csr-spline of its samples (Section 4), joined like any piece (Fig. 9).
    join_tolerance: end points of consecutive pieces closer than this (model units) are
        averaged into one control point; farther apart they are joined by an edge; equal
        end points are shared.
    Rational curves of degree <= 3 (conics) are kept exact from their second mark to the
    second last (to their free end at the ends of the design); spirals and other curves
    are approximated (Section 5). Raises InputError on bad input.
    """
    if isinstance(pieces, tuple) and len(pieces) == 2 and not isinstance(pieces[0], (tuple, Samples)):
        pieces = [pieces]
    if isinstance(pieces, Samples) or (isinstance(pieces, tuple) and len(pieces) == 2
                                       and isinstance(pieces[0], Samples) and pieces[1] is None):
        pieces = [pieces]
    if isinstance(pieces, (str, bytes)) or not hasattr(pieces, "__iter__"):
        raise InputError(f"pieces must be a list of (basic curve, marks) pairs, got {pieces!r}")
    pieces = list(pieces)
    if not pieces:
        raise InputError("a design needs at least one piece")
    join_tolerance = as_real(join_tolerance, "join_tolerance", minimum=0)
    details = as_flag(details, "details")
    polygons = []
    for index, item in enumerate(pieces):
        curve, marks = _piece(item, index)
        if isinstance(curve, Samples):  # its csr-spline's polygon, made and checked when it was built
            polygons.append(curve._polygon)
            continue
        try:
            polygons.append(kernel.piece_polygon(curve._curve, piece_marks(curve, marks)))
        except InputError as exc:
            raise InputError(f"piece {index}: {exc}") from None
    curve, joins, ranges = kernel.merge_pieces(polygons, join_tolerance)
    part = to_part(curve)
    if not details:
        return part
    return DesignResult(part, joins, ranges, [p.marks for p in polygons], [p.marks_added for p in polygons])


def revolve_profile(curve: CurveLike, axis_point: VectorLike = (0, 0, 0),
                    axis_direction: VectorLike = (0, 0, 1)) -> Part.BSplineSurface:
    """The exact surface of revolution of a profile (Part curve or edge, e.g. a designed
    spline) about an axis: a Part.BSplineSurface, the profile's NURBS in u times a
    rational circle in v (the paper's profile test)."""
    from .basic import _vector3
    from .kernel import surface_to_part

    surface = kernel.revolve(from_part(curve), _vector3(axis_point, "axis_point"),
                             _vector3(axis_direction, "axis_direction"))
    return surface_to_part(surface)


ApproximationError = namedtuple("ApproximationError",
                                "quintic_position quintic_curvature cubic_position cubic_curvature")
ApproximationError.__doc__ = (
    "Largest deviation from a basic curve, at equal parameters, of the quintics of eq. (7) and of the cubic "
    "C2 spline (Section 5), in position and in curvature, over [u_2, u_(m-2)] for the spline."
)


def approximation_error(curve: BasicCurve, marks: Sequence[Any], samples: int = 40) -> ApproximationError:
    """Measure the Section 5 approximation of a basic curve with the given marks.

    The quintic pieces are evaluated for all pieces and samples at once (numpy), so the
    cost is one pass over marks x samples points, not a Python loop per point."""
    if not isinstance(curve, BasicCurve):
        raise InputError(f"curve must be a fw.basic curve, got {type(curve).__name__}")
    samples = as_count(samples, "samples", 1, 10_000)
    u = kernel.complete_marks(piece_marks(curve, marks))
    m = len(u) - 1
    quintic = np.asarray(kernel.quintic_pieces(curve._curve, u)).reshape(m, 6, -1)
    h = np.diff(u)
    x = np.linspace(0.0, 1.0, samples + 1)

    def bernstein(degree):
        k = np.arange(degree + 1)
        binomial = np.array([math.comb(degree, j) for j in k], dtype=float)
        return binomial * (1 - x[:, None]) ** (degree - k) * x[:, None] ** k

    # Points and derivatives in u of every piece at every sample: (pieces, samples, dim).
    p = np.einsum("sk,mkd->msd", bernstein(5), quintic)
    d1 = 5 * np.einsum("sk,mkd->msd", bernstein(4), np.diff(quintic, axis=1)) / h[:, None, None]
    d2 = 20 * np.einsum("sk,mkd->msd", bernstein(3), np.diff(quintic, 2, axis=1)) / h[:, None, None] ** 2
    uu = (u[:-1, None] + x[None, :] * h[:, None]).ravel()
    p, d1, d2 = (a.reshape(-1, a.shape[-1]) for a in (p, d1, d2))
    exact, exact_k = _jets(curve, uu)
    qp = float(np.max(np.linalg.norm(p - exact, axis=1)))
    qk = _max_ignoring_undefined(np.abs(_curvature(d1, d2) - exact_k))
    spline, _, _ = kernel.merge_pieces([kernel.piece_polygon(curve._curve, u)], 0.0)
    part = to_part(spline)
    lo, hi = (u[2], u[m - 2]) if m >= 4 else (0.0, 1.0)
    t = np.linspace(lo, hi, samples * m + 1)
    exact, exact_k = _jets(curve, t)
    values = np.array([tuple(part.value(float(v))) for v in t])
    kappa = _part_curvatures(part, t)
    cp = float(np.max(np.linalg.norm(values - exact, axis=1)))
    ck = _max_ignoring_undefined(np.abs(kappa - exact_k))
    return ApproximationError(qp, qk, cp, ck)


def _jets(curve, t):
    """Points and curvatures of a basic curve at the parameters t (arrays)."""
    values = np.array([curve._curve.value(float(v)) for v in t])
    d1 = np.array([curve._curve.d1(float(v)) for v in t])
    d2 = np.array([curve._curve.d2(float(v)) for v in t])
    return values, _curvature(d1, d2)


def _part_curvatures(part, t):
    """OCCT's curvature of a Part curve at the parameters t; NaN where OCCT says it is not
    defined (LProp_CLProps::CurvatureNotDefined: the tangent vanishes to double precision, as
    where weights 3.965 and 1e12 pull a rational cubic into one point), as at a cusp."""
    import Part

    kappa = np.empty(len(t))
    for i, v in enumerate(t):
        try:
            kappa[i] = part.curvature(float(v))
        except Part.OCCError:
            kappa[i] = math.nan
    return kappa


def _curvature(d1, d2):
    """|d1 x d2| / |d1|^3, row by row for (n, 3) arrays or for one pair of vectors; NaN where
    the curve stops (a cusp, as where an involute starts: no curvature there)."""
    d1, d2 = np.asarray(d1, dtype=float), np.asarray(d2, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.linalg.norm(np.cross(d1, d2), axis=-1) / np.linalg.norm(d1, axis=-1) ** 3


def _max_ignoring_undefined(errors):
    """The largest error where the curvature is defined (cusps give NaN; 0 if none is)."""
    errors = errors[np.isfinite(errors)]
    return float(errors.max()) if errors.size else 0.0
