"""Fair blends: planar cubic B-splines between two end conditions whose curvature is
monotone, proved by the exact certificate (check_monotone_curvature), with as many spans as
the ends need.

    import freecad_workbench as fw
    curve, report = fw.fair_blend(line.toShape(), "end", arc.toShape(), "start")   # G2
    report.monotone, report.spans, report.variation

G1 ends (points and tangent directions) are solved for every pair of distinct points: the
blend follows the G1 Hermite clothoid of the ends (Bertolazzi & Frego 2015; the one turning
less than a full turn, and of those the one whose curvature varies least), whose curvature
is linear in arc length, as a C2 cubic spline (rational about a circle of the same turning,
so arcs stay exact) with the clothoid's end curvatures, refined until the certificate proves
its curvature monotone. G2 ends (also the signed end curvatures) follow the fairest spiral
whose curvature runs monotonically from one end curvature to the other (a cubic of arc
length, else a clothoid spline); ends that admit none are named (equal curvatures off a
common circle, osculating circles not nested: Tait-Kneser) and still get the fairest curve
found, marked not monotone. Fairness: closeness to the clothoid (G1) or the least
scale-free variation L^3 * integral (dkappa/ds)^2 ds of the spiral (G2); the report gives
that variation for the returned curve. docs/FAIR_BLENDS.md has the construction and the
measured coverage.

Curvatures are signed about the plane normal: positive turns counter-clockwise seen from
the normal's tip (+Z for data in the XY plane).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Optional, Tuple, Union

import numpy as np

from . import kernel
from .errors import InputError, NoMonotoneSolution
from .kernel import CurveLike, VectorLike, as_choice, as_vector, require_bounded, to_part
from .monotone import METHODS as PAPER_METHODS
from .monotone import MonotonicityReport, SpanVerdict, monotone_curvature_solution, report_from_certificate

if TYPE_CHECKING:
    import Part

CONTINUITIES = ("G1", "G2")
METHODS = ("fair",) + PAPER_METHODS
END_NAMES = ("start", "end")


@dataclass(frozen=True)
class FairBlendReport:
    """How a fair blend came out."""

    monotone: bool  #: the certificate proves the curvature monotone
    continuity: str  #: "G1" or "G2": what the ends were matched to
    kappa0: float  #: curvature at the start, signed about `normal`
    kappa1: float  #: curvature at the end
    turning: float  #: total tangent turning, radians, signed about `normal`
    length: float  #: arc length of the clothoid the blend follows
    variation: float  #: scale-free curvature variation L^3 * integral (dkappa/ds)^2 ds
    spans: int  #: knot spans of the cubic
    extrema: Tuple[Tuple[float, float, bool], ...]  #: interior curvature extrema (u, kappa, is_maximum)
    normal: Tuple[float, float, float]
    certificate: MonotonicityReport
    reason: str
    torsion_sign_changes: int = 0  #: sign changes of the torsion along the blend (0 for a planar blend)
    planar: bool = True  #: the ends are coplanar and the blend lies in their plane

    def __bool__(self):
        return self.monotone


def curvature_extrema_of(certificate):
    """The curvature extrema a MonotonicityReport shows, as (u, kappa, is_maximum): one inside
    every span where kappa' changes sign, and one at every knot where the spans on its two
    sides run opposite ways."""
    extrema, direction = [], 0
    for span in certificate.spans:
        entering = leaving = {"increasing": 1, "decreasing": -1}.get(span.trend, 0)
        if span.extremum is not None:
            entering = 1 if span.extremum[2] else -1
            leaving = -entering
        if entering and direction and entering != direction:
            extrema.append((span.u0, span.kappa0, direction > 0))
        if span.extremum is not None:
            extrema.append(span.extremum)
        if leaving:
            direction = leaving
    return tuple(extrema)


def _optional_curvature(value, name):
    if value is None:
        return float("nan")
    try:
        k = float(value)
    except (TypeError, ValueError):
        raise InputError(f"{name} must be a number, got {value!r}") from None
    if not np.isfinite(k):
        raise InputError(f"{name} must be finite, got {k}")
    return k


def fair_blend_solution(p0: VectorLike, t0: VectorLike, p1: VectorLike, t1: VectorLike,
                        k0: Union[None, float, VectorLike] = None, k1: Union[None, float, VectorLike] = None,
                        normal: Optional[VectorLike] = None) -> tuple[Part.BSplineCurve, FairBlendReport]:
    """The fair blend from p0 with direction t0 to p1 with direction t1 (G1), or also with
    the signed end curvatures k0, k1 (G2): (Part.BSplineCurve, FairBlendReport).
    normal: the plane normal the curvatures refer to (default: +Z for data in the XY plane,
    else derived from the data, which needs no sign for G1 only).
    Never raises for ends that admit no monotone curve: the report says so (report.monotone
    False, report.reason why) and the curve is the fairest found, still meeting the ends.
    Raises InputError on bad input: NaN, a zero tangent, coincident points, ends not in one
    plane, only one of k0 and k1, curvatures of ends outside the XY plane without a normal.

    In space: k0, k1 may be the end curvature vectors kappa N (3 numbers each, as OCCT
    evaluates an edge: (d1 x d2) x d1 / |d1|^4); and G1 ends that do not lie in one plane
    (no normal given) get the fair blend in space (fair_blend_space_solution)."""
    if _is_vector(k0) or _is_vector(k1):
        return fair_blend_space_solution(p0, t0, p1, t1, k0, k1)
    if normal is None and k0 is None and k1 is None and not _coplanar(p0, t0, p1, t1):
        return fair_blend_space_solution(p0, t0, p1, t1)
    result = kernel.fair_blend(
        as_vector(p0, "p0"),
        as_vector(t0, "t0"),
        as_vector(p1, "p1"),
        as_vector(t1, "t1"),
        _optional_curvature(k0, "k0"),
        _optional_curvature(k1, "k1"),
        np.zeros(3) if normal is None else as_vector(normal, "normal"),
    )
    kernel_curve = result["curve"]
    certificate = report_from_certificate(result["certificate"], kernel_curve)
    extrema = curvature_extrema_of(certificate)
    report = FairBlendReport(
        monotone=bool(result["monotone"]),
        continuity="G1" if k0 is None and k1 is None else "G2",
        kappa0=float(result["kappa0"]),
        kappa1=float(result["kappa1"]),
        turning=float(result["turning"]),
        length=float(result["length"]),
        variation=float(result["variation"]),
        spans=int(result["spans"]),
        extrema=extrema,
        normal=tuple(float(c) for c in result["normal"]),
        certificate=certificate,
        reason=result["reason"],
    )
    return to_part(kernel_curve), report


def _is_vector(value):
    return value is not None and not isinstance(value, (int, float, np.floating, np.integer))


def _coplanar(p0, t0, p1, t1, tol=1e-9):
    """Do the chord and the two tangents lie in one plane (within the planar solver's 1e-9)?"""
    u = as_vector(p1, "p1") - as_vector(p0, "p0")
    vectors = [v / np.linalg.norm(v) for v in (u, as_vector(t0, "t0"), as_vector(t1, "t1")) if np.linalg.norm(v) > 0]
    if len(vectors) < 3 or not all(np.all(np.isfinite(v)) for v in vectors):
        return True  # the kernel names the problem
    return abs(float(np.dot(vectors[0], np.cross(vectors[1], vectors[2])))) <= tol


def _space_report(cert):
    """A MonotonicityReport of the kernel's space certificate (curvatures unsigned, no plane)."""
    extrema = [tuple(e) for e in cert["extrema"]]
    spans = []
    for i, s in enumerate(cert["spans"]):
        inside = [e for e in extrema if s["u0"] <= e[0] <= s["u1"]] if s["trend"] == "extremum" else []
        extremum = (float(inside[0][0]), float(inside[0][1]), bool(inside[0][2])) if inside else None
        trend = s["trend"] if s["trend"] != "extremum" or extremum else "undecided"
        spans.append(SpanVerdict(i, s["u0"], s["u1"], s["kappa0"], s["kappa1"], trend, s["reason"], extremum, None))
    return MonotonicityReport(bool(cert["monotone"]), bool(cert["increasing"]), bool(cert["decreasing"]),
                              float(cert["kappa_start"]), float(cert["kappa_end"]), (0.0, 0.0, 0.0), cert["reason"],
                              tuple(spans))


def _curvature_vector(value, name):
    if value is None:
        return np.full(3, np.nan)
    return as_vector(value, name)


def fair_blend_space_solution(p0: VectorLike, t0: VectorLike, p1: VectorLike, t1: VectorLike,
                              K0: Optional[VectorLike] = None,
                              K1: Optional[VectorLike] = None) -> tuple[Part.BSplineCurve, FairBlendReport]:
    """The fair blend between two ends anywhere in space: from p0 with direction t0 to p1 with
    direction t1 (G1), or also with the end curvature vectors K0, K1 (kappa N, G2).
    Coplanar ends get the planar fair blend in their plane; otherwise the blend follows a
    space spiral (curvature monotone in arc length, torsion of one sign where it can) as a C2
    cubic whose curvature the space certificate proves monotone (docs/FAIR_BLENDS.md).
    report.kappa0/kappa1 are the curvatures (unsigned) at the ends, report.turning the angle
    between the end tangents, report.torsion_sign_changes and report.planar say how it twists.
    Never raises for ends that admit no monotone curve (report.monotone False, report.reason).
    Raises InputError on bad input: NaN, a zero tangent, coincident points, only one of K0 and
    K1, a curvature vector along its tangent."""
    if (K0 is None) != (K1 is None):
        raise InputError("give both end curvature vectors K0 and K1 for a G2 blend, or neither for G1")
    a0, a1 = as_vector(t0, "t0"), as_vector(t1, "t1")
    result = kernel.fair_blend_space(as_vector(p0, "p0"), a0, as_vector(p1, "p1"), a1,
                                     _curvature_vector(K0, "K0"), _curvature_vector(K1, "K1"))
    kernel_curve = result["curve"]
    cert = result["certificate"]
    certificate = _space_report(cert)
    n0, n1 = np.linalg.norm(a0), np.linalg.norm(a1)
    turning = float(np.arctan2(np.linalg.norm(np.cross(a0, a1)), np.dot(a0, a1))) if n0 > 0 and n1 > 0 else 0.0
    report = FairBlendReport(
        monotone=bool(result["monotone"]),
        continuity="G1" if K0 is None else "G2",
        kappa0=float(cert["kappa_start"]),
        kappa1=float(cert["kappa_end"]),
        turning=turning,
        length=float(result["length"]),
        variation=float(result["variation"]),
        spans=int(result["spans"]),
        extrema=tuple((float(u), float(k), bool(m)) for u, k, m in cert["extrema"]),
        normal=tuple(float(c) for c in result["normal"]),
        certificate=certificate,
        reason=result["reason"],
        torsion_sign_changes=int(result["torsion_sign_changes"]),
        planar=bool(result["planar"]),
    )
    return to_part(kernel_curve), report


# ---------------------------------------------------------------------------------------
# Ends taken from edges.


@dataclass(frozen=True)
class EdgeEnd:
    """Where a blend meets an edge: the point, the blend's direction there, and the second
    derivative of the edge traversed in that direction (for the signed curvature)."""

    point: np.ndarray
    tangent: np.ndarray  #: unit, the blend's direction of travel
    d1: np.ndarray  #: first derivative along the blend's direction of travel
    d2: np.ndarray  #: second derivative, same traversal


def _edge_of(item, name):
    import Part

    if isinstance(item, Part.Edge):
        return item
    if isinstance(item, Part.Shape):
        if len(item.Edges) == 1:
            return item.Edges[0]
        raise InputError(f"{name} has {len(item.Edges)} edges: give one edge")
    if hasattr(item, "toShape"):  # a Part curve or a Sketcher geometry
        try:
            return item.toShape()
        except Exception as exc:  # noqa: BLE001  (OCCT's message names the problem)
            raise InputError(f"{name} cannot be made an edge: {exc}") from None
    raise InputError(f"{name} is not an edge or a curve: {item!r}")


def _end_parameter(edge, end, name):
    first, last = edge.FirstParameter, edge.LastParameter
    require_bounded(first, last, type(edge.Curve).__name__)
    if isinstance(end, str):
        if end not in END_NAMES:
            raise InputError(f"{name} must be 'start', 'end', a vertex or a point, got {end!r}")
        return first if end == "start" else last
    import Part

    point = end.Point if isinstance(end, Part.Vertex) else end
    q = as_vector(point, name)
    ends = [(np.linalg.norm(np.array(edge.valueAt(u)) - q), u) for u in (first, last)]
    return min(ends)[1]


def edge_end(edge_like, end, leaving, name="edge"):
    """The EdgeEnd of an edge (Part.Edge, a one-edge shape, a Part curve or a Sketcher
    geometry) at `end` ("start", "end", or a vertex or point: the nearer end). leaving: the
    blend leaves the edge there (it continues the edge), else it arrives (and runs on into
    the edge). Derivatives are OCCT's at the edge's end parameter."""
    edge = _edge_of(edge_like, name)
    u = _end_parameter(edge, end, name + " end")
    at_last = u == edge.LastParameter
    # The blend travels along the edge's parameter if it leaves at the last end or arrives at
    # the first; otherwise against it, which flips the first derivative only.
    forward = at_last == leaving
    d1 = np.array(edge.derivative1At(u))
    d2 = np.array(edge.derivative2At(u))
    if not forward:
        d1 = -d1
    norm = np.linalg.norm(d1)
    if not (norm > 0.0 and np.isfinite(norm)):
        raise InputError(f"{name} has no tangent at that end (zero derivative)")
    return EdgeEnd(np.array(edge.valueAt(u)), d1 / norm, d1, d2)


def _plane_normal(a, b):
    """A normal of the plane of two ends: +Z when everything lies in a plane parallel to XY;
    else the plane of the chord and the tangents, or of the chord and the edges' second
    derivatives when the tangents run along the chord. None when all is on one line."""
    chord = b.point - a.point
    vectors = [chord, a.tangent, b.tangent, a.d2, b.d2]
    scale = max(np.linalg.norm(v) for v in vectors)
    if all(abs(v[2]) <= 1e-12 * max(scale, 1e-300) for v in vectors):
        return np.array([0.0, 0.0, 1.0])
    u = chord / np.linalg.norm(chord)
    for candidates in ((a.tangent, b.tangent), (a.d2, b.d2)):
        n = max((np.cross(u, v) for v in candidates), key=np.linalg.norm)
        if np.linalg.norm(n) > 1e-12 * max(np.linalg.norm(candidates[0]), np.linalg.norm(candidates[1]), 1e-300):
            return n / np.linalg.norm(n)
    return None


def curvature_vector(end):
    """kappa N of an EdgeEnd, as OCCT's derivatives give it: (d1 x d2) x d1 / |d1|^4."""
    return np.cross(np.cross(end.d1, end.d2), end.d1) / np.linalg.norm(end.d1) ** 4


def _ends_in_plane(a, b, normal, g2, tol=1e-9):
    """Do the ends lie in the plane of `normal` as the planar solver needs (the chord and the
    tangents within 1e-9; for G2 the curvature vectors too, relative to their length)? No
    normal: everything on one line, which the planar solver handles."""
    if normal is None:
        return True
    chord = b.point - a.point
    vectors = [chord / max(np.linalg.norm(chord), 1e-300), a.tangent, b.tangent]
    if g2:
        vectors += [v / np.linalg.norm(v) for v in (curvature_vector(a), curvature_vector(b)) if np.linalg.norm(v) > 0]
    return all(abs(float(np.dot(v, normal))) <= tol for v in vectors)


def _signed_curvature(end, normal):
    return float(np.dot(np.cross(end.d1, end.d2), normal) / np.linalg.norm(end.d1) ** 3)


def monotone_curvature_spline(p0: VectorLike, t0: VectorLike, p1: VectorLike, t1: VectorLike,
                              k0: Optional[float] = None, k1: Optional[float] = None,
                              normal: Optional[VectorLike] = None, method: str = "fair") -> Part.BSplineCurve:
    """A planar cubic B-spline from p0 with direction t0 to p1 with direction t1 (and with
    the signed curvatures k0, k1 there, G2, when given) whose curvature is monotone, proved by
    the exact certificate. Curvatures are signed about `normal` (+Z for data in the XY plane).

    method: "fair" (default) is the fair blend (fair_blend_solution): every G1 problem with
    distinct points is solved. "paper" and "grid" are the paper's Algorithm 2 and its grid
    search, one short cubic, G1 only: the baselines (see monotone_curvature_solution).
    Raises NoMonotoneSolution (an InputError) with the reason when no monotone curve is found,
    InputError on bad input."""
    as_choice(method, "method", METHODS + ("fairest",))
    if method != "fair":
        if k0 is not None or k1 is not None:
            raise InputError("the paper's Algorithm 2 is G1: end curvatures need method='fair'")
        return monotone_curvature_solution(p0, t0, p1, t1, method).curve
    curve, report = fair_blend_solution(p0, t0, p1, t1, k0, k1, normal)
    if not report.monotone:
        raise NoMonotoneSolution("no monotone-curvature curve: " + report.reason)
    return curve


def fair_blend(edge_a: CurveLike, end_a: Union[str, Part.Vertex, VectorLike], edge_b: CurveLike,
               end_b: Union[str, Part.Vertex, VectorLike],
               continuity: str = "G2") -> tuple[Part.BSplineCurve, FairBlendReport]:
    """The fair blend from edge_a's end `end_a` to edge_b's end `end_b`: it leaves edge_a
    continuing it and runs on into edge_b, matching their tangents (G1) or also their
    curvatures (G2), as OCCT evaluates the edges there. Edges: Part or Sketcher lines, arcs,
    conics, B-splines (an edge, a one-edge shape, or the geometry). end_*: "start", "end", or
    a vertex or point (the nearer end of that edge).
    Returns (Part.BSplineCurve, FairBlendReport): where the ends admit no monotone curve the
    curve is the fairest found (still G1 or G2 to both edges) and the report says why.
    Raises InputError on bad input."""
    as_choice(continuity, "continuity", CONTINUITIES)
    a = edge_end(edge_a, end_a, leaving=True, name="edge_a")
    b = edge_end(edge_b, end_b, leaving=False, name="edge_b")
    normal = _plane_normal(a, b)
    if not _ends_in_plane(a, b, normal, continuity == "G2"):  # in space: curvature vectors, not signs
        if continuity == "G2":
            return fair_blend_space_solution(a.point, a.tangent, b.point, b.tangent, curvature_vector(a),
                                             curvature_vector(b))
        return fair_blend_space_solution(a.point, a.tangent, b.point, b.tangent)
    k0 = k1 = None
    if continuity == "G2":
        if normal is None:  # straight ends and straight edges: any plane through them, curvatures 0
            normal = np.cross(a.tangent, [1.0, 0.0, 0.0] if abs(a.tangent[0]) < 0.9 else [0.0, 1.0, 0.0])
            normal /= np.linalg.norm(normal)
        k0, k1 = _signed_curvature(a, normal), _signed_curvature(b, normal)
    return fair_blend_solution(a.point, a.tangent, b.point, b.tangent, k0, k1, normal)
