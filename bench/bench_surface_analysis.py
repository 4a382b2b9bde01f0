"""Python benchmark of surface analysis (issue 27), each against its baseline in one run:

- fw.surface_curvature on N points of a bicubic B-spline face (7 x 7 knot spans) against a
  Python loop over Face.curvatureAt at the same points, interleaved runs, best and median:
  on every core (the default) and on one (threads=1); and the kernel binding alone (the call
  without the BRep export of the face), in points per second;
- fw.curvature_map of a torus against the Mesh workbench's curvature (Mesh.getCurvaturePerVertex)
  on a meshing of the same face: time, and the error of each against the closed form;
- fw.curvature_map of 10 filleted boxes (260 faces) meshed to 0.001 mm: build time;
- the curvature map as the GUI draws it (gui/curvature_map.CurvatureMapNode, its coin nodes
  built without a 3D view) on 4 filleted boxes (104 faces) at about 10^5 vertices: built
  (meshed, evaluated, handed to coin) and recoloured after a range change;
- fw.edge_continuity on a shape of about 500 edges (10 filleted boxes) and on a C2 blend
  shell of B-spline faces, in seconds per call.

    /usr/bin/python3 bench/bench_surface_analysis.py [smoke]

(smoke: N = 2000 and one filleted box, for `make bench-smoke`.)
"""
import gc
import itertools
import math
import os
import statistics
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


def bicubic_face():
    n = 10  # 10 x 10 poles, 7 x 7 spans
    poles = [[V(i, j, 0.5 * math.sin(0.9 * i) * math.cos(0.7 * j) + 0.02 * i * j) for j in range(n)] for i in range(n)]
    knots = list(range(n - 2))
    mults = [4] + [1] * (n - 4) + [4]
    s = Part.BSplineSurface()
    s.buildFromPolesMultsKnots(poles, mults, mults, knots, knots, False, False, 3, 3)
    return Part.Face(s)


def interleaved(calls, repeats):
    """(best, median, first) seconds of each function's calls, the functions taking turns
    (the machine is shared: its load moves between runs), with the garbage collector off;
    first: the first call, a warm-up (its results land in fresh memory)."""
    first = []
    for f in calls:
        t0 = time.perf_counter()
        f()
        first.append(time.perf_counter() - t0)
    was_enabled = gc.isenabled()
    gc.collect()
    gc.disable()
    try:
        times = [[] for _ in calls]
        for _ in range(repeats):
            for f, t in zip(calls, times):
                t0 = time.perf_counter()
                f()
                t.append(time.perf_counter() - t0)
    finally:
        if was_enabled:
            gc.enable()
    return [(min(t), statistics.median(t), t1) for t, t1 in zip(times, first)]


def curvature(n, repeats):
    face = bicubic_face()
    u0, u1, v0, v1 = face.ParameterRange
    rng = np.random.default_rng(27)
    uv = np.c_[rng.uniform(u0, u1, n), rng.uniform(v0, v1, n)]
    brep = face.exportBrepToString()
    pairs = uv.tolist()

    def loop():
        for u, v in pairs:
            face.curvatureAt(u, v)

    (whole, whole_median, whole_first), (single, single_median, _), (core, core_median, _), (occt, occt_median, _) = \
        interleaved([lambda: fw.surface_curvature(face, uv), lambda: fw.surface_curvature(face, uv, threads=1),
                     lambda: kernel.surface_curvature(brep, uv), loop], repeats)
    cores = os.cpu_count()
    print(f"surface_curvature, {n} points of a bicubic face (7 x 7 spans), best / median of {repeats}, interleaved:")
    print(f"  fw.surface_curvature ({cores} cores) {whole * 1e3:7.2f} / {whole_median * 1e3:7.2f} ms   "
          f"kernel binding alone {core * 1e3:7.2f} / {core_median * 1e3:7.2f} ms "
          f"({n / core / 1e6:.1f} / {n / core_median / 1e6:.1f} million points/s)")
    print(f"  fw.surface_curvature (threads=1) {single * 1e3:7.2f} / {single_median * 1e3:7.2f} ms")
    print(f"  Python loop over Face.curvatureAt {occt * 1e3:7.1f} / {occt_median * 1e3:7.1f} ms   "
          f"ratio {occt / whole:.1f}x / {occt_median / whole_median:.1f}x ({cores} cores), "
          f"{occt / single:.1f}x / {occt_median / single_median:.1f}x (one core)")
    print(f"  first call of fw.surface_curvature (fresh memory) {whole_first * 1e3:7.2f} ms   "
          f"ratio to the loop's best {occt / whole_first:.1f}x")


def mesh_baseline(deflection):
    """The torus R = 4, r = 1.25: principal curvatures 1/r and cos(v)/(R + r cos(v)), with
    cos(v) = (rho - R)/r at a point rho from the axis (convex positive, outward normals)."""
    import Mesh

    R, r = 4.0, 1.25
    torus = Part.makeTorus(R, r)

    def exact(points):
        rho = np.hypot(points[:, 0], points[:, 1])
        cos_v = (rho - R) / r
        k = np.c_[np.full(len(points), 1 / r), cos_v / (R + r * cos_v)]
        return np.sort(k, axis=1)[:, ::-1]

    ours = best(lambda: fw.curvature_map(torus, "max", deflection=deflection, levels=0), 3, sample=0.2)
    m = fw.curvature_map(torus, "max", deflection=deflection, levels=0)
    our_error = np.abs(m.values - exact(m.points)[:, 0]).max()
    mesh = Mesh.Mesh(torus.tessellate(deflection))
    theirs = best(lambda: mesh.getCurvaturePerVertex(), 3, sample=0.2)
    points = np.array([[p.x, p.y, p.z] for p in mesh.Points])
    k = np.array([c[:2] for c in mesh.getCurvaturePerVertex()])
    mesh_error = np.abs(np.sort(k, axis=1)[:, ::-1] - exact(points)).max(axis=0)
    print(f"curvature of a torus (R 4, r 1.25), mesh deflection {deflection}:")
    print(f"  fw.curvature_map ({len(m.points)} vertices) {ours * 1e3:.1f} ms, largest error of k1 {our_error:.1e} /mm")
    print(f"  Mesh.getCurvaturePerVertex ({len(points)} vertices) {theirs * 1e3:.1f} ms (curvature only), largest "
          f"error of k1 {mesh_error[0]:.2e}, of k2 {mesh_error[1]:.2e} /mm (k1 = 1/r = 0.8)")


def filleted_boxes(count):
    box = Part.makeBox(10, 10, 10)
    one = box.makeFillet(1.5, box.Edges)
    return Part.makeCompound([one.translated(V(15 * i, 0, 0)) for i in range(count)])


def map_build(count, deflection):
    shape = filleted_boxes(count)
    seconds = best(lambda: fw.curvature_map(shape, "mean", deflection=deflection), 3, sample=0.5)
    m = fw.curvature_map(shape, "mean", deflection=deflection)
    print(f"curvature_map of {count} filleted boxes ({len(shape.Faces)} faces), deflection {deflection}: "
          f"{len(m.points)} vertices, {len(m.triangles)} triangles in {seconds * 1e3:.1f} ms")


def map_recolour(count, deflection):
    """The GUI's curvature map of `count` filleted boxes: build and recolour times."""
    from freecad_workbench.gui.curvature_map import CurvatureMapNode

    doc = FreeCAD.newDocument("BenchMap")
    obj = doc.addObject("Part::Feature", "Boxes")
    obj.Shape = filleted_boxes(count)
    node = CurvatureMapNode(obj)
    node.deflection = deflection
    build = best(node.update, 3, sample=0.5)
    lower, upper = node.range
    ranges = itertools.cycle([(lower * f, upper * f) for f in np.linspace(0.5, 1.5, 7)])

    def change_range():
        node.manual = next(ranges)
        node.recolour()

    recolour = best(change_range, 5, sample=0.2)
    print(f"curvature map in the GUI, {count} filleted boxes ({len(obj.Shape.Faces)} faces), "
          f"{len(node.data.points)} vertices: built in {build * 1e3:.0f} ms, recoloured after a range change "
          f"in {recolour * 1e3:.1f} ms")
    FreeCAD.closeDocument(doc.Name)


def continuity(count):
    shapes = [(f"{count} filleted boxes", filleted_boxes(count))]
    if count > 1:
        zone = fw.shapes.SphereZone((0, 0, 0), 2.0, list(np.linspace(0, 2 * math.pi, 25)),
                                    [-1.2, -0.8, -0.4, 0.0, 0.4, 0.8, 1.2])
        shapes.append(("C2 blend shell", fw.blend_basic_shape(zone).shell))
    print("edge_continuity:")
    for name, shape in shapes:
        seconds = best(lambda: fw.edge_continuity(shape), 3, sample=0.5)
        records = fw.edge_continuity(shape)
        verdicts = {v: sum(r.continuity == v for r in records) for v in sorted({r.continuity for r in records})}
        samples = sum(r.samples for r in records)
        print(f"  {name}: {len(shape.Edges)} edges, {len(shape.Faces)} faces: {seconds * 1e3:.1f} ms "
              f"({samples} evaluations; {verdicts})")


if __name__ == "__main__":
    smoke = sys.argv[1:] == ["smoke"]
    curvature(2000 if smoke else 200000, 3 if smoke else 7)
    mesh_baseline(0.05 if smoke else 0.01)
    map_build(1 if smoke else 10, 0.05 if smoke else 0.001)
    map_recolour(1 if smoke else 4, 0.05 if smoke else 0.00035)
    continuity(1 if smoke else 10)
