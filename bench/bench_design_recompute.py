"""Python benchmark: the FreeCAD recompute of a Design spline of 4 basic curves with 40
marks after one mark moves (what a slider move does), beside the same-run cost of the
nearest OCCT route in FreeCAD (each piece to a B-spline, joined by
Part.BSplineCurve.join, which is GeomConvert_CompCurveToBSplineCurve: G1 joins); and
fw.approximation_error of a circle arc with 2000 marks (issue 13: 15-25 s with a Python
loop per sample point; tests/kernel/test_hardening.py checks its measure, not its time).

    /usr/bin/python3 bench/bench_design_recompute.py [smoke]
"""
import math
import os
import statistics
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))

import numpy as np  # noqa: E402

import freecad_workbench as fw  # noqa: E402,F401  (imports FreeCAD)
import FreeCAD  # noqa: E402
import Part  # noqa: E402
from freecad_workbench.features.design_spline import get_marks, make_design_spline, set_marks  # noqa: E402

V = FreeCAD.Vector


def main(repeats=301):
    doc = FreeCAD.newDocument("BenchDesign")
    edges = [
        Part.ArcOfCircle(Part.Circle(V(0, 0, 0), V(0, 0, 1), 1.0), 0.0, math.pi / 2),
        Part.LineSegment(V(0, 1, 0), V(-2, 1, 0)),
        Part.ArcOfCircle(Part.Circle(V(-2, 0, 0), V(0, 0, 1), 1.0), math.pi / 2, math.pi),
        Part.LineSegment(V(-3, 0, 0), V(-3, -2, 0)),
    ]
    objects = []
    for i, edge in enumerate(edges):
        obj = doc.addObject("Part::Feature", f"Piece{i}")
        obj.Shape = edge.toShape()
        objects.append(obj)
    marks = list(np.linspace(1 / 11, 10 / 11, 10))
    design = make_design_spline(doc, [(obj, marks) for obj in objects])
    doc.recompute()
    assert design.Status == "ok", design.Status

    times = []
    for r in range(repeats):
        per_piece = get_marks(design)
        per_piece[r % 4][5] = 0.5 + 0.03 * math.sin(r)  # one slider moves
        set_marks(design, per_piece)
        t0 = time.perf_counter()
        doc.recompute()
        times.append(time.perf_counter() - t0)
    recompute = statistics.median(times)

    occt = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        joined = edges[0].toBSpline()
        for edge in edges[1:]:
            joined.join(edge.toBSpline())
        occt.append(time.perf_counter() - t0)
    route = statistics.median(occt)
    FreeCAD.closeDocument(doc.Name)
    print(f"Design spline of 4 basic curves with 40 marks, median of {repeats}")
    print(f"{'FreeCAD recompute after one mark moves (C2)':<56} {recompute * 1e3:8.3f} ms")
    print(f"{'OCCT route in FreeCAD: toBSpline + join (G1 joins)':<56} {route * 1e3:8.3f} ms")
    print(f"{'ratio':<56} {recompute / route:8.2f}")
    arc = fw.basic.CircleArc((0, 0, 0), 10, 0, 3)
    many = [i / 2001 for i in range(1, 2001)]
    t0 = time.perf_counter()
    fw.approximation_error(arc, many)
    print(f"{'fw.approximation_error, circle arc with 2000 marks (one run)':<56} {time.perf_counter() - t0:8.3f} s")


if __name__ == "__main__":
    main(11 if sys.argv[1:] == ["smoke"] else 301)  # smoke: `make bench-smoke`, a few recomputes
