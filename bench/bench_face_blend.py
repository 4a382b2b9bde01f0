"""Benchmark of G2 face blends (issue 29), against its baselines in one run, on the same gap
between two bicubic B-spline faces (different knot vectors):

- fw.blend_faces (G2): time (the whole call without the referee, and the kernel alone), and its
  errors measured by the OCCT referee fw.blend_errors (101 points per edge: gap relative to the
  size, normal angle in degrees, jump of normal curvature across and at 45 degrees relative to
  the curvature scale);
- FreeCAD's Surface::Filling with G2 (BoundaryOrder 3 = GeomAbs_G2) on the two edges, closed by two straight
  edges (C0): its recompute time and the same errors;
- the CurvesWB-style baseline re-created with OCCT calls: 20 exact G2 cross sections (the
  blend's own, so the sections themselves are exact) and a surface interpolating them
  (Part.BSplineSurface.interpolate through 20 x 40 points), as BlendSurface's Gordon surface:
  its errors between the sections.

Ratios printed: time of Filling over the blend, and each error of Filling and of the baseline
over the blend's.

    /usr/bin/python3 bench/bench_face_blend.py [smoke]
"""
import math
import os
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))

import numpy as np  # noqa: E402

import freecad_workbench as fw  # noqa: E402
from freecad_workbench import kernel  # noqa: E402
import FreeCAD  # noqa: E402
import Part  # noqa: E402

from bench_handover import best  # noqa: E402

V = FreeCAD.Vector


def bicubic(nu, nv, y0, interior, lift, flip=False):
    poles = [[V(2.0 * i / (nu - 1), y0 + 1.0 * j / (nv - 1),
                lift + 0.15 * math.sin(1.3 * i + 0.7 * j) * (j / (nv - 1)) ** 2) for j in range(nv)]
             for i in range(nu)]
    if flip:
        poles = [row[::-1] for row in poles]
    knots = [0.0] + interior + [1.0]
    mults = [4] + [1] * len(interior) + [4]
    s = Part.BSplineSurface()
    s.buildFromPolesMultsKnots(poles, mults, [4, 4], knots, [0.0, 1.0], False, False, 3, 3)
    return s.toShape()


def faces():
    a = bicubic(7, 4, 0.0, [0.2, 0.5, 0.8], 0.0)
    b = bicubic(6, 4, 1.8, [0.35, 0.65], 0.4, flip=True)
    edge_a = [e for e in a.Edges if abs(e.CenterOfMass.y - 1.0) < 1e-9][0]
    edge_b = [e for e in b.Edges if abs(e.CenterOfMass.y - 1.8) < 1e-9][0]
    return a, edge_a, b, edge_b


def errors(surface, a, ea, b, eb, size, s_a, s_b):
    return [fw.blend_errors(surface, a, ea, s_a, size=size), fw.blend_errors(surface, b, eb, s_b, size=size)]


def worst(errs):
    return {k: max(e[k] for e in errs) for k in ("gap", "angle", "curvature_jump")}


def filling(a, ea, b, eb, order=3):
    """Surface::Filling on the gap; order is FreeCAD's BoundaryOrder, read as OCCT's GeomAbs_Shape
    (FeatureFilling.cpp casts it): 0 C0, 1 G1, 2 C1, 3 G2."""
    import Surface  # noqa: F401  (registers Surface::Filling)

    doc = FreeCAD.newDocument("bench_face_blend")
    fa = doc.addObject("Part::Feature", "A")
    fa.Shape = a
    fb = doc.addObject("Part::Feature", "B")
    fb.Shape = b
    ia = [i for i, e in enumerate(a.Edges) if e.isSame(ea)][0] + 1
    ib = [i for i, e in enumerate(b.Edges) if e.isSame(eb)][0] + 1
    lines = []
    for k in (0, 1):
        line = doc.addObject("Part::Feature", f"L{k}")
        pa = ea.Vertexes[k].Point
        pb = min((v.Point for v in eb.Vertexes), key=lambda p: (p - pa).Length)
        line.Shape = Part.makeLine(pa, pb)
        lines.append(line)
    fill = doc.addObject("Surface::Filling", "Filling")
    fill.BoundaryEdges = [(fa, f"Edge{ia}"), (lines[0], "Edge1"), (fb, f"Edge{ib}"), (lines[1], "Edge1")]
    fill.BoundaryFaces = ["Face1", "", "Face1", ""]
    fill.BoundaryOrder = [order, 0, order, 0]
    t0 = time.perf_counter()
    doc.recompute()
    seconds = time.perf_counter() - t0
    face = fill.Shape.Faces[0]
    FreeCAD.closeDocument(doc.Name)
    filling.tolerance = max(e.Tolerance for e in face.Edges)  # how far OCCT let the surface leave its edges
    return face.Surface, seconds


def gordon_like(blend, sections=20, points=40):
    """CurvesWB's BlendSurface re-created: exact G2 sections at 20 values of u, and a surface
    interpolating them (Part.BSplineSurface.interpolate)."""
    grid = []
    for u in np.linspace(0.0, 1.0, sections):
        grid.append([blend.value(float(u), float(s)) for s in np.linspace(0.0, 1.0, points)])
    surface = Part.BSplineSurface()
    t0 = time.perf_counter()
    surface.interpolate(grid)
    return surface, time.perf_counter() - t0


def main(smoke):
    a, ea, b, eb = faces()
    repeats = 1 if smoke else 5
    blend, report = fw.blend_faces(a, ea, b, eb)
    size = report.size
    ia = [i for i, e in enumerate(a.Edges) if e.isSame(ea)][0] + 1
    ib = [i for i, e in enumerate(b.Edges) if e.isSame(eb)][0] + 1
    brep_a, brep_b = a.exportBrepToString(), b.exportBrepToString()
    whole = best(lambda: fw.blend_faces(a, ea, b, eb, measure=False), repeats, sample=0.05)
    core = best(lambda: kernel.blend_faces(brep_a, ia, brep_b, ib), repeats, sample=0.05)
    ours = worst(report.errors)
    print("G2 face blend between two bicubic B-spline faces (7 and 6 poles along, different knots):")
    print(f"  fw.blend_faces      {whole * 1e3:8.2f} ms   kernel alone {core * 1e3:8.2f} ms   (target 50 ms)")
    print(f"    gap {ours['gap']:.2e}   angle {ours['angle']:.2e} deg   curvature jump {ours['curvature_jump']:.2e}")
    extrema = [s["curvature_extrema"] for s in report.sections]
    monotone = sum(s["monotone"] for s in report.sections)
    print(f"    sections: {monotone}/{len(extrema)} certified monotone, curvature extrema {extrema}")

    fill_surface, fill_seconds = filling(a, ea, b, eb)
    theirs = worst(errors(fill_surface, a, ea, b, eb, size, None, None))
    print(f"  Surface::Filling G2 {fill_seconds * 1e3:8.2f} ms   ratio Filling / blend {fill_seconds / whole:8.1f}"
          f"   (its edges' tolerance {filling.tolerance:.2g})")
    print(f"    gap {theirs['gap']:.2e}   angle {theirs['angle']:.2e} deg   "
          f"curvature jump {theirs['curvature_jump']:.2e}")
    g0 = worst(errors(filling(a, ea, b, eb, order=0)[0], a, ea, b, eb, size, None, None))
    if all(abs(g0[k] - theirs[k]) <= 1e-12 * max(theirs[k], 1e-300) for k in theirs):
        print("    (BoundaryOrder 0 gives the same errors: Filling's G2 boundary constraint had no effect here)")
    else:
        print(f"    (BoundaryOrder 0, C0: gap {g0['gap']:.2e}   angle {g0['angle']:.2e} deg   "
              f"curvature jump {g0['curvature_jump']:.2e})")
    floor = 1e-16
    print("    error ratios Filling / blend: " + "   ".join(
        f"{k} {theirs[k] / max(ours[k], floor):.1e}" for k in ("gap", "angle", "curvature_jump")) +
        "   (target >= 1000)")

    gordon, gordon_seconds = gordon_like(blend, points=20 if smoke else 40)
    between = worst(errors(gordon, a, ea, b, eb, size, None, None))
    print(f"  20 sections + interpolating surface (CurvesWB-style) {gordon_seconds * 1e3:8.2f} ms (interpolation)")
    print(f"    gap {between['gap']:.2e}   angle {between['angle']:.2e} deg   "
          f"curvature jump {between['curvature_jump']:.2e}")
    print("    error ratios baseline / blend: " + "   ".join(
        f"{k} {between[k] / max(ours[k], floor):.1e}" for k in ("gap", "angle", "curvature_jump")))


if __name__ == "__main__":
    main(len(sys.argv) > 1 and sys.argv[1] == "smoke")
