// Internal: the fairest solver of Algorithm 2 (analytic_centre.cpp) in the normalized frame
// (C_0 = 0, T_0 = +x, |C_4| = 1, a left turn with the curvature falling from C_0), exposed
// for the tests.
// Unknowns x = (s, lambda, C^2_1): C^1_0 = (s, 0), C^1_3 = lambda T; eqs. (3), (5) and the
// end conditions fix C^2_0 and C^2_2 linearly.
#pragma once
#include <Eigen/Core>
#include <array>
#include <optional>

namespace fairsplines::detail {

/// -sum of the logarithms of the ten Theorem 2 slacks at x; +infinity outside the interior.
double barrier(const Eigen::Vector4d& x, const Eigen::Vector2d& P, const Eigen::Vector2d& T);

/// The smallest slack as a fraction of the interval it lives in (0 on the boundary).
double margin(const Eigen::Vector4d& x, const Eigen::Vector2d& P, const Eigen::Vector2d& T);

/// The curve with C^2_{i+1} = q R(-theta) C^2_i, q = k cos(theta) (each C^2 turned by theta and
/// shrunk inside its circle) that meets the end conditions (a 3x3 linear system), if it is
/// strictly inside Theorem 2's conditions.
std::optional<Eigen::Vector4d> geometricStart(const Eigen::Vector2d& P, const Eigen::Vector2d& T, double k,
                                              double theta);

/// geometricStart over (k, theta) from far inside to near the parabola (k -> 1, theta -> 0),
/// where the admissible set gets thin: the first strictly interior point, if any.
std::optional<Eigen::Vector4d> interiorStart(const Eigen::Vector2d& P, const Eigen::Vector2d& T);

/// Damped Newton (exact second derivatives) for the analytic centre from an interior point;
/// every iterate stays interior. `iterations` receives the number of Newton steps.
Eigen::Vector4d analyticCentre(Eigen::Vector4d x, const Eigen::Vector2d& P, const Eigen::Vector2d& T, int& iterations);

/// The normalized poles C_0..C_4 of x (C_0 = 0, C_4 = P): C_1 = (s / 3, 0), C_2 = C_1 + D_1 / 1.5,
/// C_3 = P - lambda T / 3.
std::array<Eigen::Vector2d, 5> polesOf(const Eigen::Vector4d& x, const Eigen::Vector2d& P, const Eigen::Vector2d& T);

}  // namespace fairsplines::detail
