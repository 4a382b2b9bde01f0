// Algorithm 2's fairest solver (Karčiauskas & Peters, curves of monotone curvature): the
// hodograph of the five-pole curve, the ten Theorem 2 slacks, their log barrier, and the
// damped Newton iteration to its analytic centre (exact second derivatives by jet.hpp);
// declared in monotone_detail.hpp.
#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

#include "jet.hpp"
#include "monotone_common.hpp"
#include "monotone_detail.hpp"

namespace fairsplines {

using detail::Jet;
using detail::kPi;
using detail::Vec2;

// ---------------------------------------------------------------------------------------
// Algorithm 2: the hodograph of the five-pole curve and the Theorem 2 slacks.
//
// With knots (0,0,0,0,1,2,2,2,2), eqs. (3) and (5) give C^1 = (3 V0, 1.5 V1, 1.5 V2, 3 V3)
// =: (w0, D1, D2, D3) and C^2 = (E0, E1, E2) with D1 = w0 + E0/2, D2 = D1 + E1,
// D3 = D2 + E2/2, and C4 - C0 = 2 w0 + (5 E0 + 6 E1 + E2)/6. In the normalized frame
// w0 = (s, 0) and D3 = lambda T; the unknowns x = (s, lambda, E1) fix E0 and E2 linearly.

namespace {

using std::atan2;
using std::log;
using std::sqrt;

template <class T>
struct V {
  T x, y;
};
template <class T>
V<T> operator+(const V<T>& a, const V<T>& b) {
  return {a.x + b.x, a.y + b.y};
}
template <class T>
V<T> operator-(const V<T>& a, const V<T>& b) {
  return {a.x - b.x, a.y - b.y};
}
template <class T>
V<T> operator*(double s, const V<T>& a) {
  return {s * a.x, s * a.y};
}
template <class T>
T crossT(const V<T>& a, const V<T>& b) {
  return a.x * b.y - a.y * b.x;
}
template <class T>
T dotT(const V<T>& a, const V<T>& b) {
  return a.x * b.x + a.y * b.y;
}
/// Angle from a to b, in (-pi, pi].
template <class T>
T angle(const V<T>& a, const V<T>& b) {
  return atan2(crossT(a, b), dotT(a, b));
}

constexpr int kSlacks = 10;

/// The hodograph of x = (s, lambda, E1x, E1y) for the end conditions (P, T).
template <class T>
struct Hodograph {
  V<T> w0, E0, E1, E2, D1, D2;
};

template <class T>
Hodograph<T> hodograph(const T* x, const Vec2& P, const Vec2& Tan) {
  const T& s = x[0];
  const T& lambda = x[1];
  Hodograph<T> h;
  h.w0 = {s, T(0.0)};
  h.E1 = {x[2], x[3]};
  const V<T> lt{lambda * Tan.x(), lambda * Tan.y()};
  const V<T> R1 = 2.0 * (lt - h.w0) - 2.0 * h.E1;                           // E0 + E2
  const V<T> R2 = 6.0 * (V<T>{T(P.x()) - 2.0 * s, T(P.y())}) - 6.0 * h.E1;  // 5 E0 + E2
  h.E0 = 0.25 * (R2 - R1);
  h.E2 = R1 - h.E0;
  h.D1 = h.w0 + 0.5 * h.E0;
  h.D2 = h.D1 + h.E1;
  return h;
}

/// The ten Theorem 2 slacks: C^2_0 = E0 within the first quadrant (2 angles); for each
/// span, C^2 within its fair location: 2 angles to its sides, 2 radial fractions.
template <class T>
void slacks(const T* x, const Vec2& P, const Vec2& Tan, T* m) {
  const Hodograph<T> h = hodograph(x, P, Tan);
  const V<T> ex{T(1.0), T(0.0)}, ey{T(0.0), T(1.0)};
  m[0] = angle(ex, h.E0);  // psi0 >= 0
  m[1] = angle(h.E0, ey);  // psi0 <= pi/2
  const T r0 = sqrt(dotT(h.E0, h.E0)), r1 = sqrt(dotT(h.E1, h.E1)), r2 = sqrt(dotT(h.E2, h.E2));
  m[2] = angle(h.D1, h.E1);                                  // arg C^1_1 <= arg C^2_1 (Lemma 3)
  m[3] = angle(h.E1, h.E0);                                  // arg C^2_1 <= arg C^2_0 (Lemma 3)
  m[4] = r1 / r0;                                            // |C^2_1| > 0
  m[5] = (dotT(h.E0, h.E1) - dotT(h.E1, h.E1)) / (r0 * r1);  // inside the circle (Lemma 2)
  m[6] = angle(h.D2, h.E2);
  m[7] = angle(h.E2, h.E1);
  m[8] = r2 / r1;
  m[9] = (dotT(h.E1, h.E2) - dotT(h.E2, h.E2)) / (r1 * r2);
}

bool interior(const double* m) {
  for (int i = 0; i < kSlacks; ++i) {
    if (!(m[i] > 0.0) || !std::isfinite(m[i])) return false;
  }
  for (int i : {0, 1, 2, 3, 6, 7}) {
    if (!(m[i] < kPi)) return false;
  }
  return true;
}

}  // namespace

namespace detail {

/// -sum log(slacks), +inf outside.
double barrier(const Eigen::Vector4d& x, const Vec2& P, const Vec2& Tan) {
  double m[kSlacks];
  slacks(x.data(), P, Tan, m);
  if (!interior(m)) return std::numeric_limits<double>::infinity();
  double f = 0.0;
  for (double v : m) f -= std::log(v);
  return f;
}

Jet barrierJet(const Eigen::Vector4d& x, const Vec2& P, const Vec2& Tan) {
  Jet xj[4];
  for (int k = 0; k < 4; ++k) {
    xj[k].v = x[k];
    xj[k].g[k] = 1.0;
  }
  Jet m[kSlacks];
  slacks(xj, P, Tan, m);
  Jet f(0.0);
  for (const Jet& v : m) f = f - log(v);
  return f;
}

/// Normalized margin: the slacks as fractions of the intervals they live in.
double margin(const Eigen::Vector4d& x, const Vec2& P, const Vec2& Tan) {
  double m[kSlacks];
  slacks(x.data(), P, Tan, m);
  const double fractions[] = {m[0] / (0.5 * kPi),   m[1] / (0.5 * kPi),   m[2] / (m[2] + m[3]), m[3] / (m[2] + m[3]),
                              m[4] / (m[4] + m[5]), m[5] / (m[4] + m[5]), m[6] / (m[6] + m[7]), m[7] / (m[6] + m[7]),
                              m[8] / (m[8] + m[9]), m[9] / (m[8] + m[9])};
  return *std::min_element(std::begin(fractions), std::end(fractions));
}

std::optional<Eigen::Vector4d> geometricStart(const Vec2& P, const Vec2& Tan, double k, double theta) {
  const Eigen::Matrix2d I = Eigen::Matrix2d::Identity();
  const double q = k * std::cos(theta);
  Eigen::Matrix2d R;
  R << std::cos(theta), std::sin(theta), -std::sin(theta), std::cos(theta);  // rotation by -theta
  const Eigen::Matrix2d qR = q * R, q2R2 = qR * qR;
  const Eigen::Matrix2d L = (5.0 * I + 6.0 * qR + q2R2) / 6.0;  // C4 - C0 = 2 s ex + L E0
  const Eigen::Matrix2d K = (I + 2.0 * qR + q2R2) / 2.0;        // D3 = s ex + K E0
  Eigen::Matrix3d A;
  A << 2.0, L(0, 0), L(0, 1), 0.0, L(1, 0), L(1, 1), Tan.y(), K(0, 0) * Tan.y() - K(1, 0) * Tan.x(),
      K(0, 1) * Tan.y() - K(1, 1) * Tan.x();
  const Eigen::Vector3d sol = A.partialPivLu().solve(Eigen::Vector3d(P.x(), P.y(), 0.0));
  const Vec2 E0 = sol.tail<2>();
  const Vec2 E1 = qR * E0;
  const double lambda = (Vec2(sol[0], 0.0) + K * E0).dot(Tan);
  const Eigen::Vector4d x(sol[0], lambda, E1.x(), E1.y());
  double m[kSlacks];
  slacks(x.data(), P, Tan, m);
  if (x.allFinite() && interior(m)) return x;
  return std::nullopt;
}

std::optional<Eigen::Vector4d> interiorStart(const Vec2& P, const Vec2& Tan) {
  static const double ks[] = {0.8, 0.95, 0.99, 0.997, 0.999, 0.9997, 0.9999, 0.99997, 0.99999, 0.999997, 0.999999};
  static const double thetas[] = {0.3, 0.1, 0.03, 0.01, 0.003, 1e-3, 3e-4, 1e-4, 3e-5, 1e-5, 3e-6, 1e-6};
  for (double k : ks) {
    for (double theta : thetas) {
      if (std::optional<Eigen::Vector4d> x = geometricStart(P, Tan, k, theta)) return x;
    }
  }
  return std::nullopt;
}

Eigen::Vector4d analyticCentre(Eigen::Vector4d x, const Vec2& P, const Vec2& Tan, int& iterations) {
  double f = barrier(x, P, Tan);
  for (iterations = 0; iterations < 100; ++iterations) {
    const Jet j = barrierJet(x, P, Tan);
    if (!j.g.allFinite() || !j.h.allFinite()) break;
    Eigen::Matrix4d H = j.h;
    Eigen::LDLT<Eigen::Matrix4d> ldlt(H);
    double shift = 1e-12 * std::max(1.0, H.diagonal().cwiseAbs().maxCoeff());
    while (ldlt.info() != Eigen::Success || !(ldlt.vectorD().minCoeff() > 0.0)) {  // not convex here: regularize
      H = j.h + shift * Eigen::Matrix4d::Identity();
      ldlt.compute(H);
      shift *= 10.0;
    }
    const Eigen::Vector4d d = -ldlt.solve(j.g);
    // Newton decrement squared: about twice f - min f. Below f's rounding the steps only
    // wander along flat directions.
    const double decrement = -j.g.dot(d);
    if (!(decrement > 1e-18 * std::max(1.0, std::abs(f)))) break;
    double t = 1.0;
    bool moved = false;
    for (int k = 0; k < 60; ++k, t *= 0.5) {
      const Eigen::Vector4d next = x + t * d;
      const double fn = barrier(next, P, Tan);
      if (fn <= f - 0.25 * t * decrement && fn < f) {
        x = next;
        f = fn;
        moved = true;
        break;
      }
    }
    if (!moved) break;
  }
  return x;
}

/// The normalized poles C0..C4 of x.
std::array<Vec2, 5> polesOf(const Eigen::Vector4d& x, const Vec2& P, const Vec2& Tan) {
  const Hodograph<double> h = hodograph(x.data(), P, Tan);
  std::array<Vec2, 5> c;
  c[0] = Vec2::Zero();
  c[1] = Vec2(x[0] / 3.0, 0.0);              // V0 = w0 / 3
  c[2] = c[1] + Vec2(h.D1.x, h.D1.y) / 1.5;  // V1 = D1 / 1.5
  c[3] = P - x[1] / 3.0 * Tan;               // V3 = D3 / 3 = lambda T / 3
  c[4] = P;
  return c;
}

}  // namespace detail

}  // namespace fairsplines
