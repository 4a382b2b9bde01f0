// Monotone spirals for G2 ends: curves whose curvature runs from k0 to k1 as a cubic in arc
// length, kappa = k0 + (k1 - k0) tau + tau (1 - tau) (a + b (1 - 2 tau)), tau = s / L.
// a = b = 0 is the clothoid; the curvature is monotone where d kappa / d tau keeps the sign
// of k1 - k0. The bump (a, b) also serves equal end curvatures, where no monotone curve but
// the circle exists, for the fairest non-monotone answer.
// Private to the kernel: the fair-blend solver follows these curves for G2 ends.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace fairsplines::detail {

struct Spiral {
  Eigen::Vector2d start = Eigen::Vector2d::Zero();
  double theta0 = 0.0, k0 = 0.0, k1 = 0.0, length = 1.0, a = 0.0, b = 0.0;

  double kappa(double s) const;
  double dkappa(double tau) const;  ///< d kappa / d tau
  double theta(double s) const;     ///< theta0 + integral_0^s kappa
  Eigen::Vector2d point(double s) const;
  /// min over tau in [0, 1] of sign(k1 - k0) (d kappa / d tau) / |k1 - k0|: 1 for the
  /// clothoid; the curvature is strictly monotone when > 0.
  double minSlope() const;
  /// L^3 int (dkappa/ds)^2 ds = L^2 int_0^1 (d kappa / d tau)^2.
  double variation() const;
};

/// The richer family, tried where no cubic profile is monotone: n clothoid pieces of equal
/// length L / n, the curvature continuous and piecewise linear through the node values
/// k0 + (k1 - k0) C_j, C_0 = 0 <= C_1 <= ... <= C_n = 1 (monotone by construction).
struct ClothoidSpline {
  double theta0 = 0.0, k0 = 0.0, k1 = 0.0, length = 1.0;
  std::vector<double> C;  ///< n + 1 node fractions

  int pieces() const { return static_cast<int>(C.size()) - 1; }
  double kappa(double s) const;
  double theta(double s) const;
  Eigen::Vector2d point(double s) const;
  double minSlope() const;   ///< n min_i (C_i - C_{i-1}): the least c' of the profile
  double variation() const;  ///< L^2 (k1 - k0)^2 n sum (C_i - C_{i-1})^2
};

/// The outcome of the G2 problem in the chord frame (p0 = (0, 0), p1 = (1, 0)).
struct SpiralSolution {
  std::optional<Spiral> monotone;        ///< the fairest cubic-profile solution with minSlope >= kMinSlope
  std::optional<ClothoidSpline> spline;  ///< else a monotone clothoid spline, if one was found
  std::optional<Spiral> fallback;        ///< else the fairest solution found (curvature not monotone)
  std::string reason;                    ///< why no monotone curve exists (a necessary condition fails), or ""
};

/// The least minSlope a solution must keep to count as monotone: the cubic that follows it
/// needs kappa' away from 0 to be certified.
constexpr double kMinSlope = 0.02;

/// Why no curve of monotone curvature that turns less than a full turn goes from (0, 0),
/// angle theta0, curvature k0, to (1, 0), angle theta1, curvature k1 (chord units, angles
/// principal, k0 != k1), or "" where one exists (docs/FAIR_BLENDS.md section 5):
/// - the osculating circles at the ends are nested without inflection and disjoint across
///   one, and clear of a straight end's tangent line (Tait-Kneser; together exactly Q < 0);
/// - with curvature of one sign, the tangent meets the chord at a larger angle at the end of
///   larger curvature (Vogt's theorem for convex arcs; past them checked numerically only).
std::string g2Refusal(double theta0, double k0, double theta1, double k1);

/// Solves the G2 problem from (0, 0), angle theta0, curvature k0, to (1, 0), angle theta1,
/// curvature k1 (chord units), over the windings of total turning (theta1 - theta0) + 2 pi n
/// that turn less than a full turn, by Newton on the length and the shape from several starts. First the necessary
/// conditions of monotone curvature are checked: equal end curvatures need a common circle,
/// and g2Refusal. Its reason is kept only where no monotone curve is found, so a refusal
/// never hides a solution.
SpiralSolution solveG2Spiral(double theta0, double k0, double theta1, double k1);

}  // namespace fairsplines::detail
