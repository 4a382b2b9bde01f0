// Bernstein-Bézier algebra on [0, 1]; see bernstein.hpp.
#include "bernstein.hpp"

namespace fairsplines::bernstein {

double binomial(int n, int k) {
  double r = 1;
  for (int j = 1; j <= k; ++j) r = r * (n - k + j) / j;
  return r;
}

Eigen::VectorXd product(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  const int m = static_cast<int>(a.size()) - 1, n = static_cast<int>(b.size()) - 1;
  Eigen::VectorXd c = Eigen::VectorXd::Zero(m + n + 1);
  for (int i = 0; i <= m; ++i) {
    const double ai = binomial(m, i) * a[i];
    for (int j = 0; j <= n; ++j) c[i + j] += ai * binomial(n, j) * b[j];
  }
  for (int k = 0; k <= m + n; ++k) c[k] /= binomial(m + n, k);
  return c;
}

PointMatrix composeQuadratic(const PointMatrix& quadratic, const Eigen::VectorXd& rbar, const Eigen::VectorXd& rlow) {
  const Eigen::VectorXd diff = rlow - rbar;
  const Eigen::VectorXd basis[3] = {product(diff, diff), 2 * product(diff, rbar), product(rbar, rbar)};
  PointMatrix out = PointMatrix::Zero(basis[0].size(), quadratic.cols());
  for (int k = 0; k < 3; ++k) out += basis[k] * quadratic.row(k);
  return out;
}

namespace {

void certifyLower(const Eigen::VectorXd& a, double lo, double hi, double tol, int depth, Bound& out) {
  if (!out.holds || out.undecided) return;
  const Eigen::Index n = a.size() - 1;
  if (a.minCoeff() >= -tol) {
    ++out.pieces;
    return;
  }
  if (a[0] < -tol || a[n] < -tol) {  // an end coefficient is the exact value there
    out.holds = false;
    out.witness = a[0] < -tol ? lo : hi;
    return;
  }
  if (depth >= kMaxDepth || out.pieces >= kMaxPieces) {
    out.undecided = true;
    out.witness = 0.5 * (lo + hi);
    return;
  }
  Eigen::VectorXd left, right;
  split(a, 0.5, left, right);  // de Casteljau at 1/2: the two halves
  const double mid = 0.5 * (lo + hi);
  certifyLower(left, lo, mid, tol, depth + 1, out);
  certifyLower(right, mid, hi, tol, depth + 1, out);
}

}  // namespace

Bound certifyLower(const Eigen::VectorXd& a, double tol) {
  Bound out;
  certifyLower(a, 0.0, 1.0, tol, 0, out);
  return out;
}

double bisectRoot(const Eigen::VectorXd& a, double t0, double t1) {
  double f0 = value(a, t0)[0];
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (t0 + t1), fm = value(a, mid)[0];
    if ((fm < 0) == (f0 < 0)) {
      t0 = mid;
      f0 = fm;
    } else {
      t1 = mid;
    }
  }
  return 0.5 * (t0 + t1);
}

}  // namespace fairsplines::bernstein
