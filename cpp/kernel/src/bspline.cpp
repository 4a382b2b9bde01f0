#include "fairsplines/bspline.hpp"

#include <sstream>

#include "fairsplines/errors.hpp"

namespace fairsplines {

Eigen::VectorXd betaFromKnots(const Eigen::VectorXd& knots) {
  const Eigen::Index n = knots.size();
  Eigen::VectorXd beta(std::max<Eigen::Index>(n - 2, 0));
  for (Eigen::Index i = 1; i + 1 < n; ++i) {
    beta[i - 1] = (knots[i + 1] - knots[i]) / (knots[i] - knots[i - 1]);  // eq. (1)
  }
  return beta;
}

G2Spline g2FromDeBoor(const PointMatrix& c, const Eigen::VectorXd& beta) {
  const Eigen::Index K1 = c.rows();  // K + 1 control points c_0..c_K
  if (K1 < 4) throw InputError("the G2 form needs at least 4 control points");
  if (beta.size() != K1) throw InputError("the G2 form needs one beta per control point");
  for (Eigen::Index i = 0; i < K1; ++i) {
    if (!(beta[i] > 0.0)) {
      std::ostringstream msg;
      msg << "beta_" << i << " = " << beta[i] << " is not positive";
      throw InputError(msg.str());
    }
  }
  const Eigen::Index K = K1 - 1;
  // Eq. (2): the interior coefficients of the segment starting at t_i.
  auto e = [&](Eigen::Index i) { return 1.0 / (1.0 + beta[i] + beta[i] * beta[i + 1]); };
  auto eTilde = [&](Eigen::Index i) { return beta[i] * beta[i + 1] / (1.0 + beta[i] + beta[i] * beta[i + 1]); };
  auto b1 = [&](Eigen::Index i) -> Eigen::RowVectorXd { return (1.0 - e(i)) * c.row(i) + e(i) * c.row(i + 1); };
  auto b2 = [&](Eigen::Index i) -> Eigen::RowVectorXd {
    return eTilde(i) * c.row(i) + (1.0 - eTilde(i)) * c.row(i + 1);
  };
  // b_0^i = b_3^{i-1} = (1 - x_i) b_2^{i-1} + x_i b_1^i,  x_i = 1 / (1 + beta_i).
  auto b0 = [&](Eigen::Index i) -> Eigen::RowVectorXd {
    const double x = 1.0 / (1.0 + beta[i]);
    return (1.0 - x) * b2(i - 1) + x * b1(i);
  };
  const Eigen::Index m = K - 2;  // pieces starting at t_1 .. t_{K-2}
  G2Spline g2;
  g2.bezier.resize(4 * m, c.cols());
  g2.beta = beta.segment(1, m + 1);
  for (Eigen::Index k = 0; k < m; ++k) {
    const Eigen::Index i = k + 1;
    g2.bezier.row(4 * k + 0) = b0(i);
    g2.bezier.row(4 * k + 1) = b1(i);
    g2.bezier.row(4 * k + 2) = b2(i);
    g2.bezier.row(4 * k + 3) = b0(i + 1);
  }
  return g2;
}

PointMatrix deBoorFromG2(const G2Spline& g2) {
  const int m = g2.pieces();
  if (m < 1 || g2.beta.size() != m + 1) throw InputError("a G2 spline needs one beta more than it has pieces");
  PointMatrix c(m + 1, g2.bezier.cols());
  for (int k = 0; k <= m; ++k) {
    const double beta = g2.beta[k];
    if (k > 0) {
      // eq. (3), left: c_i = -beta_i b_1^{i-1} + (1 + beta_i) b_2^{i-1}
      c.row(k) = -beta * g2.bezier.row(4 * (k - 1) + 1) + (1.0 + beta) * g2.bezier.row(4 * (k - 1) + 2);
    } else {
      // eq. (3), right: c_i = (1 + 1/beta_i) b_1^i - (1/beta_i) b_2^i
      c.row(k) = (1.0 + 1.0 / beta) * g2.bezier.row(4 * k + 1) - (1.0 / beta) * g2.bezier.row(4 * k + 2);
    }
  }
  return c;
}

BSplineCurve clampedCubic(PointMatrix poles, const Eigen::VectorXd& t) {
  const Eigen::Index n = t.size();
  BSplineCurve curve;
  curve.degree = 3;
  curve.poles = std::move(poles);
  curve.knots = t;
  curve.mults = Eigen::VectorXi::Ones(n);
  curve.mults[0] = curve.mults[n - 1] = 4;
  return curve;
}

BSplineCurve periodicCubic(PointMatrix poles, const Eigen::VectorXd& t) {
  const Eigen::Index n = poles.rows();
  BSplineCurve curve;
  curve.degree = 3;
  // OCCT's periodic pole j (0-based) belongs to the basis function whose support starts
  // at knot j - 1 of the periodic sequence; pole i here is centred on t_i, i.e. its
  // support starts at t_{i-2}: rotate by one.
  curve.poles.resize(n, poles.cols());
  for (Eigen::Index j = 0; j < n; ++j) curve.poles.row(j) = poles.row((j + 1) % n);
  curve.knots = t;
  curve.mults = Eigen::VectorXi::Ones(t.size());
  curve.periodic = true;
  return curve;
}

}  // namespace fairsplines
