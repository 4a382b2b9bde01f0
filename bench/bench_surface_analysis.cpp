// Benchmark: the kernel's surfaceCurvature on N scattered points of a bicubic B-spline face
// (10 x 10 poles, 7 x 7 spans) against OCCT's own per-point route, GeomLProp_SLProps (what
// Face.curvatureAt runs, without Python), in the same run. The kernel on one core and on
// every core (threads = 0: one a core), writing into a block it is given (the binding hands
// it numpy's), and on one core into a block of its own allocated at each call. Figures: best
// and median of interleaved runs.
#include <BRepAdaptor_Surface.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepLProp_SLProps.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <thread>
#include <utility>
#include <vector>

#include "fairsplines/surface_analysis.hpp"
#include "bench_timing.hpp"

using namespace fairsplines;

namespace {

TopoDS_Face bicubicFace() {
  const int n = 10;
  TColgp_Array2OfPnt poles(1, n, 1, n);
  for (int i = 1; i <= n; ++i) {
    for (int j = 1; j <= n; ++j) {
      poles(i, j) = gp_Pnt(i, j, 0.5 * std::sin(0.9 * i) * std::cos(0.7 * j) + 0.02 * i * j);
    }
  }
  TColStd_Array1OfReal knots(1, n - 2);
  TColStd_Array1OfInteger mults(1, n - 2);
  for (int i = 1; i <= n - 2; ++i) {
    knots(i) = i - 1;
    mults(i) = (i == 1 || i == n - 2) ? 4 : 1;
  }
  return BRepBuilderAPI_MakeFace(new Geom_BSplineSurface(poles, knots, knots, mults, mults, 3, 3), 1e-7).Face();
}

/// The fastest and the median of the timings.
std::pair<double, double> bestAndMedian(std::vector<double> t) {
  std::sort(t.begin(), t.end());
  return {t.front(), t[t.size() / 2]};
}

}  // namespace

int main(int argc, char** argv) {
  const bool smoke = bench::smokeRun(argc, argv);
  const int n = smoke ? 2000 : 200000, repeats = smoke ? 2 : 9;
  const TopoDS_Face face = bicubicFace();
  std::mt19937 random(27);
  std::uniform_real_distribution<double> along(0.0, 7.0);
  PointMatrix uv(n, 2);  // row-major, as numpy hands it over
  for (Eigen::Index i = 0; i < n; ++i) uv(i, 0) = along(random), uv(i, 1) = along(random);

  double sink = 0.0;
  // The kernel writing into one block it is given (as the binding's numpy block), reused
  // between calls; and into a block of its own allocated at each call (fresh memory: page faults).
  SurfaceCurvature block;
  block.values.resize(n, Eigen::NoChange);
  block.state.resize(n);
  // Interleaved: the machine is shared, its load moves between the runs.
  std::vector<double> given, shared, fresh, occt;
  for (int r = 0; r < repeats; ++r) {
    given.push_back(bench::timings(
        [&] {
          surfaceCurvature(face, uv, block.values, block.state, 1);
          sink += block.k1().sum();
        },
        1)[0]);
    shared.push_back(bench::timings(
        [&] {
          surfaceCurvature(face, uv, block.values, block.state, 0);
          sink += block.k1().sum();
        },
        1)[0]);
    fresh.push_back(bench::timings([&] { sink += surfaceCurvature(face, uv, 1).k1().sum(); }, 1)[0]);
    occt.push_back(bench::timings(
        [&] {
          BRepAdaptor_Surface surface(face);
          BRepLProp_SLProps props(surface, 2, 1e-9);
          for (Eigen::Index i = 0; i < n; ++i) {
            props.SetParameters(uv(i, 0), uv(i, 1));
            sink += props.MaxCurvature();
          }
        },
        1)[0]);
  }
  const auto [givenBest, givenMedian] = bestAndMedian(given);
  const auto [sharedBest, sharedMedian] = bestAndMedian(shared);
  const auto [freshBest, freshMedian] = bestAndMedian(fresh);
  const auto [occtBest, occtMedian] = bestAndMedian(occt);
  std::printf("surfaceCurvature, %d scattered points of a bicubic face (7 x 7 spans), best / median of %d:\n", n,
              repeats);
  std::printf("  kernel, one core, into a given block   %7.2f / %7.2f ms (%.2f / %.2f million points/s)\n",
              givenBest * 1e3, givenMedian * 1e3, n / givenBest / 1e6, n / givenMedian / 1e6);
  std::printf("  kernel, %u cores, into a given block    %7.2f / %7.2f ms (%.2f / %.2f million points/s)\n",
              std::thread::hardware_concurrency(), sharedBest * 1e3, sharedMedian * 1e3, n / sharedBest / 1e6,
              n / sharedMedian / 1e6);
  std::printf("  kernel, one core, into a new block     %7.2f / %7.2f ms (%.2f / %.2f million points/s)\n",
              freshBest * 1e3, freshMedian * 1e3, n / freshBest / 1e6, n / freshMedian / 1e6);
  std::printf(
      "  OCCT BRepLProp_SLProps loop, one core %7.2f / %7.2f ms   ratio one core %.2f / %.2f, all cores %.2f / %.2f\n",
      occtBest * 1e3, occtMedian * 1e3, occtBest / givenBest, occtMedian / givenMedian, occtBest / sharedBest,
      occtMedian / sharedMedian);
  std::printf("(checksum %g)\n", sink);
  return 0;
}
