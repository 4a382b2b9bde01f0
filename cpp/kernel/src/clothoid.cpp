// Clothoid arcs and the G1 Hermite clothoid of Bertolazzi & Frego (2015); see clothoid.hpp.
#include "clothoid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fairsplines::detail {

double normalizeAngle(double a) {
  a = std::remainder(a, 2.0 * kPi);
  return a <= -kPi ? a + 2.0 * kPi : a;
}

// ---------------------------------------------------------------------------------------
// Generalized Fresnel moments (Bertolazzi & Frego, eq. (9)).

FresnelMoments fresnelMoments(double a, double b, double c) {
  // The phase psi(tau) = a tau^2 / 2 + b tau + c turns at most max(|b|, |a + b|) per unit.
  const double rate = std::max(std::abs(b), std::abs(a + b));
  const int panels = std::max(1, static_cast<int>(std::ceil(rate / 0.5)));
  const double h = 1.0 / panels;
  FresnelMoments m{{0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}};
  for (int p = 0; p < panels; ++p) {
    const double mid = (p + 0.5) * h;
    for (int k = 0; k < 8; ++k) {
      const double tau = mid + (k < 4 ? -0.5 : 0.5) * h * kGaussX[k % 4];
      const double w = 0.5 * h * kGaussW[k % 4];
      const double psi = tau * (0.5 * a * tau + b) + c;
      const double cw = w * std::cos(psi), sw = w * std::sin(psi);
      m.X[0] += cw;
      m.Y[0] += sw;
      m.X[1] += tau * cw;
      m.Y[1] += tau * sw;
      m.X[2] += tau * tau * cw;
      m.Y[2] += tau * tau * sw;
    }
  }
  return m;
}

// ---------------------------------------------------------------------------------------
// Clothoid arcs.

Eigen::Vector2d Clothoid::point(double s) const {
  // x(s) = x0 + s X_0(dkappa s^2, kappa0 s, theta0), likewise y with Y_0.
  const FresnelMoments m = fresnelMoments(dkappa * s * s, kappa0 * s, theta0);
  return start + s * Eigen::Vector2d(m.X[0], m.Y[0]);
}

Eigen::Vector2d Clothoid::tangent(double s) const {
  const double t = theta(s);
  return {std::cos(t), std::sin(t)};
}

// ---------------------------------------------------------------------------------------
// The G1 Hermite problem (Bertolazzi & Frego, Section 3).

Clothoid clothoidG1(const Eigen::Vector2d& p0, double theta0, const Eigen::Vector2d& p1, double theta1) {
  const Eigen::Vector2d d = p1 - p0;
  const double r = d.norm(), phi = std::atan2(d.y(), d.x());
  const double phi0 = normalizeAngle(theta0 - phi), phi1 = normalizeAngle(theta1 - phi);
  const double delta = phi1 - phi0;

  // g(A) = Y_0(2A, delta - A, phi0), g'(A) = X_2 - X_1 (eq. (14) and its derivative).
  auto g = [&](double A, double* dg, double* x0) {
    const FresnelMoments m = fresnelMoments(2.0 * A, delta - A, phi0);
    if (dg) *dg = m.X[2] - m.X[1];
    if (x0) *x0 = m.X[0];
    return m.Y[0];
  };

  // The paper's first guess, eq. (17): A ~ (phi0 + phi1)(c1 + c2 phi0 phi1 + c3 (phi0^2 + phi1^2)).
  const double c1 = 3.070645, c2 = 0.947923, c3 = -0.673029;
  double A = (phi0 + phi1) * (c1 + c2 * phi0 * phi1 + c3 * (phi0 * phi0 + phi1 * phi1));
  for (int it = 0; it < 50; ++it) {
    double dg = 0.0;
    const double value = g(A, &dg, nullptr);
    if (value == 0.0 || !(std::abs(dg) > 1e-300)) break;
    const double cap = 1.0 + std::abs(A);  // no wild jumps where g is flat
    const double step = std::clamp(value / dg, -cap, cap);
    A -= step;
    if (std::abs(step) <= 1e-15 * (1.0 + std::abs(A))) break;
  }
  // Of all roots (each is a clothoid of turning delta through the ends), the fairest has
  // the least |A|: its scale-free variation L^3 int kappa'^2 ds is 4 A^2. g is smooth in A
  // (its phase moves by at most |tau^2 - tau| <= 1/4 per unit of A), so a scan in steps
  // of 1/2 from 0 outwards finds every sign change before |A| of Newton's root.
  auto refine = [&](double lo, double hi) {  // g(lo), g(hi) of opposite signs
    double glo = g(lo, nullptr, nullptr);
    for (int k = 0; k < 200 && std::abs(hi - lo) > 1e-15 * (1.0 + std::abs(lo)); ++k) {
      const double m = 0.5 * (lo + hi), gm = g(m, nullptr, nullptr);
      if ((gm <= 0.0) == (glo <= 0.0))
        lo = m, glo = gm;
      else
        hi = m;
    }
    return 0.5 * (lo + hi);
  };
  double newtonX0 = 0.0;
  const bool newtonRoot = std::abs(g(A, nullptr, &newtonX0)) < 1e-13 && newtonX0 > 0.0;
  const double reach = newtonRoot ? std::abs(A) : 4.0 * kPi + 3.0 * std::abs(phi0 + phi1);
  double best = A;
  bool found = newtonRoot;
  double prev[2] = {0.0, 0.0}, gPrev[2];
  gPrev[0] = gPrev[1] = g(0.0, nullptr, nullptr);
  for (double step = 0.5; step - 0.5 < reach; step += 0.5) {
    double nearest = std::numeric_limits<double>::quiet_NaN();
    for (int k = 0; k < 2; ++k) {  // k = 0: A > 0, k = 1: A < 0
      const double a = (k == 0 ? 1.0 : -1.0) * std::min(step, reach), ga = g(a, nullptr, nullptr);
      if (gPrev[k] == 0.0 || (gPrev[k] < 0.0) != (ga < 0.0)) {
        const double root = gPrev[k] == 0.0 ? prev[k] : refine(prev[k], a);
        double x0 = 0.0;
        g(root, nullptr, &x0);
        if (x0 > 0.0 && !(std::abs(root) >= std::abs(nearest))) nearest = root;
      }
      prev[k] = a, gPrev[k] = ga;
    }
    if (!std::isnan(nearest)) {  // the sign changes nearest to 0
      if (!found || std::abs(nearest) < std::abs(best)) best = nearest;
      found = true;
      break;
    }
  }
  A = best;
  double x0 = 0.0;
  g(A, nullptr, &x0);
  Clothoid c;
  c.start = p0;
  c.length = r / x0;
  c.theta0 = phi + phi0;
  c.kappa0 = (delta - A) / c.length;
  c.dkappa = 2.0 * A / (c.length * c.length);
  return c;
}

}  // namespace fairsplines::detail
