"""Curvature comb geometry and curvature plot, headless (no GUI, Agg backend)."""
import math

import numpy as np
import pytest

import FreeCAD
import Part

import freecad_workbench as fw
from freecad_workbench.gui.comb import AUTO_LENGTH, REACH, auto_scale, comb_lines

S_DATA = [(0, 0, 0), (10, 6, 0), (20, 8, 0), (30, 4, 0), (40, -4, 0), (50, -8, 0), (60, -6, 0), (70, 0, 0)]


def test_comb_of_a_circle_points_to_the_centre_with_length_scale_over_r():
    r, scale = 8.0, 20.0
    edge = Part.makeCircle(r, FreeCAD.Vector(1, 2, 3))
    comb = comb_lines(edge, scale=scale, n=64)
    centre = np.array([1.0, 2.0, 3.0])
    assert len(comb.base) >= 64
    np.testing.assert_allclose(np.linalg.norm(comb.base - centre, axis=1), r, atol=1e-9)
    np.testing.assert_allclose(np.linalg.norm(comb.tip - comb.base, axis=1), scale / r, rtol=1e-6)
    np.testing.assert_allclose(np.linalg.norm(comb.tip - centre, axis=1), r - scale / r, rtol=1e-6)


def test_negative_scale_draws_the_comb_on_the_other_side():
    edge = Part.makeCircle(5.0)
    inside, outside = comb_lines(edge, 10.0, 32), comb_lines(edge, -10.0, 32)
    np.testing.assert_allclose(np.linalg.norm(outside.tip, axis=1), 5.0 + 2.0, rtol=1e-6)
    np.testing.assert_allclose(inside.tip - inside.base, -(outside.tip - outside.base), atol=1e-12)


def test_planar_comb_changes_sides_where_the_curvature_changes_sign():
    curve = fw.interpolate_classic(S_DATA)
    comb = comb_lines(curve, scale=100.0, n=400)
    profile = fw.curvature_profile(curve, 400)
    np.testing.assert_array_equal(comb.kappa, profile.kappa)
    tangent = np.gradient(comb.base, axis=0)
    side = np.sign(np.cross(tangent, comb.tip - comb.base)[:, 2])  # +1 left of the curve, -1 right
    strong = np.abs(comb.kappa) > 0.2 * np.abs(comb.kappa).max()
    # left of the tangent where the curve turns left (kappa > 0 about +z), right elsewhere
    normal_sign = np.sign(profile.normal[2])
    np.testing.assert_array_equal(side[strong], np.sign(comb.kappa[strong]) * normal_sign)
    assert (side[strong] > 0).any() and (side[strong] < 0).any()


def test_space_curve_comb_points_along_the_principal_normal():
    r, pitch = 10.0, 8.0
    helix = Part.makeHelix(pitch, 2 * pitch, r)
    comb = comb_lines(helix.Edges[0], scale=1.0, n=128)
    kappa = r / (r**2 + (pitch / (2 * math.pi)) ** 2)
    teeth = comb.tip - comb.base
    np.testing.assert_allclose(np.linalg.norm(teeth, axis=1), kappa, rtol=1e-3)
    # the principal normal of a helix points at its axis, horizontally
    radial = -comb.base[:, :2] / np.linalg.norm(comb.base[:, :2], axis=1)[:, None]
    np.testing.assert_allclose(teeth[:, :2] / kappa, radial, atol=2e-3)
    np.testing.assert_allclose(teeth[:, 2], 0.0, atol=2e-3 * kappa)


def test_straight_edge_has_a_flat_comb():
    edge = Part.makeLine((0, 0, 0), (10, 5, 0))
    comb = comb_lines(edge, scale=50.0, n=16)
    np.testing.assert_allclose(comb.tip, comb.base, atol=1e-12)
    assert auto_scale([edge]) == 1.0


@pytest.mark.parametrize("shape", ["s-curve", "quarter-circle"])
def test_auto_scale_makes_the_longest_tooth_a_quarter_of_the_size_at_most(shape):
    """The longest tooth is a quarter of the size unless that would take a tooth REACH of
    the way to its centre of curvature: on the S-curve the reach rule decides, on a
    quarter circle (radius 0.71 of the box diagonal) the size rule."""
    if shape == "s-curve":
        edge = fw.csr_spline(S_DATA).toShape()
    else:
        edge = Part.Edge(Part.Circle(FreeCAD.Vector(), FreeCAD.Vector(0, 0, 1), 10.0), 0.0, math.pi / 2)
    scale = auto_scale([edge], n=256)
    comb = comb_lines(edge, scale, n=256)
    length = np.linalg.norm(comb.tip - comb.base, axis=1)
    diagonal = np.linalg.norm(comb.base.max(axis=0) - comb.base.min(axis=0))
    assert diagonal == pytest.approx(edge.BoundBox.DiagonalLength, rel=0.05)
    kappa_max = np.abs(comb.kappa).max()
    assert length.max() == pytest.approx(min(AUTO_LENGTH * diagonal, REACH / kappa_max), rel=1e-9)
    reach_decides = REACH / kappa_max < AUTO_LENGTH * diagonal
    assert reach_decides == (shape == "s-curve")
    assert (length * np.abs(comb.kappa) <= REACH * (1 + 1e-12)).all()  # no tooth past REACH of its radius


def test_comb_of_a_trimmed_edge_covers_only_the_edge():
    circle = Part.Circle(FreeCAD.Vector(0, 0, 0), FreeCAD.Vector(0, 0, 1), 4.0)
    edge = Part.Edge(circle, 0.0, math.pi / 2)  # quarter circle in the first quadrant
    comb = comb_lines(edge, scale=1.0, n=32)
    assert (comb.base[:, :2] >= -1e-9).all()
    np.testing.assert_allclose(comb.base[0], (4, 0, 0), atol=1e-9)
    np.testing.assert_allclose(comb.base[-1], (0, 4, 0), atol=1e-9)


def test_curvature_plot_writes_a_png_with_one_line_per_curve(tmp_path, artifacts):
    import matplotlib.image

    from freecad_workbench.gui.plot import curvature_plot

    csr = fw.csr_spline(S_DATA)
    classic = fw.interpolate_classic(S_DATA)
    path = tmp_path / "curvature.png"
    fig = curvature_plot([(csr.toShape(), "csr-spline"), (classic, "classic")], path=path)
    curvature_plot([(csr.toShape(), "csr-spline"), (classic, "classic")], path=f"{artifacts}/curvature_plot.png")
    ax = fig.axes[0]
    lines = [line for line in ax.get_lines() if line.get_label() in ("csr-spline", "classic")]
    assert [line.get_label() for line in lines] == ["csr-spline", "classic"]
    legend = [t.get_text() for t in ax.get_legend().get_texts()]
    assert legend == ["csr-spline", "classic", "curvature maximum", "curvature minimum"]
    profile = fw.curvature_profile(csr, 1024)
    np.testing.assert_array_equal(lines[0].get_xdata(), profile.s)
    np.testing.assert_array_equal(lines[0].get_ydata(), profile.kappa)
    assert (ax.get_xlabel(), ax.get_ylabel()) == ("arc length (mm)", "signed curvature (1/mm)")
    image = matplotlib.image.imread(str(path))
    assert image.shape[:2] == (450, 800)
    assert (image[..., :3] < 0.9).any()  # something drawn on the white page


def test_curvature_plot_needs_something_to_plot(tmp_path):
    from freecad_workbench.gui.plot import curvature_plot

    with pytest.raises(ValueError, match="nothing to plot"):
        curvature_plot([], path=tmp_path / "empty.png")


def test_plot_links_labels_edges_of_objects(doc):
    from freecad_workbench.gui.plot import link_edges

    fit = doc.addObject("Part::Feature", "Fit")
    fit.Shape = fw.csr_spline(S_DATA).toShape()
    fit.Label = "My fit"
    box = doc.addObject("Part::Box", "Box")
    doc.recompute()
    labelled = link_edges([(fit, ""), (box, "Edge3"), (box, "Face1")])
    assert [label for _, label in labelled] == ["My fit", "Box.Edge3"]
    ends = [tuple(v.Point) for v in labelled[1][0].Vertexes]
    assert ends == [tuple(v.Point) for v in box.Shape.Edge3.Vertexes]
