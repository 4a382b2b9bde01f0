"""csr-spline (Section 4, eq. (6)) through the macro API, judged by OCCT evaluation of
the returned Part.BSplineCurve."""
import math

import numpy as np
import pytest

import freecad_workbench as fw
from tests.kernel.fig2 import distance_to_curve, fig2_samples, sign_changes, signed_curvatures

import FreeCAD  # noqa: E402  (made importable by freecad_workbench)
import Part  # noqa: E402


def test_fig2_classic_interpolation_oscillates_and_csr_does_not():
    q = fig2_samples()
    classic = fw.interpolate_classic(q)
    csr = fw.csr_spline(q)
    assert sign_changes(signed_curvatures(classic)) >= 2
    assert sign_changes(signed_curvatures(csr)) == 0
    # The kernel's own analysis agrees with the OCCT-evaluated count.
    assert fw.curvature_sign_changes(classic) >= 2
    assert fw.curvature_sign_changes(csr) == 0


def test_fig2_quasi_interpolant_oscillates():
    assert sign_changes(signed_curvatures(fw.quasi_interpolant(fig2_samples()))) >= 2


def test_csr_stays_within_stated_distance_of_the_data():
    # Stated in the README: on the Fig. 2 data (spacing pi/12 on a unit circle) every
    # sample is within 0.0037 of the csr-spline (0.4% of the radius; measured 0.00367).
    q = fig2_samples()
    csr = fw.csr_spline(q)
    worst = max(distance_to_curve(csr, (x, y, 0.0)) for x, y in q)
    assert worst < 3.8e-3
    assert fw.max_distance(csr, q) == pytest.approx(worst, rel=1e-6, abs=1e-12)


def test_csr_is_cubic_c2_with_exact_end_points():
    q = fig2_samples()
    c = fw.csr_spline(q)
    assert isinstance(c, Part.BSplineCurve)
    assert c.Degree == 3
    assert c.Continuity == "C2"
    assert set(c.getMultiplicities()[1:-1]) == {1}
    start, end = c.value(c.FirstParameter), c.value(c.LastParameter)
    assert (start.x, start.y, start.z) == (q[0, 0], q[0, 1], 0.0)
    assert (end.x, end.y, end.z) == (q[-1, 0], q[-1, 1], 0.0)


def test_second_derivative_continuous_across_every_knot():
    c = fw.csr_spline(fig2_samples())
    knots = c.getKnots()
    span = knots[-1] - knots[0]
    d3 = max(c.getD3(u)[3].Length for u in np.linspace(knots[0], knots[-1], 400))
    delta = 1e-7 * span
    for k in knots[1:-1]:
        jump = (c.getD2(k + delta)[2] - c.getD2(k - delta)[2]).Length
        # C2: the second derivative moves only by the third derivative's share.
        assert jump <= 2.5 * delta * d3


def test_quadratic_data_reproduced_exactly_at_non_uniform_parameters():
    rng = np.random.default_rng(3)
    t = np.cumsum(np.r_[0.0, 0.05 + rng.random(14)])

    def f(x):
        return np.array([1 + 2 * x - x * x, 0.5 * x * x, 3 - x])

    q = np.array([f(x) for x in t])
    c = fw.csr_spline(q, parameters=t)
    for u in np.linspace(t[0], t[-1], 301):
        v = c.value(u)
        assert np.linalg.norm(np.array([v.x, v.y, v.z]) - f(u)) <= 1e-12 * np.linalg.norm(f(u)) + 1e-13


def test_dense_circle_curvature_is_inverse_radius():
    r = 3.0
    a = np.linspace(0, 2 * math.pi, 150, endpoint=False)
    c = fw.csr_spline(np.c_[r * np.cos(a), r * np.sin(a)], closed=True)
    assert c.isPeriodic()
    for u in np.linspace(c.FirstParameter, c.LastParameter, 700):
        assert c.curvature(u) == pytest.approx(1 / r, abs=1e-3)


def test_closed_curve_is_periodic_and_c2_through_the_seam():
    a = np.linspace(0, 2 * math.pi, 30, endpoint=False)
    q = np.c_[2 * np.cos(a), np.sin(a), 0.3 * np.sin(2 * a)]
    c = fw.csr_spline(q, closed=True)
    assert c.isPeriodic() and c.isClosed()
    assert c.Continuity == "C2"
    first, last = c.FirstParameter, c.LastParameter
    for k in range(3):
        d_first = c.getD2(first)[k]
        d_last = c.getD2(last)[k]
        assert (d_first - d_last).Length <= 1e-10 * max(1.0, d_first.Length)


def test_collinear_data_gives_a_straight_line():
    s = np.array([0.0, 0.3, 1.1, 1.5, 3.0, 3.2, 5.0])
    direction = np.array([0.6, -0.48, 0.64])
    q = np.array([1.0, 2.0, -1.0]) + s[:, None] * direction
    c = fw.csr_spline(q)
    for u in np.linspace(c.FirstParameter, c.LastParameter, 200):
        v = c.value(u)
        offset = np.array([v.x, v.y, v.z]) - q[0]
        assert np.linalg.norm(np.cross(offset, direction)) < 1e-12 * 10
        assert c.curvature(u) < 1e-9


def test_input_forms_give_identical_curves():
    q = fig2_samples()[:10]
    forms = [
        q,
        np.c_[q, np.zeros(len(q))],
        [tuple(p) for p in q],
        [FreeCAD.Vector(x, y, 0) for x, y in q],
        [Part.Vertex(FreeCAD.Vector(x, y, 0)) for x, y in q],
    ]
    reference = [tuple(p) for p in fw.csr_spline(forms[0]).getPoles()]
    for form in forms[1:]:
        assert [tuple(p) for p in fw.csr_spline(form).getPoles()] == reference


def test_parametrizations_differ_and_all_fit():
    q = fig2_samples()
    curves = {p: fw.csr_spline(q, parametrization=p) for p in ("chordal", "centripetal", "uniform")}
    knots = {p: tuple(c.getKnots()) for p, c in curves.items()}
    assert len(set(knots.values())) == 3
    assert knots["uniform"] == tuple(float(i) for i in range(len(q)))
    for c in curves.values():
        assert fw.max_distance(c, q) < 0.02


def test_epsilon_rules_agree_on_curved_data():
    q = fig2_samples()
    a = np.array([tuple(p) for p in fw.csr_spline(q, epsilon_rule="case").getPoles()])
    b = np.array([tuple(p) for p in fw.csr_spline(q, epsilon_rule="additive").getPoles()])
    assert np.abs(a - b).max() < 1e-6


def line_then_arc(n=30, spacing=1.0, radius=2e4):
    """n points on the x axis up to the origin, then n on a circle tangent to it there,
    spacing apart along the curve. size (bounding-box diagonal) = 59, so curvature * size
    = 59 / radius = 3e-3: between epsilon = 1e-9 and 1e-2 in units of 1/size."""
    line = np.c_[np.arange(-n, 0) * spacing, np.zeros(n)]
    a = np.arange(n) * (spacing / radius)
    return np.r_[line, np.c_[radius * np.sin(a), radius * (1 - np.cos(a))]]


def csr_poles(q, **options):
    return np.array([tuple(p) for p in fw.csr_spline(q, **options).getPoles()])


def test_epsilon_switches_the_case_rule_where_curvature_is_below_it():
    # The weights differ from 1/2 only where the line meets the arc (kappa 0 | 1/radius).
    # At epsilon = 1e-2 that sum (1/radius) is below epsilon/size and the case rule takes
    # 1/2 there. Measured: poles move by 4.2e-6; 1e-12 vs 1e-9 move them by 0.
    q = line_then_arc()
    default = csr_poles(q, epsilon=1e-9)
    np.testing.assert_array_equal(csr_poles(q, epsilon=1e-12), default)
    assert np.abs(csr_poles(q, epsilon=1e-2) - default).max() > 4e-7


def test_case_and_additive_rules_differ_at_moderate_epsilon_and_agree_at_tiny_epsilon():
    # Measured on line_then_arc(): at epsilon = 1e-3 the rules' poles differ by 2.1e-6
    # (additive weights (kappa + eps)/(sum + 2 eps) are pulled towards 1/2, case keeps
    # kappa_a/sum since sum > epsilon/size); at 1e-9 by 4.7e-12.
    q = line_then_arc()
    case, additive = (csr_poles(q, epsilon=1e-3, epsilon_rule=rule) for rule in ("case", "additive"))
    assert np.abs(case - additive).max() > 2e-7
    case, additive = (csr_poles(q, epsilon=1e-9, epsilon_rule=rule) for rule in ("case", "additive"))
    assert np.abs(case - additive).max() < 1e-8


def test_huge_epsilon_makes_every_case_weight_one_half():
    # Beyond the largest curvature sum every weight is 1/2: the value no longer matters
    # (bit for bit), yet the fit differs from the default's (measured 4.2e-6).
    q = line_then_arc()
    huge = csr_poles(q, epsilon=1e6)
    np.testing.assert_array_equal(csr_poles(q, epsilon=1e7), huge)
    assert np.abs(huge - csr_poles(q, epsilon=1e-9)).max() > 4e-7


@pytest.mark.parametrize("rule", ["case", "additive"])
@pytest.mark.parametrize("epsilon", [0.0, -0.0, -1e-9, -1.0, float("nan"), float("inf"), -float("inf")])
def test_non_positive_or_infinite_epsilon_raises_input_error(epsilon, rule):
    with pytest.raises(fw.InputError, match="epsilon must be positive and finite"):
        fw.csr_spline(line_then_arc(), epsilon=epsilon, epsilon_rule=rule)


BAD_INPUT = [
    ([(0, 0), (1, 1)], "at least 3 points, got 2"),
    ([], "at least 3 points, got 0"),
    ([(0, 0), (1, 1), (1, 1), (2, 0)], "points 1 and 2 coincide"),
    ([(1, 2, 3)] * 5, "all points coincide"),
    ([(0, 0), (1, float("nan")), (2, 0)], "point 1 is not finite"),
    ([(0, 0), (1, float("inf")), (2, 0)], "point 1 is not finite"),
    ([(0, 0, 0, 0)] * 4, r"shape \(N, 2\) or \(N, 3\)"),
    ([(0, 0), (1, 1, 1), (2, 0)], "mix 2D and 3D"),
    ([(0, 0), "ab", (2, 0)], r"points\[1\] is not a point"),
]


@pytest.mark.parametrize("points, message", BAD_INPUT)
def test_bad_input_raises_input_error_naming_the_problem(points, message):
    with pytest.raises(fw.InputError, match=message):
        fw.csr_spline(points)


def test_input_error_is_a_value_error_and_other_bad_arguments():
    assert issubclass(fw.InputError, ValueError)
    q = fig2_samples()
    with pytest.raises(fw.InputError, match="unknown parametrization"):
        fw.csr_spline(q, parametrization="affine")
    with pytest.raises(fw.InputError, match="epsilon must be positive"):
        fw.csr_spline(q, epsilon=0.0)
    with pytest.raises(fw.InputError, match="parameters must increase strictly"):
        fw.csr_spline(q[:4], parameters=[0, 1, 1, 2])
    with pytest.raises(fw.InputError, match="leave it out for closed data"):
        fw.csr_spline(np.r_[q[:5], q[:1]], closed=True)


def test_neighbours_too_close_along_the_data_are_refused_naming_them_and_the_fair_fit_fits_them():
    """Issue 26: 2000 samples a radian apart on a unit circle (1900 long in a box 2.8 wide) with
    one 1e-10 from the one before: not coincident in the box, but a spline through both would
    have knots closer than 1e-12 of its parameter range. bench_csr's data died this way deep in
    the fit ("knots ... are too close together"); now the samples are named up front, with the
    way out, which works: the fair fit of such data (a half circle with a sample 3e-12 after
    another) is a valid curve near every sample."""
    n, k = 2000, 1000
    q = np.c_[np.cos(np.arange(n)), np.sin(np.arange(n))]
    q[k + 1] = q[k] + (1e-10, 0.0)
    for closed in (False, True):
        with pytest.raises(fw.InputError, match=f"samples {k} and {k + 1} are too close together along the data.*"
                                                r"fw\.fair_fit"):
            fw.csr_spline(q, closed=closed)
    a = np.linspace(0, math.pi, 200)
    half = np.c_[np.cos(a), np.sin(a)]
    half = np.insert(half, 101, half[100] + (0.0, 3e-12), axis=0)
    with pytest.raises(fw.InputError, match="samples 100 and 101 are too close together"):
        fw.csr_spline(half)
    fair = fw.fair_fit(half, 1e-4)
    assert fair.toShape().isValid()
    assert fw.max_distance(fair, half) <= 1e-4 * 1.01
