// Benchmark: the kernel's surfaceCurvature on N scattered points of a bicubic B-spline face
// (10 x 10 poles, 7 x 7 spans) against OCCT's own per-point route, GeomLProp_SLProps (what
// Face.curvatureAt runs, without Python), in the same run, one core; and edgeContinuity on
// filleted boxes (about 56 edges each). Figures: best of several runs, warm memory.
#include <BRepAdaptor_Surface.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepLProp_SLProps.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>

#include <cmath>
#include <cstdio>
#include <random>

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

}  // namespace

int main(int argc, char** argv) {
  const bool smoke = bench::smokeRun(argc, argv);
  const int n = smoke ? 2000 : 200000, repeats = smoke ? 2 : 7;
  const TopoDS_Face face = bicubicFace();
  std::mt19937 random(27);
  std::uniform_real_distribution<double> along(0.0, 7.0);
  Eigen::MatrixXd uv(n, 2);
  for (Eigen::Index i = 0; i < n; ++i) uv(i, 0) = along(random), uv(i, 1) = along(random);

  double sink = 0.0;
  const double kernel = bench::bestSeconds([&] { sink += surfaceCurvature(face, uv).k1.sum(); }, repeats);
  const double occt = bench::bestSeconds(
      [&] {
        BRepAdaptor_Surface surface(face);
        BRepLProp_SLProps props(surface, 2, 1e-9);
        for (Eigen::Index i = 0; i < n; ++i) {
          props.SetParameters(uv(i, 0), uv(i, 1));
          sink += props.MaxCurvature();
        }
      },
      repeats);
  std::printf("surfaceCurvature, %d scattered points of a bicubic face (7 x 7 spans), one core:\n", n);
  std::printf("  kernel %8.2f ms (%.2f million points/s)   OCCT BRepLProp_SLProps loop %8.2f ms   ratio %.2f\n",
              kernel * 1e3, n / kernel / 1e6, occt * 1e3, occt / kernel);
  std::printf("(checksum %g)\n", sink);
  return 0;
}
