"""Surface fairness analysis on any face (issue 27): principal curvatures at parameters,
continuity across a shape's edges, and a curvature map. Accepts Part faces and shapes of
every kind (Part, PartDesign, Surface, imports); docs/SURFACE_ANALYSIS.md.

Sign convention: convex is positive as seen from the side the face normal points to
(``Face.normalAt``, the face's orientation included). OCCT's ``Face.curvatureAt`` ignores
the orientation and calls a convex sphere negative; the kernel converts
(cpp/kernel/src/surface_analysis.cpp, FaceSurface).

Shapes reach the kernel as BRep text (``exportBrepToString``), which every FreeCAD and
OCCT version writes and reads alike.
"""
from __future__ import annotations

from collections import namedtuple
from typing import Any, Optional

import numpy as np

from . import kernel
from .kernel import InputError, PointsLike, as_choice, as_count, as_real

# The most points one call evaluates (about 1 s of kernel work).
MAX_POINTS = 10_000_000
QUANTITIES = ("gaussian", "mean", "max_abs", "min", "max", "radius")
# Default tolerances of the continuity verdict (docs/SURFACE_ANALYSIS.md).
ANGLE_TOLERANCE = 0.1  # degrees, as Alias's default angular tolerance
CURVATURE_TOLERANCE = 0.02  # relative to the largest normal curvature along the edge

SurfaceCurvature = namedtuple("SurfaceCurvature", "k1 k2 gaussian mean dir1 dir2 normal points umbilic degenerate")
SurfaceCurvature.__module__ = "freecad_workbench"
SurfaceCurvature.__doc__ = (
    "Curvature at N points of a face (numpy arrays): principal curvatures k1 >= k2 (1/length, convex positive "
    "as seen from the face normal), gaussian = k1 k2, mean = (k1 + k2) / 2, unit principal directions dir1, "
    "dir2 (N, 3) with dir1 x dir2 = normal, the unit face normal (Face.normalAt's) and the surface points; "
    "umbilic: k1 = k2 there (dir1 is then the unit u-direction); degenerate: the point is singular (a sphere's "
    "pole) and the values are the limit from inside the face."
)
EdgeContinuity = namedtuple(
    "EdgeContinuity",
    "edge faces kind continuity gap angle curvature_jump curvature_jump_abs curvature_scale "
    "gap_point angle_point curvature_point gap_parameter angle_parameter curvature_parameter samples")
EdgeContinuity.__module__ = "freecad_workbench"
EdgeContinuity.__doc__ = (
    "The continuity of one edge: edge ('Edge3') and faces (['Face1', 'Face2'], one for a seam or a boundary) by "
    "FreeCAD's names; kind 'shared', 'seam', 'boundary', 'free' (no face), 'degenerate' or 'non-manifold'; "
    "continuity 'gap', 'G0', 'G1', 'G2', 'boundary', 'free' or 'degenerate'; gap (largest distance between the "
    "sides and the edge), angle (largest angle between the normals, degrees), curvature_jump (largest jump of "
    "normal curvature across the edge and at 45 degrees to it, relative to curvature_scale, the largest normal "
    "curvature along the edge), "
    "curvature_jump_abs (1/length); the worst points (FreeCAD Vectors) and the edge's parameters there; samples: "
    "evaluations made."
)
CurvatureMap = namedtuple("CurvatureMap", "quantity points triangles values face face_ranges normals")
CurvatureMap.__module__ = "freecad_workbench"
CurvatureMap.__doc__ = (
    "A triangulation of a shape's faces coloured by a quantity: points (N, 3), triangles (M, 3) of point "
    "indices counter-clockwise about the face normal, values (N,) of the quantity (1/length, 1/length^2 for "
    "gaussian, length for radius), face (M,) the face (from 1, 'Face<i>') of each triangle, face_ranges "
    "(faces, 2) the (min, max) of each face, normals (N, 3) the face's unit normal at each point, evaluated "
    "exactly (the face's orientation included; at a singular point, its neighbours' mean)."
)


def _brep(shape: Any, name: str) -> str:
    import Part

    if not isinstance(shape, Part.Shape):
        raise InputError(f"{name} must be a Part shape or face, got {type(shape).__name__}")
    if shape.isNull():
        raise InputError(f"{name} is a null shape")
    return shape.exportBrepToString()


def _uv(uv) -> np.ndarray:
    if isinstance(uv, (str, bytes)) or uv is None:
        raise InputError(f"uv must be an (N, 2) array of surface parameters, got {uv!r}")
    try:
        array = np.asarray(uv, dtype=float)
    except (TypeError, ValueError):
        raise InputError(f"uv must be an (N, 2) array of surface parameters, got {uv!r}") from None
    if array.ndim == 1 and array.shape == (2,):
        array = array.reshape(1, 2)
    if array.ndim != 2 or array.shape[1] != 2:
        raise InputError(f"uv must be an (N, 2) array of surface parameters, got shape {array.shape}")
    if len(array) == 0:
        raise InputError("uv is empty: no points to evaluate")
    if len(array) > MAX_POINTS:
        raise InputError(f"uv has {len(array)} points, more than {MAX_POINTS}: split the call")
    return array  # the kernel names a point that is not finite, in its one pass over uv


def surface_curvature(face: Any, uv: PointsLike, threads: Optional[int] = None) -> SurfaceCurvature:
    """Principal curvatures, Gaussian and mean curvature, principal directions and normal at
    the parameters uv (N, 2) of a Part.Face (or a shape of one face), in one kernel call.

    Convex is positive as seen from Face.normalAt's side. Raises InputError for bad uv (wrong
    shape, NaN, more than 10% outside the face's parameter range), where the surface cannot
    be evaluated, or at a singular point without a limit (a cone's apex), naming the point.
    threads: at most this many threads share a call of 32,768 points or more on a B-spline
    or Bezier face (None: one a core, at most 8; 1: this thread only); the values are the
    same bits whatever it is."""
    count = 0 if threads is None else as_count(threads, "threads", 1, 64)
    # Views of one (16, N) block the kernel wrote in place (cpp/python/bind_surface_analysis.cpp).
    k1, k2, gaussian, mean, dir1, dir2, normal, points, state = kernel.surface_curvature(
        _brep(face, "face"), _uv(uv), count)
    return SurfaceCurvature(k1, k2, gaussian, mean, dir1, dir2, normal, points, state == 1, state == 2)


def edge_continuity(shape: Any, samples: Optional[int] = None, gap_tolerance: Optional[float] = None,
                    angle_tolerance: float = ANGLE_TOLERANCE,
                    curvature_tolerance: float = CURVATURE_TOLERANCE) -> list[EdgeContinuity]:
    """One EdgeContinuity per edge of the shape, in FreeCAD's order (Edge1, Edge2, ...).

    The verdict: 'gap' where the sides part by more than gap_tolerance (default: twice the
    edge's own tolerance or 1e-6 of the shape's size, whichever is larger), else 'G0' where
    the normals differ by more than angle_tolerance degrees (0.1), else 'G1' where the
    relative curvature jump exceeds curvature_tolerance (0.02), else 'G2'. samples: samples
    inside each span of the edge (between its knots, its pcurves' knots and the faces' knot
    lines); None adapts (4 a span, at least 16 an edge, more where the edge turns). The
    worst sample of each measure is then refined by golden-section search."""
    per_span = 0 if samples is None else as_count(samples, "samples", 1, 1000)
    gap = -1.0 if gap_tolerance is None else as_real(gap_tolerance, "gap_tolerance", minimum=0)
    records = kernel.edge_continuity(_brep(shape, "shape"), per_span, gap,
                                     as_real(angle_tolerance, "angle_tolerance", minimum=0),
                                     as_real(curvature_tolerance, "curvature_tolerance", minimum=0))
    import FreeCAD

    def vector(p):
        return FreeCAD.Vector(*map(float, p))

    return [EdgeContinuity(f"Edge{r['edge']}", [f"Face{i}" for i in r["faces"]], r["kind"], r["continuity"],
                           r["gap"], r["angle"], r["curvature_jump"], r["curvature_jump_abs"], r["curvature_scale"],
                           vector(r["gap_point"]), vector(r["angle_point"]), vector(r["curvature_point"]),
                           r["gap_parameter"], r["angle_parameter"], r["curvature_parameter"], r["samples"])
            for r in records]


def curvature_map(shape: Any, quantity: str = "gaussian", deflection: Optional[float] = None,
                  fraction: float = 0.05, levels: int = 3) -> CurvatureMap:
    """A triangulation of the shape's faces with the quantity at every vertex, evaluated on the
    exact surfaces: 'gaussian', 'mean', 'max_abs' (max |k|), 'min' (k2), 'max' (k1) or
    'radius' (1 / max |k|, capped at 1000 x the shape's size where flat).

    deflection: the mesh's chordal deflection (default 1e-3 of the shape's size). Then edges
    whose values differ by more than `fraction` of the range over the shape are split, up to
    `levels` times, so that colours do not alias on small fillets."""
    quantity = as_choice(quantity, "quantity", QUANTITIES)
    d = 0.0 if deflection is None else as_real(deflection, "deflection", positive=True)
    f = as_real(fraction, "fraction", positive=True)
    if f > 1.0:
        raise InputError(f"fraction must be at most 1, got {f:g}")
    levels = as_count(levels, "levels", 0, 8)
    brep = _brep(shape, "shape")
    points, triangles, values, face, ranges, normals = kernel.curvature_map(brep, quantity, d, f, levels)
    return CurvatureMap(quantity, points, triangles, values, face, ranges, normals)
