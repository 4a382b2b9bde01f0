// Knot removal in one pass (The NURBS Book, Piegl & Tiller, 2nd ed., Section 5.4, Algorithm
// A5.8, one removal at a time): a spline in Bezier form (every interior knot of multiplicity
// p) brought down to multiplicity q at every interior knot where it is smooth enough.
// OpenCASCADE's RemoveUKnot copies the whole pole array at every removal, so a grid of K arcs
// cost O(K^2) (issue 26: 6.3 s of 6.8 s at 400 arcs); here the removals run left to right on
// the poles built so far, each touching only the p + 1 poles at its knot: O(K).
#pragma once
#include <Eigen/Core>
#include <vector>

namespace fairsplines::detail {

/// Rows are control points (of any dimension: a whole row of a surface's homogeneous
/// poles is one point when removing along the other direction).
using PointRows = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

/// What removeKnotsBezier built: the poles and the knot vector (the distinct knots with
/// multiplicities p + 1 at the ends and q inside).
struct KnotRemoval {
  PointRows poles;
  Eigen::Index failedKnot = 0;  ///< 0 when every interior knot came down; else the first one that did not (from 1)
  long work = 0;                ///< pole rows written (a work unit: O(knots x p), never O(knots^2))
};

/// The spline of degree p >= 1 on the distinct knots T (K + 1 increasing values) with the
/// p K + 1 poles `bezier` (piece k: rows p k .. p k + p) as a spline with interior knots of
/// multiplicity q (0 <= q <= p), each removal checked to `tolerance` in every coordinate.
/// Stops at the first knot that does not come down (failedKnot). Throws nothing.
KnotRemoval removeKnotsBezier(const PointRows& bezier, const Eigen::VectorXd& T, int p, int q, double tolerance);

}  // namespace fairsplines::detail
