#include "fairsplines/g2_to_c2.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "fairsplines/errors.hpp"
#include "bernstein.hpp"
#include "finite.hpp"

namespace fairsplines {

namespace {

/// Cubic Bézier (4 rows) restricted to [a, b], by blossoming: rows f[a,a,a], f[a,a,b], f[a,b,b], f[b,b,b].
Reparam subdivide(const Reparam& c, double a, double b) {
  auto blossom = [&](double t1, double t2, double t3) {
    Eigen::Matrix<double, 4, 2> p = c;
    const double ts[3] = {t1, t2, t3};
    for (int level = 0; level < 3; ++level) {
      for (int k = 0; k < 3 - level; ++k) p.row(k) = (1 - ts[level]) * p.row(k) + ts[level] * p.row(k + 1);
    }
    return Eigen::RowVector2d(p.row(0));
  };
  Reparam out;
  out.row(0) = blossom(a, a, a);
  out.row(1) = blossom(a, a, b);
  out.row(2) = blossom(a, b, b);
  out.row(3) = blossom(b, b, b);
  return out;
}

/// Throws InputError unless r = rbar / rlow has a positive denominator and increases on [0, 1]
/// (checked on 65 samples: a reparameterization must be monotone, Section 3).
/// The InputError of a map that is not monotone, with the arc it belongs to (the Mixed
/// strategy then gives that arc sigma instead).
struct NotMonotone : InputError {
  NotMonotone(const std::string& what, int arc, bool rho) : InputError(what), arc(arc), rho(rho) {}
  int arc;
  bool rho;
};

void checkMonotone(const Reparam& r, const char* which, int arc) {
  double last = -1e300;
  for (int k = 0; k <= 64; ++k) {
    const double u = k / 64.0, b0 = (1 - u) * (1 - u) * (1 - u), b1 = 3 * u * (1 - u) * (1 - u),
                 b2 = 3 * u * u * (1 - u), b3 = u * u * u;
    const double num = b0 * r(0, 0) + b1 * r(1, 0) + b2 * r(2, 0) + b3 * r(3, 0);
    const double den = b0 * r(0, 1) + b1 * r(1, 1) + b2 * r(2, 1) + b3 * r(3, 1);
    if (!(den > 0) || !(num / den >= last - 1e-14) || !std::isfinite(num / den)) {
      std::ostringstream os;
      os << "the " << which << " reparameterization of arc " << arc
         << " is not monotone; choose new continuity scalars closer to the shape's beta"
         << (std::string(which) == "rho" ? " (or the sigma or mixed method)" : "");
      throw NotMonotone(os.str(), arc, std::string(which) == "rho");
    }
    last = num / den;
  }
}

/// The mirrored neighbour used at an open end: same opening, scalar 1.
double tauAt(const G2CircleSpline& c, int i) {
  const int n = c.pieces();
  if (c.closed) i = (i % n + n) % n;
  if (i < 0) i = 0;
  if (i >= n) i = n - 1;
  return std::tan(c.alpha[i] / 4);
}

}  // namespace

Reparam rhoEndMap(double tau0, double tau1, double betaT) {
  // Appendix 7.1.
  const double b = betaT, t0 = tau0, t1 = tau1;
  const double aM1 = t1 * (1 + t0 * t0) + 2 * t0 * t1 * (t0 + t1) * b + t0 * (1 + t1 * t1) * b * b;
  const double a0 = 2 * t1 * (t0 + t1) + (3 + 4 * t0 * t1 + 7 * t1 * t1) * b + 3 * (1 + t1 * t1) * b * b;
  const double a1 = 3 * (1 + t0 * t0) * (1 + t1 * t1) +
                    (6 + 10 * t0 * t0 + 8 * t0 * t1 + 10 * t1 * t1 + 6 * t0 * t0 * t1 * t1) * b +
                    3 * (1 + t0 * t0) * (1 + t1 * t1) * b * b;
  const double d = aM1 / (t0 * a0), nu = (1 + t0 * t0) * (1 + b) * a0 / (b * a1);
  Reparam h;
  h << 0, 1, nu * d, nu, nu * (1 - d), nu, 1, 1;
  return h;
}

Reparam reverseMap(const Reparam& r) {
  Reparam out;
  for (int k = 0; k < 4; ++k) out.row(k) << r(3 - k, 1) - r(3 - k, 0), r(3 - k, 1);
  return out;
}

std::array<Reparam, 3> rhoSplitFromMaps(const Reparam& h0, const Reparam& h1) {
  // Appendix 7.1: rho^0(u) = h^0(u/3), rho^2(u) = h^1(2/3 + u/3); eq. (13) overwrites the
  // inner end points, eq. (14) sets the middle piece; the three join C2 (uniformly).
  std::array<Reparam, 3> rho;
  rho[0] = subdivide(h0, 0.0, 1.0 / 3);
  rho[2] = subdivide(h1, 2.0 / 3, 1.0);
  const Eigen::RowVector2d r01 = rho[0].row(1), r02 = rho[0].row(2), r21 = rho[2].row(1), r22 = rho[2].row(2);
  rho[0].row(3) = -r01 / 3 + 7 * r02 / 6 + r21 / 3 - r22 / 6;  // eq. (13)
  rho[2].row(0) = -r01 / 6 + r02 / 3 + 7 * r21 / 6 - r22 / 3;
  rho[1].row(0) = rho[0].row(3);  // eq. (14)
  rho[1].row(1) = 2 * rho[0].row(3) - r02;
  rho[1].row(2) = 2 * rho[2].row(0) - r21;
  rho[1].row(3) = rho[2].row(0);
  return rho;
}

std::array<Reparam, 3> rhoSplit(double tauPrev, double tau, double tauNext, double betaLeft, double betaRight) {
  // h^0 from h^1 by tau_1 -> tau_{-1}, beta_1 -> 1 / beta_0 (Appendix 7.1); both are symmetric maps.
  return rhoSplitFromMaps(rhoEndMap(tau, tauPrev, 1.0 / betaLeft), rhoEndMap(tau, tauNext, betaRight));
}

Reparam transitionMap(double tau, double tauBar, const Reparam& h, double betaT) {
  // Appendix 7.2, with h_1 = (nu_1 d_1, nu_1), h_2 = (nu_2 d_2, nu_2).
  const double nu1 = h(1, 1), d1 = h(1, 0) / nu1, nu2 = h(2, 1), d2 = h(2, 0) / nu2, b = betaT;
  const double e1 = 1 + tau * tau, e2 = 1 + tauBar * tauBar, e3 = -1 + 2 * tau * tauBar + tau * tau,
               e4 = -2 * tau * (tau + tauBar);
  const double a1 = 2 * (e1 + e3 * nu2 + e4 * d2 * nu2), a2 = -e1 - e3 * nu1 - e4 * d1 * nu1;
  const double nub1 = (2 * e1 + a1 * b) / (2 * e1), nub2 = (e1 + a1 * b + (a1 + a2) * b * b) / e1;
  const double db1 = b * tau * nu2 * (1 - d2) * e2 / (e1 * tauBar * nub1);
  const double db2 =
      b * tau * e2 * (2 * nu2 - 2 * d2 * nu2 + (2 * nu2 - 2 * d2 * nu2 - nu1 + d1 * nu1) * b) / (e1 * tauBar * nub2);
  Reparam hb;
  hb << 0, 1, nub1 * db1, nub1, nub2 * db2, nub2, 1, 1;
  return hb;
}

Eigen::Vector2d projectToHalfAngle(const Eigen::Vector2d& p) {
  // Eq. (7): P(x, y) = (c x, c - 1 + c y), c = 1 / sqrt(x^2 + (y + 1)^2).
  const double c = 1.0 / std::sqrt(p.x() * p.x() + (p.y() + 1) * (p.y() + 1));
  return {c * p.x(), c - 1 + c * p.y()};
}

Eigen::Vector3d projectBack(const Eigen::Vector2d& p) {
  // Eq. (8): (x, y) -> (2 x (1 + y), (1 + y)^2 - x^2, x^2 + (y + 1)^2).
  const double x = p.x(), y1 = 1 + p.y();
  return {2 * x * y1, y1 * y1 - x * x, x * x + y1 * y1};
}

namespace {

/// Eq. (8) reads, with z = x + i (1 + y), as (X + i Y, W) = (-i z^2, |z|^2). So with
/// zeta := e^{-i pi/4} z the circle point is (zeta^2, |zeta|^2): zeta is a square root of
/// the point, at half its angle. The conic of arc i is (lambda(s)^2, |lambda(s)|^2) with
/// lambda(s) = lambda_0 (1 - s) + lambda_1 s, lambda_0 = e^{i theta_i/2},
/// lambda_1 = e^{i theta_{i+1}/2}. So q∘sigma equals the sextic exactly when
/// lambda_0 (sigmaLow - sigmaBar) + lambda_1 sigmaBar = zeta: a 2 x 2 real system per
/// Bézier coefficient, which gives sigma in closed form.
Eigen::Vector2d zetaOf(const Eigen::Vector2d& projected) {
  const double x = projected.x(), y1 = 1 + projected.y(), s = std::sqrt(0.5);
  return {s * (x + y1), s * (y1 - x)};  // e^{-i pi/4} (x + i y1)
}

/// Sigma maps of the arcs of a run: knots theta[0..k] (k arcs), betaT[j] between arc j-1 and
/// arc j of the run (betaT[0]: closing join when cyclic). cyclic: the run is a full circle.
std::vector<Reparam> sigmaRun(const Eigen::VectorXd& theta, const Eigen::VectorXd& betaT, bool cyclic, int arcOffset) {
  const int k = static_cast<int>(theta.size()) - 1;
  // Knot intervals with h_j / h_{j-1} = betaT_j.
  Eigen::VectorXd h(k);
  h[0] = 1.0;
  for (int j = 1; j < k; ++j) h[j] = h[j - 1] * betaT[j];
  if (cyclic && std::abs(h[k - 1] * betaT[0] - 1.0) > 1e-9) {
    throw InputError("the continuity scalars of a closed circle must multiply to 1 around it");
  }
  // Projected points, eq. (7), continued on the 'Southern' semicircle (sign flip) where the
  // half angle passes pi: zeta_j follows zeta_{j-1} e^{i alpha/2}.
  Eigen::MatrixXd zeta(k + 1, 2);
  for (int j = 0; j <= k; ++j) {
    Eigen::Vector2d z = zetaOf(projectToHalfAngle({std::cos(theta[j]), std::sin(theta[j])}));
    const double halfAngle = theta[j] / 2;
    if (z.dot(Eigen::Vector2d(std::cos(halfAngle), std::sin(halfAngle))) < 0) z = -z;
    zeta.row(j) = z.transpose();
  }
  // C2 cubic interpolation: derivatives m_j at the knots,
  // h_j m_{j-1} + 2 (h_{j-1} + h_j) m_j + h_{j-1} m_{j+1} = 3 (h_j D_{j-1} / h_{j-1} + h_{j-1} D_j / h_j).
  Eigen::MatrixXd m(k + 1, 2);
  auto delta = [&](int j) -> Eigen::RowVector2d { return zeta.row(j + 1) - zeta.row(j); };
  if (!cyclic) {
    // Open ends: the speed of the identity reparameterization (the chord of zeta).
    m.row(0) = delta(0) / h[0];
    m.row(k) = delta(k - 1) / h[k - 1];
    const int n = k - 1;  // unknowns m_1..m_{k-1}: a tridiagonal system (Thomas algorithm)
    if (n > 0) {
      Eigen::VectorXd a(n), b(n), c(n);
      Eigen::MatrixXd r(n, 2);
      for (int q = 0; q < n; ++q) {
        const int j = q + 1;
        a[q] = h[j];
        b[q] = 2 * (h[j - 1] + h[j]);
        c[q] = h[j - 1];
        r.row(q) = 3 * (h[j] * delta(j - 1) / h[j - 1] + h[j - 1] * delta(j) / h[j]);
      }
      r.row(0) -= a[0] * m.row(0);
      r.row(n - 1) -= c[n - 1] * m.row(k);
      for (int q = 1; q < n; ++q) {
        const double f = a[q] / b[q - 1];
        b[q] -= f * c[q - 1];
        r.row(q) -= f * r.row(q - 1);
      }
      m.row(n) = r.row(n - 1) / b[n - 1];
      for (int q = n - 2; q >= 0; --q) m.row(q + 1) = (r.row(q) - c[q] * m.row(q + 2)) / b[q];
    }
  } else {
    // Full circle: zeta is anti-periodic (zeta_k = -zeta_0, m_k = -m_0), a cyclic
    // tridiagonal system with sign-flipped corners, solved by Sherman-Morrison.
    const int n = k;
    auto hh = [&](int j) { return h[(j % n + n) % n]; };
    Eigen::VectorXd a(n), b(n), c(n);
    Eigen::MatrixXd r(n, 2);
    for (int j = 0; j < n; ++j) {
      const Eigen::RowVector2d dPrev =
          j > 0 ? Eigen::RowVector2d(delta(j - 1)) : Eigen::RowVector2d(zeta.row(0) + zeta.row(k - 1));
      // for j = 0: zeta_0 - zeta_{-1} with zeta_{-1} = -zeta_{k-1}
      a[j] = hh(j);
      b[j] = 2 * (hh(j - 1) + hh(j));
      c[j] = hh(j - 1);
      r.row(j) = 3 * (hh(j) * dPrev / hh(j - 1) + hh(j - 1) * delta(j) / hh(j));
    }
    // Corners: row 0 couples m_{-1} = -m_{k-1}; row n-1 couples m_n = -m_0.
    const double alphaC = -c[n - 1], betaC = -a[0];  // A[n-1][0] = alphaC, A[0][n-1] = betaC
    if (n == 1) {
      m.row(0) = r.row(0) / (b[0] + alphaC + betaC);
    } else {
      const double gammaC = -b[0];
      Eigen::VectorXd bb = b;
      bb[0] -= gammaC;
      bb[n - 1] -= alphaC * betaC / gammaC;
      auto thomas = [&](Eigen::MatrixXd rhs) {
        Eigen::VectorXd bw = bb, cw = c;
        for (int q = 1; q < n; ++q) {
          const double f = a[q] / bw[q - 1];
          bw[q] -= f * cw[q - 1];
          rhs.row(q) -= f * rhs.row(q - 1);
        }
        Eigen::MatrixXd x(n, rhs.cols());
        x.row(n - 1) = rhs.row(n - 1) / bw[n - 1];
        for (int q = n - 2; q >= 0; --q) x.row(q) = (rhs.row(q) - cw[q] * x.row(q + 1)) / bw[q];
        return x;
      };
      Eigen::MatrixXd u = Eigen::MatrixXd::Zero(n, 1);
      u(0, 0) = gammaC;
      u(n - 1, 0) = alphaC;
      const Eigen::MatrixXd y = thomas(r), z = thomas(u);
      const double vz = z(0, 0) + betaC / gammaC * z(n - 1, 0);
      for (int col = 0; col < 2; ++col) {
        const double vy = y(0, col) + betaC / gammaC * y(n - 1, col);
        for (int j = 0; j < n; ++j) m(j, col) = y(j, col) - z(j, 0) * vy / (1 + vz);
      }
    }
    m.row(k) = -m.row(0);
  }
  std::vector<Reparam> maps(k);
  for (int j = 0; j < k; ++j) {
    // Bézier points of zeta on arc j, then sigma from lambda_0 sLow + (lambda_1 - lambda_0) sBar = Z.
    Eigen::Matrix<double, 4, 2> Z;
    Z.row(0) = zeta.row(j);
    Z.row(1) = zeta.row(j) + h[j] * m.row(j) / 3;
    Z.row(2) = zeta.row(j + 1) - h[j] * m.row(j + 1) / 3;
    Z.row(3) = zeta.row(j + 1);
    Eigen::Matrix2d M;
    M.col(0) = (zeta.row(j + 1) - zeta.row(j)).transpose();  // lambda_1 - lambda_0 (times sBar)
    M.col(1) = zeta.row(j).transpose();                      // lambda_0 (times sLow)
    const Eigen::Matrix2d Minv = M.inverse();
    Reparam s;
    for (int q = 0; q < 4; ++q) s.row(q) = (Minv * Z.row(q).transpose()).transpose();
    s.row(0) << 0, 1;  // exact by construction; remove rounding
    s.row(3) << 1, 1;
    checkMonotone(s, "sigma", arcOffset + j);
    maps[j] = s;
  }
  return maps;
}

}  // namespace

std::vector<Reparam> sigmaMaps(const G2CircleSpline& circle, const Eigen::VectorXd& betaT) {
  if (betaT.size() != circle.pieces()) throw InputError("sigma needs one continuity scalar per arc");
  return sigmaRun(circle.theta, betaT, circle.closed, 0);
}

PointMatrix composeQuadratic(const PointMatrix& quadratic, const Reparam& r) {
  // Eq. (9): sum_k q_k binom(2,k) (rlow - rbar)^{2-k} rbar^k, in Bernstein form of degree 6.
  return bernstein::composeQuadratic(quadratic, r.col(0), r.col(1));
}

PointMatrix hermiteQuadratic(const PointMatrix& cubic, double t0) {
  // Value and derivatives of the cubic at t0 by de Casteljau.
  const double s = 1 - t0;
  const PointMatrix b = cubic;
  const Eigen::RowVectorXd c0 = s * b.row(0) + t0 * b.row(1), c1 = s * b.row(1) + t0 * b.row(2),
                           c2 = s * b.row(2) + t0 * b.row(3);
  const Eigen::RowVectorXd e0 = s * c0 + t0 * c1, e1 = s * c1 + t0 * c2;
  const Eigen::RowVectorXd f = s * e0 + t0 * e1, df = 3 * (e1 - e0), d2f = 6 * (c2 - 2 * c1 + c0);
  // Q(t) = f + df (t - t0) + d2f (t - t0)^2 / 2 in Bézier form over [0, 1].
  const Eigen::RowVectorXd q0 = f - t0 * df + t0 * t0 / 2 * d2f, dq0 = df - t0 * d2f;
  const Eigen::RowVectorXd q1 = f + (1 - t0) * df + (1 - t0) * (1 - t0) / 2 * d2f;
  PointMatrix q(3, cubic.cols());
  q.row(0) = q0;
  q.row(1) = q0 + dq0 / 2;
  q.row(2) = q1;
  return q;
}

PointMatrix mergeSextics(const PointMatrix& first, const PointMatrix& second) {
  PointMatrix b = second;  // eq. (10)
  b.topRows(3) = first.topRows(3);
  b.row(3) = (first.row(3) + second.row(3)) / 2;
  return b;
}

void adjustC2(PointMatrix& left, PointMatrix& right, double beta) {
  // Eq. (5): P = (beta + 1) b_5 - beta b_4, Pbar = ((beta + 1) bbar_1 - bbar_2) / beta.
  const Eigen::RowVectorXd P = (beta + 1) * left.row(5) - beta * left.row(4);
  const Eigen::RowVectorXd Pbar = ((beta + 1) * right.row(1) - right.row(2)) / beta;
  const Eigen::RowVectorXd Pnew = (P + Pbar) / 2;          // eq. (11)
  left.row(5) = (beta * left.row(4) + Pnew) / (beta + 1);  // eq. (6)
  right.row(1) = (beta * Pnew + right.row(2)) / (beta + 1);
  left.row(6) = (beta * left.row(5) + right.row(1)) / (beta + 1);  // eq. (11)
  right.row(0) = left.row(6);
}

Eigen::VectorXd C2SexticSpline::knots() const {
  const int n = pieces();
  Eigen::VectorXd t(n + 1);
  t[0] = 0.0;
  double h = 1.0;
  for (int k = 0; k < n; ++k) {
    if (k > 0) h *= beta[k];
    t[k + 1] = t[k] + h;
  }
  return t;
}

PointMatrix raiseCubicToSextic(const PointMatrix& cubic) { return bernstein::raise(cubic, 6); }

C2SexticSpline g2ToC2(const PointMatrix& cubicPieces, const std::vector<std::vector<Reparam>>& maps,
                      const Eigen::VectorXd& betaT, bool closed) {
  const int n = static_cast<int>(cubicPieces.rows() / 4);
  if (n < 1 || cubicPieces.rows() != 4 * n) throw InputError("a G2 cubic spline needs 4 Bézier points per piece");
  if (static_cast<int>(maps.size()) != n || betaT.size() != n)
    throw InputError("one map list and one scalar per piece");
  requireFinite(cubicPieces, "the G2 cubic spline", "Bezier points");
  requireModerateScalars(betaT.tail(closed ? n : n - 1), "the C2 scalar betaT at join");
  C2SexticSpline out;
  out.closed = closed;
  int total = 0;
  for (const auto& m : maps) total += static_cast<int>(m.size());
  out.bezier.resize(7 * total, cubicPieces.cols());
  out.beta = Eigen::VectorXd::Ones(total);
  out.firstPiece.assign(n + 1, total);
  int piece = 0;
  for (int i = 0; i < n; ++i) {
    out.firstPiece[i] = piece;
    const PointMatrix cubic = cubicPieces.middleRows(4 * i, 4);
    const auto& r = maps[i];
    const int parts = static_cast<int>(r.size());
    if (parts != 1 && parts != 3) throw InputError("a piece is reparameterized by one map (sigma) or three (rho)");
    // Break points in the cubic's parameter: 0, r^j(0) (j > 0), 1.
    std::vector<double> t(parts + 1);
    t[0] = 0.0;
    t[parts] = 1.0;
    for (int j = 1; j < parts; ++j) t[j] = r[j](0, 0) / r[j](0, 1);
    for (int j = 0; j < parts; ++j) {
      // Section 4.1: Hermite quadratics of the cubic at both ends of the part, each composed
      // with the part's map (eq. (9)), merged by eq. (10).
      const PointMatrix g0 = composeQuadratic(hermiteQuadratic(cubic, t[j]), r[j]);
      const PointMatrix g1 = composeQuadratic(hermiteQuadratic(cubic, t[j + 1]), r[j]);
      out.bezier.middleRows(7 * piece, 7) = mergeSextics(g0, g1);
      if (j == 0) out.beta[piece] = betaT[i];
      ++piece;
    }
  }
  if (!closed) out.beta[0] = 1.0;
  requireFinite(out.bezier, "the C2 sextic spline", "Bezier points");
  return out;
}

std::vector<CircleReparam> mixedChoice(const G2CircleSpline& circle) {
  const int n = circle.pieces();
  auto same = [&](int i, int j) {
    if (circle.closed) {
      i = (i % n + n) % n;
      j = (j % n + n) % n;
    }
    if (i < 0 || i >= n || j < 0 || j >= n) return false;
    return std::abs(circle.alpha[i] - circle.alpha[j]) <= 1e-12 * circle.alpha[i];
  };
  // rho keeps uniform and symmetric runs so (Section 3, "the best of the two approaches"):
  // an arc gets rho inside a window of at least two arcs whose openings read the same both
  // ways (a palindrome: two equal neighbours are a uniform run, 0.5, 1.2, 0.5 a symmetric one).
  std::vector<CircleReparam> choice(n, CircleReparam::Sigma);
  auto mark = [&](int first, int last) {
    for (int j = first; j <= last; ++j) choice[circle.closed ? (j % n + n) % n : j] = CircleReparam::Rho;
  };
  for (int c = 0; c < n; ++c) {
    // Odd windows centred on arc c: c - m .. c + m.
    int m = 0;
    while (2 * (m + 1) + 1 <= n && same(c - m - 1, c + m + 1)) ++m;
    if (m > 0) mark(c - m, c + m);
    // Even windows centred between arcs c and c + 1: c - m .. c + 1 + m.
    if (same(c, c + 1) && (circle.closed || c + 1 < n)) {
      m = 0;
      while (2 * (m + 1) + 2 <= n && same(c - m - 1, c + 1 + m + 1)) ++m;
      mark(c - m, c + 1 + m);
    }
  }
  return choice;
}

namespace {

/// Section 4.1 with a per-arc choice of rho or sigma (betaT checked by the caller).
CircleMaps circleMapsWith(const G2CircleSpline& circle, const std::vector<CircleReparam>& choice,
                          const Eigen::VectorXd& betaT) {
  const int n = circle.pieces();
  auto wrap = [&](int i) { return circle.closed ? (i % n + n) % n : i; };
  auto isSigma = [&](int i) {
    i = wrap(i);
    return i >= 0 && i < n && choice[i] == CircleReparam::Sigma;
  };

  // Sigma on maximal runs, each from its own tridiagonal system (cyclic for a full circle).
  std::vector<Reparam> sigma(n);
  const bool allSigma =
      std::all_of(choice.begin(), choice.end(), [](CircleReparam c) { return c == CircleReparam::Sigma; });
  if (allSigma) {
    sigma = sigmaRun(circle.theta, betaT, circle.closed, 0);
  } else {
    // Maximal sigma runs (first arc, length); on a closed circle start at a rho arc so that
    // no run wraps around the start.
    std::vector<std::pair<int, int>> runs;
    int start = 0;
    if (circle.closed) {
      while (choice[start] == CircleReparam::Sigma) ++start;
    }
    for (int step = 0; step < n;) {
      const int i = (start + step) % n;
      if (choice[i] != CircleReparam::Sigma) {
        ++step;
        continue;
      }
      int len = 0;
      while (step + len < n && choice[(start + step + len) % n] == CircleReparam::Sigma) ++len;
      runs.emplace_back(i, len);
      step += len;
    }
    for (const auto& [a, len] : runs) {
      Eigen::VectorXd theta(len + 1), beta(len);
      theta[0] = circle.theta[a];
      for (int j = 0; j < len; ++j) {
        theta[j + 1] = theta[j] + circle.alpha[(a + j) % n];
        beta[j] = j == 0 ? 1.0 : betaT[(a + j) % n];
      }
      const std::vector<Reparam> run = sigmaRun(theta, beta, false, a);
      for (int j = 0; j < len; ++j) sigma[(a + j) % n] = run[j];
    }
  }

  std::vector<std::vector<Reparam>> maps(n);
  for (int i = 0; i < n; ++i) {
    if (choice[i] == CircleReparam::Sigma) {
      maps[i] = {sigma[i]};
      continue;
    }
    const double tau = std::tan(circle.alpha[i] / 4);
    const bool hasLeft = circle.closed || i > 0, hasRight = circle.closed || i < n - 1;
    Reparam h0, h1;
    if (hasLeft && isSigma(i - 1)) {
      // Appendix 7.2 from the sigma arc on the left. Arc to arc the scalar is betaT; piece to
      // piece (a whole sigma arc, then a third of this arc) it is betaT / 3, and since
      // rho^0 = h0(u/3), the whole map h0 joins with 3 (betaT / 3) = betaT.
      h0 = transitionMap(tauAt(circle, i - 1), tau, sigma[wrap(i - 1)], betaT[i]);
    } else {
      h0 = rhoEndMap(tau, hasLeft ? tauAt(circle, i - 1) : tau, hasLeft ? 1.0 / betaT[i] : 1.0);
    }
    if (hasRight && isSigma(i + 1)) {
      // Appendix 7.2 on the reversed arcs (scalar 1 / betaT arc to arc), reversed back.
      const int r = wrap(i + 1);
      h1 = reverseMap(transitionMap(tauAt(circle, r), tau, reverseMap(sigma[r]), 1.0 / betaT[r]));
    } else {
      h1 = rhoEndMap(tau, hasRight ? tauAt(circle, i + 1) : tau, hasRight ? betaT[wrap(i + 1)] : 1.0);
    }
    // Only a third of h0 and h1 is used (and a 7.2 map for 3 betaT need not be monotone on
    // all of [0, 1]): the pieces are checked.
    if ((h0 - h1).norm() <= 1e-14) {
      // Appendix 7.1: "for a uniform partition and all betaT = 1 there is no need for such
      // splitting": the same symmetric map serves both ends, one piece per arc.
      checkMonotone(h0, "rho", i);
      maps[i] = {h0};
      continue;
    }
    const auto rho = rhoSplitFromMaps(h0, h1);
    for (const Reparam& r : rho) checkMonotone(r, "rho", i);
    maps[i] = {rho[0], rho[1], rho[2]};
  }
  // Piece to piece, the arc-to-arc scalar betaT is scaled by the pieces per arc:
  // parts_{i-1} / parts_i (1/3 from sigma to rho, 3 from rho to sigma).
  Eigen::VectorXd betaPieces = betaT;
  for (int i = 0; i < n; ++i) {
    const int left = wrap(i - 1);
    if (left < 0) continue;
    betaPieces[i] *= static_cast<double>(maps[left].size()) / static_cast<double>(maps[i].size());
  }
  return CircleMaps{maps, betaPieces};
}

}  // namespace

C2SexticSpline circleToC2(const G2CircleSpline& circle, CircleReparam method, Eigen::VectorXd betaT) {
  const CircleMaps m = circleMaps(circle, method, std::move(betaT));
  // The cubic pieces are the degree-raised conics, so every Hermite quadratic is the conic
  // itself: g2ToC2 reproduces the circle exactly.
  PointMatrix cubic(circle.cubic.rows(), 3);
  for (Eigen::Index k = 0; k < cubic.rows(); ++k) cubic.row(k) = circle.cubic.row(k);
  return g2ToC2(cubic, m.maps, m.betaPieces, circle.closed);
}

CircleMaps circleMaps(const G2CircleSpline& circle, CircleReparam method, Eigen::VectorXd betaT) {
  const int n = circle.pieces();
  if (betaT.size() == 0) betaT = circle.beta;
  if (betaT.size() != n) throw InputError("one continuity scalar per arc");
  for (int i = 0; i < n; ++i) {
    if (!(betaT[i] > 0) || !std::isfinite(betaT[i])) throw InputError("continuity scalars must be positive");
  }
  requireModerateScalars(betaT.tail(circle.closed ? n : n - 1), "the continuity scalar betaT of arc");
  if (!circle.closed) betaT[0] = 1.0;
  if (method != CircleReparam::Mixed) return circleMapsWith(circle, std::vector<CircleReparam>(n, method), betaT);
  // Mixed: rho on the uniform or symmetric runs, unless new scalars betaT far from the
  // circle's make an arc's rho map fold back; that arc then joins the sigma runs.
  std::vector<CircleReparam> choice = mixedChoice(circle);
  for (;;) {
    try {
      return circleMapsWith(circle, choice, betaT);
    } catch (const NotMonotone& e) {
      if (!e.rho || e.arc < 0 || e.arc >= n || choice[e.arc] != CircleReparam::Rho) throw;
      choice[e.arc] = CircleReparam::Sigma;
    }
  }
}

}  // namespace fairsplines
