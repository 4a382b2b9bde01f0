// Space spirals for fair blends in space (issue 28): curves given by their curvature and
// torsion as functions of arc length, integrated from a start frame by the Frenet-Serret
// equations x' = T, T' = kappa N, N' = -kappa T + tau B, B = T x N (do Carmo, Differential
// Geometry of Curves and Surfaces, section 1-5):
//   kappa(sigma) = k0 + (k1 - k0) sigma + sigma (1 - sigma) (a + b (1 - 2 sigma)),
//   tau(sigma)   = t0 + t1 sigma + t2 sigma (1 - sigma),          sigma = s / L.
// a = b = 0 is curvature linear in arc length (the space analogue of the clothoid); the
// profile is the planar spiral's (spiral.hpp), so the monotonicity test is the same.
// The G1 and G2 problems are solved in chord units (|p1 - p0| = 1, p0 = 0) by a damped
// Gauss-Newton with minimum-norm steps from planar clothoids lifted off their plane.
// Private to the kernel: fair_blend_space.cpp follows these curves with a certified cubic.
#pragma once
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

namespace fairsplines::detail {

struct SpaceSpiral {
  Eigen::Vector3d T0 = Eigen::Vector3d::UnitX(), N0 = Eigen::Vector3d::UnitY();  ///< start frame, orthonormal
  double length = 1.0;
  double k0 = 0.0, k1 = 0.0, a = 0.0, b = 0.0;  ///< curvature profile (signed: N flips where it is < 0)
  double t0 = 0.0, t1 = 0.0, t2 = 0.0;          ///< torsion profile
  int grid = 0;                                 ///< RK4 steps over the length (a power of two); 0: gridFor(1)

  double kappa(double sigma) const;
  double dkappa(double sigma) const;  ///< d kappa / d sigma
  double torsion(double sigma) const;

  struct Frame {
    Eigen::Vector3d x, T, N;
  };
  /// The RK4 grid (a power of two, 64 to 16384) whose steps turn the Darboux frame by at most
  /// 0.01 / safety rad.
  int gridFor(double safety) const;
  /// The frames at the sorted fractions sigma of the length: RK4 on `grid` equal steps, a
  /// target between grid points one short step from the point before it (spends WorkBudget
  /// units per step).
  std::vector<Frame> frames(const std::vector<double>& sigma) const;
  Frame end() const { return frames({1.0}).front(); }
  Eigen::Vector3d point(double s) const { return frames({s / length}).front().x; }

  /// min over sigma of sign(k1 - k0) (d kappa / d sigma) / |k1 - k0| (1 for linear
  /// curvature), and -1 where the curvature changes sign (|kappa| then has a minimum 0).
  double minSlope() const;
  /// Sign changes of the torsion on [0, 1] (0, 1 or 2).
  int torsionSignChanges() const;
  /// Scale-free variation L^2 int_0^1 (dkappa/dsigma)^2 + (dtau/dsigma)^2 dsigma.
  double variation() const;
};

/// The outcome of a space blend problem in chord units.
struct SpaceSpiralSolution {
  std::optional<SpaceSpiral> best;  ///< the fairest solution found (monotone first)
  bool monotone = false;            ///< best.minSlope() >= kMinSlope (spiral.hpp)
  int solutions = 0;                ///< converged starts
  std::string reason;               ///< why nothing monotone was found
};

/// G1 in space: from the origin with unit tangent T0 to p1 (|p1| = 1) with unit tangent T1.
/// Unknowns: the start normal's angle, k0, k1, t0, t1, L (a = b = t2 = 0); five conditions.
SpaceSpiralSolution solveSpaceG1(const Eigen::Vector3d& T0, const Eigen::Vector3d& p1, const Eigen::Vector3d& T1);

/// G2 in space: also the curvature vectors K0 (at the start) and K1 (at the end),
/// perpendicular to T0 and T1, in chord units. Unknowns: L, a, b, t0, t1, t2 (and the start
/// normal's angle where K0 = 0); conditions: the end point, tangent and normal direction.
SpaceSpiralSolution solveSpaceG2(const Eigen::Vector3d& T0, const Eigen::Vector3d& K0, const Eigen::Vector3d& p1,
                                 const Eigen::Vector3d& T1, const Eigen::Vector3d& K1);

}  // namespace fairsplines::detail
