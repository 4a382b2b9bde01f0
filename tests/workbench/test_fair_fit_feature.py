"""The fair fit feature, headless: Points and sketch sources, Status, failure keeps the last
shape, save and reopen."""
import re

import numpy as np

import FreeCAD
import Part
import Points
import Sketcher  # noqa: F401  (registers Sketcher::SketchObject)

from tests.kernel.fair_fit_data import arc_parabola, sign_changes, signed_curvatures, size_of, within
from tests.scenes import assert_failed_like_freecad
from freecad_workbench.features.fair_fit import FairFit, make_fair_fit

STATUS = re.compile(r"^ok: (\d+) poles, largest deviation ([0-9.e+-]+) mm, (\d+) curvature sign changes?$")


def scan(n=3000):
    """A noisy convex scan, 100 mm in size."""
    return arc_parabola(n, noise=1e-4) * 40.0


def cloud(doc, pts, name="Scan"):
    obj = doc.addObject("Points::Feature", name)
    obj.Points = Points.Points([FreeCAD.Vector(x, y, 0) for x, y in pts])
    doc.recompute()
    return obj


def curve_of(fit):
    return fit.Shape.Edges[0].Curve


def test_fit_of_a_points_object_is_within_tolerance_with_its_status(doc):
    pts = scan()
    tol = 0.1
    fit = make_fair_fit(doc, [cloud(doc, pts)], tolerance=tol)
    assert type(fit.Proxy) is FairFit
    match = STATUS.match(fit.Status)
    assert match, fit.Status
    curve = curve_of(fit)
    assert int(match.group(1)) == curve.NbPoles < 0.05 * len(pts)
    assert float(match.group(2)) <= tol
    assert int(match.group(3)) == 0 == sign_changes(signed_curvatures(curve))
    assert within(curve, pts, tol)[0]
    assert fit.getEditorMode("Status") == ["ReadOnly"]
    assert fit.getEditorMode("Samples") == ["Hidden"]  # no edge among the sources


def test_fit_of_a_sketch_uses_its_placed_points(doc):
    pts = scan(400)
    sketch = doc.addObject("Sketcher::SketchObject", "Sketch")
    for x, y in pts:
        sketch.addGeometry(Part.Point(FreeCAD.Vector(x, y, 0)))
    sketch.Placement = FreeCAD.Placement(FreeCAD.Vector(0, 0, 10), FreeCAD.Rotation(FreeCAD.Vector(1, 0, 0), 90))
    doc.recompute()
    fit = make_fair_fit(doc, [sketch], tolerance=0.2)
    assert STATUS.match(fit.Status), fit.Status
    placed = np.array([tuple(sketch.Placement.multVec(FreeCAD.Vector(x, y, 0))) for x, y in pts])
    assert within(curve_of(fit), placed, 0.2)[0]
    start = curve_of(fit).value(curve_of(fit).FirstParameter)
    assert (start - FreeCAD.Vector(*placed[0])).Length <= 1e-9  # the end point is interpolated


def test_changing_the_tolerance_recomputes_with_fewer_poles(doc):
    pts = scan()
    fit = make_fair_fit(doc, [cloud(doc, pts)], tolerance=0.05)
    tight = curve_of(fit).NbPoles
    fit.Tolerance = 1.0
    doc.recompute()
    assert curve_of(fit).NbPoles < tight
    assert within(curve_of(fit), pts, 1.0)[0]


def test_given_noise_is_used(doc):
    # The same points with two given noise levels: two different fits, each within the
    # tolerance (a feature that ignored Noise would fit both alike).
    pts = scan()
    tol = 0.2
    source = cloud(doc, pts)
    fit = make_fair_fit(doc, [source], tolerance=tol, noise=0.0)
    assert fit.Noise.Value == 0.0 and STATUS.match(fit.Status), fit.Status  # 0: estimated
    curves = {}
    for noise in (0.004, 0.04):
        fit.Noise = noise
        doc.recompute()
        assert STATUS.match(fit.Status), fit.Status
        curves[noise] = curve_of(fit)
        assert within(curves[noise], pts, tol)[0]
    a, b = curves[0.004], curves[0.04]
    apart = max(a.value(a.FirstParameter + (a.LastParameter - a.FirstParameter) * t).distanceToPoint(
        b.value(b.FirstParameter + (b.LastParameter - b.FirstParameter) * t)) for t in np.linspace(0, 1, 201))
    assert a.getPoles() != b.getPoles() and apart > 1e-6 * size_of(pts), apart


def test_bad_input_keeps_the_last_shape_and_says_why(doc):
    pts = scan()
    source = cloud(doc, pts)
    fit = make_fair_fit(doc, [source], tolerance=0.1)
    good = curve_of(fit).getPoles()
    source.Points = Points.Points([FreeCAD.Vector(0, 0, 0), FreeCAD.Vector(1, 0, 0), FreeCAD.Vector(2, 1, 0)])
    doc.recompute()
    assert_failed_like_freecad(fit, "at least")
    assert curve_of(fit).getPoles() == good
    fit.Tolerance = 1e-7  # below the noise: refused, and said so
    source.Points = Points.Points([FreeCAD.Vector(x, y, 0) for x, y in pts])
    doc.recompute()
    assert_failed_like_freecad(fit, "noise")
    assert curve_of(fit).getPoles() == good
    fit.Tolerance = 0.1
    doc.recompute()
    assert STATUS.match(fit.Status)


def test_save_close_reopen_recompute_gives_the_same_curve(doc, tmp_path):
    pts = scan()
    fit = make_fair_fit(doc, [cloud(doc, pts)], tolerance=0.1)
    poles = curve_of(fit).getPoles()
    status = fit.Status
    path = str(tmp_path / "fair_fit.FCStd")
    doc.saveAs(path)
    FreeCAD.closeDocument(doc.Name)
    reopened = FreeCAD.openDocument(path)
    try:
        again = reopened.getObject("FairFit")
        assert type(again.Proxy) is FairFit
        assert again.Tolerance.Value == 0.1 and again.Status == status
        assert curve_of(again).getPoles() == poles
        again.touch()
        reopened.recompute()
        assert curve_of(again).getPoles() == poles and again.Status == status
    finally:
        FreeCAD.closeDocument(reopened.Name)


def test_convex_scan_size_is_scale_free(doc):
    # The same scan from 1 mm to 100 m across, each fit at a thousandth of its size: convex,
    # within its tolerance, and the same curve scaled (as many poles, the poles scaled).
    pts = scan(2000)
    fits = {}
    for scale in (0.01, 1.0, 1000.0):
        scaled = pts * scale
        tol = 1e-3 * size_of(scaled)
        curve = curve_of(make_fair_fit(doc, [cloud(doc, scaled, f"Scan{len(fits)}")], tolerance=tol,
                                       name=f"Fit{len(fits)}"))
        assert sign_changes(signed_curvatures(curve)) == 0, scale
        assert within(curve, scaled, tol)[0], scale
        fits[scale] = np.array([tuple(p) for p in curve.getPoles()]) / scale
    for scale, poles in fits.items():
        assert poles.shape == fits[1.0].shape, scale
        np.testing.assert_allclose(poles, fits[1.0], rtol=0, atol=1e-6 * size_of(pts), err_msg=str(scale))


def test_corners_refused_kept_or_smoothed_as_the_feature_says(doc):
    """Issue 25: a profile with a sharp corner. Refuse (the default) keeps no shape and names
    the corner in Status; Keep gives two edges meeting at the corner, each within the
    tolerance (OCCT's distance); Smooth one edge, Status saying the corner was smoothed over."""
    import math

    a = [(1 + math.cos(t), math.sin(t), 0.0) for t in np.linspace(math.pi, math.pi / 2, 60)]
    b = [(2 + math.cos(t), 1 + math.sin(t), 0.0) for t in np.linspace(math.pi, 1.5 * math.pi, 60)[1:]]
    pts = Points.Points()
    pts.addPoints([FreeCAD.Vector(*p) * 10 for p in a + b])
    cloud = doc.addObject("Points::Feature", "Profile")
    cloud.Points = pts
    doc.recompute()
    fit = make_fair_fit(doc, [cloud], tolerance=0.01)
    assert "sharp corner at point 59" in fit.Status, fit.Status
    fit.Corners = "Keep"
    doc.recompute()
    assert fit.Status.startswith("ok:") and "2 edges meeting at 1 corner" in fit.Status, fit.Status
    assert len(fit.Shape.Edges) == 2 and fit.Shape.isValid()
    corner = FreeCAD.Vector(10, 10, 0)
    assert (fit.Shape.Edges[0].Vertexes[-1].Point - corner).Length <= 1e-9
    for p in a + b:
        assert fit.Shape.distToShape(Part.Vertex(FreeCAD.Vector(*p) * 10))[0] <= 0.01 * (1 + 1e-9)
    fit.Corners = "Smooth"
    doc.recompute()
    assert len(fit.Shape.Edges) == 1 and "1 corner smoothed over" in fit.Status, fit.Status
