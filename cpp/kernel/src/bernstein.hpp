// Internal: Bernstein-Bézier algebra on [0, 1], written once for the whole kernel: the
// binomial coefficients, the product of two polynomials in Bernstein form, de Casteljau's
// evaluation and subdivision, and degree raising. The monotone certificate (its polynomials
// N, S), the G2-to-C2 and G1-to-C1 conversions (eq. (9) of the blending paper), the basic
// curves and the blend complexes use them.
//
// A Bézier "polynomial" is a matrix whose rows are its coefficients b_0 .. b_n (degree n =
// rows - 1): an Eigen::VectorXd for a scalar polynomial, a PointMatrix or a homogeneous
// matrix for points. Every function works row by row, so one code serves all of them.
#pragma once
#include <Eigen/Core>
#include <utility>

#include "fairsplines/types.hpp"

namespace fairsplines::bernstein {

// ---------------------------------------------------------------------------------------
// Coefficients and products

/// The binomial coefficient C(n, k), 0 <= k <= n, exact for the degrees the kernel uses
/// (every intermediate value is an integer below 2^53).
double binomial(int n, int k);

/// Bézier coefficients of the product of two scalar polynomials in Bernstein form of
/// degrees m and n (the result has degree m + n):
/// c_k = sum_{i+j=k} C(m,i) a_i C(n,j) b_j / C(m+n,k).
Eigen::VectorXd product(const Eigen::VectorXd& a, const Eigen::VectorXd& b);

/// Eq. (9) of the blending paper: a homogeneous quadratic (3 Bézier rows, any number of
/// columns) composed with the rational map r = rbar / rlow (numerator and denominator in
/// Bernstein form of one degree m), common denominators dropped:
/// sum_k q_k C(2,k) (rlow - rbar)^{2-k} rbar^k, in Bernstein form of degree 2m (2m + 1 rows).
PointMatrix composeQuadratic(const PointMatrix& quadratic, const Eigen::VectorXd& rbar, const Eigen::VectorXd& rlow);

// ---------------------------------------------------------------------------------------
// Signs of a scalar polynomial on [0, 1] (the monotone certificates, planar and space)

/// Result of trying to certify a(t) >= -tol on [0, 1] by coefficients and subdivision.
struct Bound {
  bool holds = true;
  bool undecided = false;
  double witness = 0.0;  ///< where a(witness) < -tol (a certified violation), or the undecided spot
  int pieces = 0;
};

constexpr int kMaxDepth = 48;
constexpr int kMaxPieces = 20000;

/// a(t) >= -tol on [0, 1]? Decided by the Bernstein coefficients (convex hull), with
/// subdivision at 1/2 where they disagree, down to kMaxDepth levels and kMaxPieces pieces.
Bound certifyLower(const Eigen::VectorXd& a, double tol);

/// A root of a between t0 and t1 (a(t0), a(t1) of opposite signs), by bisection.
double bisectRoot(const Eigen::VectorXd& a, double t0, double t1);

// ---------------------------------------------------------------------------------------
// de Casteljau

/// The value at t of the Bézier rows b (de Casteljau: b_i <- (1 - t) b_i + t b_{i+1}).
template <class Derived>
Eigen::Matrix<double, 1, Derived::ColsAtCompileTime> value(const Eigen::MatrixBase<Derived>& b, double t) {
  typename Derived::PlainObject c = b;
  for (Eigen::Index r = c.rows() - 1; r > 0; --r) {
    for (Eigen::Index i = 0; i < r; ++i) c.row(i) = (1.0 - t) * c.row(i) + t * c.row(i + 1);
  }
  return c.row(0);
}

/// de Casteljau: the Bézier rows b split at t into the pieces over [0, t] and [t, 1].
template <class Derived>
void split(const Eigen::MatrixBase<Derived>& b, double t, typename Derived::PlainObject& left,
           typename Derived::PlainObject& right) {
  const Eigen::Index n = b.rows() - 1;
  typename Derived::PlainObject work = b;
  left.resize(n + 1, b.cols());
  right.resize(n + 1, b.cols());
  left.row(0) = work.row(0);
  right.row(n) = work.row(n);
  for (Eigen::Index r = 1; r <= n; ++r) {
    for (Eigen::Index i = 0; i <= n - r; ++i) work.row(i) = (1 - t) * work.row(i) + t * work.row(i + 1);
    left.row(r) = work.row(0);
    right.row(n - r) = work.row(n - r);
  }
}

// ---------------------------------------------------------------------------------------
// Degree raising

/// The Bézier rows b raised to `degree` (unchanged if they have that degree or more), one
/// degree at a time: e_0 = b_0, e_{n+1} = b_n, e_i = (i b_{i-1} + (n + 1 - i) b_i) / (n + 1),
/// evaluated as the convex combination a b_{i-1} + (1 - a) b_i with a = i / (n + 1), so that
/// rows near the largest doubles do not overflow (a fuzz finding: a line segment from
/// 1.7e308 gave an infinite cubic).
template <class Derived>
typename Derived::PlainObject raise(const Eigen::MatrixBase<Derived>& b, Eigen::Index degree) {
  typename Derived::PlainObject c = b;
  for (Eigen::Index n = c.rows() - 1; n < degree; ++n) {
    typename Derived::PlainObject e(n + 2, c.cols());
    e.row(0) = c.row(0);
    e.row(n + 1) = c.row(n);
    for (Eigen::Index i = 1; i <= n; ++i) {
      const double a = static_cast<double>(i) / static_cast<double>(n + 1);
      e.row(i) = a * c.row(i - 1) + (1.0 - a) * c.row(i);
    }
    c = std::move(e);
  }
  return c;
}

}  // namespace fairsplines::bernstein
