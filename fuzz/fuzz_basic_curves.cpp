// Basic curves (basic_curves.hpp): every constructor, evaluation of point, first and second
// derivative on [0, 1], the size, the homogeneous cubic, and the parameter of a point
// (eq. (4) for circle arcs, eq. (5) otherwise) for points on, near and off the curve.
#include "fuzz_basic.hpp"

using namespace fairsplines;
using namespace fairsplines::fuzz;

int fuzzOne(FuzzInput& in) {
  std::string kind;
  std::unique_ptr<BasicCurve> curve;
  if (!guarded("a basic curve's constructor", [&] { curve = basicCurve(in, kind); })) return 0;
  const char* call = kind.c_str();
  // A ParametricCurve's value, d1, d2 (and so size) pass the user's function through: its
  // overflow is the user's. What the kernel computes from them (parameterOf here, the
  // polygons in fuzz_design) is checked all the same.
  const bool passThrough = kind.rfind("ParametricCurve(", 0) == 0;  // the harness's polynomial

  const int samples = in.count(0, 4);
  for (int k = 0; k < samples + 2; ++k) {
    const double u = k == 0 ? 0.0 : k == 1 ? 1.0 : in.unit();
    if (!(u >= 0.0 && u <= 1.0)) continue;  // the curves are defined over [0, 1]
    note("u", u);
    Eigen::Vector3d p, d1, d2;
    if (!guarded(call, [&] { p = curve->value(u), d1 = curve->d1(u), d2 = curve->d2(u); }) || passThrough) continue;
    requireFinite(call, "value(u)", p);
    requireFinite(call, "d1(u)", d1);
    requireFinite(call, "d2(u)", d2);
  }
  double diagonal = 0.0;
  if (guarded(call, [&] { diagonal = curve->size(); }) && !passThrough) requireFinite(call, "size()", diagonal);
  std::optional<HomogeneousBezier> cubic;
  if (guarded(call, [&] { cubic = curve->homogeneousCubic(); }) && cubic)
    requireFinite(call, "homogeneousCubic()", *cubic);

  const int points = in.count(0, 3);
  for (int k = 0; k < points; ++k) {
    Eigen::Vector3d q;
    switch (in.choice(3)) {
      case 0:    // on the curve
      case 1: {  // near it
        const double u = in.unit();
        if (!guarded(call, [&] { q = curve->value(std::clamp(u, 0.0, 1.0)); })) continue;
        if (in.flag()) {
          const double scale = in.flag() ? 1e-10 : 1e-3;
          q += in.vector3() * scale;
        }
        break;
      }
      default:
        q = in.vector3();
        break;
    }
    const double tolerance = in.byte() < 200 ? 1e-9 : in.number();
    note("parameterOf point", q);
    note("parameterOf tolerance", tolerance);
    double u = 0.0;
    if (guarded(call, [&] { u = curve->parameterOf(q, tolerance); })) requireFinite(call, "parameterOf(q)", u);
  }
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) { return runOne(data, size, fuzzOne); }
