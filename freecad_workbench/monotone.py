"""Planar cubic B-splines with monotonic curvature (Wang, He, Hou, Cai & Zhao, "Designing
planar cubic B-spline curves with monotonic curvature for curve interpolation"), and an exact
certificate that any planar B-spline or Bezier curve has monotone curvature.

    import freecad_workbench as fw
    curve = fw.monotone_curvature_solution((0, 0), (1, 0), (1, 0.5), (0.8, 0.6)).curve   # Algorithm 2
    report = fw.check_monotone_curvature(curve)
    report.monotone, report.decreasing             # True True
    print(report)                                  # one line per span, with its reason

Curvature is signed about the curve's plane normal (counter-clockwise turning positive), so
`increasing` and `decreasing` refer to the signed curvature along the curve's parameter.
"""
from __future__ import annotations

import re
from dataclasses import dataclass
from typing import TYPE_CHECKING, Optional, Sequence, Tuple

import numpy as np

from . import kernel
from .errors import InputError
from .kernel import (CurveLike, PointsLike, VectorLike, as_choice, as_points, as_real, as_reals, as_vector, from_part,
                     to_part)

if TYPE_CHECKING:
    import Part

# The paper's Algorithm 2: "paper" solves for the analytic centre of the family's admissible
# set (called "fairest" before fair blends existed; still accepted), "grid" is the paper's
# grid search.
METHODS = ("paper", "grid")
_KERNEL_METHODS = {"paper": "fairest", "fairest": "fairest", "grid": "grid"}


@dataclass(frozen=True)
class EndConditions:
    """Where G1 end conditions stand with respect to the family (see monotone_end_conditions)."""

    admissible: bool
    straight: bool  #: collinear, same direction: the straight segment
    reversed: bool  #: the curvature must increase from p0
    a: float  #: |M - p0|, M the intersection of the end tangents
    b: float  #: |p1 - M|
    turn: float  #: angle from t0 to t1, radians
    reason: str  #: why not admissible ('' when admissible)


def monotone_end_conditions(p0: VectorLike, t0: VectorLike, p1: VectorLike, t1: VectorLike) -> EndConditions:
    """Classify G1 end conditions: admissible when the end tangents meet at M ahead of p0 and
    behind p1, turn by less than 90 degrees, and min(a, b) <= max(a, b) cos(turn) with
    a = |M - p0|, b = |p1 - M| (equality: a parabola from its vertex). Raises InputError on bad
    input (a zero tangent, coincident points, NaN)."""
    info = kernel.analyze_end_conditions(as_vector(p0, "p0"), as_vector(t0, "t0"), as_vector(p1, "p1"),
                                         as_vector(t1, "t1"))
    return EndConditions(**info)


@dataclass(frozen=True)
class MonotoneSolution:
    """Algorithm 2's curve and how it was found."""

    curve: object  #: Part.BSplineCurve
    reversed: bool  #: curvature increases from p0 (else it decreases)
    boundary: bool  #: on the family's boundary: the parabola (no interior curve exists)
    margin: float  #: smallest normalized slack of Theorem 2 (fairest method; 0 on the boundary)
    iterations: int  #: Newton iterations, or grid points tried


def monotone_curvature_solution(p0: VectorLike, t0: VectorLike, p1: VectorLike, t1: VectorLike, method: str = "paper",
                                grid_step: float = 0.02) -> MonotoneSolution:
    """The paper's Algorithm 2 with the solver's diagnostics: a MonotoneSolution whose curve is
    a planar cubic B-spline (5 poles, knots 0, 1, 2 with multiplicities 4, 1, 4) from p0 with
    direction t0 to p1 with direction t1, verified by Theorem 1 and the exact certificate.

    method: "paper" (or its old name "fairest") returns the analytic centre of the family's
    admissible set, the curve deepest inside the paper's Theorem 2 conditions; "grid" the
    first hit of the paper's grid search (step grid_step), the baseline.
    Raises NoMonotoneSolution (an InputError) with the reason when no curve of the family meets
    the end conditions (or, for "grid", when the grid finds none); InputError on bad input.
    fw.monotone_curvature_spline solves every G1 problem (see fair_blend)."""
    as_choice(method, "method", METHODS + ("fairest",))
    curve, reversed_, boundary, margin, iterations = kernel.monotone_spline(
        as_vector(p0, "p0"), as_vector(t0, "t0"), as_vector(p1, "p1"), as_vector(t1, "t1"),
        _KERNEL_METHODS[method], as_real(grid_step, "grid_step", positive=True)
    )
    return MonotoneSolution(to_part(curve), bool(reversed_), bool(boundary), float(margin), int(iterations))


def _design_inputs(first_vector, differences, knots, start):
    first = as_vector(first_vector, "first_vector")
    diffs = as_points(differences, "differences")
    if first[2] != 0.0 or (diffs.shape[1] == 3 and np.any(diffs[:, 2] != 0.0)):
        raise InputError("Algorithm 1 designs in the XY plane: give vectors with z = 0")
    origin = np.zeros(2) if start is None else as_vector(start, "start")[:2]
    t = np.zeros(0) if knots is None else as_reals(knots, "knots")
    return first[:2].copy(), np.ascontiguousarray(diffs[:, :2]), t, origin


def monotone_curvature_design(first_vector: VectorLike, differences: PointsLike,
                              knots: Optional[Sequence[float]] = None,
                              start: Optional[VectorLike] = None) -> Part.BSplineCurve:
    """Algorithm 1: the cubic B-spline with control points C_0 = start (default origin),
    C_1 = C_0 + V_0, C_{i+1} = C_i + V_i, V_0 = first_vector, V_{i+1} = V_i + dV_i.

    Each difference dV_i is moved, if needed, to the nearest vector that puts the second
    derivative control point C^2_i in its fair location (Theorem 2; for dV_0: the first
    quadrant of V_0's frame, or the fourth for a right turn), so the curvature is monotone.
    differences: N >= 2 vectors in the XY plane; knots: the full knot vector t_0..t_(N+5)
    (default: clamped, uniform inside). Returns a Part.BSplineCurve in the XY plane.
    See clamp_to_fair_locations for the differences actually used."""
    curve, _, _, _ = kernel.design_monotone(*_design_inputs(first_vector, differences, knots, start))
    return to_part(curve)


def clamp_to_fair_locations(first_vector: VectorLike, differences: PointsLike,
                            knots: Optional[Sequence[float]] = None) -> tuple[np.ndarray, np.ndarray]:
    """The differences Algorithm 1 uses, as an (N, 2) array, and how far each was moved (N,)
    to reach its fair location (0 where it was kept as given)."""
    _, used, moved, _ = kernel.design_monotone(*_design_inputs(first_vector, differences, knots, None))
    return np.asarray(used), np.asarray(moved)


@dataclass(frozen=True)
class SpanVerdict:
    """The certificate's verdict on one knot span."""

    index: int
    u0: float
    u1: float
    kappa0: float  #: signed curvature at u0
    kappa1: float  #: signed curvature at u1
    trend: str  #: increasing, decreasing, constant, extremum, singular or undecided
    reason: str  #: why: the Bernstein coefficients of N, or where kappa' changes sign
    extremum: Optional[Tuple[float, float, bool]]  #: (u, kappa, is_maximum) for an extremum
    paper: Optional[str]  #: Lemmas 1-3 / Theorem 1 in the segment's frame (cubic polynomial curves)


_SPAN = re.compile(r"\bspan (\d+)")
# the curvature values of a monotone verdict: "from A to B", "constant curvature A"
_UNITS = re.compile(r"(?<=from )[-+0-9.e]+|(?<= to )[-+0-9.e]+(?= \()|(?<=constant curvature )[-+0-9.e]+")


@dataclass(frozen=True)
class MonotonicityReport:
    """check_monotone_curvature's answer."""

    monotone: bool
    increasing: bool  #: signed curvature nondecreasing along the parameter
    decreasing: bool  #: nonincreasing (both: constant curvature)
    kappa_start: float
    kappa_end: float
    normal: Tuple[float, float, float]  #: plane normal the curvature sign refers to
    reason: str
    spans: Tuple[SpanVerdict, ...]

    def __bool__(self):
        return self.monotone

    @property
    def summary(self):
        """The verdict in a designer's words, for the GUI: what the curvature does, in 1/mm,
        spans numbered from 1; no Bernstein coefficients (str() keeps the whole proof)."""
        for s in self.spans:
            if s.trend == "extremum":
                u, kappa, maximum = s.extremum
                kind = "maximum" if maximum else "minimum"
                return (f"not monotone: the curvature has a {kind} of {kappa:.6g} 1/mm "
                        f"at parameter {u:.6g} (span {s.index + 1})")
            if s.trend == "singular":
                return (f"not monotone: the curve stops (its derivative vanishes) on span {s.index + 1}, "
                        "so its curvature is undefined there")
            if s.trend == "undecided":
                return (f"not proven: the curvature is flat within rounding on span {s.index + 1} "
                        "and its direction could not be decided")
        text = _SPAN.sub(lambda m: f"span {int(m.group(1)) + 1}", self.reason)
        return _UNITS.sub(lambda m: f"{m.group(0)} 1/mm", text) if self.monotone else text

    def __str__(self):
        lines = [self.reason]
        for s in self.spans:
            line = f"  span {s.index} (u in [{s.u0:.6g}, {s.u1:.6g}]): {s.trend}: {s.reason}"
            if s.paper:
                line += f"; paper: {s.paper}"
            lines.append(line)
        return "\n".join(lines)


def check_monotone_curvature(curve: CurveLike, rel_tol: float = 1e-12) -> MonotonicityReport:
    """Exact certificate that a planar curve (Part.BSplineCurve, Part.BezierCurve, any Part
    curve or edge, converted exactly to a B-spline; polynomial or rational) has monotone
    curvature. Per knot span the sign of kappa' is the sign of one polynomial, decided from
    its Bernstein coefficients with subdivision; joints with a curvature jump or a corner count
    too. Returns a MonotonicityReport (truthy when monotone) with a verdict and reason per
    span; for non-periodic polynomial cubics also the paper's Lemmas 1-3 per segment.
    Raises InputError for a non-planar curve."""
    kernel_curve = from_part(curve)
    certificate = kernel.certify_monotone(kernel_curve, as_real(rel_tol, "rel_tol", minimum=0))
    return report_from_certificate(certificate, kernel_curve)


def report_from_certificate(cert, kernel_curve):
    """The MonotonicityReport of the kernel's certificate (a dict) of kernel_curve."""
    paper = [None] * len(cert["spans"])
    if kernel_curve.degree == 3 and not kernel_curve.rational and not kernel_curve.periodic:
        paper = [s["reason"] for s in kernel.check_segments(kernel_curve)]
    spans = []
    for i, (s, p) in enumerate(zip(cert["spans"], paper)):
        extremum = (s["at"], s["kappa_at"], bool(s["maximum"])) if s["trend"] == "extremum" else None
        spans.append(
            SpanVerdict(i, s["u0"], s["u1"], s["kappa0"], s["kappa1"], s["trend"], s["reason"], extremum, p)
        )
    return MonotonicityReport(
        bool(cert["monotone"]),
        bool(cert["increasing"]),
        bool(cert["decreasing"]),
        float(cert["kappa_start"]),
        float(cert["kappa_end"]),
        tuple(float(c) for c in cert["normal"]),
        cert["reason"],
        tuple(spans),
    )


def curvature_variation(curve: CurveLike) -> float:
    """Scale-free curvature variation L^3 * integral (dkappa/ds)^2 ds of a planar curve: 0 for
    lines and circles, small for fair spirals. Used to compare solvers."""
    return float(kernel.curvature_variation(from_part(curve)))


def derivative_polygons(curve: CurveLike) -> tuple[np.ndarray, np.ndarray]:
    """Eqs. (3) and (5): the control points C^1_i of P' and C^2_i of P'' of a non-periodic,
    non-rational cubic B-spline, as two arrays."""
    first, second = kernel.derivative_polygons(from_part(curve))
    return np.asarray(first), np.asarray(second)
