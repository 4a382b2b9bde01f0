"""Fair fit (issue 16): a cubic C2 spline within a tolerance of every sample, with few poles
and no more curvature sign changes than the data supports.

    import freecad_workbench as fw
    curve = fw.fair_fit(points, tolerance=0.01)              # Part.BSplineCurve
    curve, report = fw.fair_fit_report(points, tolerance=0.01)
    report.poles, report.max_deviation, report.sign_changes
    faired = fw.fair_edge(edge, tolerance=0.01, clamp="G2")  # keeps ends, tangents, curvatures

The curve is the csr-spline (Karčiauskas & Peters, Section 4, eq. (6)) of an adaptive subset
of noise-smoothed samples, refined until every sample lies within the tolerance (verified by
the kernel). docs/FAIR_FIT.md has the method, what is guaranteed and what is heuristic.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Optional, Tuple, Union

import numpy as np

from . import kernel
from .errors import InputError
from .kernel import CurveLike, PointsLike, VectorLike, as_choice, as_flag, as_points, as_real, as_vector, to_part

if TYPE_CHECKING:
    import Part

CLAMPS = ("G0", "G1", "G2")
CORNERS = ("refuse", "keep", "smooth")


@dataclass(frozen=True)
class FairFitReport:
    """How a fair fit came out."""

    poles: int  #: control points of the curve
    max_deviation: float  #: the largest distance from a sample to the curve the kernel found (<= tolerance)
    sign_changes: int  #: curvature sign changes of the curve (0 when it is not planar)
    data_sign_changes: int  #: sign changes of the data's smoothed curvature above its noise
    curvature_extrema: int  #: interior curvature maxima and minima of the curve
    noise: float  #: the noise used: given, or estimated (standard deviation per coordinate)
    iterations: int  #: refinement passes
    merged_points: int = 0  #: input points merged into a coincident neighbour (repeated or 1e-9 of the size apart)
    closed: bool = False  #: fitted as closed data (asked for, or recognised)
    recognised_closed: bool = False  #: open data whose last point repeats the first, fitted as closed
    corners: Tuple[int, ...] = ()  #: the input points found to be sharp corners (numbered from 0)
    pinned: int = 0  #: samples the curve was made to pass through where the csr-spline relaxes (FAIR_FIT.md, step 8)
    pieces: int = 1  #: curves returned (corners="keep": one per stretch between corners)
    corners_smoothed: bool = False  #: corners="smooth" fitted one smooth curve through the corners found

    def status(self, unit: str = "mm") -> str:
        """The one-line summary a feature shows, e.g. "ok: 42 poles, largest deviation 0.0093 mm, 0 curvature
        sign changes"."""
        changes = "curvature sign change" if self.sign_changes == 1 else "curvature sign changes"
        text = (f"ok: {self.poles} poles, largest deviation {self.max_deviation:.3g} {unit}, "
                f"{self.sign_changes} {changes}")
        if self.merged_points:
            text += f", {self.merged_points} repeated {'point' if self.merged_points == 1 else 'points'} merged"
        if self.pieces > 1:
            corners = "corner" if len(self.corners) == 1 else "corners"
            text += f", {self.pieces} edges meeting at {len(self.corners)} {corners}"
        elif self.corners_smoothed:
            text += f", {len(self.corners)} {'corner' if len(self.corners) == 1 else 'corners'} smoothed over"
        elif self.corners:  # closed data with one corner: fitted from it round to it
            text += f", corner at point {self.corners[0] + 1} kept"
        return text


def _direction(value, name, dim):
    if value is None:
        return None
    v = as_vector(value, name)
    if dim == 2:
        if abs(v[2]) > 0.0:
            raise InputError(f"{name} has a z coordinate, but the points are 2D")
        v = v[:2]
    return np.ascontiguousarray(v)


def _call(points, tolerance, closed, noise, start_tangent, end_tangent, start_curvature=None, end_curvature=None,
          corners="refuse"):
    as_choice(corners, "corners", CORNERS)
    q = as_points(points)
    tol = as_real(tolerance, "tolerance", positive=True)
    sigma = None if noise is None else as_real(noise, "noise", minimum=0)
    dim = q.shape[1]
    result = kernel.fair_fit(q, tol, as_flag(closed, "closed"), sigma, _direction(start_tangent, "start_tangent", dim),
                             _direction(end_tangent, "end_tangent", dim),
                             _direction(start_curvature, "start_curvature", dim),
                             _direction(end_curvature, "end_curvature", dim), corners)
    c = result["curve"]
    pieces = result["pieces"] or [c]
    report = FairFitReport(
        poles=int(sum(p.poles.shape[0] for p in pieces)),
        max_deviation=float(result["max_deviation"]),
        sign_changes=int(result["sign_changes"]),
        data_sign_changes=int(result["data_sign_changes"]),
        curvature_extrema=int(result["curvature_extrema"]),
        noise=float(result["noise"]),
        iterations=int(result["iterations"]),
        merged_points=int(result["merged_points"]),
        closed=bool(result["closed"]),
        recognised_closed=bool(result["recognised_closed"]),
        corners=tuple(int(i) for i in result["corners"]),
        pinned=int(result["pinned"]),
        pieces=len(pieces),
        corners_smoothed=corners == "smooth" and bool(result["corners"]),
    )
    if corners == "keep":
        import Part

        return Part.Wire([to_part(p).toShape() for p in pieces]), report
    return to_part(c), report


def fair_fit_report(points: PointsLike, tolerance: float, closed: bool = False, noise: Optional[float] = None,
                    start_tangent: Optional[VectorLike] = None, end_tangent: Optional[VectorLike] = None,
                    corners: str = "refuse") -> Tuple[Union[Part.BSplineCurve, Part.Wire], FairFitReport]:
    """fair_fit and its report (poles, largest deviation, curvature sign changes, merged
    points, corners, ...)."""
    return _call(points, tolerance, closed, noise, start_tangent, end_tangent, corners=corners)


def fair_fit(points: PointsLike, tolerance: float, closed: bool = False, noise: Optional[float] = None,
             start_tangent: Optional[VectorLike] = None, end_tangent: Optional[VectorLike] = None,
             corners: str = "refuse") -> Union[Part.BSplineCurve, Part.Wire]:
    """A cubic C2 B-spline within `tolerance` of every one of the ordered samples.

    The csr-spline of a chosen subset of noise-smoothed samples, then thinned (knots removed)
    and faired (third-derivative jumps removed) within the tolerance: few poles, no more
    curvature sign changes than the data supports, few curvature extrema (docs/FAIR_FIT.md).

    points: FreeCAD Vectors, tuples, or an (N,2)/(N,3) array; N >= 4, in order along the curve.
    tolerance: the largest distance allowed from any sample to the curve (absolute, in the
        points' units; checked by the kernel before it returns).
    closed: a periodic curve through closed data. Open data whose last point repeats the
        first are recognised as closed; repeated and near-coincident points are merged.
    noise: the samples' scatter (standard deviation per coordinate, absolute); None:
        estimated from the residuals of local quadratic fits; 0: noise-free data.
    start_tangent, end_tangent: open data only: directions (any length) the curve leaves the
        first and arrives at the last sample with. The end points of open data are interpolated.
    corners: sharp corners of the data (a turn at one point, an airfoil's trailing edge):
        "refuse" (InputError naming the point), "keep" (returns a Part.Wire with one edge per
        stretch between corners, meeting at the corners), "smooth" (one smooth curve through
        them; the report names them). Closed data with a single corner give one curve from the
        corner round to it under every choice.
    Where the csr-spline relaxes beyond the tolerance (sharp noses, hairpins) the curve is made
    to pass through the samples there, so every tolerance above the noise is met.
    Raises InputError on bad input, points out of order (naming them), corners (above), and a
    work budget exhausted.
    """
    return _call(points, tolerance, closed, noise, start_tangent, end_tangent, corners=corners)[0]


def _bspline_of(edge_or_curve: CurveLike) -> Part.BSplineCurve:
    import Part

    if isinstance(edge_or_curve, Part.Shape):
        edges = edge_or_curve.Edges
        if len(edges) != 1:
            raise InputError(f"fair_edge needs one edge, got a shape with {len(edges)} edges")
        edge = edges[0]
    elif hasattr(edge_or_curve, "toShape"):
        kernel.require_bounded(edge_or_curve.FirstParameter, edge_or_curve.LastParameter,
                               type(edge_or_curve).__name__)
        edge = edge_or_curve.toShape()
    else:
        raise InputError(f"fair_edge needs an edge or a curve, got {type(edge_or_curve).__name__}")
    kernel.require_bounded(edge.FirstParameter, edge.LastParameter, type(edge.Curve).__name__)
    return edge


def _end_jet(edge, u):
    """Point, unit tangent and curvature vector of the edge's curve at u (OCCT's D1, D2)."""
    curve = edge.Curve
    p = curve.value(u)
    d1, d2 = curve.getD2(u)[1:3]
    d1 = np.array([d1.x, d1.y, d1.z])
    d2 = np.array([d2.x, d2.y, d2.z])
    # Scaled by the largest component first, so that huge derivatives do not overflow.
    scale = float(np.max(np.abs(d1)))
    if not scale > 0:
        raise InputError("the edge's tangent vanishes at an end: its G1/G2 end conditions are undefined")
    if not math.isfinite(scale):
        raise InputError("the edge's tangent at an end is not finite")
    u = d1 / scale
    n2 = float(u @ u)
    t = u / math.sqrt(n2)
    with np.errstate(over="ignore", invalid="ignore"):
        k = ((d2 - (d2 @ t) * t) / scale) / (n2 * scale)
    if not np.all(np.isfinite(k)):
        raise InputError("the edge's curvature at an end is not finite")
    return np.array([p.x, p.y, p.z]), t, k


def fair_edge_report(edge_or_curve: CurveLike, tolerance: float, clamp: str = "G1", samples: Optional[int] = None,
                     corners: str = "refuse") -> Tuple[Union[Part.BSplineCurve, Part.Wire], FairFitReport]:
    """fair_edge and its report."""
    import Part

    as_choice(clamp, "clamp", CLAMPS)
    tol = as_real(tolerance, "tolerance", positive=True)
    edge = _bspline_of(edge_or_curve)
    n = samples if samples is not None else int(min(20000, max(1000, 50 * _pole_count(edge))))
    n = kernel.as_count(n, "samples", minimum=8)
    closed = bool(edge.isClosed()) and bool(getattr(edge.Curve, "isPeriodic", lambda: False)())
    try:
        pts = _samples_of(edge, n)
    except Part.OCCError as exc:
        raise InputError(f"the edge cannot be sampled ({exc}): is it degenerate or too large?") from None
    if closed:
        return _call(pts[:-1], tol, True, tol / 4.0, None, None, corners=corners)
    u0, u1 = edge.FirstParameter, edge.LastParameter
    if edge.Orientation == "Reversed":
        u0, u1 = u1, u0
    p0, t0, k0 = _end_jet(edge, u0)
    p1, t1, k1 = _end_jet(edge, u1)
    if edge.Orientation == "Reversed":
        t0, t1 = -t0, -t1
    pts[0], pts[-1] = p0, p1  # the end points exactly
    tangents = (t0, t1) if clamp in ("G1", "G2") else (None, None)
    curvatures = (k0, k1) if clamp == "G2" else (None, None)
    # The original curve is the data: its wiggles below the tolerance are what fairing
    # removes, so the fit smooths as if the samples had noise of a quarter of the tolerance.
    return _call(pts, tol, False, tol / 4.0, *tangents, *curvatures, corners=corners)


def _kinks(edge):
    """Parameters inside the edge where its B-spline curve is only C0 (a knot of multiplicity
    at least the degree): where it may have a corner."""
    curve = edge.Curve
    if not hasattr(curve, "getMultiplicities"):
        return []
    u0, u1 = edge.FirstParameter, edge.LastParameter
    return [u for u, m in zip(curve.getKnots(), curve.getMultiplicities()) if m >= curve.Degree and u0 < u < u1]


def _samples_of(edge, n):
    """n points equally spaced in arc length, each stretch between C0 knots on its own, so that
    a kink is a sample (the fit finds a corner at a sample, FAIR_FIT.md step 0)."""
    kinks = _kinks(edge)
    if not kinks:
        return np.array([(v.x, v.y, v.z) for v in edge.discretize(Number=n)], dtype=float)
    bounds = [edge.FirstParameter] + kinks + [edge.LastParameter]
    length = edge.Length
    out = []
    for a, b in zip(bounds[:-1], bounds[1:]):
        piece = edge.Curve.toShape(a, b)
        count = max(2, int(round(n * piece.Length / length)))
        points = [(v.x, v.y, v.z) for v in piece.discretize(Number=count)]
        out.extend(points if not out else points[1:])
    return np.array(out, dtype=float)


def _pole_count(edge):
    curve = edge.Curve
    return curve.NbPoles if hasattr(curve, "NbPoles") else 20


def fair_edge(edge_or_curve: CurveLike, tolerance: float, clamp: str = "G1", samples: Optional[int] = None,
              corners: str = "refuse") -> Union[Part.BSplineCurve, Part.Wire]:
    """Fair an existing edge or curve within `tolerance` (as Rhino's Fair).

    The edge is sampled at `samples` points equally spaced in arc length (default: 50 per
    pole, 1000 to 20000) and fitted again by fair_fit with noise = tolerance / 4, so that
    wiggles smaller than the tolerance are smoothed away. Every sample stays within
    `tolerance` of the result. The end points are kept exactly (open edges); clamp="G1" also
    keeps the end tangent directions, "G2" also the end curvature vectors, "G0" only the
    end points. A closed periodic edge gives a closed curve (no clamps). A kink of the edge
    (a sharp corner of a C0 curve) is refused, kept or smoothed over as fair_fit's `corners`
    says.
    Raises InputError for anything but one bounded edge or curve, or a tolerance it cannot meet.
    """
    return fair_edge_report(edge_or_curve, tolerance, clamp, samples, corners)[0]
