// Fair fit (fair_fit.hpp, issue 16): samples as the csr harness makes them, or a dense
// noisy arc, line or S-curve of up to 512 samples (the data the fit is for); any
// tolerance and noise, open or closed, end tangents and curvatures of any dimension,
// fairing on or off. Beyond the contract (InputError, or a finite curve OCCT accepts): the
// tolerance is a hard bound, so a returned curve must report a largest deviation within it.
#include "fairsplines/fair_fit.hpp"
#include "fuzz_check.hpp"
#include "fuzz_input.hpp"

using namespace fairsplines;
using namespace fairsplines::fuzz;

namespace {

/// n (4 to 512) samples of an arc of radius r turning by `turn` (radians), a straight line (turn 0), or
/// an S (the second half turning back), with uniform noise of amplitude `noise`.
PointMatrix denseCurve(FuzzInput& in) {
  const int n = 4 + in.u16() % 509;
  const int dim = 2 + (in.byte() & 1);
  const double r = in.positive(), turn = in.number(), noise = in.byte() < 192 ? in.unit() * 1e-2 : in.number();
  const bool s = in.flag();
  PointMatrix q = PointMatrix::Zero(n, dim);
  Eigen::Vector2d p(0.0, 0.0);
  double angle = 0.0;
  uint32_t state = in.u16() + 1u;  // a small deterministic generator for the noise
  auto uniform = [&] {
    state = state * 1664525u + 1013904223u;
    return (state >> 8) / 8388608.0 - 1.0;  // [-1, 1)
  };
  const double step = r / n;
  for (int i = 0; i < n; ++i) {
    q(i, 0) = p.x() + noise * uniform();
    q(i, 1) = p.y() + noise * uniform();
    if (dim == 3) q(i, 2) = noise * uniform() + (in.byte() < 250 ? 0.0 : in.number());
    angle += (s && 2 * i > n ? -turn : turn) / n;
    p += step * Eigen::Vector2d(std::cos(angle), std::sin(angle));
  }
  return q;
}

std::optional<Eigen::VectorXd> endVector(FuzzInput& in, Eigen::Index dim) {
  switch (in.choice(8)) {
    case 0:
      return in.numbers(dim);
    case 1:
      return in.numbers(in.count(0, 4));  // any dimension
    default:
      return std::nullopt;
  }
}

}  // namespace

int fuzzOne(FuzzInput& in) {
  const PointMatrix q = in.byte() < 96 ? samplePoints(in, 64) : denseCurve(in);
  FairFitOptions options;
  options.closed = in.byte() < 64;
  const double size = q.rows() > 0 ? (q.colwise().maxCoeff() - q.colwise().minCoeff()).norm() : 1.0;
  options.tolerance = in.byte() < 192 ? size * std::pow(10.0, -1.0 - in.byte() % 8) : in.number();
  if (in.flag()) options.noise = in.byte() < 192 ? in.unit() * options.tolerance : in.number();
  options.startTangent = endVector(in, q.cols());
  options.endTangent = endVector(in, q.cols());
  if (in.byte() < 64) options.startCurvature = endVector(in, q.cols());
  if (in.byte() < 64) options.endCurvature = endVector(in, q.cols());
  options.fairing = in.byte() < 224;
  note("points", q);
  note("closed", options.closed);
  note("tolerance", options.tolerance);
  note("noise", options.noise ? *options.noise : -1.0);
  note("start tangent", options.startTangent ? *options.startTangent : Eigen::VectorXd());
  note("end tangent", options.endTangent ? *options.endTangent : Eigen::VectorXd());
  note("start curvature", options.startCurvature ? *options.startCurvature : Eigen::VectorXd());
  note("end curvature", options.endCurvature ? *options.endCurvature : Eigen::VectorXd());
  note("fairing", options.fairing);

  FairFitResult r;
  const char* call = "fairFitReport";
  if (!guarded(call, [&] { r = fairFitReport(q, options); })) return 0;
  requireValid(call, r.curve);
  requireFinite(call, "largest deviation", r.maxDeviation);
  requireFinite(call, "noise", r.noise);
  if (!(r.maxDeviation <= options.tolerance)) fail(call, "a sample lies beyond the tolerance");
  if (r.signChanges < 0 || r.dataSignChanges < 0 || r.curvatureExtrema < 0) fail(call, "a negative count");
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) { return runOne(data, size, fuzzOne); }
