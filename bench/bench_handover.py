"""Python benchmark: the user's whole path, numpy (N,3) -> fw.csr_spline -> Part.BSplineCurve,
against the bare hand-over of the same number of poles and against the obvious
FreeCAD route (convert to Vectors, Part.BSplineCurve.interpolate), in one run.

    /usr/bin/python3 bench/bench_handover.py [smoke]

(smoke: N = 1000 only, for `make bench-smoke`.)
"""
import gc
import math
import os
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))

import numpy as np  # noqa: E402

import freecad_workbench as fw  # noqa: E402
from freecad_workbench import _kernel, kernel  # noqa: E402
import FreeCAD  # noqa: E402
import Part  # noqa: E402


def samples(n):
    """bench_csr's samples: a conical spiral at uneven steps that always go forward (before
    issue 26 they wandered back and forth, and at 10^6 two neighbours were too close together
    along the data for a spline through both)."""
    i = np.arange(n)
    s = 20.0 * (i + 0.4 * np.sin(0.7 * i)) / n
    return np.c_[(1 + s) * np.cos(s), (1 + s) * np.sin(s), 0.1 * s]


def best(f, repeats, sample=0.02):
    """Seconds per call: the fastest of `repeats` samples, each of as many calls as fill
    `sample` seconds, with the garbage collector off (timeit's method). A single call
    after a collection would time a cold cache instead: at 1e3 points that alone moved
    the ratio between 0.7 and 2."""
    f()  # warm up
    t0 = time.perf_counter()
    f()
    number = max(1, int(sample / max(time.perf_counter() - t0, 1e-9)))
    was_enabled = gc.isenabled()
    gc.collect()
    gc.disable()
    try:
        times = []
        for _ in range(repeats):
            t0 = time.perf_counter()
            for _ in range(number):
                f()
            times.append((time.perf_counter() - t0) / number)
    finally:
        if was_enabled:
            gc.enable()
    return min(times)


def main(sizes=(1000, 10000, 100000, 1000000)):
    print(f"{'N':>9} {'fw.csr_spline':>14} {'bare hand-over':>15} {'ratio':>6} {'array hand-over':>16} "
          f"{'Vectors+interpolate':>20} {'speed-up':>9}   [us per point]")
    for n in sizes:
        q = samples(n)
        repeats = 5 if n >= 1000000 else 7
        fitted = _kernel.csr_spline(q)  # the same number of poles, precomputed
        end_to_end = best(lambda: fw.csr_spline(q), repeats)
        bare = best(lambda: kernel.to_part(fitted), repeats)
        arrays = best(lambda: kernel.to_part_arrays(fitted), repeats)
        if n <= 100000:
            def classic():
                Part.BSplineCurve().interpolate([FreeCAD.Vector(*p) for p in q.tolist()])
            occt = best(classic, repeats)
        else:
            occt = math.nan  # minutes of Python objects; not informative
        us = 1e6 / n
        print(f"{n:>9} {end_to_end * us:>14.3f} {bare * us:>15.3f} {end_to_end / bare:>6.2f} {arrays * us:>16.3f} "
              f"{occt * us:>20.3f} {occt / end_to_end:>8.1f}x")


if __name__ == "__main__":
    main((1000,) if sys.argv[1:] == ["smoke"] else (1000, 10000, 100000, 1000000))
