"""Python benchmark (issue 5): the macro path fw.blend_basic_shape for a sphere zone with
8 x 4 patches plus its default ring (kernel, Part hand-over of every patch, single C2
surface, sewn shell), beside the kernel-only build of the same complex, in one run.

    /usr/bin/python3 bench/bench_blend.py
"""
import math
import os
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))

import numpy as np  # noqa: E402

import freecad_workbench as fw  # noqa: E402
from freecad_workbench import _kernel  # noqa: E402


def median(f, repeats):
    times = []
    for _ in range(repeats):
        t0 = time.perf_counter()
        f()
        times.append(time.perf_counter() - t0)
    return float(np.median(times))


def main():
    zone = fw.shapes.SphereZone((0, 0, 0), 10.0, np.linspace(0, 2 * math.pi, 9), [-0.8, -0.3, 0.1, 0.5, 0.9])
    kernel = median(lambda: _kernel.blend_sphere_zone(zone.center, zone.x_axis, zone.y_axis, zone.radius,
                                                      zone.longitudes, zone.latitudes, "rho", None, True), 50)
    full = median(lambda: fw.blend_basic_shape(zone), 10)
    naive = median(lambda: fw.blend_naive(zone), 10)
    print("sphere zone 8 x 4 + default ring (median)")
    print(f"  kernel complex (C2 both ways)      {1e3 * kernel:8.3f} ms   target <= 1 ms")
    print(f"  fw.blend_basic_shape (Part, shell) {1e3 * full:8.3f} ms")
    print(f"  fw.blend_naive (Part, shell)       {1e3 * naive:8.3f} ms")


if __name__ == "__main__":
    main()
