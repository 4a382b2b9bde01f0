"""Baselines and the quadratic design (Section 7, eq. (12)), judged by OCCT evaluation."""
import math

import numpy as np
import pytest

import freecad_workbench as fw
from tests.kernel.fig2 import fig2_samples


def poles(curve):
    return np.array([tuple(p) for p in curve.getPoles()])


def test_classic_interpolation_interpolates():
    q = fig2_samples()
    c = fw.interpolate_classic(q)
    assert c.Continuity == "C2"
    for x, y in q:
        assert fw.max_distance(c, [(x, y)]) < 1e-12


def test_quasi_interpolant_uniform_is_minus1_8_minus1_over_6():
    rng = np.random.default_rng(5)
    q = rng.random((9, 3))
    c = fw.quasi_interpolant(q, parametrization="uniform")
    expected = (-q[:-2] + 8 * q[1:-1] - q[2:]) / 6
    assert np.abs(poles(c)[2:-2] - expected).max() < 1e-14


def test_control_point_spline_uses_the_data_as_poles():
    q = fig2_samples()
    c = fw.control_point_spline(q)
    assert np.array_equal(poles(c)[:, :2], q)
    assert c.Continuity == "C2"


def test_closed_control_point_spline_uses_the_data_as_its_periodic_poles():
    q = fig2_samples()[:-5]
    c = fw.control_point_spline(q, closed=True)
    assert c.isPeriodic() and c.isClosed() and c.Continuity == "C2"
    p = poles(c)
    assert len(p) == len(q)
    assert not p[:, 2].any()
    # OCCT stores a periodic curve's poles in a cyclic order of its own: find the rotation.
    start = [i for i in range(len(q)) if np.array_equal(p[0, :2], q[i])]
    assert len(start) == 1
    assert np.array_equal(p[:, :2], np.roll(q, -start[0], axis=0))
    # Uniform knots: the curve at its knots is (q_(i-1) + 4 q_i + q_(i+1)) / 6, cyclically.
    expected = (np.roll(q, 1, axis=0) + 4 * q + np.roll(q, -1, axis=0)) / 6
    on_curve = np.array([tuple(c.value(k))[:2] for k in c.getKnots()[:-1]])
    assert len(on_curve) == len(q)
    for v in expected:
        assert np.linalg.norm(on_curve - v, axis=1).min() < 1e-12


def test_quadratic_design_interpolates_sparse_points_with_quadratic_pieces():
    a = np.linspace(0, math.pi, 6)
    q = np.c_[np.cos(a), np.sin(a)]
    c = fw.quadratic_design(q)
    assert c.Degree == 2
    p = poles(c)
    assert np.array_equal(p[::2, :2], q)  # q_i are poles, the handles m_i lie between
    for x, y in q:
        assert fw.max_distance(c, [(x, y)]) < 1e-12
    # A circle sampled sparsely: the quadratic shape stays close to it.
    for u in np.linspace(c.FirstParameter, c.LastParameter, 200):
        v = c.value(u)
        assert math.hypot(v.x, v.y) == pytest.approx(1.0, abs=0.01)


def test_quadratic_design_handles_weigh_by_the_other_sides_curvature():
    # Eq. (12): m_i = mu_{i+1} m_i^L + (1 - mu_{i+1}) m_i^R. Where f_i is straight
    # (kappa_i = 0) and f_{i+1} bends, mu_{i+1} = 1 and m_i is f_i's handle, the midpoint
    # of the straight segment.
    q = np.array([(0.0, 0.0), (1.0, 0.0), (2.0, 0.0), (3.0, 1.0), (3.0, 2.0)])
    p = poles(fw.quadratic_design(q))
    assert p[3, :2] == pytest.approx((1.5, 0.0), abs=1e-14)


def test_quadratic_design_closed_interpolates_every_point_and_closes():
    a = np.linspace(0, 2 * math.pi, 7, endpoint=False)
    q = np.c_[np.cos(a), 0.6 * np.sin(a)]
    c = fw.quadratic_design(q, closed=True)
    assert c.Degree == 2 and c.isClosed()
    assert (c.value(c.FirstParameter) - c.value(c.LastParameter)).Length == 0.0
    knots = c.getKnots()
    assert len(knots) == len(q) + 1  # a knot per data point, and the seam back to q_0
    # C0 or better at the data points: interior multiplicity at most the degree, and both
    # sides of each knot meet at the data point (checked below).
    assert max(c.getMultiplicities()[1:-1]) <= c.Degree
    for k, expected in zip(knots, np.r_[q, q[:1]]):
        v = c.value(k)
        assert (v.x, v.y, v.z) == pytest.approx((expected[0], expected[1], 0.0), abs=1e-14)
        delta = 1e-9 * (knots[-1] - knots[0])
        for u in (k - delta, k + delta):
            if knots[0] <= u <= knots[-1]:
                assert (c.value(u) - v).Length < 1e-8


@pytest.mark.parametrize(
    "function, minimum",
    [(fw.quadratic_design, 3), (fw.quasi_interpolant, 3), (fw.control_point_spline, 4), (fw.interpolate_classic, 2)],
)
def test_baselines_reject_too_few_points(function, minimum):
    q = [(float(i), float(i % 2)) for i in range(minimum - 1)]
    with pytest.raises(fw.InputError, match=f"at least {minimum}"):
        function(q)


BASELINES = [fw.interpolate_classic, fw.quadratic_design, fw.quasi_interpolant, fw.control_point_spline]
BAD_POINTS = [
    ([(0, 0), (1, float("nan")), (2, 0), (3, 1), (4, 0)], r"point 1 is not finite \(NaN or infinity\)"),
    ([(0, 0), (1, float("inf")), (2, 0), (3, 1), (4, 0)], r"point 1 is not finite \(NaN or infinity\)"),
    ([(0, 0, 0), (1, 1, 0), (2, 0, 0), (3, 1, -float("inf")), (4, 0, 0)], r"point 3 is not finite \(NaN or infinity\)"),
    ([(0, 0), (1, 1), (1, 1), (3, 1), (4, 0)], "points 1 and 2 coincide"),
    ([(0, 0, 0), (1, 1, 1), (2, 0, 0), (2, 0, 0), (4, 0, 1)], "points 2 and 3 coincide"),
]


@pytest.mark.parametrize("closed", [False, True])
@pytest.mark.parametrize("points, message", BAD_POINTS,
                         ids=["nan", "inf", "minus-inf-3d", "coincident", "coincident-3d"])
@pytest.mark.parametrize("function", BASELINES, ids=lambda f: f.__name__)
def test_baselines_reject_non_finite_and_coincident_points(function, points, message, closed):
    with pytest.raises(fw.InputError, match=message):
        function(points, closed=closed)
