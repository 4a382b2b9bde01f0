// Benchmark: csr-spline (kernel, ending in a Geom_BSplineCurve) against OCCT's
// GeomAPI_Interpolate on the same points, one core, one run.
//
// Columns: the fit alone (csrSpline, a kernel BSplineCurve); the fit ending in a
// Geom_BSplineCurve (csrSplineOcct, the route the workbench takes); the same through
// toOcct(csrSpline(q)); the Geom_BSplineCurve constructor alone on prebuilt arrays of
// the same size (a floor no fit can go below); GeomAPI_Interpolate (ending in a
// Geom_BSplineCurve too); the ratio interpolation / fit+Geom, and the ratio the
// constructor alone would reach (the bound on the first).
#include <GeomAPI_Interpolate.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "fairsplines/baselines.hpp"
#include "fairsplines/csr.hpp"
#include "fairsplines/occt.hpp"
#include "bench_timing.hpp"

using namespace fairsplines;
using fairsplines::bench::bestSeconds;

namespace {

/// A conical spiral with varying curvature, sampled at uneven steps (from 0.72 to 1.28 of
/// the mean) that always go forward. (Until issue 26 the steps were 20 / n + 0.21 cos(0.7 i):
/// the samples wandered back and forth along the curve, and at 10^6 two neighbours were
/// too close together along those 1.45 million units of data for a spline through both.)
PointMatrix samples(int n) {
  PointMatrix q(n, 3);
  for (int i = 0; i < n; ++i) {
    const double s = 20.0 * (i + 0.4 * std::sin(0.7 * i)) / n;
    q.row(i) << (1 + s) * std::cos(s), (1 + s) * std::sin(s), 0.1 * s;
  }
  return q;
}

}  // namespace

int main(int argc, char** argv) {
  const bool smoke = fairsplines::bench::smokeRun(argc, argv);  // N = 1000 only
  std::printf("csr-spline vs GeomAPI_Interpolate, same points, one core (best of several runs)\n");
  std::printf("%9s %9s %9s %13s %7s %12s %11s %14s %7s %7s\n", "N", "fit [ms]", "fit Mpt/s", "fit+Geom [ms]", "Mpt/s",
              "via toOcct", "Geom ctor", "OCCT interp", "ratio", "bound");
  for (int n : {1000, 10000, 100000, 1000000}) {
    if (smoke && n > 1000) break;
    const PointMatrix q = samples(n);
    const int repeats = n >= 1000000 ? 3 : (n >= 100000 ? 7 : 30);
    long poles = 0;
    const double fit = bestSeconds([&] { poles += csrSpline(q).poles.rows(); }, repeats);
    const double csr = bestSeconds([&] { poles += csrSplineOcct(q)->NbPoles(); }, repeats);
    const double twoStep = bestSeconds([&] { poles += toOcct(csrSpline(q))->NbPoles(); }, repeats);
    // The constructor alone, on arrays of the curve's size built beforehand.
    const BSplineCurve c = csrSpline(q);
    const int np = static_cast<int>(c.poles.rows()), nk = static_cast<int>(c.knots.size());
    const TColgp_Array1OfPnt P(*reinterpret_cast<const gp_Pnt*>(c.poles.data()), 1, np);
    const TColStd_Array1OfReal K(*c.knots.data(), 1, nk);
    const TColStd_Array1OfInteger M(*c.mults.data(), 1, nk);
    const double ctor = bestSeconds(
        [&] {
          Handle(Geom_BSplineCurve) g = new Geom_BSplineCurve(P, K, M, 3, false);
          poles += g->NbPoles();
        },
        repeats);
    const double occt =
        bestSeconds([&] { poles += classicInterpolation(q, Parametrization::Chordal, false)->NbPoles(); }, repeats);
    std::printf("%9d %9.3f %9.1f %13.3f %7.1f %12.3f %11.3f %14.3f %6.1fx %6.1fx\n", n, fit * 1e3, n / fit * 1e-6,
                csr * 1e3, n / csr * 1e-6, twoStep * 1e3, ctor * 1e3, occt * 1e3, occt / csr, occt / ctor);
    if (poles == 0) return 1;
  }
  return 0;
}
