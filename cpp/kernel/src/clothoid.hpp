// Clothoid arcs (curvature linear in arc length) and the G1 Hermite problem they solve:
// Bertolazzi & Frego, "G1 fitting with clothoids", Math. Methods Appl. Sci. 38 (2015).
// Private to the kernel: the fair-blend solver approximates these arcs.
#pragma once
#include <Eigen/Core>

namespace fairsplines::detail {

inline constexpr double kPi = 3.14159265358979323846;

/// 8-point Gauss-Legendre on [-1, 1]: the positive nodes and their weights (the composite
/// quadratures of the clothoid and the spirals).
inline constexpr double kGaussX[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363};
inline constexpr double kGaussW[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};

/// An angle in (-pi, pi].
double normalizeAngle(double a);

/// The generalized Fresnel moments of the paper's eq. (9),
///   X_k(a, b, c) = int_0^1 tau^k cos(a tau^2 / 2 + b tau + c) dtau,
///   Y_k(a, b, c) = int_0^1 tau^k sin(a tau^2 / 2 + b tau + c) dtau,   k = 0, 1, 2,
/// by composite Gauss-Legendre quadrature in panels over which the phase turns by at most
/// 0.5 rad (the integrand is then a polynomial to rounding). Cost grows with |a| + |b|.
struct FresnelMoments {
  double X[3], Y[3];
};
FresnelMoments fresnelMoments(double a, double b, double c);

/// A clothoid arc from `start`: tangent angle theta(s) = theta0 + kappa0 s + dkappa s^2 / 2,
/// curvature kappa(s) = kappa0 + dkappa s, for arc length s in [0, length].
struct Clothoid {
  Eigen::Vector2d start = Eigen::Vector2d::Zero();
  double theta0 = 0.0, kappa0 = 0.0, dkappa = 0.0, length = 0.0;

  Eigen::Vector2d point(double s) const;
  double theta(double s) const { return theta0 + s * (kappa0 + 0.5 * dkappa * s); }
  double kappa(double s) const { return kappa0 + dkappa * s; }
  Eigen::Vector2d tangent(double s) const;
};

/// The G1 Hermite clothoid (Bertolazzi & Frego, Section 3): from p0 with tangent angle
/// theta0 to p1 with tangent angle theta1, the solution whose angles phi0, phi1 between the
/// chord and the tangents lie in (-pi, pi], so its total turning phi1 - phi0 lies in
/// (-2 pi, 2 pi). Newton on A of eq. (14), g(A) = Y_0(2A, delta - A, phi0) = 0, from the
/// paper's first guess; a bracketing search where Newton does not settle.
/// Precondition: p0 != p1 (the caller checks), finite input.
Clothoid clothoidG1(const Eigen::Vector2d& p0, double theta0, const Eigen::Vector2d& p1, double theta1);

}  // namespace fairsplines::detail
