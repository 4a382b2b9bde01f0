// Benchmark: rebuilding a design of 4 basic curves with 40 marks (what every slider move
// does), against the nearest OCCT route: GeomConvert of each piece joined by
// GeomConvert_CompCurveToBSplineCurve (only G1 at the joins). Same run, same pieces.
#include <GC_MakeArcOfCircle.hxx>
#include <GC_MakeSegment.hxx>
#include <GeomConvert.hxx>
#include <GeomConvert_CompCurveToBSplineCurve.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <gp.hxx>
#include <gp_Ax2.hxx>
#include <gp_Circ.hxx>
#include <vector>

#include "fairsplines/design.hpp"
#include "fairsplines/occt.hpp"
#include "bench_timing.hpp"

using namespace fairsplines;
using fairsplines::bench::medianSeconds;

int main(int argc, char** argv) {
  const bool smoke = fairsplines::bench::smokeRun(argc, argv);  // make bench-smoke: few repeats
  const double pi = std::acos(-1.0);
  // Quarter circle (1,0)->(0,1), line to (-2,1), quarter circle to (-3,0), line to (-3,-2).
  const Frame xy{};
  const CircleArc a(xy, 1.0, 0.0, 0.5 * pi);
  const auto b = lineSegment({0, 1, 0}, {-2, 1, 0});
  const CircleArc c(Frame{{-2, 0, 0}, Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY()}, 1.0, 0.5 * pi, 0.5 * pi);
  const auto d = lineSegment({-3, 0, 0}, {-3, -2, 0});
  const Eigen::VectorXd marks = Eigen::VectorXd::LinSpaced(10, 1.0 / 11, 10.0 / 11);  // 4 x 10 = 40 marks
  const std::vector<const BasicCurve*> pieces{&a, b.get(), &c, d.get()};

  int poles = 0;
  auto design = [&] {
    std::vector<PiecePolygon> polygons;
    for (const BasicCurve* p : pieces) polygons.push_back(piecePolygon(*p, marks));
    poles += toOcct(mergePieces(polygons, 1e-9).curve)->NbPoles();
  };
  auto occt = [&] {
    GeomConvert_CompCurveToBSplineCurve joined(
        GeomConvert::CurveToBSplineCurve(GC_MakeArcOfCircle(gp_Circ(gp::XOY(), 1.0), 0.0, 0.5 * pi, true).Value()));
    joined.Add(GeomConvert::CurveToBSplineCurve(GC_MakeSegment(gp_Pnt(0, 1, 0), gp_Pnt(-2, 1, 0)).Value()), 1e-7);
    joined.Add(GeomConvert::CurveToBSplineCurve(
                   GC_MakeArcOfCircle(gp_Circ(gp_Ax2(gp_Pnt(-2, 0, 0), gp::DZ()), 1.0), 0.5 * pi, pi, true).Value()),
               1e-7);
    joined.Add(GeomConvert::CurveToBSplineCurve(GC_MakeSegment(gp_Pnt(-3, 0, 0), gp_Pnt(-3, -2, 0)).Value()), 1e-7);
    poles += joined.BSplineCurve()->NbPoles();
  };
  const int repeats = smoke ? 21 : 2001;
  for (int w = 0; w < (smoke ? 5 : 200); ++w) {  // warm-up
    design();
    occt();
  }
  const double ours = medianSeconds(design, repeats), theirs = medianSeconds(occt, repeats);
  std::printf("design of 4 basic curves, 40 marks, to a Geom_BSplineCurve (median of %d)\n", repeats);
  std::printf("%-58s %10.1f us\n", "kernel: Section 6 polygons + Fig. 9 merge (C2)", ours * 1e6);
  std::printf("%-58s %10.1f us\n", "OCCT: GeomConvert + CompCurveToBSplineCurve (G1 joins)", theirs * 1e6);
  std::printf("%-58s %10.2f\n", "ratio kernel / OCCT", ours / theirs);
  return poles > 0 ? 0 : 1;
}
