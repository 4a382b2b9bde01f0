"""Issue 13 on the Python side, found by the fuzz of tests/fuzz: wrong argument types and
shapes are an InputError naming the argument (kernel.py's as_real, as_count, as_flag,
as_choice, as_reals, as_points), counts are bounded, and nothing else escapes. Each test
here failed before its fix."""
import math

import numpy as np
import pytest

import FreeCAD
import Part

import freecad_workbench as fw

V = FreeCAD.Vector
POINTS = [(0, 0), (1, 2), (2, 4.5), (3.5, 5), (5, 4)]


def curve():
    return fw.csr_spline(POINTS)


def refused(func, *args, match, **kwargs):
    with pytest.raises(fw.InputError, match=match):
        func(*args, **kwargs)


@pytest.mark.parametrize("points", [None, 3.5, object()], ids=["None", "number", "object"])
def test_points_that_are_not_a_list_are_refused_by_name(points):
    refused(fw.csr_spline, points, match="points must be a list of points")


@pytest.mark.parametrize("closed", [None, "yes", 2, [1]], ids=["None", "str", "2", "list"])
def test_closed_must_be_a_flag(closed):
    """bool(closed) took any value: "no" meant closed."""
    for func in (fw.csr_spline, fw.interpolate_classic, fw.quasi_interpolant, fw.control_point_spline,
                 fw.quadratic_design):
        refused(func, POINTS, closed=closed, match="closed must be True or False")


def test_closed_still_takes_bools_and_0_1():
    assert fw.control_point_spline(POINTS, closed=np.bool_(True)).isPeriodic()
    assert not fw.control_point_spline(POINTS, closed=0).isPeriodic()


@pytest.mark.parametrize("rule", [[], {}, np.array([1, 2])], ids=["list", "dict", "array"])
def test_unhashable_choices_are_refused_by_name(rule):
    """`{} in EPSILON_RULES` was a TypeError, an array in a tuple a ValueError of numpy."""
    refused(fw.csr_spline, POINTS, epsilon_rule=rule, match="epsilon_rule")
    refused(fw.csr_spline, POINTS, parametrization=rule, match="parametrization")
    refused(fw.monotone_curvature_solution, (0, 0), (1, 0), (1, 0.5), (0.8, 0.6), method=rule, match="method")


@pytest.mark.parametrize("epsilon", [None, "x", [1e-9], float("nan"), complex(1, 0)],
                         ids=["None", "str", "list", "nan", "complex"])
def test_epsilon_must_be_a_finite_number(epsilon):
    refused(fw.csr_spline, POINTS, epsilon=epsilon, match="epsilon must be")
    refused(fw.quadratic_design, POINTS, epsilon=epsilon, match="epsilon must be")


@pytest.mark.parametrize("parameters", ["abc", [[0, 1], [2]], [[0, 1, 2, 3, 4]]], ids=["str", "ragged", "2d"])
def test_parameters_must_be_a_flat_list_of_numbers(parameters):
    refused(fw.csr_spline, POINTS, parameters=parameters, match="parameters must be")


@pytest.mark.parametrize("n", [None, "64", 2.5, True, float("inf")], ids=["None", "str", "2.5", "bool", "inf"])
def test_sample_counts_must_be_whole_numbers(n):
    """int(n) truncated 2.5 and raised TypeError for None, OverflowError for inf."""
    refused(fw.curvature_profile, curve(), n=n, match="n must be a whole number")
    refused(fw.curvature_extrema, curve(), n=n, match="n must be a whole number")
    refused(fw.curvature_sign_changes, curve(), samples_per_span=n, match="samples_per_span must be")


def test_sample_counts_are_bounded():
    """n = 10**12 asked the kernel for a terabyte of samples."""
    refused(fw.curvature_profile, curve(), n=10 ** 12, match="is more than")
    refused(fw.curvature_sign_changes, curve(), samples_per_span=10 ** 9, match="is more than")
    refused(fw.approximation_error, fw.basic.CircleArc(), [0.5], samples=10 ** 8, match="is more than")


def test_approximation_error_takes_a_basic_curve():
    refused(fw.approximation_error, curve(), [0.5], match="curve must be a fw.basic curve")
    refused(fw.approximation_error, fw.basic.CircleArc(), [0.5], samples=None, match="samples must be")


@pytest.mark.parametrize("value", [None, "1", [1.0]], ids=["None", "str", "list"])
def test_basic_curve_numbers_are_refused_by_name(value):
    refused(fw.basic.CircleArc, radius=value, match="radius must be a number")
    refused(fw.basic.EllipseArc, minor_radius=value, match="minor_radius must be a number")
    refused(fw.basic.ParabolaArc, t1=value, match="t1 must be a number")
    refused(fw.basic.CircleArc().value, value, match="u must be a number")
    refused(fw.basic.CircleArc().parameter_of, (1, 0, 0), tolerance=value, match="tolerance must be a number")


def test_shape_numbers_are_refused_by_name():
    refused(fw.shapes.Cylinder, (0, 0, 0), None, [0, 1, 2], [0, 1], match="radius must be a number")
    refused(fw.shapes.Torus, (0, 0, 0), 3, "1", [0, 1, 2], [0, 1], match="minor_radius must be a number")


@pytest.mark.parametrize("tolerance", [None, "0", float("nan")], ids=["None", "str", "nan"])
def test_join_tolerance_is_a_number(tolerance):
    arc = fw.basic.CircleArc()
    refused(fw.design_spline, [(arc, [0.5])], join_tolerance=tolerance, match="join_tolerance must")


def test_grid_step_and_rel_tol_are_numbers():
    refused(fw.monotone_curvature_solution, (0, 0), (1, 0), (1, 0.5), (0.8, 0.6), method="grid", grid_step="x",
            match="grid_step must be a number")
    refused(fw.monotone_curvature_solution, (0, 0), (1, 0), (1, 0.5), (0.8, 0.6), method="grid", grid_step=0.0,
            match="grid_step must be positive")
    refused(fw.check_monotone_curvature, curve(), rel_tol=None, match="rel_tol must be a number")


def test_knots_of_algorithm_1_are_numbers():
    refused(fw.monotone_curvature_design, (1, 0), [(1, 0.2), (1, 0.3)], knots="abc", match="knots must be")


@pytest.mark.parametrize("continuity", [[], None, "g2"], ids=["list", "None", "lowercase"])
def test_fair_blend_continuity_is_a_choice(continuity):
    """A list was neither 'G1' nor 'G2' and ran as G1."""
    line = Part.LineSegment(V(-1, 0, 0), V(0, 0, 0))
    arc = Part.ArcOfCircle(Part.Circle(V(2, 1, 0), V(0, 0, 1), 1), math.pi, 1.5 * math.pi)
    refused(fw.fair_blend, line, "end", arc, "start", continuity=continuity, match="continuity")


def test_blend_choices_are_refused_by_name():
    zone = fw.shapes.SphereZone((0, 0, 0), 10, [0, 1, 2.5, 4, 2 * math.pi], [-0.5, 0.2, 0.7])
    refused(fw.blend_basic_shape, zone, method=np.array(["rho", "sigma"]), match="method")
    refused(fw.blend_basic_shape, zone, at=[], match="at")


@pytest.mark.parametrize("marks", [None, 0.5, "abc"], ids=["None", "number", "str"])
def test_marks_must_be_a_list(marks):
    arc = fw.basic.CircleArc()
    refused(fw.design_spline, [(arc, marks)], match="marks must be a list")
    refused(fw.approximation_error, arc, marks, match="marks must be a list")


def test_pieces_must_be_a_list():
    refused(fw.design_spline, None, match="pieces must be a list")


def test_set_control_checks_its_indices_whatever_the_weight():
    """With a weight given, int('x') was a ValueError (the indices were checked only without one)."""
    zone = fw.shapes.SphereZone((0, 0, 0), 10, [0, 1, 2.5, 4, 2 * math.pi], [-0.5, 0.2, 0.7])
    refused(zone.set_control, "x", 0, 0, 0, (0, 0, 0), weight=1.0, match="i must be an integer")
    refused(zone.set_control, 0, 0, 0, 0, (0, 0, 0), weight="heavy", match="weight must be a number")
    assert not zone.edited  # a refused edit leaves the shape alone


def test_rational_cubic_arguments_are_refused_by_name():
    refused(fw.basic.RationalCubic, poles=object(), match="poles must be a list of points")
    refused(fw.basic.RationalCubic, homogeneous="x", match="homogeneous control points")
    refused(fw.basic.RationalCubic, poles=[(0, 0), (1, 1), (2, 0)], weights="abc", match="weights must be")


def test_from_edge_refuses_unbounded_conics():
    """A full Part.Parabola went through as a curve of infinite size."""
    refused(fw.basic.from_edge, Part.Parabola(), match="unbounded")
    refused(fw.basic.from_edge, Part.Line(V(0, 0, 0), V(1, 0, 0)), match="unbounded")


@pytest.mark.parametrize("make, size", [(lambda: fw.basic.EllipseArc(major_radius=1e300), 1e300),
                                        (lambda: fw.basic.ArchimedeanSpiral(a=1e300), 2.828e300),
                                        (lambda: fw.basic.HyperbolaArc(major_radius=1e300), 5.4308e299)],
                         ids=["ellipse", "spiral", "hyperbola"])
def test_basic_curves_of_size_1e300_are_measured_by_meaning(make, size):
    """Their size() was inf (the extent by squares), so they were refused; their geometry is
    finite, and so is what is built from them. OCCT evaluates the Part curves' ends."""
    curve = make()
    assert curve.size() == pytest.approx(size, rel=1e-4)
    part = curve.to_part()
    for u, end in ((part.FirstParameter, 0.0), (part.LastParameter, 1.0)):
        assert part.value(u).distanceToPoint(curve.value(end)) <= 1e-12 * size
    designed = fw.design_spline([(curve, [0.5])])
    assert all(math.isfinite(c) for p in designed.getPoles() for c in p)


@pytest.mark.parametrize("make", [lambda: fw.basic.EllipseArc(center=(1.7e308, 0, 0), major_radius=1.7e308),
                                  lambda: fw.basic.ArchimedeanSpiral(a=1e307, b=1e307)],
                         ids=["ellipse", "spiral"])
def test_basic_curves_whose_points_overflow_are_refused(make):
    with pytest.raises(fw.InputError, match="too large for double precision|size is not finite|too large"):
        make()


@pytest.mark.parametrize("which", ["value", "d1", "d2"])
def test_basic_curve_jets_far_outside_the_range_are_refused(which):
    """LineSegment.d1(-2**53) was (nan, nan, nan) from the kernel's extrapolation."""
    line = fw.basic.LineSegment((0, 0, 0), (1, 2, 0))
    refused(getattr(line, which), -9007199254740992.0, match="not finite: u is too far outside")
    assert getattr(line, which)(0.25).Length >= 0  # inside the range nothing changes


def test_array_choices_are_refused_before_any_comparison():
    """`continuity == "C1"` and `end == "end"` with an array was numpy's ambiguous-truth ValueError."""
    cone = fw.shapes.Cone((0, 0, 0), 1, 0.2, [0, 1, 2], [0, 1])
    choice = np.array(["a", "b"])
    refused(fw.blend_basic_shape, cone, continuity=choice, match="continuity")
    refused(fw.freeform_knots, cone, continuity=choice, match="continuity")
    refused(cone.pole_at, choice, match="end")
    zone = fw.shapes.SphereZone((0, 0, 0), 10, [0, 1, 2.5, 4, 2 * math.pi], [-0.5, 0.2, 0.7])
    refused(zone.pole_at, choice, match="end")


def test_fair_blend_refuses_unbounded_edges():
    """An infinite Part.Line ended at -2e100: the blend's variation was NaN."""
    arc = Part.ArcOfCircle(Part.Circle(V(2, 1, 0), V(0, 0, 1), 1), math.pi, 1.5 * math.pi)
    refused(fw.fair_blend, arc, "start", Part.Line(V(0, 0, 0), V(1, 0, 0)), "start", match="unbounded")


def test_c1_blend_of_a_non_shape_is_refused_by_name():
    """shape.edited was read before the shape was checked: an AttributeError."""
    refused(fw.blend_basic_shape, fw.basic.CircleArc(), continuity="C1", match="shape must be one of")


@pytest.mark.parametrize("make", [
    lambda a: fw.shapes.Cylinder((0, 0, 0), 1, a, a),
    lambda a: fw.shapes.Cone((0, 0, 0), 1, 0.1, a, a),
    lambda a: fw.shapes.SphereZone((0, 0, 0), 1, a, np.linspace(-1, 1, 5000)),
    lambda a: fw.shapes.Torus((0, 0, 0), 3, 1, a, a),
], ids=["cylinder", "cone", "sphere zone", "torus"])
def test_shape_partitions_are_bounded(make):
    """5000 angles each way (25 million patches) ran out of memory building the G2 structure."""
    with pytest.raises(fw.InputError, match="patches, more than"):
        make(np.linspace(0, 2 * math.pi, 5000))


@pytest.mark.parametrize("points", [np.array([[0, 0], [1, 2j], [2, 4]]), np.array([[0, 0], [1, 1], [2, 0]], dtype=bool),
                                    np.array([["0", "0"], ["1", "2"], ["2", "4"]])],
                         ids=["complex", "bool", "strings"])
def test_arrays_of_points_must_hold_real_numbers(points):
    """numpy cast a complex array to its real part with only a warning: a silently other curve."""
    with pytest.raises(fw.InputError, match="must be real numbers"):
        fw.csr_spline(points)


def _scaled_bspline(s):
    """A planar cubic B-spline with one curvature maximum, its poles multiplied by s."""
    c = Part.BSplineCurve()
    poles = [V(0, 0, 0), V(1, 0.2, 0), V(2, 0.9, 0), V(2.6, 2, 0), V(2.7, 3.1, 0), V(2.4, 4, 0)]
    c.buildFromPolesMultsKnots([p * s for p in poles], [4, 1, 1, 4], [0, 1, 2, 3], False, 3)
    return c


@pytest.mark.parametrize("s", [1e300, 1e-300], ids=["huge", "tiny"])
def test_analyses_of_huge_and_tiny_curves_are_those_of_the_unit_curve_scaled(s):
    """curvature_profile, curvature_variation and check_monotone_curvature of a curve with poles
    1e300 or 1e-300 apart gave NaN (the Python fuzz's "huge" and "tiny"; "tiny" was also "not
    planar"). The referee is OpenCASCADE's curvature of the unit-size curve."""
    unit, curve = _scaled_bspline(1.0), _scaled_bspline(s)
    profile = fw.curvature_profile(curve, n=200)
    assert np.isfinite(profile.kappa).all() and np.isfinite(profile.s).all()
    assert profile.signed
    occt = np.array([unit.curvature(u) for u in profile.u])
    np.testing.assert_allclose(np.abs(profile.kappa) * s, occt, rtol=1e-12)
    assert profile.s[-1] / s == pytest.approx(unit.length(), rel=1e-9)
    assert fw.curvature_variation(curve) == pytest.approx(fw.curvature_variation(unit), rel=1e-12)
    report, unit_report = fw.check_monotone_curvature(curve), fw.check_monotone_curvature(unit)
    assert report.monotone == unit_report.monotone
    assert np.isfinite(report.normal).all()
    assert report.kappa_start * s == pytest.approx(unit.curvature(0.0), rel=1e-12)


def test_a_curve_that_does_not_move_is_refused_by_that_name():
    """All poles equal: curvature_profile gave NaN curvatures and curvature_variation NaN."""
    point = Part.BSplineCurve()
    point.buildFromPolesMultsKnots([V(1, 1, 0)] * 4, [4, 4], [0, 1], False, 3)
    for analysis in (fw.curvature_profile, fw.curvature_variation, fw.check_monotone_curvature):
        refused(analysis, point, match="the curve does not move")


@pytest.mark.parametrize("differences", [
    [(0, 0), (1e307, 1e307), (2e307, 0), (3e307, 1e307), (4e307, 0)],
    [(0, 0), (0, 1e300), (0, 0)],
], ids=["1e307 apart", "1e300 step"])
def test_algorithm_1_of_huge_differences_is_the_scaled_design(differences):
    """clamp_to_fair_locations of differences 1e307 apart returned NaN differences."""
    scale = max(abs(x) for d in differences for x in d)
    clamped, moved = fw.clamp_to_fair_locations((1, 0), differences)
    assert np.isfinite(clamped).all() and np.isfinite(moved).all()
    unit_clamped, unit_moved = fw.clamp_to_fair_locations((1 / scale, 0), np.asarray(differences) / scale)
    np.testing.assert_allclose(clamped / scale, unit_clamped, rtol=1e-12, atol=1e-15)
    np.testing.assert_allclose(moved / scale, unit_moved, rtol=1e-12, atol=1e-15)


def test_a_fair_blend_of_ends_very_close_together_is_finite():
    """Ends 2.4e-63 apart gave an infinite curvature variation."""
    curve, report = fw.fair_blend_solution((2.4308653429145085e-63, 0.0), (0.0, 1.0), (0.0, 0.0), (1.0, 0.0))
    assert math.isfinite(report.variation) and report.monotone
    assert all(math.isfinite(c) for p in curve.getPoles() for c in p)
    assert curve.value(curve.FirstParameter).distanceToPoint(V(2.4308653429145085e-63, 0, 0)) < 1e-75


def test_basic_curve_refusals_name_the_shape():
    """A parabola whose points overflow was called "the rational curve"."""
    refused(fw.basic.ParabolaArc, focal=0.0098, t0=-6.0, t1=1e160, match="parabola arc")


def test_a_line_segment_1e300_long_has_its_size():
    """Its extent was computed by squares: "the extent overflows"."""
    segment = fw.basic.LineSegment((1e300, 0, 0), (1e300, 1e300, 0))
    assert segment.size() == pytest.approx(1e300, rel=1e-12)
    part = segment.to_part()  # a B-spline: OCCT's lines stop at 2e100 (its length() overflows)
    assert part.value(part.FirstParameter) == V(1e300, 0, 0)
    assert part.value(part.LastParameter) == V(1e300, 1e300, 0)
    assert part.value(0.5 * (part.FirstParameter + part.LastParameter)) == V(1e300, 5e299, 0)
