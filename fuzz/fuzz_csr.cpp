// csr-spline fitting (Section 4, eq. (6)): open and closed data, the three
// parametrizations, both epsilon rules, explicit parameters; csrSplineOcct, which must give
// the same curve bit for bit (occt.hpp); and the baselines on the same data.
#include <Geom_BSplineCurve.hxx>

#include "fairsplines/baselines.hpp"
#include "fairsplines/csr.hpp"
#include "fairsplines/occt.hpp"
#include "fuzz_check.hpp"
#include "fuzz_input.hpp"

using namespace fairsplines;
using namespace fairsplines::fuzz;

int fuzzOne(FuzzInput& in) {
  const PointMatrix q = samplePoints(in, 64);
  CsrOptions options;
  options.closed = in.flag();
  options.parametrization = static_cast<Parametrization>(in.choice(3));
  options.rule = in.flag() ? EpsilonRule::Additive : EpsilonRule::CaseDistinction;
  if (in.flag()) options.epsilon = in.number();
  switch (in.choice(4)) {
    case 0:  // explicit parameters, any numbers
      options.parameters = in.numbers(q.rows() + (options.closed ? 1 : 0) - (in.byte() == 255 ? 1 : 0));
      break;
    case 1: {  // explicit parameters, increasing from any start, steps scaled by any number
      const double start = in.byte() < 128 ? 0.0 : in.number();
      const double scale = in.byte() < 128 ? 1.0 : in.number();
      options.parameters = in.increasing(q.rows() + (options.closed ? 1 : 0), 0.0) * scale;
      options.parameters.array() += start;
      break;
    }
    default:  // from the parametrization
      break;
  }
  note("points", q);
  note("closed", options.closed);
  note("parametrization", static_cast<int>(options.parametrization));
  note("rule (0 case distinction, 1 additive)", static_cast<int>(options.rule));
  note("epsilon", options.epsilon);
  note("parameters", options.parameters);

  BSplineCurve curve;
  const bool fitted = guarded("csrSpline", [&] { curve = csrSpline(q, options); });
  if (fitted) requireValid("csrSpline", curve);

  Handle(Geom_BSplineCurve) occt;
  const bool fittedOcct = guarded("csrSplineOcct", [&] { occt = csrSplineOcct(q, options); });
  if (fittedOcct != fitted) {
    fail("csrSplineOcct", fitted ? "threw where csrSpline returned" : "returned where csrSpline threw");
  }
  if (fittedOcct) {
    requireValid("csrSplineOcct", occt);
    const BSplineCurve back = fromOcct(occt);
    if (back.poles.rows() != curve.poles.rows() || back.knots.size() != curve.knots.size()) {
      fail("csrSplineOcct", "not the curve of csrSpline (sizes differ)");
    }
    for (Eigen::Index i = 0; i < curve.poles.rows(); ++i) {
      for (Eigen::Index j = 0; j < curve.poles.cols(); ++j) {
        if (back.poles(i, j) != curve.poles(i, j)) fail("csrSplineOcct", "not the curve of csrSpline (a pole differs)");
      }
    }
    for (Eigen::Index i = 0; i < curve.knots.size(); ++i) {
      if (back.knots[i] != curve.knots[i]) fail("csrSplineOcct", "not the curve of csrSpline (a knot differs)");
    }
  }

  // The baselines (Fig. 2, Fig. 15) on the same samples.
  switch (in.choice(4)) {
    case 0: {
      BSplineCurve c;
      if (guarded("quasiInterpolant", [&] { c = quasiInterpolant(q, options.parametrization, options.closed); }))
        requireValid("quasiInterpolant", c);
      break;
    }
    case 1: {
      BSplineCurve c;
      if (guarded("controlPointSpline", [&] { c = controlPointSpline(q, options.closed); }))
        requireValid("controlPointSpline", c);
      break;
    }
    case 2: {
      Handle(Geom_BSplineCurve) c;
      if (guarded("classicInterpolation",
                  [&] { c = classicInterpolation(q, options.parametrization, options.closed); }))
        requireValid("classicInterpolation", c);
      break;
    }
    default:
      break;
  }
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) { return runOne(data, size, fuzzOne); }
