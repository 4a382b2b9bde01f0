// G2 to C2 for curves: Karčiauskas & Peters, "Free-Form Splines Combining NURBS and Basic
// Shapes", Section 3 (rho, sigma), Section 4.1 (eqs. (5), (6), (9)-(11)) and Appendix
// 7.1-7.2. A G2 rational cubic spline (homogeneous Bézier pieces) becomes a sextic
// spline that is C2 in homogeneous space and keeps circle pieces exact.
#pragma once
#include <array>
#include <vector>

#include "fairsplines/blend_shapes.hpp"
#include "fairsplines/types.hpp"

namespace fairsplines {

/// A rational cubic reparameterization r = rbar / rlow of [0, 1] in homogeneous form: row
/// k is (rbar_k, rlow_k), the Bézier coefficients of numerator and denominator.
using Reparam = Eigen::Matrix<double, 4, 2, Eigen::RowMajor>;

/// Appendix 7.1: the symmetric map h with h_0 = (0,1), h_1 = (nu d, nu), h_2 = (nu(1-d), nu),
/// h_3 = (1,1), from tau0 = tan(alpha_0/4), tau1 = tan(alpha_1/4) and the scalar betaT
/// between arc 0 and arc 1 (the right end of arc 0).
/// Throws nothing; tau0, tau1 and betaT must be positive (circleToC2 checks them).
Reparam rhoEndMap(double tau0, double tau1, double betaT);

/// Appendix 7.1, eqs. (13)-(14): the ternary split rho^{i,0}, rho^{i,1}, rho^{i,2} of arc i
/// (tau = tan(alpha_i/4)) between its neighbours tauPrev, tauNext, with the new scalars
/// betaLeft (join with arc i-1) and betaRight (join with arc i+1). The three pieces join C2.
/// Throws nothing; the openings and scalars must be positive (circleToC2 checks them).
std::array<Reparam, 3> rhoSplit(double tauPrev, double tau, double tauNext, double betaLeft, double betaRight);

/// Eqs. (13)-(14) for given whole-arc maps at the two ends: rho^{i,0}(u) = h0(u / 3),
/// rho^{i,2}(u) = h1(2/3 + u/3), their inner end points overwritten by (13) and the middle
/// piece by (14), so that the three pieces join C2 (with scalar 1).
/// Throws nothing.
std::array<Reparam, 3> rhoSplitFromMaps(const Reparam& h0, const Reparam& h1);

/// The map of the reversed arc: u -> 1 - r(1 - u), in the normal form.
/// Throws nothing.
Reparam reverseMap(const Reparam& r);

/// Appendix 7.2: given the map h of an arc (opening tan(alpha/4) = tau) in the normal form
/// h_0 = (0,1), h_3 = (1,1), the map hbar of the next arc (tauBar) such that q∘h and
/// qbar∘hbar join C2 in homogeneous space with scalar betaT.
/// Throws nothing; the openings and betaT must be positive (circleToC2 checks them).
Reparam transitionMap(double tau, double tauBar, const Reparam& h, double betaT);

/// Section 3, eqs. (7)-(8): the numerical sigma maps of a circle partition (one per arc),
/// from the cubic C2 spline with knot ratios betaT (betaT[i] between arc i-1 and arc i;
/// betaT[0] is the closing join of a closed circle, ignored otherwise) that interpolates
/// the projected points, eq. (7), solved as one tridiagonal (cyclic for a closed circle)
/// system. Open ends: the end derivative of the identity reparameterization (keeps the
/// original parameter speed at the ends). Throws InputError if a map is not monotone.
std::vector<Reparam> sigmaMaps(const G2CircleSpline& circle, const Eigen::VectorXd& betaT);

/// Eq. (7): the projection of a point of the unit circle to the semicircle about C = (0,-1).
/// Throws nothing; p = (0, -1), the centre C itself, has no image.
Eigen::Vector2d projectToHalfAngle(const Eigen::Vector2d& p);
/// Eq. (8): back to the circle, homogeneous (x, y, w).
/// Throws nothing.
Eigen::Vector3d projectBack(const Eigen::Vector2d& p);

/// Eq. (9): a homogeneous quadratic (3 Bézier rows, any number of columns, last column the
/// weight) composed with a rational cubic map, common denominators dropped: 7 rows.
/// Throws nothing; the quadratic must have 3 rows (not checked).
PointMatrix composeQuadratic(const PointMatrix& quadratic, const Reparam& r);

/// The quadratic (3 homogeneous Bézier rows over [0, 1]) that matches a homogeneous cubic
/// (4 rows) up to second order at parameter t0 (the Hermite quadratics of Section 4.1).
/// Throws nothing; the cubic must have 4 rows (not checked).
PointMatrix hermiteQuadratic(const PointMatrix& cubic, double t0);

/// Eq. (10): merge of two sextics: b_0..b_2 of the first, b_4..b_6 of the second and the
/// average of the two b_3.
/// Throws nothing; both must have 7 rows of the same width (not checked).
PointMatrix mergeSextics(const PointMatrix& first, const PointMatrix& second);

/// Eqs. (5), (6), (11): C2 adjustment of the join of a sextic (left, 7 rows) and the next
/// (right, 7 rows) with scalar beta: P_new = (P + Pbar)/2, then b_5, bbar_1 by (6) and
/// b_6 = bbar_0 = (beta b_5 + bbar_1) / (beta + 1).
/// Throws nothing; beta must be positive and both sextics 7 rows (not checked).
void adjustC2(PointMatrix& left, PointMatrix& right, double beta);

/// A sextic spline, C2 in homogeneous space: 7 homogeneous Bézier rows per piece; beta[k] is
/// the scalar at the start of piece k (beta[0] the closing join of a closed spline).
struct C2SexticSpline {
  PointMatrix bezier;
  Eigen::VectorXd beta;
  bool closed = false;
  /// Piece index where each original cubic piece (arc) starts; one more entry: pieces().
  std::vector<int> firstPiece;
  int pieces() const { return static_cast<int>(bezier.rows() / 7); }
  /// Knots t_0 = 0 < t_1 < ... with (t_{k+1} - t_k) / (t_k - t_{k-1}) = beta[k], t_1 = 1.
  /// Throws nothing.
  Eigen::VectorXd knots() const;
};

enum class CircleReparam { Rho, Sigma, Mixed };

/// Per-arc choice of the Mixed strategy (Section 3, "the best of the two approaches"):
/// rho on uniform or symmetric runs, i.e. on every window of two or more consecutive arcs
/// whose openings read the same both ways (equal neighbours; or 0.5, 1.2, 0.5), sigma
/// elsewhere. A rho arc next to a sigma arc takes that end third from transitionMap (7.2),
/// mirrored at its right end.
/// Throws nothing.
std::vector<CircleReparam> mixedChoice(const G2CircleSpline& circle);

/// Section 4.1 for a circle partition: every arc's quadratic composed with rho (three
/// pieces per arc; one where both end maps agree, as inside uniform runs with betaT = 1),
/// sigma (one piece) or the mixed choice (mixedChoice; an arc whose rho map would not be
/// monotone for the given betaT gets sigma instead); betaT defaults (empty) to the
/// circle's beta (betaT[i] is arc to arc; piece to piece it is scaled by
/// parts_{i-1} / parts_i, i.e. 1 inside a rho arc, 1/3 from a sigma arc to a rho arc and 3
/// back). The circle stays exact; the result is C2 in homogeneous space.
/// Open ends: rho uses a mirrored neighbour (same opening, scalar 1), sigma the identity's
/// end speed. Throws InputError for a non-monotone map or wrong betaT size.
C2SexticSpline circleToC2(const G2CircleSpline& circle, CircleReparam method, Eigen::VectorXd betaT = {});

/// The reparameterizations circleToC2 uses for a partition: per arc one map (sigma) or three
/// (rho), and the piece-to-piece scalars. With g2ToC2 they convert any G2 cubic spline on
/// that partition, e.g. an edited control structure (Fig. 4a).
struct CircleMaps {
  std::vector<std::vector<Reparam>> maps;
  Eigen::VectorXd betaPieces;  ///< scalar at the start of each arc's first piece (g2ToC2's betaT)
};
/// Throws InputError for a betaT that is not one per arc, a betaT that is not positive and
/// finite or outside [1e-12, 1e12] (requireModerateScalars), or a map that is not monotone.
CircleMaps circleMaps(const G2CircleSpline& circle, CircleReparam method, Eigen::VectorXd betaT = {});

/// Section 4.1 for a general G2 rational cubic spline whose pieces are given in homogeneous
/// form (4 rows per piece, any columns, last column the weight): piece i is composed with
/// the maps `maps[i]` (one map: sigma-like, Hermite quadratics at 0 and 1; three maps:
/// rho-like, Hermite quadratics at 0, r(1/3), r(2/3), 1) and merged by eq. (10). With the
/// circle's maps and its conics this reproduces circleToC2.
/// Throws InputError unless cubicPieces is 4 rows per piece (at least one), maps and betaT one
/// per piece, each piece one map (sigma) or three (rho); for Bézier points that are not finite,
/// a betaT outside [1e-12, 1e12], or a result that is not finite.
C2SexticSpline g2ToC2(const PointMatrix& cubicPieces, const std::vector<std::vector<Reparam>>& maps,
                      const Eigen::VectorXd& betaT, bool closed);

/// Degree raise of a homogeneous cubic Bézier piece (4 rows) to degree 6 (7 rows): the
/// identity reparameterization of Section 4.1.
/// Throws nothing; the cubic must have 4 rows (not checked).
PointMatrix raiseCubicToSextic(const PointMatrix& cubic);

}  // namespace fairsplines
