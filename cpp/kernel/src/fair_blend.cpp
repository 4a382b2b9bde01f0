// Fair blends: the G1 Hermite clothoid followed by a certified C2 cubic; see fair_blend.hpp
// and docs/FAIR_BLENDS.md.
#include "fairsplines/fair_blend.hpp"

#include <BSplCLib.hxx>
#include <Geom_BSplineCurve.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <math_Matrix.hxx>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <tuple>
#include <utility>
#include <vector>

#include "fairsplines/errors.hpp"
#include "fairsplines/occt.hpp"
#include "clothoid.hpp"
#include "finite.hpp"
#include "spiral.hpp"
#include "work_budget.hpp"

namespace fairsplines {
namespace {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
using detail::Clothoid;
using detail::kPi;

// ---------------------------------------------------------------------------------------
// The plane of the blend.

struct Plane {
  Vec3 origin, e1, e2, normal;  // e1 along the chord, e2 = normal x e1
  Vec2 local(const Vec3& v) const { return {v.dot(e1), v.dot(e2)}; }
};

/// The plane of the ends; throws InputError where there is none or it is ambiguous.
Plane planeOf(const BlendEnds& e, bool curvaturesGiven) {
  requireFiniteInput(e.p0, "p0");
  requireFiniteInput(e.p1, "p1");
  requireFiniteInput(e.t0, "t0");
  requireFiniteInput(e.t1, "t1");
  requireFiniteInput(e.normal, "the normal");
  const Vec3 d = e.p1 - e.p0;
  const double scale = std::max(e.p0.cwiseAbs().maxCoeff(), e.p1.cwiseAbs().maxCoeff());
  if (!(d.norm() > 1e-14 * std::max(scale, 1e-300)))
    throw InputError("the end points p0 and p1 coincide: a blend needs two points");
  if (!(e.t0.norm() > 0.0)) throw InputError("the start tangent t0 is zero");
  if (!(e.t1.norm() > 0.0)) throw InputError("the end tangent t1 is zero");
  const Vec3 u = d.normalized(), a = e.t0.normalized(), b = e.t1.normalized();
  Plane p;
  p.origin = e.p0;
  p.e1 = u;
  if (e.normal.norm() > 0.0) {
    p.normal = e.normal.normalized();
  } else if (std::abs(u.z()) <= 1e-12 && std::abs(a.z()) <= 1e-12 && std::abs(b.z()) <= 1e-12) {
    p.normal = Vec3::UnitZ();  // data in a plane parallel to XY: +Z, as the designer sees it
  } else {
    // The plane of the chord and the tangent farthest from it.
    const Vec3 na = u.cross(a), nb = u.cross(b);
    const Vec3 n = na.norm() >= nb.norm() ? na : nb;
    if (!(n.norm() > 1e-12)) {  // all along the chord: any plane through it
      Vec3 any = std::abs(u.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
      p.normal = u.cross(any).normalized();
    } else {
      if (curvaturesGiven) {
        throw InputError(
            "the ends are not in the XY plane: give the plane normal, which decides the sign of the "
            "end curvatures");
      }
      p.normal = n.normalized();
    }
  }
  const auto outOfPlane = [&](const Vec3& v) { return std::abs(v.dot(p.normal)) > 1e-9; };
  if (outOfPlane(u)) throw InputError("the end points do not lie in one plane with the normal");
  if (outOfPlane(a)) throw InputError("the start tangent t0 leaves the blend's plane");
  if (outOfPlane(b)) throw InputError("the end tangent t1 leaves the blend's plane");
  p.e1 = (u - u.dot(p.normal) * p.normal).normalized();
  p.e2 = p.normal.cross(p.e1);
  return p;
}

// ---------------------------------------------------------------------------------------
// The reference circle: the symmetric rational quadratic of the clothoid's total turning
// Theta, over u in [0, 1]. Its weight w(u) and its arc length sigma(u) (as a fraction of
// the whole) make the homogeneous target w (Q(L sigma(u)), 1) a quadratic polynomial when
// the clothoid is that circle, so the C2 cubic below reproduces circles exactly and its
// error elsewhere scales with the clothoid's departure from a circle.
//   angle psi(u) = Theta / 2 + 2 atan(t (2u - 1)), t = tan(Theta / 4),
//   w(u) = (1 + t^2 (2u - 1)^2) / (1 + t^2),   sigma = psi / Theta.

struct Jet1 {
  double v = 0.0, d1 = 0.0, d2 = 0.0;
};

struct ReferenceCircle {
  double Theta = 0.0, t = 0.0;
  // Beyond 1.75 pi the weights of the middle would fall towards 0: the reference turns
  // that much at most (the construction stays valid; circles of more turning are then
  // followed, not reproduced).
  explicit ReferenceCircle(double turning)
      : Theta(std::clamp(turning, -1.75 * kPi, 1.75 * kPi)), t(std::tan(0.25 * Theta)) {}
  Jet1 weight(double u) const {
    const double v = 2.0 * u - 1.0, q = 1.0 + t * t;
    return {(1.0 + t * t * v * v) / q, 4.0 * t * t * v / q, 8.0 * t * t / q};
  }
  /// The u where sigma(u) = fraction.
  double parameterAt(double fraction) const {
    if (Theta == 0.0) return fraction;
    return 0.5 * (1.0 + std::tan((fraction - 0.5) * 0.5 * Theta) / t);
  }
  Jet1 sigma(double u) const {
    if (Theta == 0.0) return {u, 1.0, 0.0};
    const double v = 2.0 * u - 1.0, den = 1.0 + t * t * v * v;
    return {0.5 + 2.0 * std::atan(t * v) / Theta, 4.0 * t / (Theta * den), -16.0 * t * t * t * v / (Theta * den * den)};
  }
};

// ---------------------------------------------------------------------------------------
// The C2 cubic following the guide curve (the G1 clothoid, or a G2 spiral).

constexpr int kMaxRounds = 12;       // refinement rounds
constexpr int kMaxSpans = 400;       // spans at the most
constexpr double kWorkBudget = 2e6;  // detail::WorkBudget units of one fairBlend

/// End data in the normalized plane (chord from (0, 0) to (1, 0)).
struct Ends2 {
  Vec2 p0, p1, T0, T1;  // unit tangents
  double k0, k1;
};

/// The first knots: m spans at equal arc lengths of the reference circle (its rational
/// parametrization runs up to 1 + t^2 times faster in the middle), as fractions sigma of
/// the length, plus one knot in the middle of each end span. The knots next to the ends
/// are not interpolated: they make room for the end 2-jets.
std::vector<double> firstKnots(int m) {
  std::vector<double> sigma{0.0, 0.5 / m};
  for (int j = 1; j < m; ++j) sigma.push_back(static_cast<double>(j) / m);
  sigma.push_back(1.0 - 0.5 / m);
  sigma.push_back(1.0);
  return sigma;
}

/// The C2 cubic on the knots u = ref.parameterAt(sigma) that follows the curve c (a
/// Clothoid or a Spiral: its length and point(s)): its homogeneous form
/// F = (w x, w y, w) interpolates the target at every interior knot but the first and
/// the last, and has the target's 2-jets at u = 0 and u = 1. nullopt when a control
/// weight is not positive.
template <class Curve>
std::optional<BSplineCurve> followCurve(const Curve& c, const ReferenceCircle& ref, const Ends2& e,
                                        const std::vector<double>& sigma) {
  const int K = static_cast<int>(sigma.size());  // distinct knots
  Eigen::VectorXd u(K);
  for (int i = 0; i < K; ++i) u[i] = ref.parameterAt(sigma[i]);
  u[0] = 0.0;
  u[K - 1] = 1.0;
  // Knots that do not separate (a reference circle degenerate in double precision, e.g. for
  // a denormal tangent angle) leave no basis to evaluate: no cubic on them.
  for (int i = 1; i < K; ++i) {
    if (!(u[i] - u[i - 1] > kRelativeKnotGap)) return std::nullopt;
  }
  const int n = K + 2;  // poles: spans + 3
  TColStd_Array1OfReal knots(1, n + 4);
  for (int i = 0; i < n + 4; ++i) knots(i + 1) = u[std::clamp(i - 3, 0, K - 1)];
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n);
  Eigen::MatrixXd B(n, 3);
  int row = 0;
  math_Matrix basis(1, 3, 1, 4);
  auto addRow = [&](double u, int order, const Eigen::Vector3d& rhs) {
    Standard_Integer first = 0;
    BSplCLib::EvalBsplineBasis(order, 4, knots, u, first, basis);
    for (int j = 0; j < 4; ++j) A(row, first - 1 + j) = basis(order + 1, j + 1);
    B.row(row++) = rhs.transpose();
  };
  // The homogeneous target's 2-jet at u from the point, unit tangent and curvature there.
  auto endRows = [&](double u, const Vec2& P, const Vec2& T, double kappa) {
    const Jet1 w = ref.weight(u), s = ref.sigma(u);
    const Vec2 N(-T.y(), T.x());
    const Vec2 X1 = c.length * s.d1 * T;
    const Vec2 X2 = c.length * s.d2 * T + c.length * c.length * s.d1 * s.d1 * kappa * N;
    const Vec2 F0 = w.v * P, F1 = w.d1 * P + w.v * X1, F2 = w.d2 * P + 2.0 * w.d1 * X1 + w.v * X2;
    addRow(u, 0, {F0.x(), F0.y(), w.v});
    addRow(u, 1, {F1.x(), F1.y(), w.d1});
    addRow(u, 2, {F2.x(), F2.y(), w.d2});
  };
  endRows(0.0, e.p0, e.T0, e.k0);
  for (int j = 2; j <= K - 3; ++j) {
    const Jet1 w = ref.weight(u[j]);
    const Vec2 P = c.point(c.length * sigma[j]);
    addRow(u[j], 0, {w.v * P.x(), w.v * P.y(), w.v});
  }
  endRows(1.0, e.p1, e.T1, e.k1);
  const Eigen::MatrixXd H = A.partialPivLu().solve(B);
  if (!H.allFinite() || !(H.col(2).minCoeff() > 0.0)) return std::nullopt;

  BSplineCurve curve;
  curve.degree = 3;
  curve.poles.resize(n, 2);
  for (int i = 0; i < n; ++i) curve.poles.row(i) << H(i, 0) / H(i, 2), H(i, 1) / H(i, 2);
  curve.poles.row(0) = e.p0.transpose();  // exact ends: the first and last poles are the points
  curve.poles.row(n - 1) = e.p1.transpose();
  if (ref.Theta != 0.0) {
    curve.weights = H.col(2);
    curve.weights /= curve.weights[0];
    curve.weights[0] = 1.0;
  }
  curve.knots = u;
  curve.mults.setOnes(K);
  curve.mults[0] = curve.mults[K - 1] = 4;
  return curve;
}

/// The straight segment as one cubic span, parametrized uniformly.
BSplineCurve segment(const Vec2& p0, const Vec2& p1) {
  BSplineCurve curve;
  curve.degree = 3;
  curve.poles.resize(4, 2);
  for (int i = 0; i < 4; ++i) curve.poles.row(i) = (p0 + (i / 3.0) * (p1 - p0)).transpose();
  curve.poles.row(3) = p1.transpose();
  curve.knots.resize(2);
  curve.knots << 0.0, 1.0;
  curve.mults.resize(2);
  curve.mults << 4, 4;
  return curve;
}

/// The local curve in the model: the end poles are the given points and the poles next to
/// them lie on the given tangents exactly (the end tangent of a B-spline, rational or not,
/// is the direction from the end pole to its neighbour).
BSplineCurve toModel(const BSplineCurve& local, const Plane& p, double r, const BlendEnds& e) {
  BSplineCurve out = local;
  const Eigen::Index n = local.poles.rows();
  out.poles.resize(n, 3);
  for (Eigen::Index i = 0; i < n; ++i) {
    out.poles.row(i) = (p.origin + r * (local.poles(i, 0) * p.e1 + local.poles(i, 1) * p.e2)).transpose();
  }
  const Vec3 t0 = e.t0.normalized(), t1 = e.t1.normalized();
  const Vec3 second = out.poles.row(1).transpose(), last2 = out.poles.row(n - 2).transpose();
  out.poles.row(0) = e.p0.transpose();
  out.poles.row(n - 1) = e.p1.transpose();
  out.poles.row(1) = (e.p0 + (second - e.p0).dot(t0) * t0).transpose();
  out.poles.row(n - 2) = (e.p1 - (e.p1 - last2).dot(t1) * t1).transpose();
  return out;
}

/// Signed curvature about n at the start (atEnd false) or the end of the curve, by OCCT.
double endCurvature(const BSplineCurve& curve, const Vec3& n, bool atEnd) {
  const Handle(Geom_BSplineCurve) c = toOcct(curve);
  gp_Pnt p;
  gp_Vec d1, d2;
  c->D2(atEnd ? c->LastParameter() : c->FirstParameter(), p, d1, d2);
  const gp_Vec x = d1.Crossed(d2);
  return (x.X() * n.x() + x.Y() * n.y() + x.Z() * n.z()) / std::pow(d1.Magnitude(), 3);
}

/// G2 ends to rounding: the end curvature of a B-spline, rational or not, is proportional
/// to the distance of the third pole from the tangent line through the first two, so that
/// distance is scaled by target / actual (one step is exact; the interior moves by the
/// 1e-9 that the solve left).
void matchEndCurvatures(BSplineCurve& curve, const Vec3& n, const BlendEnds& e) {
  const Eigen::Index last = curve.poles.rows() - 1;
  if (last < 5) return;
  for (const bool atEnd : {false, true}) {
    const double target = atEnd ? e.k1 : e.k0, actual = endCurvature(curve, n, atEnd);
    const Eigen::Index i1 = atEnd ? last - 1 : 1, i2 = atEnd ? last - 2 : 2;
    const Vec3 P1 = curve.poles.row(i1).transpose(), P2 = curve.poles.row(i2).transpose();
    const Vec3 t = (atEnd ? e.t1 : e.t0).normalized();
    const Vec3 along = (P2 - P1).dot(t) * t, across = (P2 - P1) - along;
    if (!(std::abs(actual) > 0.0)) {
      if (target == 0.0) continue;
      return;  // nothing to scale: left as solved
    }
    curve.poles.row(i2) = (P1 + along + (target / actual) * across).transpose();
  }
}

/// Curvature extrema the certificate shows: one inside every span where kappa' changes sign,
/// and one at every knot where the spans on its two sides run opposite ways.
int curvatureExtrema(const MonotonicityCertificate& cert) {
  int extrema = 0, direction = 0;  // +1 rising, -1 falling, 0 not yet known
  for (const SpanCertificate& span : cert.spans) {
    int entering = 0, leaving = 0;
    if (span.trend == CurvatureTrend::Increasing) entering = leaving = 1;
    if (span.trend == CurvatureTrend::Decreasing) entering = leaving = -1;
    if (span.trend == CurvatureTrend::Extremum) {
      ++extrema;
      entering = span.maximum ? 1 : -1;
      leaving = -entering;
    }
    if (entering != 0 && direction != 0 && entering != direction) ++extrema;
    if (leaving != 0) direction = leaving;
  }
  return extrema;
}

std::string describeTrend(const MonotonicityCertificate& cert) {
  if (cert.increasing && cert.decreasing) return "constant";
  return cert.increasing ? "increasing" : "decreasing";
}

/// The cubic that follows c, certified: spans are halved where the certificate does not
/// prove the curvature to run the way `wanted` (with two neighbours on each side), until it
/// does or the limits are reached (refine = false: one try). Returns the last cubic and
/// whether it was proved monotone.
template <class Curve>
std::pair<BSplineCurve, bool> certifiedFollow(const Curve& c, double turning, const Ends2& e, CurvatureTrend wanted,
                                              bool refine) {
  const ReferenceCircle ref(turning);
  std::vector<double> sigma = firstKnots(refine ? 4 : 8);
  BSplineCurve local;
  for (int round = 0; round < kMaxRounds && static_cast<int>(sigma.size()) - 1 <= kMaxSpans; ++round) {
    // Each round certifies every span: a span costs about as much as 64 Gauss panels.
    detail::WorkBudget::spend(64.0 * static_cast<double>(sigma.size()));
    std::optional<BSplineCurve> candidate = followCurve(c, ref, e, sigma);
    std::vector<double> refined{sigma[0]};
    const int spans = static_cast<int>(sigma.size()) - 1;
    std::vector<char> halve(spans, 0);
    if (!candidate) {  // a control weight is not positive: halve every span
      std::fill(halve.begin(), halve.end(), 1);
    } else {
      local = std::move(*candidate);
      const MonotonicityCertificate cert = certifyMonotoneCurvature(local);
      if (cert.monotone) return {local, true};
      if (!refine) break;
      // The error of a span comes from its neighbours too: halve two spans on each side.
      for (int i = 0; i < spans; ++i) {
        const CurvatureTrend t = cert.spans[i].trend;
        if (t == wanted || t == CurvatureTrend::Constant) continue;
        for (int k = std::max(0, i - 2); k <= std::min(spans - 1, i + 2); ++k) halve[k] = 1;
      }
    }
    for (int i = 0; i < spans; ++i) {
      if (halve[i]) refined.push_back(0.5 * (sigma[i] + sigma[i + 1]));
      refined.push_back(sigma[i + 1]);
    }
    sigma = std::move(refined);
  }
  if (local.poles.rows() == 0) {
    throw InputError("no cubic following the guide curve has positive weights (turning " +
                     std::to_string(turning * 180.0 / kPi) + " degrees)");
  }
  return {local, false};
}

}  // namespace

FairBlend fairBlend(const BlendEnds& ends) {
  const bool g2 = !std::isnan(ends.k0) || !std::isnan(ends.k1);
  if (g2 && (std::isnan(ends.k0) || std::isnan(ends.k1))) {
    throw InputError("give both end curvatures k0 and k1 for a G2 blend, or neither for G1");
  }
  if (g2 && !(std::isfinite(ends.k0) && std::isfinite(ends.k1))) throw InputError("the end curvatures must be finite");
  const Plane plane = planeOf(ends, g2);
  // The solve's work budget (Gauss panels, clothoid pieces, certified spans): far above
  // what the test sets' blends need, well under a second of work in a release build.
  detail::WorkBudget budget(kWorkBudget, "the fair blend of these ends");
  // Normalized: chord from (0, 0) to (1, 0); lengths scale by 1 / r, curvatures by r.
  const double r = (ends.p1 - ends.p0).norm();
  const Vec2 a = plane.local(ends.t0).normalized(), b = plane.local(ends.t1).normalized();
  const double theta0 = std::atan2(a.y(), a.x()), theta1 = std::atan2(b.y(), b.x());

  FairBlend out;
  out.normal = plane.normal;
  BSplineCurve local;
  std::ostringstream why;
  const bool straight = std::abs(theta0) <= 1e-14 && std::abs(theta1) <= 1e-14;
  if (straight && (!g2 || (ends.k0 == 0.0 && ends.k1 == 0.0))) {
    local = segment(Vec2::Zero(), Vec2::UnitX());
    out.length = r;
    why << "straight ends: the segment";
  } else if (!g2) {
    const Clothoid c = detail::clothoidG1(Vec2::Zero(), theta0, Vec2::UnitX(), theta1);
    const Ends2 e{Vec2::Zero(), Vec2::UnitX(), a, b, c.kappa0, c.kappa(c.length)};
    out.length = c.length * r;
    out.turning = c.theta(c.length) - c.theta0;
    const CurvatureTrend wanted = c.dkappa > 0.0 ? CurvatureTrend::Increasing : CurvatureTrend::Decreasing;
    bool proved = false;
    std::tie(local, proved) = certifiedFollow(c, out.turning, e, wanted, true);
    why << "G1 clothoid (turning " << out.turning * 180.0 / kPi << " degrees) followed by " << local.knots.size() - 1
        << " C2 spans";
    if (!proved) why << ", not all proved monotone";
  } else {
    // The curvatures in chord units: beyond kMaxChordCurvature the radius is below a
    // millionth of the chord (no blend to speak of); below kZeroChordCurvature the end is
    // straight, as far as double precision can tell (a denormal curvature would give 0/0).
    constexpr double kMaxChordCurvature = 1e6, kZeroChordCurvature = 1e-15;
    auto chordCurvature = [&](double k, const char* name) {
      const double kr = k * r;
      if (!(std::abs(kr) <= kMaxChordCurvature)) {
        throw InputError(std::string("the end curvature ") + name + " = " + exactNumber(k) +
                         " is too large for the chord " + exactNumber(r) +
                         ": its radius would be below a millionth of the chord");
      }
      return std::abs(kr) < kZeroChordCurvature ? 0.0 : kr;
    };
    const double k0 = chordCurvature(ends.k0, "k0"), k1 = chordCurvature(ends.k1, "k1");
    const Ends2 e{Vec2::Zero(), Vec2::UnitX(), a, b, k0, k1};
    const detail::SpiralSolution sol = detail::solveG2Spiral(theta0, k0, theta1, k1);
    const CurvatureTrend wanted = k1 > k0 ? CurvatureTrend::Increasing : CurvatureTrend::Decreasing;
    if (sol.spline) {
      const detail::ClothoidSpline& s = *sol.spline;
      out.length = s.length * r;
      out.turning = s.theta(s.length) - s.theta0;
      bool proved = false;
      std::tie(local, proved) = certifiedFollow(s, out.turning, e, wanted, true);
      why << "G2 clothoid spline (" << s.pieces() << " pieces, turning " << out.turning * 180.0 / kPi
          << " degrees) followed by " << local.knots.size() - 1 << " C2 spans";
    } else if (sol.monotone) {
      const detail::Spiral& s = *sol.monotone;
      out.length = s.length * r;
      out.turning = s.theta(s.length) - s.theta0;
      bool proved = false;
      std::tie(local, proved) = certifiedFollow(s, out.turning, e, wanted, true);
      why << "G2 spiral (curvature cubic in arc length, turning " << out.turning * 180.0 / kPi
          << " degrees) followed by " << local.knots.size() - 1 << " C2 spans";
    } else {
      // No monotone curve: of the non-monotone spiral found and the G1 clothoid with the
      // given end curvatures (both G2 at the ends), the one with the fewest curvature
      // extrema, then the least variation.
      struct Fallback {
        BSplineCurve curve;
        double length, turning;
        int extrema;
        double variation;
        const char* what;
      };
      std::vector<Fallback> fallbacks;
      auto consider = [&](const auto& guide, double length, double turning, const char* what) {
        BSplineCurve curve = certifiedFollow(guide, turning, e, wanted, false).first;
        const int extrema = curvatureExtrema(certifyMonotoneCurvature(curve));
        const double variation = curvatureVariation(curve);
        fallbacks.push_back({std::move(curve), length, turning, extrema, variation, what});
      };
      if (sol.fallback) {
        const detail::Spiral& s = *sol.fallback;
        consider(s, s.length, s.theta(s.length) - s.theta0, "the spiral found");
      }
      const Clothoid c = detail::clothoidG1(Vec2::Zero(), theta0, Vec2::UnitX(), theta1);
      consider(c, c.length, c.theta(c.length) - c.theta0, "the G1 clothoid with the given end curvatures");
      const Fallback& best =
          *std::min_element(fallbacks.begin(), fallbacks.end(), [](const Fallback& x, const Fallback& y) {
            return x.extrema != y.extrema ? x.extrema < y.extrema : x.variation < y.variation;
          });
      local = best.curve;
      out.length = best.length * r;
      out.turning = best.turning;
      why << "no monotone-curvature curve "
          << (sol.reason.empty() ? "was found for these G2 ends" : "meets these G2 ends: " + sol.reason)
          << "; the fairest found instead (" << best.what << ", " << best.extrema << " curvature extrema)";
    }
  }
  out.reason = why.str();
  out.curve = toModel(local, plane, r, ends);
  if (g2) matchEndCurvatures(out.curve, plane.normal, ends);
  out.spans = static_cast<int>(out.curve.knots.size()) - 1;
  out.certificate = certifyMonotoneCurvature(out.curve);
  out.monotone = out.certificate.monotone;
  const double sign = out.certificate.normal.dot(plane.normal) < 0.0 ? -1.0 : 1.0;
  out.kappa0 = sign * out.certificate.kappaStart;
  out.kappa1 = sign * out.certificate.kappaEnd;
  out.variation = curvatureVariation(out.curve);
  if (out.monotone)
    out.reason += "; curvature " + describeTrend(out.certificate) + ", certified";
  else
    out.reason += "; " + out.certificate.reason;  // the certificate says "not monotone: ..."
  return out;
}

}  // namespace fairsplines
