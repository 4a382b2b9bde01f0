#include "fairsplines/basic_curves.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "fairsplines/errors.hpp"
#include "bernstein.hpp"

namespace fairsplines {

namespace {

constexpr double kPi = 3.14159265358979323846;

std::string describe(const Eigen::Vector3d& p) {
  std::ostringstream out;
  out << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
  return out.str();
}

/// Homogeneous control point of weight w at the affine point p.
Eigen::RowVector4d homogeneous(const Eigen::Vector3d& p, double w) { return {w * p.x(), w * p.y(), w * p.z(), w}; }

void checkSweep(double sweep, const char* what) {
  if (!std::isfinite(sweep) || std::abs(sweep) <= 0.0 || std::abs(sweep) >= 2.0 * kPi) {
    std::ostringstream msg;
    msg << "degenerate " << what << ": the sweep angle must be in (0, 2 pi) in magnitude, got " << sweep;
    throw InputError(msg.str());
  }
}

/// The boundary rule for a basic curve: at 65 samples of [0, 1] its points and first two
/// derivatives are finite (a size or range whose evaluation overflows is refused), and its
/// extent is more than 1e-12 of its coordinates' size (below that the curve is a point in
/// double precision: tangents and parameters would be 0/0). Relative, so that a curve of
/// size 1e-300 near the origin is as good as one of size 1e300. A curve that does not move
/// at all (extent 0) may be let through (`still`): the designs refuse it by that name.
void requireEvaluable(const BasicCurve& curve, const char* what, bool still = false) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(HUGE_VAL), hi = -lo;
  for (int j = 0; j <= 64; ++j) {
    const double u = j / 64.0;
    const Eigen::Vector3d p = curve.value(u), d1 = curve.d1(u), d2 = curve.d2(u);
    if (!p.allFinite() || !d1.allFinite() || !d2.allFinite()) {
      std::ostringstream msg;
      msg << "the " << what << " is too large for double precision: its " << (!p.allFinite() ? "points" : "derivatives")
          << " would overflow (at u = " << u << ")";
      throw InputError(msg.str());
    }
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double extent = (hi - lo).stableNorm(), scale = std::max(lo.cwiseAbs().maxCoeff(), hi.cwiseAbs().maxCoeff());
  if (!std::isfinite(extent)) {
    throw InputError("the " + std::string(what) + " is too large for double precision: its extent overflows");
  }
  if (!(extent > 1e-12 * scale) && !(still && extent == 0.0)) {
    std::ostringstream msg;
    msg << "degenerate " << what << ": its extent " << extent << " is below the precision of its coordinates (" << scale
        << "): too small, or too far from the origin, for double precision";
    throw InputError(msg.str());
  }
}

/// The boundary rule for a parameter found: finite, or the curve is refused.
double requireFiniteParameter(double u, const Eigen::Vector3d& q) {
  if (!std::isfinite(u))
    throw InputError("the parameter of point " + describe(q) + " is not finite in double precision");
  return u;
}

}  // namespace

void Frame::check() const {
  if (!origin.allFinite() || !x.allFinite() || !y.allFinite()) throw InputError("the curve's placement is not finite");
  if (std::abs(x.norm() - 1.0) > 1e-9 || std::abs(y.norm() - 1.0) > 1e-9 || std::abs(x.dot(y)) > 1e-9) {
    throw InputError("the curve's placement needs two orthonormal directions");
  }
}

double BasicCurve::size() const {
  Eigen::Vector3d lo = value(0.0), hi = lo;
  for (int j = 1; j <= 64; ++j) {
    const Eigen::Vector3d p = value(j / 64.0);
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return (hi - lo).stableNorm();  // no overflow of the squares for a curve 1e300 in size
}

double BasicCurve::parameterOf(const Eigen::Vector3d& q, double tolerance) const {
  // Eq. (5): minimise |f(u) - q|^2 on [0, 1]. Coarse sampling brackets the minimum, then
  // Newton on g(u) = (f(u) - q) . f'(u), falling back to bisection of g inside the bracket.
  if (!q.allFinite()) throw InputError("the marked point is not finite");
  constexpr int samples = 128;
  int best = 0;
  double bestDistance = 1e300;
  for (int j = 0; j <= samples; ++j) {
    const double d = (value(static_cast<double>(j) / samples) - q).squaredNorm();
    if (d < bestDistance) {
      bestDistance = d;
      best = j;
    }
  }
  double lo = std::max(0, best - 1) / static_cast<double>(samples);
  double hi = std::min(samples, best + 1) / static_cast<double>(samples);
  auto g = [&](double u) { return (value(u) - q).dot(d1(u)); };
  double u = static_cast<double>(best) / samples;
  for (int it = 0; it < 60; ++it) {
    const Eigen::Vector3d r = value(u) - q, f1 = d1(u);
    const double gu = r.dot(f1), dg = f1.squaredNorm() + r.dot(d2(u));
    // Keep the bracket [lo, hi] around the root of g where g changes sign.
    if (g(lo) * gu <= 0.0)
      hi = u;
    else if (g(hi) * gu <= 0.0)
      lo = u;
    double next = dg > 0.0 ? u - gu / dg : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    if (std::abs(next - u) <= 1e-15) {
      u = next;
      break;
    }
    u = next;
  }
  // The end points are candidates too (the minimum may sit on the boundary).
  for (double end : {0.0, 1.0}) {
    if ((value(end) - q).squaredNorm() < (value(u) - q).squaredNorm()) u = end;
  }
  const double distance = (value(u) - q).norm();
  if (distance > tolerance * size()) {
    std::ostringstream msg;
    msg << "point " << describe(q) << " is not on the curve: it is " << distance << " away";
    throw InputError(msg.str());
  }
  return requireFiniteParameter(u, q);
}

RationalBezierCurve::RationalBezierCurve(HomogeneousBezier homogeneous, const char* what) : h_(std::move(homogeneous)) {
  if (h_.rows() < 2 || h_.rows() > 4) throw InputError("a rational Bézier basic curve has degree 1 to 3");
  if (!h_.allFinite()) {
    throw InputError("the " + std::string(what) + "'s homogeneous control points are not finite: its numbers are " +
                     "not finite or too large for double precision");
  }
  // The weight polynomial must keep one sign on [0, 1]; make it positive.
  double lo = 1e300, hi = -1e300;
  for (int j = 0; j <= 256; ++j) {
    Eigen::Vector4d f, df, d2f;
    jets(j / 256.0, f, df, d2f);
    lo = std::min(lo, f[3]);
    hi = std::max(hi, f[3]);
  }
  if (hi < 0.0) {
    h_ = -h_;
    std::swap(lo, hi);
    lo = -lo;
    hi = -hi;
  }
  if (lo <= 1e-12 * std::max(1.0, hi)) {
    throw InputError("the weight function of the " + std::string(what) + " vanishes on [0, 1]");
  }
  requireEvaluable(*this, what);
}

void RationalBezierCurve::jets(double u, Eigen::Vector4d& f, Eigen::Vector4d& df, Eigen::Vector4d& d2f) const {
  // de Casteljau down to degree 2 (for the second derivative), then 1, then the point.
  const int n = static_cast<int>(h_.rows()) - 1;
  Eigen::Matrix<double, 4, 4> b = Eigen::Matrix<double, 4, 4>::Zero();  // columns: control points (n + 1 used)
  for (int j = 0; j <= n; ++j) b.col(j) = h_.row(j).transpose();
  const double s = 1.0 - u;
  d2f.setZero();
  for (int level = n; level >= 1; --level) {
    if (level == 2) d2f = n * (n - 1) * (b.col(2) - 2.0 * b.col(1) + b.col(0));
    if (level == 1) df = n * (b.col(1) - b.col(0));
    for (int j = 0; j < level; ++j) b.col(j) = s * b.col(j) + u * b.col(j + 1);
  }
  f = b.col(0);
}

Eigen::Vector3d RationalBezierCurve::value(double u) const {
  Eigen::Vector4d f, df, d2f;
  jets(u, f, df, d2f);
  return f.head<3>() / f[3];
}

Eigen::Vector3d RationalBezierCurve::d1(double u) const {
  Eigen::Vector4d f, df, d2f;
  jets(u, f, df, d2f);
  const Eigen::Vector3d p = f.head<3>() / f[3];
  return (df.head<3>() - df[3] * p) / f[3];
}

Eigen::Vector3d RationalBezierCurve::d2(double u) const {
  Eigen::Vector4d f, df, d2f;
  jets(u, f, df, d2f);
  const Eigen::Vector3d p = f.head<3>() / f[3];
  const Eigen::Vector3d p1 = (df.head<3>() - df[3] * p) / f[3];
  return (d2f.head<3>() - 2.0 * df[3] * p1 - d2f[3] * p) / f[3];
}

std::optional<HomogeneousBezier> RationalBezierCurve::homogeneousCubic() const {
  return bernstein::raise(h_, 3);  // degree elevation
}

std::unique_ptr<RationalBezierCurve> lineSegment(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1) {
  if (!p0.allFinite() || !p1.allFinite()) throw InputError("the line segment's end points are not finite");
  // Scale-free: compared in units of the larger coordinate, so that points near the
  // largest doubles do not overflow (their difference may not be representable).
  const double scale = std::max({p0.cwiseAbs().maxCoeff(), p1.cwiseAbs().maxCoeff(), 1e-300});
  const Eigen::Vector3d a = p0 / scale, b = p1 / scale;
  if (!((b - a).norm() * scale < std::numeric_limits<double>::infinity())) {
    std::ostringstream msg;
    msg << "the line segment is too long for double precision: its end points are " << (b - a).norm() << " x " << scale
        << " apart";
    throw InputError(msg.str());
  }
  if ((b - a).norm() <= 1e-14 * std::max({1.0 / scale, a.norm(), b.norm()})) {
    throw InputError("degenerate line segment: its end points coincide");
  }
  HomogeneousBezier h(2, 4);
  h.row(0) = homogeneous(p0, 1.0);
  h.row(1) = homogeneous(p1, 1.0);
  return std::make_unique<RationalBezierCurve>(h, "line segment");
}

namespace {

/// Symmetric rational quadratic through frame points: unit-circle-like arcs scaled by
/// (a, b): ends at angle `start` and `start + sweep`, middle weight cos(sweep / 2). The
/// middle point is stored homogeneously, so a half arc (weight 0) is fine.
HomogeneousBezier ellipticQuadratic(const Frame& frame, double a, double b, double start, double sweep) {
  const double half = 0.5 * sweep, mid = start + half;
  HomogeneousBezier h(3, 4);
  h.row(0) = homogeneous(frame.at(a * std::cos(start), b * std::sin(start)), 1.0);
  // w1 * P1 with P1 = (a cos(mid), b sin(mid)) / cos(half) relative to the origin.
  const Eigen::Vector3d w1P1 = std::cos(half) * frame.origin + frame.dir(a * std::cos(mid), b * std::sin(mid));
  h.row(1) << w1P1.x(), w1P1.y(), w1P1.z(), std::cos(half);
  h.row(2) = homogeneous(frame.at(a * std::cos(start + sweep), b * std::sin(start + sweep)), 1.0);
  return h;
}

HomogeneousBezier checkedCircle(const Frame& frame, double radius, double start, double sweep) {
  frame.check();
  checkSweep(sweep, "circle arc");
  if (!(radius > 0.0) || !std::isfinite(radius)) throw InputError("degenerate circle arc: the radius must be positive");
  // Its points and derivatives reach a few radii from the origin (the rest is checked by
  // requireEvaluable on the samples).
  if (!(radius + frame.origin.cwiseAbs().maxCoeff() < std::numeric_limits<double>::max() / 64.0)) {
    std::ostringstream msg;
    msg << "radius " << radius << " is too large: the curve's points would overflow";
    throw InputError(msg.str());
  }
  return ellipticQuadratic(frame, radius, radius, start, sweep);
}

}  // namespace

CircleArc::CircleArc(const Frame& frame, double radius, double start, double sweep)
    : RationalBezierCurve(checkedCircle(frame, radius, start, sweep), "circle arc"),
      frame_(frame),
      radius_(radius),
      start_(start),
      sweep_(sweep) {}

double CircleArc::parameterOf(const Eigen::Vector3d& q, double tolerance) const {
  if (!q.allFinite()) throw InputError("the marked point is not finite");
  const Eigen::Vector3d d = q - frame_.origin;
  const double x = d.dot(frame_.x), y = d.dot(frame_.y);
  const Eigen::Vector3d normal = frame_.x.cross(frame_.y);
  const double off = std::hypot(std::hypot(x, y) - radius_, d.dot(normal));
  if (off > tolerance * 2.0 * radius_) {
    std::ostringstream msg;
    msg << "point " << describe(q) << " is not on the circle arc: it is " << off << " away";
    throw InputError(msg.str());
  }
  // Angle from the arc's start, in the arc's direction.
  const double alpha = std::abs(sweep_);
  double angle = std::atan2(y, x) - start_;
  if (sweep_ < 0.0) angle = -angle;
  angle = std::fmod(angle, 2.0 * kPi);
  if (angle < 0.0) angle += 2.0 * kPi;
  const double slack = 1e-12 + tolerance;
  if (angle > alpha + slack) {
    if (angle > 2.0 * kPi - slack) return 0.0;  // just before the start
    std::ostringstream msg;
    msg << "point " << describe(q) << " is on the circle but outside the arc";
    throw InputError(msg.str());
  }
  if (angle <= 0.0) return 0.0;
  if (angle >= alpha) return 1.0;
  // Eq. (4), with the case distinction that avoids dividing by zero.
  const double a2 = 0.5 * alpha;
  if (angle < kPi) {
    return requireFiniteParameter((std::sin(angle + a2) - std::sin(a2) - std::sin(angle)) /
                                      (2.0 * (std::cos(a2) - 1.0) * (std::sin(a2) + std::sin(angle))),
                                  q);
  }
  return requireFiniteParameter((1.0 + std::cos(angle + a2) - std::cos(a2) - std::cos(angle)) /
                                    (2.0 * (std::cos(a2) - 1.0) * (std::cos(a2) + std::cos(angle))),
                                q);
}

std::unique_ptr<RationalBezierCurve> ellipseArc(const Frame& frame, double a, double b, double start, double sweep) {
  frame.check();
  checkSweep(sweep, "ellipse arc");
  if (!(a > 0.0) || !(b > 0.0) || !std::isfinite(a) || !std::isfinite(b)) {
    throw InputError("degenerate ellipse arc: both radii must be positive");
  }
  return std::make_unique<RationalBezierCurve>(ellipticQuadratic(frame, a, b, start, sweep), "ellipse arc");
}

std::unique_ptr<RationalBezierCurve> parabolaArc(const Frame& frame, double focal, double t0, double t1) {
  frame.check();
  if (!(focal > 0.0) || !std::isfinite(focal))
    throw InputError("degenerate parabola arc: the focal length must be positive");
  if (!(t1 > t0) || !std::isfinite(t0) || !std::isfinite(t1)) {
    throw InputError("degenerate parabola arc: its parameter range must be increasing");
  }
  auto point = [&](double t) { return frame.at(t * t / (4.0 * focal), t); };
  const Eigen::Vector3d tangent0 = frame.dir(t0 / (2.0 * focal), 1.0);
  HomogeneousBezier h(3, 4);
  h.row(0) = homogeneous(point(t0), 1.0);
  h.row(1) = homogeneous(point(t0) + 0.5 * (t1 - t0) * tangent0, 1.0);
  h.row(2) = homogeneous(point(t1), 1.0);
  return std::make_unique<RationalBezierCurve>(h, "parabola arc");
}

std::unique_ptr<RationalBezierCurve> hyperbolaArc(const Frame& frame, double a, double b, double t0, double t1) {
  frame.check();
  if (!(a > 0.0) || !(b > 0.0) || !std::isfinite(a) || !std::isfinite(b)) {
    throw InputError("degenerate hyperbola arc: both radii must be positive");
  }
  if (!(t1 > t0) || !std::isfinite(t0) || !std::isfinite(t1)) {
    throw InputError("degenerate hyperbola arc: its parameter range must be increasing");
  }
  // The analogue of the circle: middle weight cosh(half) and w1 P1 = (a cosh(mid), b sinh(mid)).
  const double half = 0.5 * (t1 - t0), mid = t0 + half;
  HomogeneousBezier h(3, 4);
  h.row(0) = homogeneous(frame.at(a * std::cosh(t0), b * std::sinh(t0)), 1.0);
  const Eigen::Vector3d w1P1 = std::cosh(half) * frame.origin + frame.dir(a * std::cosh(mid), b * std::sinh(mid));
  h.row(1) << w1P1.x(), w1P1.y(), w1P1.z(), std::cosh(half);
  h.row(2) = homogeneous(frame.at(a * std::cosh(t1), b * std::sinh(t1)), 1.0);
  return std::make_unique<RationalBezierCurve>(h, "hyperbola arc");
}

ParametricCurve::ParametricCurve(Jet jet, double s0, double s1) : jet_(std::move(jet)), s0_(s0), s1_(s1) {
  if (!(s1 > s0) || !std::isfinite(s0) || !std::isfinite(s1)) {
    throw InputError("degenerate parametric curve: its parameter range must be increasing");
  }
  if (!std::isfinite(s1 - s0)) {
    std::ostringstream msg;
    msg << "the parametric curve's range [" << s0 << ", " << s1 << "] is too large for double precision";
    throw InputError(msg.str());
  }
  requireEvaluable(*this, "parametric curve", true);
}

Eigen::Vector3d ParametricCurve::value(double u) const {
  Eigen::Vector3d f, df, d2f;
  jet_(s0_ + u * (s1_ - s0_), f, df, d2f);
  return f;
}

Eigen::Vector3d ParametricCurve::d1(double u) const {
  Eigen::Vector3d f, df, d2f;
  jet_(s0_ + u * (s1_ - s0_), f, df, d2f);
  return df * (s1_ - s0_);
}

Eigen::Vector3d ParametricCurve::d2(double u) const {
  Eigen::Vector3d f, df, d2f;
  jet_(s0_ + u * (s1_ - s0_), f, df, d2f);
  return d2f * ((s1_ - s0_) * (s1_ - s0_));
}

std::unique_ptr<ParametricCurve> archimedeanSpiral(const Frame& frame, double a, double b, double theta0,
                                                   double theta1) {
  frame.check();
  if (!std::isfinite(a)) throw InputError("the spiral's a is not finite");
  if (!std::isfinite(b)) throw InputError("the spiral's b is not finite");
  if (b == 0.0) throw InputError("degenerate spiral: b must be non-zero");
  if (!(theta1 > theta0)) throw InputError("degenerate spiral: its angle range must be increasing");
  // r = a + b theta must not vanish inside the range (the spiral would pass its centre).
  const double r0 = a + b * theta0, r1 = a + b * theta1;
  if (r0 * r1 < 0.0 || std::abs(r0) < 1e-12 * std::abs(b) || std::abs(r1) < 1e-12 * std::abs(b)) {
    throw InputError("degenerate spiral: r = a + b theta vanishes in the angle range");
  }
  auto jet = [frame, a, b](double t, Eigen::Vector3d& f, Eigen::Vector3d& df, Eigen::Vector3d& d2f) {
    const double r = a + b * t, c = std::cos(t), s = std::sin(t);
    f = frame.at(r * c, r * s);
    df = frame.dir(b * c - r * s, b * s + r * c);
    d2f = frame.dir(-2.0 * b * s - r * c, 2.0 * b * c - r * s);
  };
  return std::make_unique<ParametricCurve>(jet, theta0, theta1);
}

std::unique_ptr<ParametricCurve> circleInvolute(const Frame& frame, double r, double t0, double t1) {
  frame.check();
  if (!(r > 0.0) || !std::isfinite(r)) throw InputError("degenerate involute: the radius must be positive");
  if (!(t1 > t0) || !(t0 >= 0.0))
    throw InputError("degenerate involute: its range must be increasing and start at t >= 0");
  auto jet = [frame, r](double t, Eigen::Vector3d& f, Eigen::Vector3d& df, Eigen::Vector3d& d2f) {
    const double c = std::cos(t), s = std::sin(t);
    f = frame.at(r * (c + t * s), r * (s - t * c));
    df = frame.dir(r * t * c, r * t * s);
    d2f = frame.dir(r * (c - t * s), r * (s + t * c));
  };
  return std::make_unique<ParametricCurve>(jet, t0, t1);
}

}  // namespace fairsplines
