// Non-uniform cubic C2 B-splines and their piecewise Bézier G2 (beta) form,
// Karčiauskas & Peters, "Curvature-sensitive splines and design with basic curves", Section 3.1.
#pragma once
#include "fairsplines/types.hpp"

namespace fairsplines {

/// A cubic spline given piece by piece, each piece in Bézier form over [0,1],
/// consecutive pieces joined with the G2 continuity of eq. (1).
struct G2Spline {
  PointMatrix bezier;    ///< 4*m rows: b_0^i, b_1^i, b_2^i, b_3^i of piece i = 0..m-1
  Eigen::VectorXd beta;  ///< m+1 scalars: beta[k] belongs to the start of piece k; beta[m] to the end of the last piece
  int pieces() const { return static_cast<int>(bezier.rows() / 4); }
};

/// beta_i = h_i / h_{i-1} of eq. (1) for every knot t_i with both neighbours;
/// `knots` holds t_0..t_{n-1}, the result beta_1..beta_{n-2} (size n-2).
/// Throws nothing; the knots must increase (a repeated knot gives an infinite or NaN beta).
Eigen::VectorXd betaFromKnots(const Eigen::VectorXd& knots);

/// Eq. (2): Bézier pieces from de Boor points c_0..c_K (c_i corresponds to knot t_i,
/// support [t_{i-2}, t_{i+2}]) and their scalars beta_0..beta_K.
/// Returns the pieces over [t_1,t_2] .. [t_{K-2},t_{K-1}] (K-2 pieces) with beta_1..beta_{K-1}.
/// Throws InputError for fewer than 4 control points or a non-positive beta.
G2Spline g2FromDeBoor(const PointMatrix& c, const Eigen::VectorXd& beta);

/// Eq. (3): the de Boor points of a G2 spline, c_i as the intersection of the lines
/// b_1^{i-1} b_2^{i-1} and b_1^i b_2^i. Returns m+1 points, one per beta: the left
/// form of (3) where a piece on the left exists, else the right form.
/// Throws InputError unless g2 has at least one piece and one beta more than pieces.
PointMatrix deBoorFromG2(const G2Spline& g2);

/// Clamped cubic C2 B-spline with simple interior knots t_1..t_{n-2} and end knots of
/// multiplicity 4, from its n+2 poles (blossoms F[t_0,t_0,t_0], F[t_0,t_0,t_1],
/// F[t_{i-1},t_i,t_{i+1}] for i = 1..n-2, F[t_{n-2},t_{n-1},t_{n-1}], F[t_{n-1},t_{n-1},t_{n-1}]).
/// Throws nothing; expects n + 2 poles for the n knots t (not checked: toOcct refuses what
/// OpenCASCADE would not accept).
BSplineCurve clampedCubic(PointMatrix poles, const Eigen::VectorXd& t);

/// Periodic cubic C2 B-spline with simple knots t_0..t_n (t_n closes the period) and n
/// poles, pole i being the blossom F[t_{i-1}, t_i, t_{i+1}] (indices taken cyclically).
/// Throws nothing; expects n poles for the n + 1 knots t (not checked: toOcct refuses what
/// OpenCASCADE would not accept).
BSplineCurve periodicCubic(PointMatrix poles, const Eigen::VectorXd& t);

}  // namespace fairsplines
