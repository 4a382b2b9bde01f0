"""G1 and G2 blends between two faces along their edges (issue 29; docs/FACE_BLENDS.md).

``blend_faces(face_a, edge_a, face_b, edge_b)`` returns a Part.BSplineSurface that meets each
face along the whole edge: in position and normal (G1), and in normal curvature in every
direction (G2). Where the edge is an isoparametric boundary of a B-spline, Bezier or analytic
face (or a straight edge of a plane), the match is exact to rounding: the kernel takes the
cross-boundary derivatives from the face's homogeneous poles (cpp/kernel/src/face_blend.cpp).
Elsewhere (trimmed edges, seams, other surfaces) the face is sampled along the edge and its
position, normal and normal curvature fitted until the tolerances hold between the samples
(cpp/kernel/src/face_blend_fitted.cpp); the report says which way each side was done.
The free magnitudes of the derivatives are chosen for fair cross sections (fewest curvature
extrema, then least variation), and the report gives the errors as OCCT measures them on the
returned surface (``blend_errors``).

Faces reach the kernel as BRep text; an edge is a Part.Edge of the face, its number (from 1,
as ``Face.Edges``) or its name ('Edge2'). A basic shape of ``fw.shapes`` (SphereZone, Cylinder,
Cone, Torus) is one side too: its exact analytic face, with edge 'start' or 'end' (the rim at
the first or last height, latitude or tube angle).
"""
from __future__ import annotations

import math
from collections import namedtuple
from typing import Any, Optional

import numpy as np

from . import kernel, shapes
from .kernel import InputError, as_choice, as_count, as_flag, as_real, surface_to_part

# The tolerances (docs/FACE_BLENDS.md section 4).
GAP_TOLERANCE = 1e-7  # relative to the blend's size
ANGLE_TOLERANCE = 1e-4  # degrees
CURVATURE_TOLERANCE = 1e-4  # relative to the curvature scale
REFEREE_SAMPLES = 101

FaceBlendReport = namedtuple("FaceBlendReport", "sides sections errors valid evaluations size")
FaceBlendReport.__module__ = "freecad_workbench"
FaceBlendReport.__doc__ = (
    "The report of blend_faces: sides (two dicts, a then b: method 'exact' or 'fitted', reason (why fitted), "
    "surface_type, isoparametric 'u', 'v', 'line' or 'none' (fitted), alpha and beta of "
    "v(s) = v0 - alpha s + beta s^2 / 2, scale = alpha over the default magnitude, bend = beta / alpha, rational, "
    "closed, continuity 1 or 2; fitted sides also spans, refinements, samples and the fit's worst fit_gap (of "
    "both edges' box), "
    "fit_angle (degrees), fit_curvature (of the curvature scale) between its samples); sections (one dict per "
    "cross section: u in [0, 1], monotone (certified), curvature_extrema (certificate), sampled_extrema, "
    "kappa_min, kappa_max, variation, reason); "
    "errors (two dicts from blend_errors, a then b, or None when measure=False); valid (BRepCheck of the blend's "
    "face); evaluations (candidates judged by the fairness search); size (diagonal of the blend's pole box)."
)

_SHAPE_TYPES = (shapes.SphereZone, shapes.Cylinder, shapes.Cone, shapes.Torus)


def _basic_face(shape) -> Any:
    """The exact analytic face of a basic shape, in its frame (u around the axis, v along the profile)."""
    import FreeCAD
    import Part

    if isinstance(shape, shapes.SphereZone):
        surface = Part.Sphere()
        surface.Radius = shape.radius
        u, v = shape.longitudes, shape.latitudes
    elif isinstance(shape, shapes.Cylinder):
        surface = Part.Cylinder()
        surface.Radius = shape.radius
        u, v = shape.angles, shape.heights
    elif isinstance(shape, shapes.Cone):
        semi = math.atan(shape.slope)
        if not shape.radius0 > 0:
            raise InputError("a cone side needs radius0 > 0")
        surface = Part.Cone()
        surface.SemiAngle = semi
        surface.Radius = shape.radius0
        u, v = shape.angles, np.asarray(shape.heights) / math.cos(semi)
    else:
        surface = Part.Toroid()
        surface.MajorRadius = shape.major_radius
        surface.MinorRadius = shape.minor_radius
        u, v = shape.angles_u, shape.angles_v
    x, y, z = shape.x_axis, shape.y_axis, shape.axis
    c = shape.center
    matrix = FreeCAD.Matrix(x[0], y[0], z[0], c[0], x[1], y[1], z[1], c[1], x[2], y[2], z[2], c[2], 0, 0, 0, 1)
    surface.transform(matrix)
    face = Part.Face(Part.RectangularTrimmedSurface(surface, float(u[0]), float(u[-1]), float(v[0]), float(v[-1])))
    return face, surface, (float(u[0]), float(u[-1])), (float(v[0]), float(v[-1]))


def _side(face: Any, edge: Any, name: str) -> tuple[Any, int]:
    """(the Part.Face, the edge's number in face.Edges from 1)."""
    import Part

    if isinstance(face, _SHAPE_TYPES):
        end = as_choice(edge, f"edge_{name}", ("start", "end"))
        part_face, surface, (u0, u1), (v0, v1) = _basic_face(face)
        target = surface.value(0.5 * (u0 + u1), v0 if end == "start" else v1)
        for i, e in enumerate(part_face.Edges):
            if e.distToShape(Part.Vertex(target))[0] <= 1e-9 * max(1.0, part_face.BoundBox.DiagonalLength):
                return part_face, i + 1
        raise InputError(f"edge_{name}: the basic shape's {end} rim was not found")
    if not isinstance(face, Part.Shape) or face.isNull():
        raise InputError(f"face_{name} must be a Part face or a basic shape of fw.shapes, got {type(face).__name__}")
    faces = face.Faces
    if len(faces) != 1:
        raise InputError(f"face_{name} must be one face, got a shape with {len(faces)} faces")
    face = faces[0]
    edges = face.Edges
    if isinstance(edge, str) and edge.startswith("Edge"):
        try:
            edge = int(edge[4:])
        except ValueError:
            raise InputError(f"edge_{name} {edge!r} is not an edge name such as 'Edge1'") from None
    if isinstance(edge, (int, np.integer)) and not isinstance(edge, bool):
        if not 1 <= edge <= len(edges):
            raise InputError(f"edge_{name} is edge {edge} of face_{name}, which has {len(edges)} edges")
        return face, int(edge)
    if not isinstance(edge, Part.Shape) or edge.isNull() or len(edge.Edges) != 1:
        raise InputError(f"edge_{name} must be an edge of face_{name}, its number from 1 or its name, got {edge!r}")
    edge = edge.Edges[0]
    for i, e in enumerate(edges):
        if e.isSame(edge):
            return face, i + 1
    size = max(face.BoundBox.DiagonalLength, 1e-300)
    for i, e in enumerate(edges):
        points = [edge.valueAt(edge.FirstParameter + f * (edge.LastParameter - edge.FirstParameter))
                  for f in (0.0, 0.37, 0.5, 1.0)]
        if all(e.distToShape(Part.Vertex(p))[0] <= 1e-9 * size for p in points):
            return face, i + 1
    raise InputError(f"edge_{name} is not an edge of face_{name}")


def _fraction(value, name, default):
    return default if value is None else as_real(value, name)


def _continuities(continuity: Any) -> tuple[int, int]:
    """(edge a's, edge b's) continuity as 1 (G1) or 2 (G2), from "G1", "G2" or a pair of them."""
    if isinstance(continuity, (tuple, list)):
        if len(continuity) != 2:
            raise InputError(f"continuity must be 'G1', 'G2' or a pair of them (edge a's, edge b's), "
                             f"got {continuity!r}")
        pair = (as_choice(continuity[0], "edge a's continuity", ("G1", "G2")),
                as_choice(continuity[1], "edge b's continuity", ("G1", "G2")))
    else:
        g = as_choice(continuity, "continuity", ("G1", "G2"))
        pair = (g, g)
    return tuple(1 if g == "G1" else 2 for g in pair)


def blend_faces(face_a: Any, edge_a: Any, face_b: Any, edge_b: Any, continuity: Any = "G2", flip: bool = False,
                start: Optional[float] = None, end: Optional[float] = None, sections: int = 13,
                scale_a: Optional[float] = None, scale_b: Optional[float] = None,
                measure: bool = True) -> tuple[Any, FaceBlendReport]:
    """(Part.BSplineSurface, FaceBlendReport): the G1 or G2 blend from face_a along edge_a to
    face_b along edge_b (docs/FACE_BLENDS.md); continuity "G1", "G2" or a pair for the two edges,
    e.g. ("G2", "G1") (across the blend: degree 5 for G2 both, 4 for G2 and G1, 3 for G1 both).
    u runs along the edges in [0, 1] (edge_a's
    direction; flip=True pairs edge_a's start with edge_b's end), v from edge_a (0) to edge_b (1).
    start, end: the part of each edge covered, fractions of its parameter range (default 0, 1).
    scale_a, scale_b > 0 fix the cross-boundary derivative magnitudes as multiples of the default
    (mean chord over mean cross-boundary speed); None: chosen for fair sections. measure=False
    skips the OCCT referee of the report (errors None).
    Raises InputError naming the problem: an edge not on its face, a degenerate edge, a fitted
    edge (not an isoparametric boundary: trimmed, a seam) whose fit spends its budget, faces that
    touch, a blend that would cross itself, or a result BRepCheck calls invalid."""
    ka, kb = _continuities(continuity)
    flip = as_flag(flip, "flip")
    measure = as_flag(measure, "measure")
    t0, t1 = _fraction(start, "start", 0.0), _fraction(end, "end", 1.0)
    if not 0.0 <= t0 < t1 <= 1.0:
        raise InputError(f"start and end must satisfy 0 <= start < end <= 1, got {t0}, {t1}")
    count = as_count(sections, "sections", minimum=2, maximum=1000)
    sa = 0.0 if scale_a is None else as_real(scale_a, "scale_a", positive=True)
    sb = 0.0 if scale_b is None else as_real(scale_b, "scale_b", positive=True)
    fa, ia = _side(face_a, edge_a, "a")
    fb, ib = _side(face_b, edge_b, "b")
    surface, raw = kernel.blend_faces(fa.exportBrepToString(), ia, fb.exportBrepToString(), ib,
                                      ka, flip, t0, t1, count, sa, sb, kb)
    blend = surface_to_part(surface)
    face = blend.toShape()
    valid = bool(face.isValid())
    if not valid:
        raise InputError("the blend's face is not valid by BRepCheck")
    errors = None
    if measure:
        errors = (blend_errors(blend, fa, fa.Edges[ia - 1], 0.0, t0, t1, raw["size"]),
                  blend_errors(blend, fb, fb.Edges[ib - 1], 1.0, t0, t1, raw["size"]))
    report = FaceBlendReport(tuple(raw["sides"]), list(raw["sections"]), errors, valid, raw["evaluations"],
                             raw["size"])
    return blend, report


def _normal_curvature(surface, u, v, d, n):
    """II(d, d) / I(d, d) of the tangent direction d (3-vector) at (u, v), against the unit normal n."""
    su, sv = (np.array(surface.getDN(u, v, 1, 0)), np.array(surface.getDN(u, v, 0, 1)))
    suu, suv, svv = (np.array(surface.getDN(u, v, 2, 0)), np.array(surface.getDN(u, v, 1, 1)),
                     np.array(surface.getDN(u, v, 0, 2)))
    jacobian = np.c_[su, sv]
    (a, b), *_ = np.linalg.lstsq(jacobian, d, rcond=None)
    tangent = a * su + b * sv
    return float(np.dot(a * a * suu + 2 * a * b * suv + b * b * svv, n) / np.dot(tangent, tangent))


def _vec(v) -> np.ndarray:
    return np.array([v.x, v.y, v.z], dtype=float)


def blend_errors(blend: Any, face: Any, edge: Any, s: Optional[float], start: float = 0.0, end: float = 1.0,
                 size: Optional[float] = None, samples: int = REFEREE_SAMPLES) -> dict:
    """The match of a blend surface's boundary v = s (0 or 1; None: where the edge's points project) with a
    face along its edge, as OCCT
    evaluates both at `samples` points of the edge's part [start, end]: gap (largest distance of
    the face and of the blend from the edge, relative to size: the blend's size by default), angle
    between the normals (degrees), and the jumps of normal curvature across the edge and at 45
    degrees to it, relative to the curvature scale max(largest |normal curvature| of both sides
    along the edge, 1 / size). within: the issue's tolerances hold (curvature only counts for G2;
    compare curvature_jump yourself)."""
    import Part

    if not all(hasattr(blend, name) for name in ("getDN", "parameter", "normal")):
        raise InputError(f"blend must be a Part surface, got {type(blend).__name__}")
    if not isinstance(face, Part.Face) or face.isNull():
        raise InputError(f"face must be a Part.Face, got {type(face).__name__}")
    if not isinstance(edge, Part.Edge) or edge.isNull():
        raise InputError(f"edge must be a Part.Edge, got {type(edge).__name__}")
    s = None if s is None else as_real(s, "s")
    start, end = as_real(start, "start"), as_real(end, "end")
    samples = as_count(samples, "samples", minimum=2, maximum=100_000)
    surface = face.Surface
    if size is None:
        size = blend.toShape().BoundBox.DiagonalLength
    f0, f1 = edge.FirstParameter, edge.LastParameter
    gap = angle = 0.0
    across, oblique, scale = [], [], 0.0
    for t in np.linspace(start, end, samples):
        p = edge.valueAt(f0 + t * (f1 - f0))
        uf, vf = surface.parameter(p)
        ub, vb = blend.parameter(p)
        if s is not None:
            vb = s
        pf, pb = _vec(surface.value(uf, vf)), _vec(blend.value(ub, vb))
        gap = max(gap, float(np.linalg.norm(pf - _vec(p))), float(np.linalg.norm(pb - _vec(p))))
        nf, nb = _vec(surface.normal(uf, vf)), _vec(blend.normal(ub, vb))
        angle = max(angle, math.degrees(math.atan2(np.linalg.norm(np.cross(nf, nb)), abs(np.dot(nf, nb)))))
        tangent = _vec(edge.tangentAt(f0 + t * (f1 - f0)))
        tangent /= np.linalg.norm(tangent)
        cross = np.cross(nf, tangent)
        diagonal = (tangent + cross) / math.sqrt(2.0)
        values = []
        for d in (tangent, cross, diagonal):
            values.append((_normal_curvature(surface, uf, vf, d, nf), _normal_curvature(blend, ub, vb, d, nf)))
        scale = max(scale, *(abs(x) for pair in values for x in pair))
        across.append(abs(values[1][0] - values[1][1]))
        oblique.append(abs(values[2][0] - values[2][1]))
    scale = max(scale, 1.0 / size)
    jump_across, jump_oblique = max(across) / scale, max(oblique) / scale
    return {
        "gap": gap / size, "gap_abs": gap, "angle": angle, "curvature_jump": max(jump_across, jump_oblique),
        "curvature_jump_across": jump_across, "curvature_jump_45": jump_oblique, "curvature_scale": scale,
        "samples": samples,
        "within": gap / size <= GAP_TOLERANCE and angle <= ANGLE_TOLERANCE,
    }


__all__ = ["FaceBlendReport", "blend_faces", "blend_errors"]
