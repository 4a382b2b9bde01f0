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

}  // namespace fairsplines::bernstein
