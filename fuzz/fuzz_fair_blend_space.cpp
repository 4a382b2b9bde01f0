// Fair blends in space (fair_blend.hpp, fairBlendSpace; issue 28): two ends anywhere in
// space, G1 (points and tangent directions) or G2 (also curvature vectors kappa N), mostly
// shaped as a designer's edges give them (unit or scaled tangents, curvature vectors across
// their tangents, at any scale and place), sometimes coplanar (the planar solver's path),
// sometimes nearly so, and sometimes any numbers at all. Checked: the documented refusals
// only, a valid finite cubic, its end points where they were asked for, and a report that
// agrees with its own certificate.
#include <Eigen/Geometry>

#include "fairsplines/fair_blend.hpp"
#include "fuzz_check.hpp"
#include "fuzz_input.hpp"

using namespace fairsplines;
using namespace fairsplines::fuzz;

namespace {

/// A unit vector from two angles (a direction a designer's edge could have).
Eigen::Vector3d direction(FuzzInput& in) {
  const double azimuth = in.number(), elevation = in.number();
  return Eigen::Vector3d(std::cos(elevation) * std::cos(azimuth), std::cos(elevation) * std::sin(azimuth),
                         std::sin(elevation));
}

/// A tangent: a unit direction, or one of any length.
Eigen::Vector3d tangent(FuzzInput& in) {
  const double length = in.byte() < 128 ? 1.0 : in.positive();
  return length * direction(in);
}

/// A curvature vector across the tangent t: kappa times the part of a direction normal to t
/// (sometimes zero: a straight end; sometimes along t: refused by name).
Eigen::Vector3d curvatureVector(FuzzInput& in, const Eigen::Vector3d& t) {
  switch (in.choice(8)) {
    case 0:
      return Eigen::Vector3d::Zero();
    case 1:
      return in.number() * t;
    case 2:
      return in.vector3();
    default: {
      const Eigen::Vector3d d = direction(in);
      const Eigen::Vector3d across = d - d.dot(t) / t.squaredNorm() * t;
      const double kappa = in.byte() < 128 ? in.positive() : in.number();
      return kappa * across.normalized();
    }
  }
}

}  // namespace

int fuzzOne(FuzzInput& in) {
  SpaceBlendEnds ends;
  const int shape = in.choice(8);
  if (shape < 6) {  // shaped: in space, or in one plane (shape 5), at any scale and place
    const double scale = in.byte() < 200 ? 1.0 : in.number();
    ends.p0 = in.vector3();
    const double chord = in.positive();  // (reads in sequence: operands' order is unspecified)
    ends.p1 = ends.p0 + scale * chord * direction(in);
    ends.t0 = tangent(in);
    ends.t1 = tangent(in);
    if (shape == 5) {  // project onto the plane z = p0.z: the planar solver's path
      ends.p1.z() = ends.p0.z();
      ends.t0.z() = 0.0;
      ends.t1.z() = 0.0;
    }
    if (in.flag()) {  // G2, curvatures scaled with the ends
      const double perLength = scale == 0.0 ? 1.0 : 1.0 / scale;
      ends.K0 = perLength * curvatureVector(in, ends.t0);
      ends.K1 = perLength * curvatureVector(in, ends.t1);
      if (shape == 5) ends.K0.z() = ends.K1.z() = 0.0;
    }
  } else {  // any numbers, one curvature vector only, NaN components...
    ends.p0 = in.vector3();
    ends.p1 = in.vector3();
    ends.t0 = in.vector3();
    ends.t1 = in.vector3();
    if (in.flag()) ends.K0 = in.vector3();
    if (in.flag()) ends.K1 = in.vector3();
  }
  note("p0", ends.p0);
  note("t0", ends.t0);
  note("K0", ends.K0);
  note("p1", ends.p1);
  note("t1", ends.t1);
  note("K1", ends.K1);

  SpaceFairBlend blend;
  const char* call = "fairBlendSpace";
  if (!guarded(call, [&] { blend = fairBlendSpace(ends); })) return 0;
  requireValid(call, blend.curve);
  requireFinite(call, "normal", blend.normal);
  requireFinite(call, "length", blend.length);
  requireFinite(call, "variation", blend.variation);
  const PointMatrix& poles = blend.curve.poles;
  if (poles.cols() != 3 || poles.rows() < 4) fail(call, "not a space cubic with at least 4 poles");
  // Points are exact: the first and last poles (documented), to rounding of the ends' size.
  const double size = std::max({ends.p0.cwiseAbs().maxCoeff(), ends.p1.cwiseAbs().maxCoeff(), 1e-300});
  if ((poles.row(0).transpose() - ends.p0).norm() > 1e-9 * size ||
      (poles.row(poles.rows() - 1).transpose() - ends.p1).norm() > 1e-9 * size)
    fail(call, "the end points moved");
  for (const SpaceSpanCertificate& s : blend.certificate.spans) {
    requireFinite(call, "certificate span range", Eigen::Vector2d(s.u0, s.u1));
    if (s.trend != CurvatureTrend::Singular)
      requireFinite(call, "certificate curvature", Eigen::Vector2d(s.kappa0, s.kappa1));
  }
  if (!blend.planar && blend.monotone != blend.certificate.monotone)
    fail(call, "monotone differs from the certificate's");
  if (!blend.planar && blend.curvatureExtrema != static_cast<int>(blend.certificate.extrema.size()))
    fail(call, "curvatureExtrema differs from the certificate's");
  if (blend.torsionSignChanges != static_cast<int>(blend.certificate.torsionSignChanges.size()))
    fail(call, "torsionSignChanges differs from the certificate's");
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) { return runOne(data, size, fuzzOne); }
