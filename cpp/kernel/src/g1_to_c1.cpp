#include "fairsplines/g1_to_c1.hpp"

#include <cmath>
#include <sstream>

#include "fairsplines/errors.hpp"
#include "bernstein.hpp"
#include "finite.hpp"

namespace fairsplines {

double etaStart(double wPrev, double w, double beta, double betaT) {
  // Appendix 7.3, derived: with P the joint, the end derivatives of q∘eta are
  // a (P + w m) - 2 P (start) and 2 P - a (P + w m) (end); C1 with betaT splits into a part
  // along P (the printed denominators) and one along the tangent, which gives
  // betaT a_1^{i-1} = beta_i a_0^i. The printed numerators hold for betaT = beta.
  return 2 * (1 + betaT) / beta / (w / beta + wPrev + 1 / beta + 1);
}

double etaEnd(double w, double wNext, double betaNext, double betaTNext) {
  return 2 * betaNext * (1 + 1 / betaTNext) / (w * betaNext + wNext + betaNext + 1);
}

std::array<Reparam2, 2> etaSplit(double a0, double a1) {
  // h(t) with coefficients (0,1), a (1/2, 1), (1,1): subdivide h^0 on [0, 1/2], h^1 on [1/2, 1].
  std::array<Reparam2, 2> eta;
  // Blossoms of h^0 at (0, 1/2) and (1/2, 1/2); of h^1 at (1/2, 1/2) and (1/2, 1).
  auto blossom = [](double a, double s, double t) {
    const Eigen::RowVector2d h0(0, 1), h1(a / 2, a), h2(1, 1);
    return Eigen::RowVector2d((1 - s) * (1 - t) * h0 + ((1 - s) * t + s * (1 - t)) * h1 + s * t * h2);
  };
  eta[0].row(0) = blossom(a0, 0, 0);
  eta[0].row(1) = blossom(a0, 0, 0.5);
  eta[1].row(1) = blossom(a1, 0.5, 1);
  eta[1].row(2) = blossom(a1, 1, 1);
  // Overwrite the common point so that the two pieces join C1 (with scalar 1).
  eta[0].row(2) = (eta[0].row(1) + eta[1].row(1)) / 2;
  eta[1].row(0) = eta[0].row(2);
  return eta;
}

PointMatrix composeQuadratic2(const PointMatrix& q, const Reparam2& eta) {
  // Eq. (9) with a quadratic map: Bernstein products of degree 2 x 2 -> 4, (low - bar)^2,
  // 2 (low - bar) bar, bar^2.
  return bernstein::composeQuadratic(q, eta.col(0), eta.col(1));
}

C1QuarticSpline g1ToC1(const PointMatrix& quadratics, const Eigen::VectorXd& beta, const Eigen::VectorXd& betaT,
                       bool closed) {
  const int n = static_cast<int>(quadratics.rows() / 3);
  if (n < 1 || quadratics.rows() != 3 * n) throw InputError("a G1 quadratic spline needs 3 Bézier points per piece");
  if (beta.size() != n || betaT.size() != n)
    throw InputError("one scalar per piece (index i: join of pieces i-1 and i)");
  requireFinite(quadratics, "the G1 quadratic spline", "Bezier points");
  {
    const int first = closed ? 0 : 1;  // an open spline's scalars 0 are not used
    requireModerateScalars(beta.tail(n - first), "the G1 scalar beta at join");
    requireModerateScalars(betaT.tail(n - first), "the C1 scalar betaT at join");
  }
  const int wc = static_cast<int>(quadratics.cols()) - 1;
  Eigen::VectorXd w(n);
  for (int i = 0; i < n; ++i) {
    w[i] = quadratics(3 * i + 1, wc);
    if (!(w[i] > 0) || !(quadratics(3 * i, wc) > 0) || !(quadratics(3 * i + 2, wc) > 0)) {
      std::ostringstream os;
      os << "piece " << i << " has a non-positive weight";
      throw InputError(os.str());
    }
    if ((i > 0 || closed) && (!(beta[i] > 0) || !(betaT[i] > 0))) throw InputError("G1 scalars must be positive");
  }
  C1QuarticSpline out;
  out.closed = closed;
  out.bezier.resize(10 * n, quadratics.cols());
  out.beta = Eigen::VectorXd::Ones(2 * n);
  for (int i = 0; i < n; ++i) {
    const bool hasPrev = closed || i > 0, hasNext = closed || i + 1 < n;
    const int prev = (i + n - 1) % n, next = (i + 1) % n;
    // Open ends: a mirrored neighbour (same weight, scalar 1).
    const double a0 = hasPrev ? etaStart(w[prev], w[i], beta[i], betaT[i]) : etaStart(w[i], w[i], 1.0, 1.0);
    const double a1 = hasNext ? etaEnd(w[i], w[next], beta[next], betaT[next]) : etaEnd(w[i], w[i], 1.0, 1.0);
    const auto eta = etaSplit(a0, a1);
    const PointMatrix q = quadratics.middleRows(3 * i, 3);
    out.bezier.middleRows(10 * i, 5) = composeQuadratic2(q, eta[0]);  // eq. (12)
    out.bezier.middleRows(10 * i + 5, 5) = composeQuadratic2(q, eta[1]);
    out.beta[2 * i] = hasPrev ? betaT[i] : 1.0;
  }
  requireFinite(out.bezier, "the C1 quartic spline", "Bezier points");
  return out;
}

void g1Circle(const Eigen::VectorXd& theta, PointMatrix& quadratics, Eigen::VectorXd& beta, bool& closed) {
  const int n = static_cast<int>(theta.size()) - 1;
  const double pi = std::acos(-1.0);
  if (n < 1) throw InputError("a circle partition needs at least two angles");
  for (int i = 1; i <= n; ++i) {
    if (!(theta[i] > theta[i - 1]) || !std::isfinite(theta[i])) {
      std::ostringstream os;
      os << "angles must increase: angle " << i << " is not greater than angle " << i - 1;
      throw InputError(os.str());
    }
    if (theta[i] - theta[i - 1] >= pi - 1e-12) {
      throw InputError("a rational quadratic arc must open less than pi (its weight cos(alpha/2) must be positive)");
    }
  }
  requireSeparateKnots(theta, "the circle partition's angles");
  closed = std::abs(theta[n] - theta[0] - 2 * pi) <= 1e-12;
  quadratics.resize(3 * n, 3);
  beta = Eigen::VectorXd::Ones(n);
  for (int i = 0; i < n; ++i) {
    const double t0 = theta[i], a = theta[i + 1] - theta[i];
    quadratics.row(3 * i) << std::cos(t0), std::sin(t0), 1.0;
    quadratics.row(3 * i + 1) << std::cos(t0 + a / 2), std::sin(t0 + a / 2), std::cos(a / 2);
    quadratics.row(3 * i + 2) << std::cos(t0 + a), std::sin(t0 + a), 1.0;
    const int p = (i + n - 1) % n;
    if (i > 0 || closed) beta[i] = std::sin(a / 2) / std::sin((theta[p + 1] - theta[p]) / 2);
  }
}

}  // namespace fairsplines
