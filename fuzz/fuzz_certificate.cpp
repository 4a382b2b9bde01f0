// The exact monotonicity certificates (certifyMonotoneCurvature, and certifySpaceCurvature
// for space curves) and the curvature variation of arbitrary B-splines: degrees 1 to 7, polynomial or rational, clamped, unclamped or
// periodic, in the plane, in a tilted plane or not planar; mostly well-formed (knots
// increasing, multiplicities that fit the pole count), sometimes any structure at all.
// For cubics also the derivative polygons (eqs. (3), (5)) and the per-segment conditions.
#include <algorithm>

#include <Eigen/Geometry>

#include "fairsplines/monotone.hpp"
#include "fuzz_check.hpp"
#include "fuzz_input.hpp"

using namespace fairsplines;
using namespace fairsplines::fuzz;

namespace {

BSplineCurve wellFormed(FuzzInput& in) {
  BSplineCurve c;
  c.degree = in.count(1, 7);
  c.periodic = in.byte() < 64;
  const int k = in.count(2, 8);  // distinct knots
  c.knots = in.increasing(k, in.byte() < 128 ? 0.0 : in.number());
  if (in.byte() < 32) c.knots *= in.number();
  c.mults.resize(k);
  for (int i = 0; i < k; ++i) c.mults[i] = in.byte() < 160 ? 1 : in.count(1, c.degree);
  int poles = 0;
  if (c.periodic) {
    c.mults[k - 1] = c.mults[0];
    poles = c.mults.sum() - c.mults[k - 1];
  } else {
    if (in.byte() < 224) c.mults[0] = c.mults[k - 1] = c.degree + 1;  // clamped
    poles = c.mults.sum() - c.degree - 1;
  }
  poles = std::clamp(poles, 0, 32);
  c.poles.resize(poles, 2);
  for (int i = 0; i < poles; ++i) c.poles.row(i) = in.vector2().transpose();
  if (in.byte() < 128) {
    c.weights.resize(poles);
    for (int i = 0; i < poles; ++i) c.weights[i] = in.byte() < 64 ? 1.0 : in.positive();
  }
  return c;
}

BSplineCurve anyStructure(FuzzInput& in) {
  BSplineCurve c;
  c.degree = in.count(-1, 9);
  c.periodic = in.flag();
  const int n = in.count(0, 12), dim = in.count(0, 4);
  c.poles.resize(n, dim);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < dim; ++j) c.poles(i, j) = in.number();
  c.knots = in.numbers(in.count(0, 8));
  c.mults.resize(in.byte() < 224 ? c.knots.size() : in.count(0, 8));
  for (Eigen::Index i = 0; i < c.mults.size(); ++i) c.mults[i] = in.count(-1, 9);
  if (in.flag()) c.weights = in.numbers(in.byte() < 224 ? n : in.count(0, 12));
  return c;
}

/// Planar poles (2 columns) into space: the plane z = 0, a tilted plane, or off any plane.
void placeInSpace(FuzzInput& in, BSplineCurve& c) {
  const int how = in.choice(4);
  if (how == 0) return;  // 2 columns
  PointMatrix p = PointMatrix::Zero(c.poles.rows(), 3);
  p.leftCols(2) = c.poles;
  if (how == 2) {
    const double angle = in.number();
    const Eigen::Vector3d axis = in.vector3().normalized();
    const Eigen::Matrix3d rotation = Eigen::Matrix3d(Eigen::AngleAxisd(angle, axis));
    if (rotation.allFinite()) p = (p * rotation.transpose()).eval();
  } else if (how == 3) {
    for (Eigen::Index i = 0; i < p.rows(); ++i) p(i, 2) = in.byte() < 200 ? 0.0 : in.number();
  }
  c.poles = p;
}

}  // namespace

int fuzzOne(FuzzInput& in) {
  BSplineCurve curve;
  if (in.byte() < 224) {
    curve = wellFormed(in);
    placeInSpace(in, curve);
  } else {
    curve = anyStructure(in);
  }
  const double relTol = in.byte() < 224 ? 1e-12 : in.number();
  note("curve", curve);
  note("relTol", relTol);

  MonotonicityCertificate cert;
  bool singular = false;
  if (guarded("certifyMonotoneCurvature", [&] { cert = certifyMonotoneCurvature(curve, relTol); })) {
    const char* call = "certifyMonotoneCurvature";
    requireFinite(call, "normal", cert.normal);
    for (size_t i = 0; i < cert.spans.size(); ++i) {
      const SpanCertificate& s = cert.spans[i];
      requireFinite(call, "span range", Eigen::Vector2d(s.u0, s.u1));
      if (s.trend == CurvatureTrend::Singular) {  // curvature undefined there: documented
        singular = true;
        continue;
      }
      requireFinite(call, "span end curvature", Eigen::Vector2d(s.kappa0, s.kappa1));
      requireFinite(call, "span 'at'", Eigen::Vector2d(s.at, s.kappaAt));
    }
    if (!singular) requireFinite(call, "end curvature", Eigen::Vector2d(cert.kappaStart, cert.kappaEnd));
    if (cert.monotone && singular) fail(call, "monotone with a singular span");
  }
  // The space certificate (issue 28) of the same curve: planar or not, polynomial or rational.
  SpaceCurvatureCertificate space;
  if (guarded("certifySpaceCurvature", [&] { space = certifySpaceCurvature(curve, relTol); })) {
    const char* call = "certifySpaceCurvature";
    bool spaceSingular = false;
    for (const SpaceSpanCertificate& s : space.spans) {
      requireFinite(call, "span range", Eigen::Vector2d(s.u0, s.u1));
      if (s.trend == CurvatureTrend::Singular) {
        spaceSingular = true;
        continue;
      }
      requireFinite(call, "span end curvature", Eigen::Vector2d(s.kappa0, s.kappa1));
      requireFinite(call, "span 'at'", Eigen::Vector2d(s.at, s.kappaAt));
      if (s.kappa0 < 0.0 || s.kappa1 < 0.0) fail(call, "a negative curvature");
      for (double u : s.torsionChanges) requireFinite(call, "torsion change", u);
    }
    for (const auto& [u, kappa, maximum] : space.extrema) requireFinite(call, "extremum", Eigen::Vector2d(u, kappa));
    for (double u : space.torsionSignChanges) requireFinite(call, "torsion sign change", u);
    if (space.monotone && spaceSingular) fail(call, "monotone with a singular span");
  }
  double variation = 0.0;
  if (guarded("curvatureVariation", [&] { variation = curvatureVariation(curve); }) && !singular) {
    requireFinite("curvatureVariation", "variation", variation);
  }
  if (curve.degree == 3 && !curve.periodic && !curve.isRational()) {
    DerivativePolygons d;
    if (guarded("derivativePolygons", [&] { d = derivativePolygons(curve); })) {
      requireFinite("derivativePolygons", "first derivative control point", d.first);
      requireFinite("derivativePolygons", "second derivative control point", d.second);
    }
    std::vector<SegmentReport> reports;
    if (guarded("checkSegments", [&] { reports = checkSegments(curve); })) {
      for (const SegmentReport& r : reports) {
        requireFinite("checkSegments", "segment range", Eigen::Vector2d(r.u0, r.u1));
        describe(r.check);
      }
    }
  }
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) { return runOne(data, size, fuzzOne); }
