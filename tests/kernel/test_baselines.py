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
    closed = fw.control_point_spline(q[:-5], closed=True)
    assert closed.isPeriodic()


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


def test_quadratic_design_closed_returns_to_start():
    a = np.linspace(0, 2 * math.pi, 7, endpoint=False)
    c = fw.quadratic_design(np.c_[np.cos(a), np.sin(a)], closed=True)
    assert (c.value(c.FirstParameter) - c.value(c.LastParameter)).Length == 0.0


@pytest.mark.parametrize(
    "function, minimum",
    [(fw.quadratic_design, 3), (fw.quasi_interpolant, 3), (fw.control_point_spline, 4), (fw.interpolate_classic, 2)],
)
def test_baselines_reject_too_few_points(function, minimum):
    q = [(float(i), float(i % 2)) for i in range(minimum - 1)]
    with pytest.raises(fw.InputError, match=f"at least {minimum}"):
        function(q)
