"""Curvature plot: curvature against arc length, one line per curve, with matplotlib.

Axes in FreeCAD's model unit: arc length in mm, curvature in 1/mm (signed for planar
curves). Every interior local maximum and minimum of each curve's curvature is marked.

Three ways to show it, one drawing:
- with a path: drawn with the Agg canvas (no Qt, no pyplot) and written as a PNG, so
  freecadcmd scripts can use it;
- in the FreeCAD GUI: a tab of the main window (a subwindow of its QMdiArea holding a
  matplotlib Qt canvas and its toolbar, which saves to PNG), made the active one;
- else (plain python with a display): a pyplot window.
Importing this module imports neither Qt nor matplotlib: they are loaded when a plot is made.

    from freecad_workbench.gui.plot import curvature_plot
    curvature_plot([(csr, "csr-spline"), (classic, "classic C2")], path="curvature.png")
"""
import numpy as np

import FreeCAD
import Part

from ..analysis import curvature_extrema, curvature_profile

DEFAULT_SAMPLES = 1024
# A curvature extremum is marked when the curvature rises and falls by at least this fraction
# of the curve's largest |curvature| on both sides: the last digits of an arc's or a line's
# constant curvature, or the approximation noise of a helix (2e-4), are no extrema.
EXTREMUM_TOLERANCE = 1e-3
PLOT_TAB = "FairSplinesCurvaturePlot"  # objectName of the widget in every plot tab
FIGURE_SIZE, DPI = (8, 4.5), 100
MAXIMUM_MARKER, MINIMUM_MARKER = "v", "^"  # drawn just above a maximum, just below a minimum
EXTREMUM_MARKER_SIZE = 7


def curvature_plot(edges_with_labels, path=None, n=None, title="Curvature", marks=()):
    """Plot curvature against arc length.

    edges_with_labels: items (edge or curve, label), or bare edges/curves (labelled
    "curve 1", "curve 2", ...). Curvature is signed for planar curves.
    path: write a PNG there (Agg canvas) instead of showing the plot.
    marks: points to mark on the lines, as (index of the curve, parameter u, label, matplotlib
    marker such as "v"), drawn at u's arc length and curvature. The curvature extrema are
    marked anyway (one legend entry "curvature maximum", one "curvature minimum"), except
    where an explicit mark already is.
    Returns the matplotlib Figure. Shown in a tab of the FreeCAD main window, the figure's
    `fairsplines_subwindow` is that tab (a QMdiSubWindow; close() closes it).
    n: samples per curve; None takes the PlotSamples preference (DEFAULT_SAMPLES unless set).
    Raises ValueError when there is nothing to plot.
    """
    from .. import preferences

    n = int(preferences.get("PlotSamples")) if n is None else int(n)
    items = []
    for index, item in enumerate(edges_with_labels, start=1):
        curve, label = item if isinstance(item, tuple) else (item, f"curve {index}")
        profile = curvature_profile(curve, n)
        items.append((profile, str(label), _marked_extrema(curve, profile, n)))
    if not items:
        raise ValueError("nothing to plot: give at least one edge or curve")

    mdi = None if path is not None else _mdi_area()
    if path is not None:
        from matplotlib.backends.backend_agg import FigureCanvasAgg
        from matplotlib.figure import Figure

        fig = Figure(figsize=FIGURE_SIZE, dpi=DPI, layout="tight")
        FigureCanvasAgg(fig)
    elif mdi is not None:
        fig = _tab_figure()
    else:
        import matplotlib.pyplot as plt

        fig = plt.figure(figsize=FIGURE_SIZE, dpi=DPI, layout="tight")
    _draw(fig, items, title, marks)
    if path is not None:
        fig.savefig(str(path))
    elif mdi is not None:
        _show_in_tab(mdi, fig, f"{title}: {_plotted(label for _, label, _ in items)}")
    else:
        fig.show()
    return fig


def _draw(fig, items, title, marks):
    from matplotlib.transforms import offset_copy

    ax = fig.add_subplot(1, 1, 1)
    for profile, label, _ in items:
        ax.plot(profile.s, profile.kappa, label=label, linewidth=1.5)
    for index, u, label, marker in marks:
        profile = items[index][0]
        s, kappa = np.interp(u, profile.u, profile.s), np.interp(u, profile.u, profile.kappa)
        ax.plot([s], [kappa], marker, color="#d42a2a", markersize=9, linestyle="none", label=label)
    # The markers sit beside the point, their tip on the line: above a maximum, below a minimum.
    lift = EXTREMUM_MARKER_SIZE / 2 + 1  # points
    kinds = ((True, MAXIMUM_MARKER, "curvature maximum"), (False, MINIMUM_MARKER, "curvature minimum"))
    for maximum, marker, label in kinds:
        found = [(s, kappa) for index, (_, _, extrema) in enumerate(items) for s, kappa, is_max in extrema
                 if is_max == maximum and not _explicitly_marked(s, index, items, marks)]
        if found:
            s, kappa = np.array(found).T
            ax.plot(s, kappa, marker, color="0.15", markersize=EXTREMUM_MARKER_SIZE, linestyle="none", label=label,
                    transform=offset_copy(ax.transData, fig, y=lift if maximum else -lift, units="points"))
    ax.axhline(0.0, color="0.5", linewidth=0.8)
    ax.set_xlabel("arc length (mm)")
    signed = all(profile.signed for profile, _, _ in items)
    ax.set_ylabel("signed curvature (1/mm)" if signed else "curvature (1/mm)")
    ax.set_title(title)
    ax.grid(True, alpha=0.3)
    ax.margins(y=0.08)  # room for the extremum markers
    ax.legend()


def _explicitly_marked(s, index, items, marks):
    """Whether one of the explicit marks of curve `index` is at arc length s already."""
    profile = items[index][0]
    near = 5e-3 * profile.s[-1]
    return any(i == index and abs(np.interp(u, profile.u, profile.s) - s) <= near for i, u, _, _ in marks)


def _marked_extrema(curve, profile, n):
    """The curvature extrema to mark: [(s, kappa, is_maximum)], by arc length.

    A maximum is a sample where the curvature, since the last extremum (or the start), rose
    by EXTREMUM_TOLERANCE (relative) and then falls by as much before rising above it again;
    minima the other way round. Its place: the one maximum the kernel finds (a parabola fit
    on a finer sampling) on the stretch around the sample where the curvature stays within
    that tolerance of it; where there are none or several (a flat stretch: a kept arc between
    transitions, or noise), the middle of the stretch."""
    kappa, s = profile.kappa, profile.s
    delta = EXTREMUM_TOLERANCE * float(np.abs(kappa).max()) if len(kappa) else 0.0
    if delta == 0.0:
        return []
    turning = _turning_points(kappa, delta)
    if not turning:
        return []
    fine = curvature_extrema(curve, max(2 * n, 2048))
    result = []
    for j, is_max in turning:
        sign = 1.0 if is_max else -1.0
        lo = hi = j  # the stretch around j within delta of kappa[j]
        while lo > 0 and sign * (kappa[j] - kappa[lo - 1]) <= delta:
            lo -= 1
        while hi + 1 < len(kappa) and sign * (kappa[j] - kappa[hi + 1]) <= delta:
            hi += 1
        a, b = s[max(lo - 1, 0)], s[min(hi + 1, len(s) - 1)]
        inside = [e for e in fine if e.maximum == is_max and a <= e.s <= b]
        if len(inside) == 1:
            result.append((inside[0].s, inside[0].kappa, is_max))
        else:  # flat (or noisy) stretch
            middle = 0.5 * (s[lo] + s[hi])
            result.append((middle, float(np.interp(middle, s, kappa)), is_max))
    return result


def _turning_points(kappa, delta):
    """Interior extrema of the samples kappa that rise and fall by at least delta on both
    sides (a zigzag filter): [(index, is_maximum)], alternating."""
    turning, direction, extreme = [], 0, 0
    for i in range(1, len(kappa)):
        k = kappa[i]
        if direction == 0:  # since the start, no swing of delta yet
            if k >= kappa[0] + delta:
                direction, extreme = 1, i
            elif k <= kappa[0] - delta:
                direction, extreme = -1, i
        elif direction * (k - kappa[extreme]) > 0:
            extreme = i
        elif direction * (kappa[extreme] - k) >= delta:
            turning.append((extreme, direction > 0))
            direction, extreme = -direction, i
    return turning


def _plotted(labels, most=4):
    labels = list(labels)
    if len(labels) > most:
        return ", ".join(labels[: most - 1]) + f", and {len(labels) - most + 1} more"
    return ", ".join(labels)


# --- the plot tab in the FreeCAD main window ---------------------------------------------


def _mdi_area():
    """The QMdiArea of the FreeCAD main window, or None outside the GUI."""
    if not FreeCAD.GuiUp:
        return None
    from .qt import QtWidgets

    window = main_window()
    return window.findChild(QtWidgets.QMdiArea) if window is not None else None


def main_window():
    """FreeCAD's main window (see qt.main_window); Qt is imported only here."""
    from .qt import main_window as find

    return find()


def _qt_backend():
    """matplotlib's Qt canvas and toolbar, on the binding the workbench uses (qt.py).
    matplotlib picks an already imported binding (PyQt6, PySide6, PyQt5, PySide2 in that
    order), and qt.py has imported FreeCAD's: PySide2 under Qt5, PySide6 under FreeCAD 1.1."""
    from .qt import BINDING

    from matplotlib.backends import backend_qtagg, qt_compat

    if qt_compat.QT_API != BINDING:
        raise RuntimeError(f"matplotlib took {qt_compat.QT_API}, FreeCAD runs on {BINDING}: a PyQt was imported first")
    return backend_qtagg.FigureCanvasQTAgg, backend_qtagg.NavigationToolbar2QT


def _tab_figure():
    from matplotlib.figure import Figure

    canvas_class, _ = _qt_backend()
    fig = Figure(figsize=FIGURE_SIZE, dpi=DPI, layout="tight")
    canvas_class(fig)
    return fig


def _show_in_tab(mdi, fig, name):
    """Put the figure's canvas with its toolbar into a new subwindow of the MDI area, shown
    maximized (a tab, like FreeCAD's 3D views) and active."""
    from .qt import QtCore, QtGui, QtWidgets

    from . import icon_path

    _, toolbar_class = _qt_backend()
    canvas = fig.canvas
    canvas.get_default_filename = lambda: _file_name(name)  # the toolbar's Save offers it
    widget = QtWidgets.QWidget()
    widget.setObjectName(PLOT_TAB)
    widget.setWindowTitle(name)
    layout = QtWidgets.QVBoxLayout(widget)
    layout.setContentsMargins(0, 0, 0, 0)
    layout.setSpacing(0)
    layout.addWidget(toolbar_class(canvas, widget))
    layout.addWidget(canvas)
    canvas.setFocusPolicy(QtCore.Qt.FocusPolicy.StrongFocus)
    sub = mdi.addSubWindow(widget)  # a new QMdiSubWindow, deleted when closed
    sub.setAttribute(QtCore.Qt.WidgetAttribute.WA_DeleteOnClose)
    sub.setWindowTitle(name)
    sub.setWindowIcon(QtGui.QIcon(icon_path("FairSplines_CurvaturePlot")))
    sub.showMaximized()
    mdi.setActiveSubWindow(sub)
    canvas.draw_idle()
    fig.fairsplines_subwindow = sub


def _file_name(name):
    keep = "".join(c if c.isalnum() or c in "-_." else "_" for c in name.replace(": ", "_").replace(", ", "_"))
    return (keep.strip("_.") or "curvature") + ".png"


def plot_tabs():
    """The open curvature plot tabs of the FreeCAD main window (QMdiSubWindow), oldest first;
    the figure of one is tab.widget().findChild(FigureCanvasQTAgg).figure, or figures()."""
    mdi = _mdi_area()
    if mdi is None:
        return []
    return [sub for sub in mdi.subWindowList() if sub.widget() is not None and sub.widget().objectName() == PLOT_TAB]


def figures():
    """The matplotlib Figures of the open plot tabs, oldest first."""
    if not plot_tabs():
        return []
    canvas_class, _ = _qt_backend()
    return [tab.widget().findChild(canvas_class).figure for tab in plot_tabs()]


def close_plot_tabs():
    """Close every curvature plot tab, and let Qt delete them now."""
    tabs = plot_tabs()
    if not tabs:
        return
    from .qt import QtCore, QtWidgets

    for tab in tabs:
        tab.close()
    QtCore.QCoreApplication.sendPostedEvents(None, QtCore.QEvent.Type.DeferredDelete)
    QtWidgets.QApplication.processEvents()


# --- selections ------------------------------------------------------------------------


def link_edges(links):
    """(edge, label) for selection-style links [(obj, sub)]: the named edge, or every
    edge of a whole object (labelled with the object's Label, plus EdgeN if several)."""
    result = []
    for obj, sub in links:
        if sub:
            shape = Part.getShape(obj, sub, needSubElement=True)
            if not shape.isNull() and shape.ShapeType == "Edge":
                result.append((shape, f"{obj.Label}.{sub}"))
            continue
        edges = Part.getShape(obj).Edges
        for i, edge in enumerate(edges, start=1):
            result.append((edge, obj.Label if len(edges) == 1 else f"{obj.Label}.Edge{i}"))
    return result


def plot_links(links, path=None, n=None):
    """curvature_plot of the edges of selection-style links [(obj, sub)]."""
    return curvature_plot(link_edges(links), path=path, n=n)
