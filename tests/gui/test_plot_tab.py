"""The curvature plot as a tab of the FreeCAD main window (a matplotlib Qt canvas in a
subwindow of its QMdiArea), with units on the axes and the curvature extrema marked; the
extrema are checked against OCCT's own curvature of the Part curves, found here
independently of the plotting code. A picture of the tab goes to out/test-artifacts/."""
import math
import os
import sys

import numpy as np
import pytest

import FreeCAD
import Part

import freecad_workbench as fw
from freecad_workbench.gui import plot

V = FreeCAD.Vector
S_DATA = [(0, 0, 0), (10, 6, 0), (20, 8, 0), (30, 4, 0), (40, -4, 0), (50, -8, 0), (60, -6, 0), (70, 0, 0)]
A, B = 30.0, 10.0  # ellipse semi-axes: curvature a/b^2 at the ends of the major axis, b/a^2 of the minor


def mdi_area():
    from freecad_workbench.gui.qt import QtWidgets

    return plot.main_window().findChild(QtWidgets.QMdiArea)


def settle():
    """Let Qt deliver what is pending, deletions of closed tabs included."""
    from freecad_workbench.gui.qt import QtCore, QtWidgets

    for _ in range(3):
        QtCore.QCoreApplication.sendPostedEvents(None, QtCore.QEvent.Type.DeferredDelete)
        QtWidgets.QApplication.processEvents()


def visible_top_levels():
    """The visible top-level widgets; hold on to the list: the same widget then comes back
    as the same Python object."""
    from freecad_workbench.gui.qt import QtWidgets

    return [w for w in QtWidgets.QApplication.topLevelWidgets() if w.isVisible()]


@pytest.fixture
def mdi(doc):
    """The main window's MDI area with the document's 3D view and no plot tab; every plot tab
    is closed afterwards."""
    FreeCAD.setActiveDocument(doc.Name)
    plot.close_plot_tabs()  # any left by other tests
    area = mdi_area()
    yield area
    plot.close_plot_tabs()
    settle()
    assert plot.plot_tabs() == []


def markers(fig, label):
    """(s, kappa) of the extremum markers labelled `label`, by arc length."""
    lines = [line for line in fig.axes[0].get_lines() if line.get_label() == label]
    assert len(lines) <= 1
    if not lines:
        return np.zeros((0, 2))
    points = np.column_stack([lines[0].get_xdata(), lines[0].get_ydata()])
    return points[np.argsort(points[:, 0])]


def occt_extrema(curve, u0, u1, samples=20000):
    """Interior extrema of the signed curvature (about +z) of a planar Part curve, from OCCT's
    curvature() and its derivatives: [(arc length from u0, kappa, is_maximum)]."""

    def kappa(u):
        _, d1, d2 = curve.getD2(u)
        return curve.curvature(u) * math.copysign(1.0, d1.cross(d2).z)

    u = np.linspace(u0, u1, samples + 1)
    k = np.array([kappa(x) for x in u])
    found = []
    for j in range(1, samples):
        for sign in (1.0, -1.0):
            if sign * k[j] > sign * k[j - 1] and sign * k[j] >= sign * k[j + 1]:
                a, b = u[j - 1], u[j + 1]  # golden section search on the bracket
                g = (math.sqrt(5.0) - 1.0) / 2.0
                for _ in range(60):
                    c, d = b - g * (b - a), a + g * (b - a)
                    if sign * kappa(c) > sign * kappa(d):
                        b = d
                    else:
                        a = c
                um = 0.5 * (a + b)
                found.append((curve.length(u0, um), kappa(um), sign > 0))
    return found


def ellipse_arc(doc, t0=-0.6, t1=2.2):
    """An ellipse arc across the end of its major axis (t = 0) and of its minor axis (pi/2)."""
    ellipse = Part.Ellipse(V(5, -3, 0), A, B)
    obj = doc.addObject("Part::Feature", "Arch")
    obj.Shape = Part.Edge(ellipse, t0, t1)
    doc.recompute()
    return obj, ellipse, t0, t1


def test_plot_links_opens_one_tab_in_the_main_window_holding_the_canvas(mdi, doc):
    from matplotlib.backends import qt_compat
    from matplotlib.backends.backend_qtagg import FigureCanvasQTAgg, NavigationToolbar2QT

    from freecad_workbench.gui.qt import BINDING, QtWidgets

    fit = doc.addObject("Part::Feature", "Fit")
    fit.Shape = fw.csr_spline(S_DATA).toShape()
    fit.Label = "My fit"
    arch, *_ = ellipse_arc(doc)
    before, tops = list(mdi.subWindowList()), visible_top_levels()
    figures = set(sys.modules["matplotlib.pyplot"].get_fignums()) if "matplotlib.pyplot" in sys.modules else set()
    fig = plot.plot_links([(fit, "Edge1"), (arch, "")])
    settle()
    added = [sub for sub in mdi.subWindowList() if sub not in before]
    assert len(added) == 1
    (tab,) = added
    assert fig.fairsplines_subwindow is tab and plot.plot_tabs() == [tab] and plot.figures() == [fig]
    assert tab.windowTitle() == "Curvature: My fit.Edge1, Arch"
    assert mdi.activeSubWindow() is tab and tab.isMaximized() and tab.isVisible()
    canvas = tab.widget().findChild(FigureCanvasQTAgg)
    assert canvas is fig.canvas and canvas.isVisible()
    assert isinstance(canvas, QtWidgets.QWidget) and qt_compat.QT_API == BINDING  # one Qt binding
    toolbar = tab.widget().findChild(NavigationToolbar2QT)
    assert toolbar is not None and toolbar.canvas is canvas  # its Save writes a PNG:
    assert canvas.get_default_filetype() == "png" and canvas.get_default_filename().endswith(".png")
    # the canvas fills the tab: wider than the 800 px of a PNG, as wide as the MDI area
    assert canvas.width() >= mdi.viewport().width() - 2 and canvas.height() > 0.6 * mdi.viewport().height()
    # no floating window, no pyplot figure
    assert [w for w in visible_top_levels() if not any(w is top for top in tops)] == []
    if "matplotlib.pyplot" in sys.modules:
        assert set(sys.modules["matplotlib.pyplot"].get_fignums()) == figures
    ax = fig.axes[0]
    assert ax.get_xlabel() == "arc length (mm)"
    assert ax.get_ylabel() == "signed curvature (1/mm)"
    legend = [t.get_text() for t in ax.get_legend().get_texts()]
    assert legend == ["My fit.Edge1", "Arch", "curvature maximum", "curvature minimum"]


def test_tab_shows_the_plot_and_its_picture_is_saved(mdi, doc, artifacts, tmp_path):
    import matplotlib.image

    arch, *_ = ellipse_arc(doc)
    classic = doc.addObject("Part::Feature", "Classic")
    classic.Shape = fw.interpolate_classic(S_DATA).toShape()
    classic.Label = "Classic C2"
    doc.recompute()
    fig = plot.plot_links([(arch, ""), (classic, "")])
    settle()
    fig.canvas.draw()
    settle()
    path = os.path.join(artifacts, "plot_tab.png")
    assert mdi.grab().save(path)  # the MDI area: the tab and its tab bar
    picture = matplotlib.image.imread(path)
    # the plot fills the main area, whatever size FreeCAD gave the window (587 px wide on 1.1)
    canvas = fig.canvas
    assert picture.shape[1] == mdi.width() and canvas.width() >= 0.9 * mdi.width()
    blue = (np.abs(picture[..., :3] - np.array([0x1F, 0x77, 0xB4]) / 255).max(axis=-1) < 0.08).sum()
    orange = (np.abs(picture[..., :3] - np.array([0xFF, 0x7F, 0x0E]) / 255).max(axis=-1) < 0.08).sum()
    assert blue > 300 and orange > 300  # both curves are drawn in the tab
    # The tab's figure saves to PNG like the toolbar's Save button does.
    fig.savefig(str(tmp_path / "saved.png"))
    assert matplotlib.image.imread(str(tmp_path / "saved.png")).shape[1] > 0


def test_in_windowed_mode_the_plot_is_maximized_and_active_too(mdi, doc):
    """FreeCAD's preference "Document window: windowed" puts the MDI area in sub-window mode:
    the plot still fills the main area, like a 3D view, and is the active window."""
    from freecad_workbench.gui.qt import QtWidgets

    arch, *_ = ellipse_arc(doc)
    mode = mdi.viewMode()
    mdi.setViewMode(QtWidgets.QMdiArea.ViewMode.SubWindowView)
    try:
        for sub in mdi.subWindowList():
            sub.showNormal()
        mdi.setActiveSubWindow(mdi.subWindowList()[0])
        settle()
        fig = plot.plot_links([(arch, "")])
        settle()
        tab = fig.fairsplines_subwindow
        assert tab.isMaximized() and mdi.activeSubWindow() is tab
        assert tab.width() >= mdi.viewport().width() - 2
    finally:
        plot.close_plot_tabs()
        mdi.setViewMode(mode)
        settle()


def test_closing_the_tab_leaves_no_subwindow(mdi, doc):
    arch, *_ = ellipse_arc(doc)
    before = list(mdi.subWindowList())
    fig = plot.plot_links([(arch, "")])
    settle()
    assert len(mdi.subWindowList()) == len(before) + 1
    fig.fairsplines_subwindow.close()
    settle()
    assert mdi.subWindowList() == before and plot.plot_tabs() == []
    plot.plot_links([(arch, "")])
    plot.plot_links([(arch, "Edge1")])
    settle()
    assert len(plot.plot_tabs()) == 2
    plot.close_plot_tabs()
    assert mdi.subWindowList() == before and plot.plot_tabs() == []


def test_ellipse_arc_gets_its_vertices_marked_at_their_arc_lengths(mdi, doc):
    arch, ellipse, t0, t1 = ellipse_arc(doc)
    fig = plot.plot_links([(arch, "")])
    expected = occt_extrema(ellipse, t0, t1)
    # OCCT finds the two vertices: maximum a/b^2 at t = 0, minimum b/a^2 at t = pi/2
    assert [is_max for _, _, is_max in expected] == [True, False]
    assert [k for _, k, _ in expected] == pytest.approx([A / B**2, B / A**2], rel=1e-9)
    assert expected[0][0] == pytest.approx(Part.Edge(ellipse, t0, 0.0).Length, rel=1e-6)
    length = arch.Shape.Length
    for label, (s, k, _) in (("curvature maximum", expected[0]), ("curvature minimum", expected[1])):
        (found,) = markers(fig, label)
        assert found[0] == pytest.approx(s, abs=1e-4 * length)  # a tenth of the plot's sample spacing
        assert found[1] == pytest.approx(k, rel=1e-6)


def test_bspline_gets_every_curvature_extremum_marked(mdi, doc):
    curve = fw.interpolate_classic(S_DATA)  # an S: two maxima and two minima of signed curvature
    obj = doc.addObject("Part::Feature", "Classic")
    obj.Shape = curve.toShape()
    doc.recompute()
    fig = plot.plot_links([(obj, "")])
    expected = occt_extrema(curve, curve.FirstParameter, curve.LastParameter)
    assert len(expected) == 4
    length = obj.Shape.Length
    for label, maximum in (("curvature maximum", True), ("curvature minimum", False)):
        want = np.array([(s, k) for s, k, is_max in expected if is_max == maximum])
        found = markers(fig, label)
        assert found.shape == want.shape == (2, 2)
        np.testing.assert_allclose(found[:, 0], want[:, 0], rtol=0, atol=1e-4 * length)
        np.testing.assert_allclose(found[:, 1], want[:, 1], rtol=1e-5)


def test_a_kept_arc_between_transitions_is_marked_once_at_its_middle(mdi, doc):
    """A design with basic curves keeps the middle of a half circle exact between two lines:
    the curvature overshoots 1/r at both transitions and is flat on the kept arc, whose
    noise is no extremum; its minimum is marked once, in the middle of the arc."""
    import freecad_workbench.basic as basic

    r, marks = 10.0, [0.25, 0.5, 0.75]
    pieces = [
        (basic.LineSegment((-20, -r, 0), (0, -r, 0)), marks),
        (basic.CircleArc((0, 0, 0), r, -math.pi / 2, math.pi / 2), [0.1 * i for i in range(1, 10)]),
        (basic.LineSegment((0, r, 0), (-20, r, 0)), marks),
    ]
    curve = fw.design_spline(pieces)
    obj = doc.addObject("Part::Feature", "Design")
    obj.Shape = curve.toShape()
    doc.recompute()
    fig = plot.plot_links([(obj, "")])
    u = np.linspace(curve.FirstParameter, curve.LastParameter, 40001)
    on_arc = u[np.abs(np.array([curve.curvature(x) for x in u]) - 1.0 / r) < 1e-9]
    s0, s1 = curve.length(u[0], on_arc[0]), curve.length(u[0], on_arc[-1])
    assert s1 - s0 > 0.25 * obj.Shape.Length  # a long flat stretch
    (minimum,) = markers(fig, "curvature minimum")
    assert minimum[0] == pytest.approx(0.5 * (s0 + s1), abs=2 * obj.Shape.Length / plot.DEFAULT_SAMPLES)
    assert minimum[1] == pytest.approx(1.0 / r, rel=1e-9)
    maxima = markers(fig, "curvature maximum")  # the overshoots, one before and one after the arc
    assert len(maxima) == 2 and maxima[0, 0] < s0 and maxima[1, 0] > s1 and (maxima[:, 1] > 1.0 / r).all()


@pytest.mark.parametrize("kind", ["arc", "circle", "line", "helix"])
def test_constant_curvature_gets_no_extremum_marker(mdi, doc, kind):
    shape = {
        "arc": lambda: Part.Edge(Part.Circle(V(1, 2, 0), V(0, 0, 1), 12.0), 0.3, 4.0),
        "circle": lambda: Part.makeCircle(7.0, V(0, 0, 0), V(1, 1, 1)),
        "line": lambda: Part.makeLine((0, 0, 0), (20, 5, 3)),
        "helix": lambda: Part.makeHelix(8.0, 24.0, 10.0).Edges[0],  # an approximation: noisy curvature
    }[kind]()
    obj = doc.addObject("Part::Feature", kind.title())
    obj.Shape = shape
    doc.recompute()
    fig = plot.plot_links([(obj, "")])
    assert markers(fig, "curvature maximum").size == 0 and markers(fig, "curvature minimum").size == 0
    assert [t.get_text() for t in fig.axes[0].get_legend().get_texts()] == [kind.title()]
    if kind == "helix":
        assert fig.axes[0].get_ylabel() == "curvature (1/mm)"  # a space curve: unsigned


def test_explicit_marks_replace_the_extremum_marker_there(mdi, doc):
    arch, ellipse, t0, t1 = ellipse_arc(doc)
    edge = arch.Shape.Edges[0]
    (maximum, minimum) = fw.curvature_extrema(edge)
    fig = plot.curvature_plot([(edge, "Arch")], marks=[(0, maximum.u, "Arch: curvature maximum", "v")])
    assert markers(fig, "curvature maximum").size == 0  # marked once, by the caller's mark
    assert markers(fig, "Arch: curvature maximum")[0, 0] == pytest.approx(maximum.s, rel=1e-6)
    assert markers(fig, "curvature minimum")[0, 0] == pytest.approx(minimum.s, rel=1e-6)


def test_png_path_writes_the_file_and_opens_no_tab(mdi, doc, tmp_path):
    import matplotlib.image
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    arch, *_ = ellipse_arc(doc)
    before = list(mdi.subWindowList())
    path = tmp_path / "curvature.png"
    fig = plot.plot_links([(arch, "")], path=path)
    settle()
    assert type(fig.canvas) is FigureCanvasAgg and not hasattr(fig, "fairsplines_subwindow")
    assert mdi.subWindowList() == before
    image = matplotlib.image.imread(str(path))
    assert image.shape[:2] == (450, 800) and (image[..., :3] < 0.9).any()
    assert len(markers(fig, "curvature maximum")) == 1 and len(markers(fig, "curvature minimum")) == 1
