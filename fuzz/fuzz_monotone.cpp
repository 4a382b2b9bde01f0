// Monotone-curvature cubics (monotone.hpp): the end conditions, Algorithm 2 by the fairest
// solver and by the paper's grid search (a grid step in [0.1, 0.5], so that an input runs
// in milliseconds), Algorithm 1 from control vectors, and the per-segment conditions of
// every curve returned.
#include "fairsplines/monotone.hpp"
#include "fuzz_check.hpp"
#include "fuzz_input.hpp"

using namespace fairsplines;
using namespace fairsplines::fuzz;

namespace {

/// A direction: mostly in the plane z = 0 at an angle, with any length; else any vector.
Eigen::Vector3d direction(FuzzInput& in) {
  if (in.byte() < 200) {
    const double angle = in.number(), length = in.byte() < 128 ? 1.0 : in.number();
    return length * Eigen::Vector3d(std::cos(angle), std::sin(angle), 0.0);
  }
  return in.vector3();
}

Eigen::Vector3d point(FuzzInput& in) {
  if (in.byte() < 200) return in.planar3();
  return in.vector3();
}

void requireSegments(const char* call, const BSplineCurve& cubic) {
  std::vector<SegmentReport> reports;
  if (!guarded("checkSegments", [&] { reports = checkSegments(cubic); })) return;
  for (const SegmentReport& r : reports) {
    requireFinite(call, "segment range", Eigen::Vector2d(r.u0, r.u1));
  }
}

}  // namespace

int fuzzOne(FuzzInput& in) {
  if (in.byte() < 192) {  // Algorithm 2
    const Eigen::Vector3d p0 = point(in), t0 = direction(in);
    Eigen::Vector3d p1 = point(in);
    if (in.flag()) p1 += p0;
    const Eigen::Vector3d t1 = direction(in);
    const bool grid = in.byte() < 64;
    const double gridStep = 0.1 + 0.4 * (in.byte() / 255.0);
    note("p0", p0);
    note("t0", t0);
    note("p1", p1);
    note("t1", t1);
    note("method (0 fairest, 1 paper grid)", static_cast<int>(grid));
    note("grid step", gridStep);
    EndConditions ends;
    if (guarded("analyzeEndConditions", [&] { ends = analyzeEndConditions(p0, t0, p1, t1); }) && ends.admissible) {
      requireFinite("analyzeEndConditions", "a, b, turn", Eigen::Vector3d(ends.a, ends.b, ends.turn));
    }
    MonotoneSpline spline;
    const char* call = grid ? "monotoneCurvatureSpline(PaperGrid)" : "monotoneCurvatureSpline(Fairest)";
    if (!guarded(call, [&] {
          spline = monotoneCurvatureSpline(p0, t0, p1, t1, grid ? MonotoneMethod::PaperGrid : MonotoneMethod::Fairest,
                                           gridStep);
        })) {
      return 0;
    }
    requireValid(call, spline.curve);
    requireFinite(call, "margin", spline.margin);
    requireSegments(call, spline.curve);
  } else {  // Algorithm 1
    const Eigen::Vector2d first = in.vector2();
    const int m = in.count(0, 8);
    PointMatrix differences(m, 2);
    for (int i = 0; i < m; ++i) differences.row(i) = in.vector2().transpose();
    Eigen::VectorXd knots;
    switch (in.choice(3)) {
      case 0:
        knots = in.increasing(m + 6, in.number());
        break;
      case 1:
        knots = in.numbers(in.count(0, 16));
        break;
      default:
        break;
    }
    const Eigen::Vector2d start = in.byte() < 128 ? Eigen::Vector2d::Zero() : in.vector2();
    note("first vector", first);
    note("differences", differences);
    note("flat knots", knots);
    note("start", start);
    MonotoneDesign design;
    if (!guarded("designMonotone", [&] { design = designMonotone(first, differences, knots, start); })) return 0;
    requireValid("designMonotone", design.curve);
    requireFinite("designMonotone", "difference", design.differences);
    requireFinite("designMonotone", "moved", design.moved);
    requireSegments("designMonotone", design.curve);
  }
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) { return runOne(data, size, fuzzOne); }
