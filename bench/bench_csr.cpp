// Benchmark: csr-spline (kernel, ending in a Geom_BSplineCurve) against OCCT's
// GeomAPI_Interpolate on the same points, one core, one run.
#include <GeomAPI_Interpolate.hxx>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <algorithm>

#include "bench_timing.hpp"
#include "fairsplines/baselines.hpp"
#include "fairsplines/csr.hpp"
#include "fairsplines/occt.hpp"

using namespace fairsplines;
using fairsplines::bench::bestSeconds;

namespace {

/// A planar spiral-like curve with varying curvature, sampled at uneven steps.
PointMatrix samples(int n) {
  PointMatrix q(n, 3);
  for (int i = 0; i < n; ++i) {
    const double s = 20.0 * i / n + 0.3 * std::sin(0.7 * i);
    q.row(i) << (1 + s) * std::cos(s), (1 + s) * std::sin(s), 0.1 * s;
  }
  return q;
}


}  // namespace

int main() {
  std::printf("csr-spline vs GeomAPI_Interpolate, same points, one core (best of several runs)\n");
  std::printf("%9s %11s %10s %15s %10s %17s %8s\n", "N", "fit [ms]", "fit Mpt/s", "fit+Geom [ms]", "Mpt/s",
              "OCCT interp [ms]", "ratio");
  for (int n : {1000, 10000, 100000, 1000000}) {
    const PointMatrix q = samples(n);
    const int repeats = n >= 1000000 ? 3 : (n >= 100000 ? 7 : 30);
    long poles = 0;
    const double fit = bestSeconds([&] { poles += csrSpline(q).poles.rows(); }, repeats);
    const double csr = bestSeconds([&] { poles += toOcct(csrSpline(q))->NbPoles(); }, repeats);
    const double occt = bestSeconds(
        [&] { poles += classicInterpolation(q, Parametrization::Chordal, false)->NbPoles(); }, repeats);
    std::printf("%9d %11.3f %10.1f %15.3f %10.1f %17.3f %7.1fx\n", n, fit * 1e3, n / fit * 1e-6, csr * 1e3,
                n / csr * 1e-6, occt * 1e3, occt / csr);
    if (poles == 0) return 1;
  }
  return 0;
}
