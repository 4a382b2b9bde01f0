// Fair blends (fair_blend.hpp): G1 ends (points and tangent directions: the clothoid
// followed by a certified C2 cubic) and G2 ends (also signed curvatures: the fairest
// monotone spiral), with the plane normal derived or given.
#include "fairsplines/fair_blend.hpp"
#include "fuzz_check.hpp"
#include "fuzz_input.hpp"

using namespace fairsplines;
using namespace fairsplines::fuzz;

namespace {

Eigen::Vector3d planar(FuzzInput& in, double length) {
  const double angle = in.number();
  return length * Eigen::Vector3d(std::cos(angle), std::sin(angle), 0.0);
}

}  // namespace

int fuzzOne(FuzzInput& in) {
  BlendEnds ends;
  const bool inPlane = in.byte() < 224;
  if (inPlane) {
    ends.p0 = in.planar3();
    ends.p1 = ends.p0 + planar(in, in.positive());
    ends.t0 = planar(in, in.byte() < 128 ? 1.0 : in.positive());
    ends.t1 = planar(in, in.byte() < 128 ? 1.0 : in.positive());
  } else {
    ends.p0 = in.vector3();
    ends.p1 = in.vector3();
    ends.t0 = in.vector3();
    ends.t1 = in.vector3();
  }
  switch (in.choice(4)) {
    case 0:  // G1
      break;
    case 1:  // G2
    case 2:
      ends.k0 = in.number();
      ends.k1 = in.number();
      break;
    default:  // only one curvature (refused), or any
      ends.k0 = in.number();
      if (in.flag()) ends.k1 = in.number();
      break;
  }
  switch (in.choice(4)) {
    case 0:
    case 1:
      break;  // derived
    case 2:
      ends.normal = Eigen::Vector3d(0.0, 0.0, in.flag() ? 1.0 : -1.0);
      break;
    default:
      ends.normal = in.vector3();
      break;
  }
  note("p0", ends.p0);
  note("t0", ends.t0);
  note("p1", ends.p1);
  note("t1", ends.t1);
  note("k0", ends.k0);
  note("k1", ends.k1);
  note("normal", ends.normal);

  FairBlend blend;
  const char* call = "fairBlend";
  if (!guarded(call, [&] { blend = fairBlend(ends); })) return 0;
  requireValid(call, blend.curve);
  requireFinite(call, "normal", blend.normal);
  requireFinite(call, "end curvature", Eigen::Vector2d(blend.kappa0, blend.kappa1));
  requireFinite(call, "turning", blend.turning);
  requireFinite(call, "length", blend.length);
  requireFinite(call, "variation", blend.variation);
  for (const SpanCertificate& s : blend.certificate.spans) {
    requireFinite(call, "certificate span range", Eigen::Vector2d(s.u0, s.u1));
    if (s.trend != CurvatureTrend::Singular)
      requireFinite(call, "certificate curvature", Eigen::Vector2d(s.kappa0, s.kappa1));
  }
  if (blend.monotone != blend.certificate.monotone) fail(call, "monotone differs from the certificate's");
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) { return runOne(data, size, fuzzOne); }
