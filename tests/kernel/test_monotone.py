"""Monotonic-curvature cubics through the macro API, judged by OCCT's own evaluation of the
returned Part curves (value, getD1, tangent, curvature), independently of the construction."""
import math
import re

import numpy as np
import pytest

import FreeCAD
import Part

import freecad_workbench as fw

V = FreeCAD.Vector


def random_frame(rng, in_space):
    """Origin, two orthonormal in-plane axes (XY plane or a random plane of space)."""
    origin = rng.uniform(-100, 100, 3)
    if not in_space:
        origin[2] = 0.0
        angle = rng.uniform(0, 2 * math.pi)
        return (origin, np.array([math.cos(angle), math.sin(angle), 0.0]),
                np.array([-math.sin(angle), math.cos(angle), 0.0]))
    q, _ = np.linalg.qr(rng.normal(size=(3, 3)))
    return origin, q[:, 0], q[:, 1]


def random_ends(rng, count, admissible=True):
    """G1 end conditions built from turn, legs a = |M - p0|, b = |p1 - M| (admissible: the
    shorter leg below the longer times cos(turn)), placed anywhere, mirrored, scaled; each
    with whether the curvature has to increase from p0."""
    out = []
    for k in range(count):
        turn = math.radians(rng.uniform(0.5, 89.5))
        limit = math.cos(turn) / (1 + math.cos(turn))
        if admissible:
            r = rng.uniform(0.001, 0.999) * limit
        else:  # between the two limits: too near a circular arc either way
            r = limit + rng.uniform(0.01, 0.99) * (1 - 2 * limit)
        a, b = r, 1 - r
        q0, d0 = np.zeros(2), np.array([1.0, 0.0])
        d1 = np.array([math.cos(turn), math.sin(turn)])
        q1 = np.array([a, 0.0]) + b * d1
        increasing = bool(rng.random() < 0.5)
        if increasing:
            q0, q1, d0, d1 = q1, q0, -d1, -d0
        mirror = -1.0 if rng.random() < 0.5 else 1.0
        scale = 10 ** rng.uniform(-2, 3)
        origin, e1, e2 = random_frame(rng, k % 2 == 1)

        def place(v, point):
            w = (scale if point else rng.uniform(0.1, 10)) * np.array([v[0], mirror * v[1]])
            return (origin if point else 0) + w[0] * e1 + w[1] * e2

        out.append((place(q0, True), place(d0, False), place(q1, True), place(d1, False), increasing))
    return out


def unsigned_curvature(curve, n=200):
    u = np.linspace(curve.FirstParameter, curve.LastParameter, n + 1)
    return np.array([curve.curvature(float(x)) for x in u])


def direction(values, rel_tol=1e-9):
    """+1 nondecreasing, -1 nonincreasing (within rel_tol of the largest), 0 neither."""
    tol = rel_tol * np.max(np.abs(values))
    steps = np.diff(values)
    return 1 if np.all(steps >= -tol) else (-1 if np.all(steps <= tol) else 0)


def test_thousand_random_admissible_ends_give_monotone_interpolants():
    rng = np.random.default_rng(2026)
    for k, (p0, t0, p1, t1, increasing) in enumerate(random_ends(rng, 1000)):
        curve = fw.monotone_curvature_spline(V(*p0), V(*t0), V(*p1), V(*t1), method="paper")
        assert isinstance(curve, Part.BSplineCurve) and curve.Degree == 3
        size = np.linalg.norm(p1 - p0)
        first, last = curve.FirstParameter, curve.LastParameter
        assert np.linalg.norm(np.array(curve.value(first)) - p0) <= 1e-12 * size, k
        assert np.linalg.norm(np.array(curve.value(last)) - p1) <= 1e-12 * size, k
        # Tangents: the direction of a short end leg between large coordinates is known to
        # about eps * |coordinates| / |leg|.
        poles = np.array([tuple(p) for p in curve.getPoles()])
        coords = np.abs(poles).max()
        for u, t, leg in ((first, t0, poles[1] - poles[0]), (last, t1, poles[4] - poles[3])):
            d = np.array(curve.getD1(u)[1])
            tangent = np.array(curve.tangent(u)[0])
            sin = np.linalg.norm(np.cross(d / np.linalg.norm(d), t / np.linalg.norm(t)))
            assert sin <= 1e-12 + 8e-16 * coords / np.linalg.norm(leg), k
            assert np.dot(d, t) > 0 and np.dot(tangent, t) > 0, k
        # Planar: every pole in the plane of the data.
        normal = np.cross(t0, p1 - p0)
        if np.linalg.norm(normal) > 0:
            normal /= np.linalg.norm(normal)
            assert np.abs((poles - p0) @ normal).max() <= 1e-12 * max(size, coords), k
        # OCCT's curvature is monotone: down from p0, or up when the ends ask for it.
        kappa = unsigned_curvature(curve)
        assert direction(kappa) == (1 if increasing else -1), k
        report = fw.check_monotone_curvature(curve)
        assert report.monotone, (k, report.reason)
        magnitude_down = report.decreasing if report.kappa_start > 0 else report.increasing
        assert magnitude_down == (not increasing), (k, report.reason)


def test_fairest_curves_lie_strictly_inside_the_family():
    solution = fw.monotone_curvature_solution((0, 0), (1, 0), (1, 0.5), (0.8, 0.6))
    assert not solution.boundary and not solution.reversed
    assert solution.margin > 0.05
    report = fw.check_monotone_curvature(solution.curve)
    assert [s.trend for s in report.spans] == ["decreasing", "decreasing"]
    assert all(s.paper.startswith("Theorem 1 holds") for s in report.spans)


@pytest.mark.parametrize(
    "p1, t1, reason",
    [
        ((1, 1), (0, 1), "turns by 90 deg"),
        ((-1, 1), (-1, 0.1), "turns by"),
        ((1, 1), (1, -0.2), "outside the admissible wedge"),
        ((1, 1), (1, 0.5), "outside the admissible wedge"),
        ((1, 1), (0.2, 1), "too central"),
        ((2, 1), (1, 0), "parallel"),
        ((2, 1, 0), (1, 1, 1), "not planar"),
        ((2, 0), (1, 1), "start tangent"),
        ((-2, 0), (-1, 0), "behind p0"),
    ],
)
def test_inadmissible_ends_raise_no_monotone_solution_saying_why(p1, t1, reason):
    with pytest.raises(fw.NoMonotoneSolution, match=reason):
        fw.monotone_curvature_spline((0, 0), (1, 0), p1, t1, method="paper")
    assert not fw.monotone_end_conditions((0, 0), (1, 0), p1, t1).admissible


def test_random_inadmissible_ends_raise_and_the_grid_finds_nothing_either():
    rng = np.random.default_rng(4)
    for p0, t0, p1, t1, _ in random_ends(rng, 60, admissible=False):
        with pytest.raises(fw.NoMonotoneSolution, match="too central"):
            fw.monotone_curvature_spline(p0, t0, p1, t1, method="paper")
        with pytest.raises(fw.NoMonotoneSolution):
            fw.monotone_curvature_spline(p0, t0, p1, t1, method="grid")


def test_the_grid_agrees_on_feasibility_wherever_it_finds_a_curve():
    rng = np.random.default_rng(8)
    grid_found = fairest_only = 0
    for _ in range(200):
        p1 = (rng.uniform(0.2, 1.2), rng.uniform(0.0, 1.2))
        turn = rng.uniform(0, 2.1)
        t1 = (math.cos(turn), math.sin(turn))
        try:
            grid = fw.monotone_curvature_spline((0, 0), (1, 0), p1, t1, method="grid")
        except fw.NoMonotoneSolution:
            grid = None
        try:
            fairest = fw.monotone_curvature_spline((0, 0), (1, 0), p1, t1, method="paper")
        except fw.NoMonotoneSolution:
            fairest = None
        if grid is not None:
            grid_found += 1
            assert fairest is not None, (p1, t1)
            assert fw.check_monotone_curvature(grid).monotone
            assert direction(unsigned_curvature(grid)) != 0
        elif fairest is not None:
            fairest_only += 1
    assert grid_found > 10 and fairest_only > 10


def test_the_straight_segment_and_the_parabola_limit():
    line = fw.monotone_curvature_spline((1, 1, 1), (1, 1, 1), (3, 3, 3), (2, 2, 2), method="paper")
    assert np.allclose([line.curvature(u) for u in np.linspace(0, 2, 9)], 0.0, atol=1e-14)
    # a = b cos(turn): only the parabola y = x^2 from its vertex remains.
    parabola = fw.monotone_curvature_solution((0, 0), (1, 0), (1, 1), (1, 2))
    assert parabola.boundary
    for u in np.linspace(0, 2, 11):
        p = parabola.curve.value(float(u))
        assert p.y == pytest.approx(p.x**2, abs=1e-12)


@pytest.mark.parametrize(
    "args, message",
    [
        (((0, 0), (0, 0), (1, 1), (1, 0)), "t0 is zero"),
        (((0, 0), (1, 0), (1, 1), (0, 0, 0)), "t1 is zero"),
        (((1, 1), (1, 0), (1, 1), (1, 0)), "p0 and p1 coincide"),
        (((0, 0), (1, 0), (float("nan"), 1), (1, 0)), "p1 is not finite"),
        ((("a", "b"), (1, 0), (1, 1), (1, 0)), "p0 is not a point"),
        (((0, 0), (1, 0, 0, 0), (1, 1), (1, 0)), "t0 needs 2 or 3 coordinates"),
    ],
)
def test_bad_input_raises_input_error_naming_the_problem(args, message):
    with pytest.raises(fw.InputError, match=message) as info:
        fw.monotone_curvature_spline(*args)
    assert not isinstance(info.value, fw.NoMonotoneSolution)
    assert isinstance(info.value, ValueError)


def test_no_monotone_solution_is_an_input_error():
    assert issubclass(fw.NoMonotoneSolution, fw.InputError)
    assert fw.NoMonotoneSolution.__module__ == "freecad_workbench"
    with pytest.raises(fw.InputError, match="method"):
        fw.monotone_curvature_spline((0, 0), (1, 0), (1, 0.5), (0.8, 0.6), method="newton")


# --- the certificate -----------------------------------------------------------------------


def cubic_graph(x0, x1):
    """y = x^3 over [x0, x1] as a Bezier curve whose parameter runs over [0, 1]."""
    xs = [(x0, x0, x0), (x0, x0, x1), (x0, x1, x1), (x1, x1, x1)]
    bezier = Part.BezierCurve()
    bezier.setPoles([V(sum(x) / 3, x[0] * x[1] * x[2], 0) for x in xs])
    return bezier


def test_certificate_locates_the_curvature_maximum_of_x_cubed():
    bezier = cubic_graph(0.2, 0.6)
    report = fw.check_monotone_curvature(bezier)
    assert not report.monotone and not report
    (span,) = report.spans
    assert span.trend == "extremum"
    u, kappa, maximum = span.extremum
    x = bezier.value(u).x
    assert maximum and x == pytest.approx(45 ** -0.25, abs=1e-9)
    assert kappa == pytest.approx(bezier.curvature(u), rel=1e-9)
    # OCCT's own samples rise before and fall after it.
    assert bezier.curvature(u - 1e-3) < kappa > bezier.curvature(u + 1e-3)
    assert "maximum" in report.reason and "paper" in str(report)


def test_certificate_rejects_constructed_extrema():
    # A parabola arc through its vertex.
    through = Part.Parabola()  # x = y^2 / 4, parameter y, turning clockwise: signed curvature < 0
    report = fw.check_monotone_curvature(through.toShape(-1.0, 2.0))
    assert not report.monotone
    (span,) = [s for s in report.spans if s.trend == "extremum"]
    u, kappa, maximum = span.extremum
    assert kappa == pytest.approx(-0.5, rel=1e-9) and not maximum  # |kappa| largest at the vertex
    assert u == pytest.approx(0.0, abs=1e-9)
    # An ellipse arc across the end of its major axis (rational).
    ellipse = Part.Ellipse(V(0, 0, 0), 3.0, 1.0).toShape(-0.5, 0.3)
    report = fw.check_monotone_curvature(ellipse)
    assert not report.monotone
    assert [s.extremum[1] for s in report.spans if s.extremum] == [pytest.approx(3.0, rel=1e-9)]
    # An S-curve whose curvature falls, then rises.
    s_curve = fw.control_point_spline([(0, 0), (1, 1), (2, 1.2), (3, 0), (4, -1.2), (5, -1), (6, 0)])
    assert not fw.check_monotone_curvature(s_curve).monotone


def test_certificate_accepts_known_monotone_curves():
    assert fw.check_monotone_curvature(cubic_graph(0.0, 0.3)).increasing
    vertex_on = Part.Parabola().toShape(0.0, 2.0)  # from its vertex: curvature falls
    report = fw.check_monotone_curvature(vertex_on)
    assert report.monotone and report.kappa_start == pytest.approx(-0.5, rel=1e-12) and report.increasing
    assert direction(unsigned_curvature(vertex_on.Curve.toBSpline(0.0, 2.0))) == -1
    circle = fw.check_monotone_curvature(Part.makeCircle(2.0, V(1, 2, 3), V(1, 1, 1)))
    assert circle.monotone and circle.increasing and circle.decreasing
    assert circle.kappa_start == pytest.approx(0.5, rel=1e-12)
    line = fw.check_monotone_curvature(Part.LineSegment(V(0, 0, 0), V(1, 2, 0)))
    assert line.increasing and line.decreasing


def test_certificate_agrees_with_dense_occt_curvature_on_random_curves():
    rng = np.random.default_rng(12)
    verdicts = set()
    for _ in range(100):
        n = rng.integers(4, 9)
        points = np.c_[np.arange(n) + rng.uniform(0, 0.6, n), rng.uniform(0, 1, n) * np.arange(n) ** 1.5 / n]
        curve = fw.control_point_spline(points)
        report = fw.check_monotone_curvature(curve)
        profile = fw.curvature_profile(curve, 4000)
        sampled = direction(profile.kappa, 1e-7)
        if report.monotone:
            verdicts.add("monotone")
            assert sampled != 0 or report.increasing and report.decreasing
        else:
            verdicts.add("not")
            # OCCT's samples turn somewhere: an extremum, or a rise next to a fall.
            assert sampled == 0, report.reason
    assert verdicts == {"monotone", "not"}


def test_certificate_needs_a_planar_curve():
    with pytest.raises(fw.InputError, match="not planar"):
        fw.check_monotone_curvature(Part.makeHelix(1.0, 3.0, 1.0))


# --- Algorithm 1 ---------------------------------------------------------------------------


def test_design_keeps_fair_differences_and_moves_the_others():
    fair = [(1.0, 0.5), (0.3, 0.45), (-133 / 120, -13 / 30)]
    used, moved = fw.clamp_to_fair_locations((1, 0), fair)
    assert np.array_equal(used, np.array(fair)) and not moved.any()
    used, moved = fw.clamp_to_fair_locations((1, 0), fair[:2] + [(1.0, 2.0)])
    assert moved[2] > 0.1 and not moved[:2].any()
    curve = fw.monotone_curvature_design((1, 0), fair[:2] + [(1.0, 2.0)], start=(5, 5))
    poles = np.array([tuple(p) for p in curve.getPoles()])
    assert np.allclose(poles[0], (5, 5, 0)) and np.allclose(poles[1], (6, 5, 0))
    assert np.allclose(np.diff(np.diff(poles[:, :2], axis=0), axis=0), used)
    assert fw.check_monotone_curvature(curve).decreasing
    assert direction(unsigned_curvature(curve, 1000)) == -1


def test_design_of_random_vectors_is_monotone_and_mirrors_right_turns():
    rng = np.random.default_rng(3)
    for _ in range(50):
        diffs = rng.uniform(-1, 1, (int(rng.integers(2, 7)), 2))
        curve = fw.monotone_curvature_design(rng.uniform(-2, 2, 2), diffs)
        assert fw.check_monotone_curvature(curve).monotone
        assert direction(unsigned_curvature(curve, 1000)) == -1
    left = fw.monotone_curvature_design((1, 0), [(1, 0.5), (0.3, 0.45)])
    right = fw.monotone_curvature_design((1, 0), [(1, -0.5), (0.3, -0.45)])
    for a, b in zip(left.getPoles(), right.getPoles()):
        assert (a.x, a.y) == pytest.approx((b.x, -b.y), abs=1e-15)


@pytest.mark.parametrize(
    "first, diffs, knots, message",
    [
        ((0, 0), [(1, 1), (1, 1)], None, "first control vector is zero"),
        ((1, 0), [(1, 1)], None, "at least 2 differences"),
        ((1, 0), [(1, 1, 0), (1, 1, 1)], None, "XY plane"),
        ((1, 0), [(1, 1), (float("nan"), 1)], None, "dV_1 is not finite"),
        ((1, 0), [(1, 1), (1, 1)], [0, 0, 0, 0, 1, 1, 1], "needs 8 knots"),
        ((1, 0), [(1, 1), (1, 1)], [0, 0, 0, 0, 2, 1, 1, 1], "decrease"),
    ],
)
def test_design_bad_input_raises_input_error(first, diffs, knots, message):
    with pytest.raises(fw.InputError, match=message):
        fw.monotone_curvature_design(first, diffs, knots)


def test_derivative_polygons_are_eqs_3_and_5():
    curve = fw.monotone_curvature_spline((0, 0), (1, 0), (1, 0.5), (0.8, 0.6), method="paper")
    first, second = fw.derivative_polygons(curve)
    assert first.shape == (4, 3) and second.shape == (3, 3)
    # The hodograph's end points are OCCT's end derivatives; P'' is linear between C^2 points.
    assert np.allclose(first[0], tuple(curve.getD1(0.0)[1]), atol=1e-12)
    assert np.allclose(first[-1], tuple(curve.getD1(2.0)[1]), atol=1e-12)
    for u, expected in ((0.0, second[0]), (1.0, second[1]), (2.0, second[2]), (0.5, (second[0] + second[1]) / 2)):
        assert np.allclose(tuple(curve.getD2(u)[2]), expected, atol=1e-12)


def test_curvature_variation_vanishes_for_circles_only():
    fairest = fw.monotone_curvature_spline((0, 0), (1, 0), (1, 0.5), (0.8, 0.6), method="paper")
    assert fw.curvature_variation(fairest) > 1.0
    assert fw.curvature_variation(Part.makeCircle(1.0)) == pytest.approx(0.0, abs=1e-15)
    # Scale-free: the same curve 1000 times larger.
    big = fw.monotone_curvature_spline((0, 0), (1000, 0), (1000, 500), (0.8, 0.6), method="paper")
    assert fw.curvature_variation(big) == pytest.approx(fw.curvature_variation(fairest), rel=1e-9)


def test_the_summary_says_what_the_curvature_does_in_a_designers_words():
    """The GUI shows report.summary: the extremum OCCT finds by dense sampling, in 1/mm, spans
    counted from 1, and none of the proof's symbols (str(report) keeps those)."""
    curve = Part.BSplineCurve()
    curve.buildFromPoles([V(0, 0, 0), V(10, 0, 0), V(20, 10, 0), V(20, 20, 0), V(10, 30, 0)])
    report = fw.check_monotone_curvature(curve)
    u = np.linspace(curve.FirstParameter, curve.LastParameter, 20001)
    kappa = np.array([curve.curvature(float(t)) for t in u])
    maxima = [i for i in range(1, len(u) - 1) if kappa[i - 1] < kappa[i] >= kappa[i + 1]]
    minima = [i for i in range(1, len(u) - 1) if kappa[i - 1] > kappa[i] <= kappa[i + 1]]
    assert maxima  # an interior maximum: the curve is not monotone
    peak = min(maxima + minima)  # the summary names the first extremum along the curve
    assert peak in maxima
    text = report.summary
    assert text.startswith("not monotone: the curvature has a maximum of ")
    value, at = re.search(r"maximum of ([0-9.e+-]+) 1/mm at parameter ([0-9.e+-]+) \(span 1\)", text).groups()
    assert float(value) == pytest.approx(kappa[peak], rel=1e-6)
    assert float(at) == pytest.approx(u[peak], abs=2 * (u[1] - u[0]))
    for jargon in ("Bernstein", "kappa", "N(", "span 0"):
        assert jargon not in text
    assert "Bernstein" in str(report) or "N(u" in str(report)  # the proof is still there

    arc = Part.ArcOfCircle(Part.Circle(V(), V(0, 0, 1), 5), 0, 2).toShape()
    assert fw.check_monotone_curvature(arc).summary.startswith("constant curvature 0.2 1/mm")
