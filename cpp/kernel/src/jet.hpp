// Internal: a forward-mode differentiation type for the analytic centre of Algorithm 2
// (analytic_centre.cpp): a value with its gradient and Hessian in four unknowns, and the
// arithmetic, square root, logarithm and atan2 on it (exact second derivatives).
#pragma once
#include <Eigen/Core>
#include <cmath>

namespace fairsplines::detail {

/// Forward-mode jet with gradient and Hessian in the four unknowns.
struct Jet {
  double v = 0.0;
  Eigen::Vector4d g = Eigen::Vector4d::Zero();
  Eigen::Matrix4d h = Eigen::Matrix4d::Zero();
  Jet() = default;
  Jet(double value) : v(value) {}  // NOLINT: constants
};

inline Jet operator+(const Jet& a, const Jet& b) {
  Jet r;
  r.v = a.v + b.v;
  r.g = a.g + b.g;
  r.h = a.h + b.h;
  return r;
}
inline Jet operator-(const Jet& a, const Jet& b) {
  Jet r;
  r.v = a.v - b.v;
  r.g = a.g - b.g;
  r.h = a.h - b.h;
  return r;
}
inline Jet operator*(const Jet& a, const Jet& b) {
  Jet r;
  r.v = a.v * b.v;
  r.g = a.v * b.g + b.v * a.g;
  r.h = a.v * b.h + b.v * a.h + a.g * b.g.transpose() + b.g * a.g.transpose();
  return r;
}
inline Jet operator*(double s, const Jet& a) {
  Jet r;
  r.v = s * a.v;
  r.g = s * a.g;
  r.h = s * a.h;
  return r;
}
inline Jet operator*(const Jet& a, double s) { return s * a; }
/// f(a) with f, f', f'' at a.v.
inline Jet chain(const Jet& a, double f, double f1, double f2) {
  Jet r;
  r.v = f;
  r.g = f1 * a.g;
  r.h = f1 * a.h + f2 * a.g * a.g.transpose();
  return r;
}
inline Jet operator/(const Jet& a, const Jet& b) {
  return a * chain(b, 1.0 / b.v, -1.0 / (b.v * b.v), 2.0 / (b.v * b.v * b.v));
}
inline Jet sqrt(const Jet& a) {
  const double s = std::sqrt(a.v);
  return chain(a, s, 0.5 / s, -0.25 / (s * a.v));
}
inline Jet log(const Jet& a) { return chain(a, std::log(a.v), 1.0 / a.v, -1.0 / (a.v * a.v)); }
inline Jet atan2(const Jet& y, const Jet& x) {
  const double r2 = x.v * x.v + y.v * y.v, r4 = r2 * r2;
  const double fy = x.v / r2, fx = -y.v / r2;
  const double fyy = -2.0 * x.v * y.v / r4, fxx = 2.0 * x.v * y.v / r4, fxy = (y.v * y.v - x.v * x.v) / r4;
  Jet r;
  r.v = std::atan2(y.v, x.v);
  r.g = fy * y.g + fx * x.g;
  r.h = fy * y.h + fx * x.h + fyy * y.g * y.g.transpose() + fxx * x.g * x.g.transpose() +
        fxy * (x.g * y.g.transpose() + y.g * x.g.transpose());
  return r;
}

}  // namespace fairsplines::detail
