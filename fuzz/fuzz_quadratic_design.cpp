// The quadratic design of Section 7, eq. (12): sparse samples to quadratic Bézier pieces
// with shape handles, open and closed, every parametrization, any epsilon.
#include "fairsplines/csr.hpp"
#include "fuzz_check.hpp"
#include "fuzz_input.hpp"

using namespace fairsplines;
using namespace fairsplines::fuzz;

int fuzzOne(FuzzInput& in) {
  const PointMatrix q = samplePoints(in, 64);
  const bool closed = in.flag();
  const auto parametrization = static_cast<Parametrization>(in.choice(3));
  const double epsilon = in.flag() ? in.number() : 1e-9;
  note("points", q);
  note("closed", closed);
  note("parametrization", static_cast<int>(parametrization));
  note("epsilon", epsilon);

  BSplineCurve curve;
  if (guarded("quadraticDesign", [&] { curve = quadraticDesign(q, parametrization, closed, epsilon); })) {
    requireValid("quadraticDesign", curve);
  }
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) { return runOne(data, size, fuzzOne); }
