// Random clothoid arcs as blend end conditions, shared by the fair-blend tests and
// bench/bench_fair_blend.cpp: C- and S-shaped, 5 to 300 degrees of turning, random scale,
// placement, orientation and mirror image, in the XY plane or a random 3D plane. The
// clothoid is integrated independently of the kernel (Simpson's rule on the angle).
#pragma once
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <random>

#include "fairsplines/fair_blend.hpp"

namespace fairsplines::test {

using Eigen::Vector2d;
using Eigen::Vector3d;

constexpr double kPi = 3.14159265358979323846;

/// An independent clothoid integrator: Simpson's rule with 20000 intervals on the angle.
inline Vector2d clothoidPoint(double theta0, double kappa0, double dkappa, double s) {
  const int n = 20000;
  const double h = s / n;
  Vector2d sum = Vector2d::Zero();
  for (int i = 0; i <= n; ++i) {
    const double x = i * h, th = theta0 + x * (kappa0 + 0.5 * dkappa * x);
    const double w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
    sum += w * Vector2d(std::cos(th), std::sin(th));
  }
  return sum * h / 3.0;
}

/// A random clothoid arc as G1 (and G2) end data, in a random plane, scale and placement.
struct Arc {
  BlendEnds ends;
  double kappa0 = 0, kappa1 = 0;  // signed about ends.normal (kept for G2)
  double absTurning = 0;          // integral of |kappa| ds, radians
  double turning = 0;             // integral of kappa ds, radians
  bool sShaped = false;
};

inline Arc randomArc(std::mt19937& rng, bool threeD) {
  std::uniform_real_distribution<double> U(0.0, 1.0);
  Arc a;
  a.sShaped = U(rng) < 0.4;
  const double total = (5.0 + 295.0 * U(rng)) * kPi / 180.0;  // integral |kappa| ds over unit length
  double k0, k1;
  if (a.sShaped) {  // opposite signs: |k0| + |k1| from the split of the total
    const double f = 0.1 + 0.8 * U(rng);
    // integral |kappa| of a line through k0 < 0 < k1 over [0, 1] = (k0^2 + k1^2) / (2 (k1 - k0)).
    const double r = f / (1.0 - f);  // |k0| / k1
    k1 = 2.0 * total * (1.0 + r) / (r * r + 1.0);
    k0 = -r * k1;
  } else {
    const double f = U(rng);  // k0 = f * 2 total, k1 = (1 - f) * 2 total: (k0 + k1) / 2 = total
    k0 = 2.0 * total * f;
    k1 = 2.0 * total * (1.0 - f);
  }
  if (U(rng) < 0.5) std::swap(k0, k1);
  if (U(rng) < 0.5) k0 = -k0, k1 = -k1;  // mirror image
  const double theta0 = 2.0 * kPi * U(rng);
  const Vector2d q1 = clothoidPoint(theta0, k0, k1 - k0, 1.0);
  const double theta1 = theta0 + 0.5 * (k0 + k1);
  const double scale = std::pow(10.0, -3.0 + 6.0 * U(rng));
  Vector3d e1 = Vector3d::UnitX(), e2 = Vector3d::UnitY(), n = Vector3d::UnitZ();
  if (threeD) {
    n = Vector3d(U(rng) - 0.5, U(rng) - 0.5, U(rng) - 0.5).normalized();
    e1 = n.unitOrthogonal();
    e2 = n.cross(e1);
  }
  const Vector3d origin = std::pow(10.0, -2.0 + 4.0 * U(rng)) * Vector3d(U(rng) - 0.5, U(rng) - 0.5, U(rng) - 0.5);
  a.ends.p0 = origin;
  a.ends.p1 = origin + scale * (q1.x() * e1 + q1.y() * e2);
  a.ends.t0 = std::cos(theta0) * e1 + std::sin(theta0) * e2;
  a.ends.t1 = std::cos(theta1) * e1 + std::sin(theta1) * e2;
  a.ends.normal = n;
  a.kappa0 = k0 / scale;
  a.kappa1 = k1 / scale;
  a.absTurning = total;
  a.turning = 0.5 * (k0 + k1);
  return a;
}

}  // namespace fairsplines::test
