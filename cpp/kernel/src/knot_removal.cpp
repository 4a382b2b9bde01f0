// Knot removal in one left-to-right pass: The NURBS Book (Piegl & Tiller, 2nd ed.), Section
// 5.4, Algorithm A5.8, applied one removal at a time to the poles built so far.
#include "knot_removal.hpp"

#include <algorithm>
#include <cmath>

namespace fairsplines::detail {

namespace {

/// The poles and knots of the part of the spline built so far (a prefix of the whole): the
/// removal at a knot reads and writes only its last few rows, so erasing a row shifts only
/// those after it (at most p + 1).
struct Prefix {
  PointRows P;            ///< rows 0 .. n - 1 in use
  Eigen::Index n = 0;     ///< poles in use
  std::vector<double> U;  ///< the knot vector of the prefix (with the next knot's occurrences)
  long work = 0;

  void push(const Eigen::Ref<const Eigen::RowVectorXd>& row) {
    P.row(n++) = row;
    ++work;
  }
  void erase(Eigen::Index row) {
    for (Eigen::Index k = row + 1; k < n; ++k) P.row(k - 1) = P.row(k);
    work += n - row - 1;
    --n;
  }
};

/// A5.8 with one removal: the knot u = U[r] of multiplicity s once, if the spline stays within
/// tol in every coordinate; then the poles first..last are rewritten and one is erased.
bool removeOnce(Prefix& x, int p, Eigen::Index r, int s, double tol, PointRows& temp) {
  const double u = x.U[r];
  const Eigen::Index first = r - p, last = r - s, off = first - 1;
  temp.row(0) = x.P.row(off);
  temp.row(last + 1 - off) = x.P.row(last + 1);
  Eigen::Index i = first, j = last, ii = 1, jj = last - off;
  while (j - i > 0) {
    const double alfi = (u - x.U[i]) / (x.U[i + p + 1] - x.U[i]);
    const double alfj = (u - x.U[j]) / (x.U[j + p + 1] - x.U[j]);
    temp.row(ii) = (x.P.row(i) - (1.0 - alfi) * temp.row(ii - 1)) / alfi;
    temp.row(jj) = (x.P.row(j) - alfj * temp.row(jj + 1)) / (1.0 - alfj);
    ++i, ++ii, --j, --jj;
  }
  double error;
  if (j - i < 0) {
    error = (temp.row(ii - 1) - temp.row(jj + 1)).cwiseAbs().maxCoeff();
  } else {
    const double alfi = (u - x.U[i]) / (x.U[i + p + 1] - x.U[i]);
    error = (x.P.row(i) - (alfi * temp.row(ii + 1) + (1.0 - alfi) * temp.row(ii - 1))).cwiseAbs().maxCoeff();
  }
  if (!(error <= tol)) return false;
  for (i = first, j = last; j - i > 0; ++i, --j) {
    x.P.row(i) = temp.row(i - off);
    x.P.row(j) = temp.row(j - off);
    x.work += 2;
  }
  x.U.erase(x.U.begin() + r);  // within the last 2 p + 2 knots
  x.erase((2 * r - s - p) / 2);
  return true;
}

}  // namespace

KnotRemoval removeKnotsBezier(const PointRows& bezier, const Eigen::VectorXd& T, int p, int q, double tolerance) {
  const Eigen::Index K = T.size() - 1;
  KnotRemoval out;
  Prefix x;
  x.P.resize(bezier.rows(), bezier.cols());
  x.U.assign(p + 1, T[0]);
  for (Eigen::Index a = 0; a <= p; ++a) x.push(bezier.row(a));  // piece 0
  PointRows temp(2 * p + 2, bezier.cols());
  for (Eigen::Index k = 1; k <= K; ++k) {
    // Knot k (between pieces k - 1 and k) and the next knot's occurrences, and piece k's poles:
    // all that a removal at knot k reads.
    x.U.insert(x.U.end(), p, T[k]);
    if (k == K) {
      x.U.push_back(T[K]);
      break;
    }
    x.U.insert(x.U.end(), k + 1 == K ? p + 1 : p, T[k + 1]);
    for (Eigen::Index a = 1; a <= p; ++a) x.push(bezier.row(p * k + a));
    const Eigen::Index r = static_cast<Eigen::Index>(x.U.size()) - (k + 1 == K ? p + 1 : p) - 1;  // last T[k]
    for (int s = p; s > q; --s) {
      if (!removeOnce(x, p, r - (p - s), s, tolerance, temp)) {
        out.failedKnot = k;
        out.work = x.work;
        return out;
      }
    }
    x.U.resize(x.U.size() - (k + 1 == K ? p + 1 : p));  // the next knot is added with its piece
  }
  out.poles = x.P.topRows(x.n);
  out.work = x.work;
  return out;
}

}  // namespace fairsplines::detail
