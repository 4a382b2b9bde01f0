"""Curve constructions of the csr paper (Karčiauskas & Peters, "Curvature-sensitive
splines and design with basic curves") and the baselines they are compared with.
Every function returns a FreeCAD ``Part.BSplineCurve``."""
from __future__ import annotations

from typing import TYPE_CHECKING, Optional, Sequence

import numpy as np

from . import kernel
from .kernel import PointsLike, adopt, as_choice, as_flag, as_points, as_real, as_reals, has_bridge, to_part

if TYPE_CHECKING:
    import Part

PARAMETRIZATIONS = ("chordal", "centripetal", "uniform")
EPSILON_RULES = {"case": kernel.EpsilonRule.CaseDistinction, "additive": kernel.EpsilonRule.Additive}
_NO_PARAMETERS = np.zeros(0)  # read only by the kernel


def _check_parametrization(parametrization):
    as_choice(parametrization, "parametrization", PARAMETRIZATIONS)


def csr_spline(points: PointsLike, closed: bool = False, parametrization: str = "chordal", epsilon: float = 1e-9,
               epsilon_rule: str = "case", parameters: Optional[Sequence[float]] = None) -> Part.BSplineCurve:
    """Curvature-sensitive relaxed spline (Section 4, eq. (6)) through sampled data.

    A cubic C2 B-spline with a knot per sample. It stays close to the samples without
    interpolating them, and does not oscillate where the data's curvature changes
    sharply. Open data: the end points are interpolated. Closed data: periodic curve.

    points: FreeCAD Vectors, tuples, or an (N,2)/(N,3) array; N >= 3.
    parametrization: "chordal" (default), "centripetal" or "uniform".
    epsilon: tolerance of eq. (6), relative to 1/size of the data.
    epsilon_rule: "case" (mu, nu := 1/2 below epsilon, the paper's main form) or
        "additive" (epsilon added to every curvature).
    parameters: optional explicit parameters (N values, N+1 when closed).
    Raises InputError on bad input.
    """
    _check_parametrization(parametrization)
    as_choice(epsilon_rule, "epsilon_rule", EPSILON_RULES)
    q = as_points(points)
    t = _NO_PARAMETERS if parameters is None else as_reals(parameters, "parameters")
    args = (q, as_flag(closed, "closed"), parametrization, as_real(epsilon, "epsilon", finite=False),
            EPSILON_RULES[epsilon_rule], t)
    if has_bridge():  # the fit goes straight into an OCCT edge that FreeCAD adopts
        return adopt(kernel.csr_edge_capsule(*args)).Edge1.Curve
    return to_part(kernel.csr_spline(*args))


def interpolate_classic(points: PointsLike, closed: bool = False,
                        parametrization: str = "chordal") -> Part.BSplineCurve:
    """Classic C2 cubic interpolation (OCCT GeomAPI_Interpolate), the baseline."""
    _check_parametrization(parametrization)
    return to_part(kernel.classic_interpolation(as_points(points), as_flag(closed, "closed"), parametrization))


def quasi_interpolant(points: PointsLike, closed: bool = False, parametrization: str = "chordal") -> Part.BSplineCurve:
    """The cubic quasi-interpolant, (-1, 8, -1)/6 for uniform parameters (Fig. 2e)."""
    _check_parametrization(parametrization)
    return to_part(kernel.quasi_interpolant(as_points(points), as_flag(closed, "closed"), parametrization))


def control_point_spline(points: PointsLike, closed: bool = False) -> Part.BSplineCurve:
    """The cubic B-spline that uses the data as control points (Fig. 2f, red)."""
    return to_part(kernel.control_point_spline(as_points(points), as_flag(closed, "closed")))


def quadratic_design(points: PointsLike, closed: bool = False, parametrization: str = "chordal",
                     epsilon: float = 1e-9) -> Part.BSplineCurve:
    """Quadratic design (Section 7, eq. (12)): sparse points to quadratic Bézier pieces
    {q_i, m_i, q_(i+1)} whose handles m_i are the poles between the data points.
    Returns a degree-2 Part.BSplineCurve (C0 at the data points, exact quadratics)."""
    _check_parametrization(parametrization)
    return to_part(kernel.quadratic_design(as_points(points), as_flag(closed, "closed"), parametrization,
                                           as_real(epsilon, "epsilon", finite=False)))
