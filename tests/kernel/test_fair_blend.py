"""Fair blends (fw.fair_blend, fw.fair_blend_solution), judged by OCCT's evaluation of the
returned Part curves: end points, tangents and curvatures against the edges' own, and the
curvature sampled densely against the certificate's verdict."""
import math

import numpy as np
import pytest

import FreeCAD
import Part

import freecad_workbench as fw

V = FreeCAD.Vector


def signed_curvatures(curve, normal, n=3000):
    u = np.linspace(curve.FirstParameter, curve.LastParameter, n)
    out = []
    for x in u:
        d1, d2 = curve.getD2(x)[1:3]
        out.append(np.dot(np.cross(np.array(d1), np.array(d2)), normal) / np.linalg.norm(np.array(d1)) ** 3)
    return np.array(out)


def monotone_by_sampling(curve, normal):
    k = signed_curvatures(curve, normal)
    d = np.diff(k)
    tol = 1e-9 * np.max(np.abs(k))
    return bool(np.all(d >= -tol) or np.all(d <= tol))


def assert_joins(curve, edge, end, leaving):
    """The blend's end meets the edge's end point, with the edge's tangent direction."""
    u_edge = edge.FirstParameter if end == "start" else edge.LastParameter
    u_blend = curve.FirstParameter if leaving else curve.LastParameter
    p_edge, p_blend = np.array(edge.valueAt(u_edge)), np.array(curve.value(u_blend))
    size = max(1.0, np.linalg.norm(p_edge))
    assert np.linalg.norm(p_edge - p_blend) <= 1e-12 * size
    t_edge = np.array(edge.tangentAt(u_edge))
    t_blend = np.array(curve.tangent(u_blend)[0])
    # Leaving an edge's end continues it; leaving its start runs against its parameter.
    sign = 1.0 if (end == "end") == leaving else -1.0
    assert np.linalg.norm(np.cross(t_edge, t_blend)) <= 1e-11
    assert np.dot(t_edge, t_blend) * sign > 0.0


def sketch_edges():
    """A line, a circle arc, an ellipse arc and a B-spline, as a sketch holds them: the
    sketch's own geometry (Sketcher::SketchObject.Geometry), made edges by fair_blend."""
    import Sketcher  # noqa: F401  (registers Sketcher::SketchObject)

    line = Part.LineSegment(V(-4, 0, 0), V(0, 0, 0))
    arc = Part.ArcOfCircle(Part.Circle(V(6, 3, 0), V(0, 0, 1), 2.0), math.radians(200), math.radians(320))
    ellipse = Part.ArcOfEllipse(Part.Ellipse(V(2, 9, 0), 3.0, 1.5), math.radians(-60), math.radians(40))
    spline = Part.BSplineCurve()
    spline.interpolate([V(-3, 6, 0), V(-2, 7.5, 0), V(-0.5, 7.8, 0), V(1, 7, 0)])
    doc = FreeCAD.newDocument("FairBlendSketch")
    try:
        sketch = doc.addObject("Sketcher::SketchObject", "Sketch")
        for g in (line, arc, ellipse, spline):
            sketch.addGeometry(g, False)
        doc.recompute()
        geometry = [g.copy() for g in sketch.Geometry]
    finally:
        FreeCAD.closeDocument(doc.Name)
    return dict(zip(("line", "arc", "ellipse", "spline"), (g.toShape() for g in geometry)))


PAIRS = [
    ("line", "end", "arc", "start"),
    ("arc", "end", "ellipse", "start"),
    ("ellipse", "end", "spline", "end"),
    ("spline", "start", "line", "start"),
    ("line", "start", "ellipse", "end"),
]


def edge_curvature(edge, end, normal, leaving):
    """Signed curvature of the edge at its end, traversed the way the blend runs."""
    u = edge.FirstParameter if end == "start" else edge.LastParameter
    d1, d2 = np.array(edge.derivative1At(u)), np.array(edge.derivative2At(u))
    forward = (end == "end") == leaving
    return (1.0 if forward else -1.0) * np.dot(np.cross(d1, d2), normal) / np.linalg.norm(d1) ** 3


@pytest.mark.parametrize("a, end_a, b, end_b", PAIRS)
def test_g2_blend_between_sketch_edges_matches_their_curvatures(a, end_a, b, end_b):
    edges = sketch_edges()
    curve, report = fw.fair_blend(edges[a], end_a, edges[b], end_b)  # G2 is the default
    assert report.continuity == "G2"
    assert_joins(curve, edges[a], end_a, leaving=True)
    assert_joins(curve, edges[b], end_b, leaving=False)
    normal = np.array(report.normal)
    k = signed_curvatures(curve, normal, n=2)
    ka, kb = edge_curvature(edges[a], end_a, normal, True), edge_curvature(edges[b], end_b, normal, False)
    scale = max(abs(ka), abs(kb), 1e-3)
    assert k[0] == pytest.approx(ka, abs=1e-9 * scale)
    assert k[-1] == pytest.approx(kb, abs=1e-9 * scale)
    # Monotone or not, the report agrees with dense sampling.
    assert report.monotone == monotone_by_sampling(curve, normal), report.reason


@pytest.mark.parametrize("a, end_a, b, end_b", PAIRS)
def test_g1_blend_between_sketch_edges_is_tangent_to_both_and_certified_monotone(a, end_a, b, end_b):
    edges = sketch_edges()
    curve, report = fw.fair_blend(edges[a], end_a, edges[b], end_b, continuity="G1")
    assert isinstance(curve, Part.BSplineCurve) and curve.Degree == 3
    assert_joins(curve, edges[a], end_a, leaving=True)
    assert_joins(curve, edges[b], end_b, leaving=False)
    assert report.monotone
    assert monotone_by_sampling(curve, np.array(report.normal))
    assert report.normal == (0.0, 0.0, 1.0)
    # The report's end curvatures are the curve's, as OCCT evaluates them.
    k = signed_curvatures(curve, np.array(report.normal), n=2)
    assert report.kappa0 == pytest.approx(k[0], rel=1e-9, abs=1e-12)
    assert report.kappa1 == pytest.approx(k[-1], rel=1e-9, abs=1e-12)
    assert report.variation >= 0.0 and report.spans >= 1 and not report.extrema


def test_ends_on_a_circle_give_the_circle_exactly():
    """Symmetric ends on a circle: the clothoid is the arc, and the rational cubic keeps it."""
    r, c = 2.5, np.array([1.0, -2.0, 0.0])
    a0, a1 = math.radians(20), math.radians(250)
    p = lambda a: c + r * np.array([math.cos(a), math.sin(a), 0.0])  # noqa: E731
    t = lambda a: np.array([-math.sin(a), math.cos(a), 0.0])  # noqa: E731
    curve, report = fw.fair_blend_solution(p(a0), t(a0), p(a1), t(a1))
    assert report.monotone and report.turning == pytest.approx(a1 - a0, rel=1e-12)
    for u in np.linspace(curve.FirstParameter, curve.LastParameter, 200):
        assert np.linalg.norm(np.array(curve.value(u)) - c) == pytest.approx(r, rel=1e-12)
        assert curve.curvature(u) == pytest.approx(1.0 / r, rel=1e-12)


def test_a_3d_plane_and_a_mirror_image_are_solved_alike():
    rot = FreeCAD.Rotation(V(1, 2, 3), 47.0)
    p0, t0, p1, t1 = V(0, 0, 0), V(1, 0, 0), V(3, 2, 0), V(0.2, 1, 0)
    flat, flat_report = fw.fair_blend_solution(p0, t0, p1, t1)
    tilted, tilted_report = fw.fair_blend_solution(rot.multVec(p0), rot.multVec(t0), rot.multVec(p1), rot.multVec(t1))
    mirrored, mirrored_report = fw.fair_blend_solution(p0, t0, V(3, -2, 0), V(0.2, -1, 0))
    assert flat_report.monotone and tilted_report.monotone and mirrored_report.monotone
    assert tilted_report.variation == pytest.approx(flat_report.variation, rel=1e-9)
    assert mirrored_report.kappa0 == pytest.approx(-flat_report.kappa0, rel=1e-9)
    for u in np.linspace(0.0, 1.0, 9):
        expected = rot.multVec(flat.value(u))
        assert (tilted.value(u) - expected).Length <= 1e-12 * 4


@pytest.mark.parametrize(
    "args, message",
    [
        (((0, 0, 0), (1, 0, 0), (0, 0, 0), (1, 0, 0)), "p0 and p1 coincide"),
        (((0, 0, 0), (0, 0, 0), (1, 0, 0), (1, 0, 0)), "start tangent t0 is zero"),
        (((0, 0, 0), (1, 0, 0), (1, 1, 0), (math.nan, 0, 0)), "not finite"),
        # With a plane normal the ends must lie in that plane (without one, ends in space get
        # the fair blend in space: tests/kernel/test_fair_blend_space.py).
        (((0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 0, 1), None, None, (0, 0, 1)), "leaves the blend's plane"),
    ],
)
def test_bad_ends_raise_input_error_naming_the_problem(args, message):
    with pytest.raises(fw.InputError, match=message):
        fw.fair_blend_solution(*args)


def test_unknown_continuity_and_end_names_are_refused():
    edges = sketch_edges()
    with pytest.raises(fw.InputError, match="continuity"):
        fw.fair_blend(edges["line"], "end", edges["arc"], "start", continuity="G3")
    with pytest.raises(fw.InputError, match="'start', 'end'"):
        fw.fair_blend(edges["line"], "middle", edges["arc"], "start", continuity="G1")


def test_the_default_solver_solves_every_end_the_papers_algorithm_solves():
    from tests.kernel.test_monotone import random_ends

    rng = np.random.default_rng(2026)
    for k, (p0, t0, p1, t1, _) in enumerate(random_ends(rng, 200)):
        paper = fw.monotone_curvature_spline(V(*p0), V(*t0), V(*p1), V(*t1), method="paper")
        fair = fw.monotone_curvature_spline(V(*p0), V(*t0), V(*p1), V(*t1))
        assert fw.check_monotone_curvature(paper).monotone and fw.check_monotone_curvature(fair).monotone, k
        assert fair.value(fair.FirstParameter).distanceToPoint(V(*p0)) <= 1e-12 * np.linalg.norm(p1 - p0) + 1e-15


def test_g2_ends_without_a_monotone_curve_raise_from_the_spline_and_report_from_the_blend():
    # A straight start along +x turning left, but the end lies below the start's tangent.
    args = ((0, 0, 0), (1, 0, 0), (2, -0.3, 0), (math.cos(0.3), math.sin(0.3), 0))
    with pytest.raises(fw.NoMonotoneSolution, match="crosses the tangent line"):
        fw.monotone_curvature_spline(*args, k0=0.0, k1=0.8)
    curve, report = fw.fair_blend_solution(*args, k0=0.0, k1=0.8)
    assert not report.monotone and "Tait-Kneser" in report.reason
    assert curve.curvature(curve.LastParameter) == pytest.approx(0.8, rel=1e-9)


def test_g2_ends_of_a_clothoid_give_that_clothoid_s_curvature_monotonically():
    # The clothoid kappa(s) = 0.2 + 2.3 s over s in [0, 1], integrated here (Simpson).
    s = np.linspace(0.0, 1.0, 20001)
    theta = 0.2 * s + 1.15 * s**2
    w = np.ones_like(s)
    w[1:-1:2], w[2:-1:2] = 4.0, 2.0
    end = (np.sum(w * np.cos(theta)), np.sum(w * np.sin(theta)), 0.0)
    end = tuple(c * (s[1] - s[0]) / 3.0 for c in end)
    t1 = (math.cos(theta[-1]), math.sin(theta[-1]), 0.0)
    curve = fw.monotone_curvature_spline((0, 0, 0), (1, 0, 0), end, t1, k0=0.2, k1=2.5)
    k = signed_curvatures(curve, np.array([0.0, 0.0, 1.0]))
    assert k[0] == pytest.approx(0.2, rel=1e-9) and k[-1] == pytest.approx(2.5, rel=1e-9)
    assert np.all(np.diff(k) >= -1e-9 * np.max(np.abs(k)))
    # It follows the clothoid: the curvature is linear in arc length, to the spline's accuracy.
    points = np.array([tuple(curve.value(u)) for u in np.linspace(curve.FirstParameter, curve.LastParameter, 2001)])
    arc = np.concatenate(([0.0], np.cumsum(np.linalg.norm(np.diff(points, axis=0), axis=1))))
    assert arc[-1] == pytest.approx(1.0, rel=1e-4)
    u = np.linspace(curve.FirstParameter, curve.LastParameter, 2001)
    d1 = [np.array(curve.getD2(x)[1]) for x in u]
    d2 = [np.array(curve.getD2(x)[2]) for x in u]
    kk = np.array([np.cross(a, b)[2] / np.linalg.norm(a) ** 3 for a, b in zip(d1, d2)])
    assert np.max(np.abs(kk - (0.2 + 2.3 * arc))) < 0.05 * 2.5  # 0.028 measured: the first certified spline


def test_the_papers_methods_are_g1_only():
    with pytest.raises(fw.InputError, match="Algorithm 2 is G1"):
        fw.monotone_curvature_spline((0, 0), (1, 0), (2, 1), (0, 1), k0=0.2, k1=2.5, method="paper")
    with pytest.raises(fw.InputError, match="both end curvatures"):
        fw.fair_blend_solution((0, 0), (1, 0), (2, 1), (0, 1), k0=0.2)
