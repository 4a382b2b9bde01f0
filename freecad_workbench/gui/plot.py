"""Curvature plot: curvature against arc length, one line per curve, with matplotlib.

Headless: with a path it draws with the Agg canvas (no window, no pyplot) and writes a
PNG, so freecadcmd scripts can use it. Without a path it opens a pyplot window (in the
FreeCAD GUI: a Qt window). matplotlib is imported only when a plot is made.

    from freecad_workbench.gui.plot import curvature_plot
    curvature_plot([(csr, "csr-spline"), (classic, "classic C2")], path="curvature.png")
"""
import numpy as np

import Part

from ..analysis import curvature_profile

DEFAULT_SAMPLES = 1024


def curvature_plot(edges_with_labels, path=None, n=DEFAULT_SAMPLES, title="Curvature", marks=()):
    """Plot curvature against arc length.

    edges_with_labels: items (edge or curve, label), or bare edges/curves (labelled
    "curve 1", "curve 2", ...). Curvature is signed for planar curves.
    path: write a PNG there (Agg backend) instead of showing a window.
    marks: points to mark on the lines, as (index of the curve, parameter u, label, matplotlib
    marker such as "v"), drawn at u's arc length and curvature.
    Returns the matplotlib Figure.
    """
    items = []
    for index, item in enumerate(edges_with_labels, start=1):
        curve, label = item if isinstance(item, tuple) else (item, f"curve {index}")
        items.append((curvature_profile(curve, n), str(label)))
    if not items:
        raise ValueError("nothing to plot: give at least one edge or curve")

    if path is not None:
        from matplotlib.backends.backend_agg import FigureCanvasAgg
        from matplotlib.figure import Figure

        fig = Figure(figsize=(8, 4.5), dpi=100)
        FigureCanvasAgg(fig)
    else:
        import matplotlib.pyplot as plt

        fig = plt.figure(figsize=(8, 4.5), dpi=100)
    ax = fig.add_subplot(1, 1, 1)
    for profile, label in items:
        ax.plot(profile.s, profile.kappa, label=label, linewidth=1.5)
    for index, u, label, marker in marks:
        profile = items[index][0]
        s, kappa = np.interp(u, profile.u, profile.s), np.interp(u, profile.u, profile.kappa)
        ax.plot([s], [kappa], marker, color="#d42a2a", markersize=9, linestyle="none", label=label)
    ax.axhline(0.0, color="0.5", linewidth=0.8)
    ax.set_xlabel("arc length")
    signed = all(profile.signed for profile, _ in items)
    ax.set_ylabel("signed curvature" if signed else "curvature")
    ax.set_title(title)
    ax.grid(True, alpha=0.3)
    ax.legend()
    fig.tight_layout()
    if path is not None:
        fig.savefig(str(path))
    else:
        fig.show()
    return fig


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


def plot_links(links, path=None, n=DEFAULT_SAMPLES):
    """curvature_plot of the edges of selection-style links [(obj, sub)]."""
    return curvature_plot(link_edges(links), path=path, n=n)
