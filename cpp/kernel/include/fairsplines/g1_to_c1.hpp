// G1 to C1 for curves: Karčiauskas & Peters, "Free-Form Splines Combining NURBS and Basic
// Shapes", Section 5 and Appendix 7.3: each rational quadratic piece of a G1 spline
// becomes two quartics, C1 in homogeneous space, by the quadratic reparameterization eta.
#pragma once
#include <array>

#include "fairsplines/types.hpp"

namespace fairsplines {

/// A rational quadratic reparameterization in homogeneous form: row k is (etaBar_k, etaLow_k).
using Reparam2 = Eigen::Matrix<double, 3, 2, Eigen::RowMajor>;

/// Appendix 7.3, a_0^i: the map at the start of piece i (weights w_{i-1}, w_i of the pieces
/// i-1 and i; beta_i their G1 scalar; betaT_i the new scalar). Reading: the printed formula
/// holds for betaT = beta only; in general the numerator is 2 (1 + betaT_i) / beta_i:
/// a_0^i = 2 (1 + betaT_i) / beta_i / (w_i / beta_i + w_{i-1} + 1 / beta_i + 1).
/// Throws nothing: the weights and scalars must be positive (g1ToC1 checks them).
double etaStart(double wPrev, double w, double beta, double betaT);
/// Appendix 7.3, a_1^i at the end of piece i (w_i, w_{i+1}, beta_{i+1}, betaT_{i+1}); the
/// numerator is 2 beta_{i+1} (1 + 1 / betaT_{i+1}) in general (printed: 2 (1 + betaT_{i+1})):
/// a_1^i = 2 beta_{i+1} (1 + 1/betaT_{i+1}) / (w_i beta_{i+1} + w_{i+1} + beta_{i+1} + 1).
/// Throws nothing: the weights and scalars must be positive (g1ToC1 checks them).
double etaEnd(double w, double wNext, double betaNext, double betaTNext);

/// Appendix 7.3: h^{i,j} = (0,1), a_j (1/2, 1), (1,1); eta^{i,0}(u) = h^{i,0}(u/2),
/// eta^{i,1}(u) = h^{i,1}(1/2 + u/2), the common point overwritten by the average of the
/// neighbouring coefficients so that the two join C1.
/// Throws nothing.
std::array<Reparam2, 2> etaSplit(double a0, double a1);

/// A homogeneous quadratic (3 Bézier rows) composed with a quadratic map: 5 rows (quartic).
/// Throws nothing; the quadratic must have 3 rows (not checked).
PointMatrix composeQuadratic2(const PointMatrix& quadratic, const Reparam2& eta);

/// Quartic pieces, C1 in homogeneous space: 5 rows per piece; beta[k] at the start of piece
/// k (1 inside a segment; betaT between segments; beta[0] the closing join when closed).
struct C1QuarticSpline {
  PointMatrix bezier;
  Eigen::VectorXd beta;
  bool closed = false;
  int pieces() const { return static_cast<int>(bezier.rows() / 5); }
};

/// Eq. (12) for a G1 spline of rational quadratic pieces (3 homogeneous rows each, last
/// column the weight, end weights 1, middle weight w_i) with G1 scalars beta (beta[i]
/// between pieces i-1 and i; beta[0] the closing join if closed) and new scalars betaT.
/// Open ends use a mirrored neighbour (same weight, scalar 1). Throws InputError for
/// non-positive weights or scalars, or sizes that do not match.
C1QuarticSpline g1ToC1(const PointMatrix& quadratics, const Eigen::VectorXd& beta, const Eigen::VectorXd& betaT,
                       bool closed);

/// The unit circle partition theta_0 < ... < theta_n as rational quadratic arcs (weights
/// 1, cos(alpha_i/2), 1; each arc below pi), with their G1 scalars
/// beta_i = sin(alpha_i/2) / sin(alpha_{i-1}/2). Closed when the span is 2 pi.
/// Throws InputError for fewer than two angles, angles that are not finite or not increasing
/// (naming the index), an arc of pi or more (its weight cos(alpha/2) would not be positive), or
/// angles too close together to be knots (requireSeparateKnots).
void g1Circle(const Eigen::VectorXd& theta, PointMatrix& quadratics, Eigen::VectorXd& beta, bool& closed);

}  // namespace fairsplines
