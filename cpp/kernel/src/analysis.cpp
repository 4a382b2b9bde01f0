#include "fairsplines/analysis.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>

#include "finite.hpp"

namespace fairsplines {

namespace {

Eigen::Vector3d toEigen(const gp_Pnt& p) { return {p.X(), p.Y(), p.Z()}; }

/// Where the poles are and how far they spread: offsets from the first pole, divided by a
/// power of two at least half their largest coordinate spread (finite.hpp, powerOfTwoScale).
/// The division is exact and the offsets are at most 2 in size, so the squares and cubes of
/// lengths in the numerics below neither overflow nor underflow: a curve 1e300 or 1e-300 in
/// size is measured by meaning, not by accident.
struct PoleFrame {
  Eigen::Vector3d origin;  ///< the first pole, divided by `scale`
  double scale = 1.0;
  Eigen::Vector3d offset(const gp_Pnt& p) const { return toEigen(p) / scale - origin; }
};

/// Throws InputError("the curve does not move ...") when the poles coincide to double precision.
PoleFrame poleFrame(const Handle(Geom_BSplineCurve)& curve) {
  const Eigen::Vector3d first = toEigen(curve->Pole(1));
  double half = 0.0, magnitude = 0.0;  // half the spread: no overflow near the largest doubles
  for (int i = 1; i <= curve->NbPoles(); ++i) {
    const Eigen::Vector3d p = toEigen(curve->Pole(i));
    half = std::max(half, (0.5 * p - 0.5 * first).cwiseAbs().maxCoeff());
    magnitude = std::max(magnitude, p.cwiseAbs().maxCoeff());
  }
  if (belowRounding(half, 0.5 * magnitude)) {
    throw InputError("the curve does not move: all its poles coincide to double precision");
  }
  PoleFrame frame;
  frame.scale = powerOfTwoScale(half);
  frame.origin = first / frame.scale;
  return frame;
}

/// A copy of the curve moved and scaled by its PoleFrame (weights and knots unchanged).
Handle(Geom_BSplineCurve) normalizedCopy(const Handle(Geom_BSplineCurve)& curve, const PoleFrame& frame) {
  Handle(Geom_BSplineCurve) copy = Handle(Geom_BSplineCurve)::DownCast(curve->Copy());
  for (int i = 1; i <= curve->NbPoles(); ++i) {
    const Eigen::Vector3d p = frame.offset(curve->Pole(i));
    copy->SetPole(i, gp_Pnt(p[0], p[1], p[2]));
  }
  return copy;
}

double speed(const Handle(Geom_BSplineCurve)& curve, double u) {
  gp_Pnt p;
  gp_Vec d1;
  curve->D1(u, p, d1);
  return d1.Magnitude();
}

/// Arc length between two parameters by 5-point Gauss-Legendre quadrature.
double arcLength(const Handle(Geom_BSplineCurve)& curve, double a, double b) {
  static const double x[5] = {0.0, -0.5384693101056831, 0.5384693101056831, -0.9061798459386640, 0.9061798459386640};
  static const double w[5] = {0.5688888888888889, 0.4786286704993665, 0.4786286704993665, 0.2369268850561891,
                              0.2369268850561891};
  const double mid = 0.5 * (a + b), half = 0.5 * (b - a);
  double sum = 0.0;
  for (int k = 0; k < 5; ++k) sum += w[k] * speed(curve, mid + half * x[k]);
  return sum * half;
}

/// Parameter values of the curve's knot spans over [first, last].
std::vector<double> spanBreaks(const Handle(Geom_BSplineCurve)& curve) {
  const double first = curve->FirstParameter(), last = curve->LastParameter();
  std::vector<double> breaks;
  for (int i = 1; i <= curve->NbKnots(); ++i) {
    const double k = curve->Knot(i);
    if (k >= first && k <= last) breaks.push_back(k);
  }
  return breaks;
}

}  // namespace

double curvature3D(const gp_Vec& d1, const gp_Vec& d2) {
  const double speed = d1.Magnitude();
  return d1.Crossed(d2).Magnitude() / (speed * speed * speed);
}

double signedCurvature(const gp_Vec& d1, const gp_Vec& d2, const gp_Vec& n) {
  const double speed = d1.Magnitude();
  return d1.Crossed(d2).Dot(n) / (speed * speed * speed);
}

std::optional<gp_Vec> planeNormal(const Handle(Geom_BSplineCurve)& curve, double relTol) {
  const int n = curve->NbPoles();
  const PoleFrame frame = poleFrame(curve);  // offsets of size <= 2: the covariance is finite
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero(), lo = Eigen::Vector3d::Zero(), hi = lo;
  for (int i = 1; i <= n; ++i) {
    const Eigen::Vector3d d = frame.offset(curve->Pole(i));
    centroid += d;
    lo = lo.cwiseMin(d);
    hi = hi.cwiseMax(d);
  }
  centroid /= n;
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (int i = 1; i <= n; ++i) {
    const Eigen::Vector3d d = frame.offset(curve->Pole(i)) - centroid;
    cov += d * d.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  Eigen::Vector3d normal = eig.eigenvectors().col(0);  // smallest spread
  const double size = (hi - lo).norm();                // the bounding box's diagonal, in the frame's units
  double offPlane = 0.0;
  for (int i = 1; i <= n; ++i)
    offPlane = std::max(offPlane, std::abs((frame.offset(curve->Pole(i)) - centroid).dot(normal)));
  if (offPlane > relTol * size) return std::nullopt;
  // A curve in a plane parallel to a coordinate plane gets exactly that axis as normal.
  for (int axis = 0; axis < 3; ++axis) {
    if (std::abs(std::abs(normal[axis]) - 1.0) < 1e-12) normal = Eigen::Vector3d::Unit(axis);
  }
  for (int axis = 2; axis >= 0; --axis) {  // orient: z, then y, then x non-negative
    if (std::abs(normal[axis]) > 1e-12) {
      if (normal[axis] < 0) normal = -normal;
      break;
    }
  }
  return gp_Vec(normal[0], normal[1], normal[2]);
}

CurvatureProfile curvatureProfile(const Handle(Geom_BSplineCurve)& curve, int n, int minPerSpan) {
  const std::vector<double> breaks = spanBreaks(curve);
  const double total = breaks.back() - breaks.front();
  std::vector<double> u;
  for (size_t k = 0; k + 1 < breaks.size(); ++k) {
    const double a = breaks[k], b = breaks[k + 1];
    const int m = std::max(minPerSpan, static_cast<int>(std::ceil(n * (b - a) / total)));
    for (int j = 0; j < m; ++j) u.push_back(a + (b - a) * j / m);
  }
  u.push_back(breaks.back());

  // Curvature and arc length are measured on the curve scaled to size about 1 and scaled
  // back (kappa = kappa' / scale, s = s' scale): a curve of size 1e300 or 1e-300 gets its
  // curvature, not 0/0.
  const PoleFrame frame = poleFrame(curve);
  const Handle(Geom_BSplineCurve) unit = normalizedCopy(curve, frame);
  CurvatureProfile profile;
  const std::optional<gp_Vec> normal = planeNormal(unit);
  profile.isSigned = normal.has_value();
  profile.normal = normal.value_or(gp_Vec(0, 0, 1));
  const Eigen::Index count = static_cast<Eigen::Index>(u.size());
  profile.u = Eigen::Map<const Eigen::VectorXd>(u.data(), count);
  profile.s.resize(count);
  profile.kappa.resize(count);
  double length = 0.0;
  for (Eigen::Index j = 0; j < count; ++j) {
    gp_Pnt p;
    gp_Vec d1, d2;
    unit->D2(u[j], p, d1, d2);
    const double kappa = profile.isSigned ? signedCurvature(d1, d2, profile.normal) : curvature3D(d1, d2);
    if (!std::isfinite(kappa)) {
      throw InputError("the curvature is undefined at u = " + exactNumber(u[j]) +
                       ": the curve's derivative vanishes there (coincident poles?)");
    }
    if (j > 0) length += arcLength(unit, u[j - 1], u[j]);
    profile.kappa[j] = kappa / frame.scale;
    profile.s[j] = length * frame.scale;
  }
  // The boundary rule: a curvature or length beyond double precision is refused by name.
  requireFinite(profile.kappa, "the curve's curvature profile", "curvatures");
  requireFinite(profile.s, "the curve's curvature profile", "arc lengths");
  return profile;
}

int curvatureSignChanges(const CurvatureProfile& profile, double zeroTol) {
  if (!profile.isSigned || profile.kappa.size() == 0) return 0;
  const double length = profile.s[profile.s.size() - 1];
  const double threshold = std::max(zeroTol * profile.kappa.cwiseAbs().maxCoeff(), 1e-10 / length);
  int changes = 0, lastSign = 0;
  for (Eigen::Index j = 0; j < profile.kappa.size(); ++j) {
    const double k = profile.kappa[j];
    if (std::abs(k) <= threshold) continue;
    const int sign = k > 0 ? 1 : -1;
    if (lastSign != 0 && sign != lastSign) ++changes;
    lastSign = sign;
  }
  return changes;
}

std::vector<CurvatureExtremum> curvatureExtrema(const CurvatureProfile& profile) {
  std::vector<CurvatureExtremum> out;
  const Eigen::Index n = profile.kappa.size();
  if (n < 3) return out;
  const double length = profile.s[n - 1];
  const double tol = 1e-12 * profile.kappa.cwiseAbs().maxCoeff() + 1e-12 / length;
  const auto& k = profile.kappa;
  for (Eigen::Index j = 1; j + 1 < n; ++j) {
    const bool isMax = k[j] - k[j - 1] > tol && k[j] - k[j + 1] > tol;
    const bool isMin = k[j - 1] - k[j] > tol && k[j + 1] - k[j] > tol;
    if (!isMax && !isMin) continue;
    // Vertex of the parabola through the three samples (in u).
    const double u0 = profile.u[j - 1], u1 = profile.u[j], u2 = profile.u[j + 1];
    const double d01 = (k[j] - k[j - 1]) / (u1 - u0), d12 = (k[j + 1] - k[j]) / (u2 - u1);
    const double second = (d12 - d01) / (u2 - u0);
    double u = u1, kappa = k[j];
    if (second != 0.0) {
      u = std::clamp(0.5 * (u0 + u1) - d01 / (2.0 * second), u0, u2);
      kappa = k[j] + (u - u1) * (d01 + second * (u - u0));
    }
    const double s = u <= u1 ? profile.s[j - 1] + (profile.s[j] - profile.s[j - 1]) * (u - u0) / (u1 - u0)
                             : profile.s[j] + (profile.s[j + 1] - profile.s[j]) * (u - u1) / (u2 - u1);
    out.push_back({u, s, kappa, isMax});
  }
  return out;
}

double maxDistanceToPoints(const Handle(Geom_BSplineCurve)& curve, PointsRef q) {
  // Every span gets a box from 9 samples, padded by a quarter of its diagonal (ample for
  // a cubic span); only spans whose box is nearer than the best distance so far are
  // searched.
  const std::vector<double> breaks = spanBreaks(curve);
  const int spans = static_cast<int>(breaks.size()) - 1;
  std::vector<Eigen::Vector3d> lo(spans), hi(spans);
  for (int k = 0; k < spans; ++k) {
    // Sample-based box, widened by the span's chord deviation bound: robust for
    // periodic and rational curves alike.
    Eigen::Vector3d l = Eigen::Vector3d::Constant(1e300), h = -l;
    for (int j = 0; j <= 8; ++j) {
      const Eigen::Vector3d p = toEigen(curve->Value(breaks[k] + (breaks[k + 1] - breaks[k]) * j / 8.0));
      l = l.cwiseMin(p);
      h = h.cwiseMax(p);
    }
    const double pad = 0.25 * (h - l).norm();
    lo[k] = l.array() - pad;
    hi[k] = h.array() + pad;
  }
  auto spanDistance = [&](const Eigen::Vector3d& p, int k) {
    double lower = 1e300;
    double u = breaks[k];
    for (int j = 0; j <= 8; ++j) {  // sample, then Newton on (C(u) - p) . C'(u) = 0
      const double uj = breaks[k] + (breaks[k + 1] - breaks[k]) * j / 8.0;
      const double d = (toEigen(curve->Value(uj)) - p).norm();
      if (d < lower) {
        lower = d;
        u = uj;
      }
    }
    for (int it = 0; it < 30; ++it) {
      gp_Pnt c;
      gp_Vec d1, d2;
      curve->D2(u, c, d1, d2);
      const gp_Vec r(gp_Pnt(p[0], p[1], p[2]), c);
      const double f = r.Dot(d1), df = d1.Dot(d1) + r.Dot(d2);
      if (df <= 0.0) break;
      const double next = std::clamp(u - f / df, breaks[k], breaks[k + 1]);
      if (std::abs(next - u) <= 1e-15 * (1.0 + std::abs(u))) break;
      u = next;
    }
    return std::min(lower, (toEigen(curve->Value(u)) - p).norm());
  };
  double worst = 0.0;
  std::vector<double> bound(spans);
  for (Eigen::Index i = 0; i < q.rows(); ++i) {
    const Eigen::Vector3d p(q(i, 0), q(i, 1), q.cols() > 2 ? q(i, 2) : 0.0);
    int nearest = 0;
    for (int k = 0; k < spans; ++k) {
      bound[k] = (lo[k] - p).cwiseMax(p - hi[k]).cwiseMax(0.0).norm();
      if (bound[k] < bound[nearest]) nearest = k;
    }
    double best = spanDistance(p, nearest);
    for (int k = 0; k < spans; ++k) {
      if (k != nearest && bound[k] < best) best = std::min(best, spanDistance(p, k));
    }
    worst = std::max(worst, best);
  }
  return worst;
}

}  // namespace fairsplines
