// Internal: the pieces of the csr-spline's eq. (6) that its two strategies (csr.cpp's
// streaming reference, csr_vectorised.cpp's windows) and the quadratic design of eq. (12)
// (quadratic_design.cpp) share: the quadratic interpolants f_i, their curvature, and the
// weights mu, nu. Karčiauskas & Peters, "Curvature-sensitive splines and design with basic
// curves", Sections 4 and 7.
#pragma once
#include <Eigen/Geometry>
#include <cmath>

#include "fairsplines/csr.hpp"
#include "csr_detail.hpp"

namespace fairsplines::detail {

// ---------------------------------------------------------------------------------------
// The quadratic interpolants f_i and their curvature

template <int D>
using Vec = Eigen::Matrix<double, D, 1>;

/// The curvature given to a quadratic interpolant whose data fold back on themselves
/// (q_{i+1} = q_{i-1}: f_i' vanishes at t_i, and |f' x f''| / |f'|^3 is 0/0). Near such
/// data the curvature grows without bound, so the weights of eq. (6) go to their limits
/// (mu -> 1 against a finite neighbour); a large finite curvature gives those limits,
/// with both epsilon rules, and keeps every sum of two finite.
constexpr double kHairpinCurvature = 1e300;

/// A curvature, with NaN (data folding back) and anything beyond kHairpinCurvature as
/// kHairpinCurvature. A comparison, so that the loops vectorise it as a blend.
inline double boundedCurvature(double kappa) { return kappa <= kHairpinCurvature ? kappa : kHairpinCurvature; }

/// |d1 x d2| / |d1|^3, with a single square root (bounded).
template <int D>
inline double curvatureOf(const Vec<D>& d1, const Vec<D>& d2) {
  double cross2;
  if constexpr (D == 2) {
    const double z = d1[0] * d2[1] - d1[1] * d2[0];
    cross2 = z * z;
  } else {
    cross2 = d1.cross(d2).squaredNorm();
  }
  const double speed2 = d1.squaredNorm();
  return boundedCurvature(std::sqrt(cross2 / (speed2 * speed2 * speed2)));
}

/// The quadratic interpolant f_i of q_{i-1}, q_i, q_{i+1} at t_{i-1}, t_i, t_{i+1},
/// written about its middle node: f_i(t) = q_i + d (t - t_i) + D (t - t_i)^2.
template <int D>
struct Quadratic {
  Vec<D> q, d, D2;  // D2 = f''/2
  /// Cubic blossom F[x, y, z] of the quadratic (degree-raised), given the arguments
  /// relative to the expansion point: (X + Y + Z)/3 and (XY + XZ + YZ)/3.
  Vec<D> blossom3(double X, double Y, double Z) const {
    return q + d * ((X + Y + Z) / 3.0) + D2 * ((X * Y + X * Z + Y * Z) / 3.0);
  }
  /// Quadratic blossom f[x, y].
  Vec<D> blossom2(double X, double Y) const { return q + d * ((X + Y) / 2.0) + D2 * (X * Y); }
  /// |curvature| at parameter offset X from the expansion point.
  double kappaAt(double X) const { return curvatureOf<D>(d + 2.0 * X * D2, 2.0 * D2); }
};

template <int D>
Vec<D> row(PointsRef q, Eigen::Index i) {
  return q.row(i).transpose().template head<D>();
}

template <int D>
Quadratic<D> interpolant(const Vec<D>& qm, const Vec<D>& q0, const Vec<D>& qp, double hm, double h0) {
  // Newton form about t_i: first divided differences on either side, then the second.
  const Vec<D> dm = (q0 - qm) / hm, d0 = (qp - q0) / h0;
  Quadratic<D> f;
  f.D2 = (d0 - dm) / (hm + h0);
  f.d = dm + f.D2 * hm;  // f'(t_i)
  f.q = q0;
  return f;
}

// ---------------------------------------------------------------------------------------
// The weights mu, nu of eq. (6)

/// Eq. (6)'s epsilon: positive and finite (infinity would make every weight NaN under the
/// additive rule).
inline bool validEpsilon(double epsilon) { return epsilon > 0.0 && epsilon < HUGE_VAL; }
constexpr const char* kEpsilonMessage = "epsilon must be positive and finite";

/// mu, nu of eq. (6): a / (a + b), with the epsilon rule.
struct Weight {
  double epsilon;  // already divided by the data size: units of curvature
  EpsilonRule rule;
  double operator()(double a, double b) const {
    if (rule == EpsilonRule::Additive) return (a + epsilon) / (a + b + 2.0 * epsilon);
    const double sum = a + b;
    return sum > epsilon ? a / sum : 0.5;
  }
};

// ---------------------------------------------------------------------------------------
// The vectorised strategy (csr_vectorised.cpp)

/// The vectorised strategy over all samples (contiguous rows), writing the poles in
/// place: open data n + 2 rows (clamped), closed data n rows in OCCT's periodic order
/// (row r holds c_{r+1}, see periodicCubic).
void csrPolesWindowed(PointsRef q, const double* t, bool closed, const Weight& weight, bool quasiOnly,
                      Eigen::Index window, double* out);

/// The open csr-spline of n >= kVectorisedFrom contiguous samples (2 or 3 columns, no
/// parameters given, a valid epsilon) in one streaming pass: each window's differences,
/// chords and parameters just before its poles. The checks, their order and every value
/// are those of validateSamplesInto, parametersInto and cubicPolesInto.
void csrOpenFusedInto(PointsRef q, const CsrOptions& options, double* t, double* poles);

}  // namespace fairsplines::detail
