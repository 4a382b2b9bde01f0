// Fair fit with the data's curvature signs imposed (issue 25, docs/FAIR_FIT.md step 11).
// Where the fit under the tolerance has more curvature sign changes than the data support
// (sparse noisy roads: small curvatures wave on the straights between curves of opposite
// turn), the fairness energy of step 10 is minimised again with the data's sign pattern as
// constraints:
// - the curvature numerator of a planar cubic span is C' x C''; with the tangent T = C' of
//   the present curve frozen, g(x) = T(x) x C''(x) is a cubic in the span's parameter and
//   linear in the new poles (sequential linearisation: the caller repeats it about the new
//   poles and counts the true sign changes of the result);
// - the Bernstein coefficients of g bound it (convex hull; variation diminishing): all of
//   one sign make the span's curvature of that sign; the first of one sign and the last of
//   the other, the middle ones free, give the switch span between runs of opposite signs;
// - the tolerance: each sample's curve point within 0.95 of it across the present tangent
//   and a few tolerances along it (it may slide along the curve; verified by projection
//   afterwards), or within the regular 16-gon inscribed in its disc;
// so each linearisation is a convex QP, the sign rows elastic (an l1 penalty), solved by a
// primal-dual interior point method (Mehrotra's predictor-corrector; Nocedal & Wright,
// Numerical Optimization, 2nd ed., Algorithm 16.4, the starting point of 16.6).
#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <vector>

#include "fair_fit_detail.hpp"

namespace fairsplines::detail::fairfit {

// ---------------------------------------------------------------------------------------
// The data's sign pattern

std::vector<SignSwitch> turningPattern(const std::vector<Vector3d>& planar, const std::vector<double>& s,
                                       double sigma) {
  const Index n = static_cast<Index>(planar.size());
  if (n < 4) return {};
  // Chords k samples long, k the least whose mean chord is 100 noise deviations long (the
  // heading's noise about 0.014 rad), at most n / 8.
  const double mean = s[n - 1] / static_cast<double>(n - 1);
  const Index k = std::clamp<Index>(static_cast<Index>(std::ceil(100.0 * sigma / mean)), 1, std::max<Index>(1, n / 8));
  // The chords start every st = ceil(k / 2) samples: a chord's neighbours then share no
  // sample with it, and a straight's headings are few and independent. (Scanned at every
  // sample, a straight of dense data gave thousands of headings, whose extremes drift
  // 4 deviations each way from noise alone: false reversals on roads sampled every 5 cm.)
  const Index st = (k + 1) / 2;
  const Index nc = (n - k + st - 1) / st;
  if (nc < 2) return {};
  std::vector<double> psi(nc), dev(nc);
  for (Index i = 0; i < nc; ++i) {
    const Vector3d d = planar[i * st + k] - planar[i * st];
    double a = std::atan2(d.y(), d.x());
    if (i > 0) a += 2.0 * M_PI * std::round((psi[i - 1] - a) / (2.0 * M_PI));  // unwrapped
    psi[i] = a;
    const double len = std::hypot(d.x(), d.y());
    dev[i] = len > 0.0 ? std::sqrt(2.0) * sigma / len : HUGE_VAL;
  }
  // Significant: a heading change beyond 5 deviations of the two headings' noise.
  constexpr double z = 5.0;
  auto beyond = [&](Index from, Index to) {
    return std::abs(psi[to] - psi[from]) > z * std::hypot(dev[from], dev[to]);
  };
  std::vector<SignSwitch> out;
  int dir = 0;
  Index lo = 0, hi = 0, e = 0;  // running extremes before the first move; the extreme since
  for (Index j = 1; j < nc; ++j) {
    if (dir == 0) {
      if (psi[j] < psi[lo]) lo = j;
      if (psi[j] > psi[hi]) hi = j;
      if (beyond(lo, j) && psi[j] > psi[lo])
        dir = 1, e = j;
      else if (beyond(hi, j) && psi[j] < psi[hi])
        dir = -1, e = j;
      if (dir != 0) out.push_back({-1, dir});
      continue;
    }
    if (dir * (psi[j] - psi[e]) >= 0.0) {
      e = j;
      continue;
    }
    if (!beyond(e, j)) continue;
    // A reversal: the heading's extreme is the inflection. Where the data are straight
    // around it (headings within the noise of the extreme), the switch is in the middle.
    Index a = e, b = e;
    while (a > 0 && !beyond(e, a - 1)) --a;
    while (b + 1 < j && !beyond(e, b + 1)) ++b;
    out.push_back({(a + b) * st / 2 + k / 2 + (k % 2), -dir});
    dir = -dir, e = j;
  }
  return out;
}

// ---------------------------------------------------------------------------------------
// A convex QP: min 1/2 x^T H x + g^T x subject to a_k . x >= b_k, each row touching the
// eight unknowns of one span (its four poles' two in-plane coordinates)

namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;
using Triplets = std::vector<Eigen::Triplet<double>>;

struct QpRow {
  Index span;
  std::array<Index, 9> col;  // unknown per local coefficient (-1: a fixed pole); 8: an elastic slack
  std::array<double, 9> a;
  double b;
};

struct Qp {
  SparseMatrix H;
  Eigen::VectorXd g;
  std::vector<QpRow> rows;
};

double rowDot(const QpRow& r, const Eigen::VectorXd& x) {
  double s = 0.0;
  for (int c = 0; c < 9; ++c)
    if (r.col[c] >= 0) s += r.a[c] * x[r.col[c]];
  return s;
}

/// Mehrotra's predictor-corrector (Nocedal & Wright, Algorithm 16.4) from x (any point: the
/// slacks start positive). Returns whether it converged (primal and dual residuals and the
/// mean complementarity below 1e-9 in the problem's scaled units); x is the last iterate.
bool solveQp(const Qp& qp, Eigen::VectorXd& x, int maxIterations, double& work) {
  const Index nv = x.size(), m = static_cast<Index>(qp.rows.size());
  if (m == 0) return false;
  Eigen::VectorXd y(m), lambda = Eigen::VectorXd::Ones(m);
  for (Index k = 0; k < m; ++k) y[k] = std::max(1.0, rowDot(qp.rows[k], x) - qp.rows[k].b);
  Triplets base;
  for (int c = 0; c < qp.H.outerSize(); ++c)
    for (SparseMatrix::InnerIterator it(qp.H, c); it; ++it) base.emplace_back(it.row(), it.col(), it.value());
  Eigen::SimplicialLDLT<SparseMatrix> ldlt;
  bool analysed = false;
  auto solve = [&](const Eigen::VectorXd& rd, const Eigen::VectorXd& rp, const Eigen::VectorXd& comp,
                   Eigen::VectorXd& dx, Eigen::VectorXd& dy, Eigen::VectorXd& dl) {
    // (H + A^T D A) dx = -r_d + A^T Y^-1 (comp - Lambda r_p), D = Lambda / Y; then
    // dy = A dx + r_p, dl = Y^-1 (comp - Lambda dy).
    Eigen::VectorXd rhs = -rd;
    for (Index k = 0; k < m; ++k) {
      const QpRow& r = qp.rows[k];
      const double w = (comp[k] - lambda[k] * rp[k]) / y[k];
      for (int c = 0; c < 9; ++c)
        if (r.col[c] >= 0) rhs[r.col[c]] += r.a[c] * w;
    }
    dx = ldlt.solve(rhs);
    dy.resize(m), dl.resize(m);
    for (Index k = 0; k < m; ++k) {
      dy[k] = rowDot(qp.rows[k], dx) + rp[k];
      dl[k] = (comp[k] - lambda[k] * dy[k]) / y[k];
    }
    return dx.allFinite();
  };
  auto stepTo = [&](const Eigen::VectorXd& v, const Eigen::VectorXd& dv) {
    double a = 1.0;
    for (Index k = 0; k < v.size(); ++k)
      if (dv[k] < 0.0) a = std::min(a, -v[k] / dv[k]);
    return a;
  };
  const double gScale = 1.0 + qp.g.lpNorm<Eigen::Infinity>();
  for (int it = 0; it < maxIterations; ++it) {
    work -= static_cast<double>(m);  // the caller's own bound (a row costs about a sample projection)
    if (!(work >= 0.0)) return false;
    // Residuals: dual r_d = H x + g - A^T lambda, primal r_p = A x - y - b.
    Eigen::VectorXd rd = qp.H * x + qp.g, rp(m);
    for (Index k = 0; k < m; ++k) {
      const QpRow& r = qp.rows[k];
      rp[k] = rowDot(r, x) - y[k] - r.b;
      for (int c = 0; c < 9; ++c)
        if (r.col[c] >= 0) rd[r.col[c]] -= r.a[c] * lambda[k];
    }
    const double mu = y.dot(lambda) / static_cast<double>(m);
    if (rp.lpNorm<Eigen::Infinity>() <= 1e-8 && rd.lpNorm<Eigen::Infinity>() <= 1e-8 * gScale && mu <= 1e-10)
      return true;
    // H + A^T D A, span blocks of 8 x 8.
    Triplets t = base;
    t.reserve(base.size() + 64 * static_cast<std::size_t>(m));
    for (Index k = 0; k < m; ++k) {
      const QpRow& r = qp.rows[k];
      const double d = lambda[k] / y[k];
      for (int a = 0; a < 9; ++a) {
        if (r.col[a] < 0 || r.a[a] == 0.0) continue;
        for (int b = 0; b < 9; ++b)
          if (r.col[b] >= 0 && r.a[b] != 0.0) t.emplace_back(r.col[a], r.col[b], d * r.a[a] * r.a[b]);
      }
    }
    SparseMatrix M(nv, nv);
    M.setFromTriplets(t.begin(), t.end());
    if (!analysed) ldlt.analyzePattern(M), analysed = true;
    ldlt.factorize(M);
    if (ldlt.info() != Eigen::Success) return false;
    // Predictor (affine scaling), then the corrector with centring sigma = (mu_aff / mu)^3.
    Eigen::VectorXd dx, dy, dl;
    Eigen::VectorXd comp = -y.cwiseProduct(lambda);
    if (!solve(rd, rp, comp, dx, dy, dl)) return false;
    if (it == 0) {
      // Mehrotra's starting point (Nocedal & Wright, 16.6): the slacks and multipliers of the
      // first affine step, at least 1.
      for (Index k = 0; k < m; ++k)
        y[k] = std::max(1.0, std::abs(y[k] + dy[k])), lambda[k] = std::max(1.0, std::abs(lambda[k] + dl[k]));
      continue;
    }
    const double aAff = std::min(stepTo(y, dy), stepTo(lambda, dl));
    const double muAff = (y + aAff * dy).dot(lambda + aAff * dl) / static_cast<double>(m);
    const double sigma = std::pow(muAff / mu, 3.0);
    comp += (sigma * mu) * Eigen::VectorXd::Ones(m) - dy.cwiseProduct(dl);
    if (!solve(rd, rp, comp, dx, dy, dl)) return false;
    const double alpha = std::min(1.0, 0.995 * std::min(stepTo(y, dy), stepTo(lambda, dl)));
    x += alpha * dx, y += alpha * dy, lambda += alpha * dl;
    y = y.cwiseMax(1e-300), lambda = lambda.cwiseMax(1e-300);
  }
  return false;
}

}  // namespace

// ---------------------------------------------------------------------------------------
// The sign-constrained fairing

SpanWeights spanWeights(const SplineSpace& S, Index j) {
  // c0 = C(t_j), c2 = C''(t_j) / 2, c3 = C''' / 6 (SplineSpace's de Boor derivative poles),
  // c1 from C(t_(j+1)) = c0 + c1 h + c2 h^2 + c3 h^3.
  SpanWeights W;
  const double h = S.knot(j + 1) - S.knot(j);
  const std::array<double, 4> N0 = S.basis(j, 0.0), N1 = S.basis(j, h), d3 = S.thirdDerivative(j);
  const std::array<std::array<double, 4>, 2> d2 = S.secondDerivative(j);
  for (int r = 0; r < 4; ++r) {
    W(0, r) = N0[r];
    W(2, r) = 0.5 * d2[0][r];
    W(3, r) = d3[r] / 6.0;
    W(1, r) = (N1[r] - W(0, r) - W(2, r) * h * h - W(3, r) * h * h * h) / h;
  }
  return W;
}

bool fairWithSigns(const SplineSpace& S, Eigen::MatrixX3d& P, SignedFairing& f) {
  const Index np = S.poles(), m = S.spans(), nq = static_cast<Index>(f.feet.size());
  if (static_cast<Index>(f.fixed.size()) != np || static_cast<Index>(f.spanSign.size()) != m) return false;
  const std::vector<Vector3d>& q = *f.q;
  const Vector3d e[2] = {f.e1, f.e2};
  // Unknowns: the in-plane coordinates of the free poles, interleaved, as displacements
  // from P in units of the tolerance L (the normal coordinates stay).
  std::vector<Index> number(np, -1);
  Index nf = 0;
  for (Index i = 0; i < np; ++i)
    if (!f.fixed[i]) number[i] = nf++;
  if (nf == 0 || nq == 0) return false;
  const double L = f.tolerance;
  const SparseMatrix E = fairnessEnergy(S);
  double scale = 0.0;
  for (Index i = 0; i < np; ++i) scale = std::max(scale, E.coeff(i, i));
  if (!(scale > 0.0) || !std::isfinite(scale)) return false;
  Qp qp;
  {
    Triplets t;
    Eigen::MatrixX3d EP = E * P;  // the energy's gradient at P (per world coordinate) / 2
    qp.g = Eigen::VectorXd::Zero(2 * nf);
    for (int c = 0; c < E.outerSize(); ++c) {
      for (SparseMatrix::InnerIterator it(E, c); it; ++it) {
        const Index r = number[it.row()], k = number[c];
        if (r < 0 || k < 0) continue;
        for (int d = 0; d < 2; ++d) t.emplace_back(2 * r + d, 2 * k + d, it.value() / scale);
      }
    }
    for (Index i = 0; i < nf; ++i)
      for (int d = 0; d < 2; ++d) t.emplace_back(2 * i + d, 2 * i + d, 1e-9);
    for (Index i = 0; i < np; ++i)
      if (number[i] >= 0)
        for (int d = 0; d < 2; ++d) qp.g[2 * number[i] + d] = EP.row(i).dot(e[d]) / (scale * L);
    qp.H.resize(2 * nf, 2 * nf);
    qp.H.setFromTriplets(t.begin(), t.end());
  }
  auto rowFor = [&](Index span) {
    QpRow r{span, {}, {}, 0.0};
    for (int p = 0; p < 4; ++p) {
      const Index k = number[S.pole(span, p)];
      for (int d = 0; d < 2; ++d) r.col[2 * p + d] = k < 0 ? -1 : 2 * k + d;
    }
    r.col[8] = -1;
    r.a.fill(0.0);
    return r;
  };
  // The tolerance. Held: v_k . (C(u_i) - q_i) <= rho_i for K directions v_k, rho_i = cos(pi /
  // K) times the in-plane radius left by the sample's normal offset (the K-gon inscribed in
  // the disc). Sliding: across the present tangent T within 0.95 of that radius, along it
  // within lambda_i = min(4 tolerance, sqrt(0.1 tolerance / kappa_i)): the curve point may
  // slide along the curve (a straight stretch need not keep its parametrisation), and the
  // sample's distance to the curve is then at most 0.95 rho + kappa lambda^2 / 2 <= rho
  // while the curvature stays about kappa_i (verified by projection afterwards).
  constexpr int K = 16;
  const double inscribed = std::cos(M_PI / K);
  const Vector3d normal = e[0].cross(e[1]);
  auto addRow = [&](Index span, const std::array<double, 4>& N, double v0, double v1, double value, double bound) {
    // -v . (sum N_p dP_p) L >= v . r - bound, over L.
    QpRow row = rowFor(span);
    for (int p = 0; p < 4; ++p) row.a[2 * p] = -N[p] * v0, row.a[2 * p + 1] = -N[p] * v1;
    row.b = (value - bound) / L;
    qp.rows.push_back(row);
  };
  for (Index i = 0; i < nq; ++i) {
    const Index span = std::clamp<Index>(f.feet[i].span, 0, m - 1);
    const std::array<double, 4> N = S.basis(span, f.feet[i].x);
    Vector3d C = Vector3d::Zero();
    for (int p = 0; p < 4; ++p) C += N[p] * P.row(S.pole(span, p)).transpose();
    const Vector3d r = C - q[f.sample[i]];
    const double off = r.dot(normal), radius = std::sqrt(std::max(0.0, L * L - off * off));
    const double r0 = r.dot(e[0]), r1 = r.dot(e[1]);
    if (f.slide) {
      const int level = i < static_cast<Index>(f.hold.size()) ? f.hold[i] : 0;
      const SpanWeights W = spanWeights(S, span);
      Eigen::Vector2d d1 = Eigen::Vector2d::Zero(), d2 = Eigen::Vector2d::Zero();
      const double x = f.feet[i].x;
      for (int p = 0; p < 4; ++p) {
        const Vector3d Pp = P.row(S.pole(span, p)).transpose();
        const Eigen::Vector2d pp(Pp.dot(e[0]), Pp.dot(e[1]));
        d1 += (W(1, p) + 2.0 * W(2, p) * x + 3.0 * W(3, p) * x * x) * pp;
        d2 += (2.0 * W(2, p) + 6.0 * W(3, p) * x) * pp;
      }
      const double speed = d1.norm();
      if (speed > 0.0) {
        const Eigen::Vector2d T = d1 / speed;
        const double kappa = std::abs(T.x() * d2.y() - T.y() * d2.x()) / (speed * speed);
        const double lambda =
            std::pow(0.3, level) * (kappa > 0.0 ? std::min(4.0 * L, std::sqrt(0.1 * L / kappa)) : 4.0 * L);
        const double margin = std::max(0.8, 0.95 - 0.05 * level);
        const double across = T.x() * r1 - T.y() * r0, along = T.x() * r0 + T.y() * r1;
        addRow(span, N, -T.y(), T.x(), across, margin * radius);
        addRow(span, N, T.y(), -T.x(), -across, margin * radius);
        addRow(span, N, T.x(), T.y(), along, lambda);
        addRow(span, N, -T.x(), -T.y(), -along, lambda);
        continue;
      }
    }
    for (int k = 0; k < K; ++k) {
      const double th = 2.0 * M_PI * k / K, v0 = std::cos(th), v1 = std::sin(th);
      addRow(span, N, v0, v1, v0 * r0 + v1 * r1, inscribed * radius);
    }
  }
  Index slacks = 0;
  std::vector<Index> slackSpan;  // per elastic slack: its span
  // The signs: the Bernstein coefficients of g on each span, s b_k >= margin speed^3 (the
  // first with the span's start sign, the last with its end sign, the middle ones only when
  // the two agree).
  for (Index j = 0; j < m; ++j) {
    const int s0 = f.spanSign[j][0], s1 = f.spanSign[j][1];
    if (s0 == 0 && s1 == 0) continue;
    const SpanWeights W = spanWeights(S, j);
    const double h = S.knot(j + 1) - S.knot(j);
    // Present coefficients c_k in plane coordinates (2D).
    std::array<Eigen::Vector2d, 4> c;
    for (int k = 0; k < 4; ++k) {
      Vector3d v = Vector3d::Zero();
      for (int p = 0; p < 4; ++p) v += W(k, p) * P.row(S.pole(j, p)).transpose();
      c[k] = Eigen::Vector2d(v.dot(e[0]), v.dot(e[1]));
    }
    // g(x) = T(x) x C''(x), T = c1 + 2 c2 x + 3 c3 x^2 the present tangent, C'' = 2 c2 + 6 c3 x
    // of the new poles: a cubic a_0 + a_1 x + a_2 x^2 + a_3 x^3 with a_k = u_k x c2 + v_k x c3.
    const std::array<Eigen::Vector2d, 4> u = {2.0 * c[1], 4.0 * c[2], 6.0 * c[3], Eigen::Vector2d::Zero()};
    const std::array<Eigen::Vector2d, 4> v = {Eigen::Vector2d::Zero(), 6.0 * c[1], 12.0 * c[2], 18.0 * c[3]};
    // d(w x c_k) / d(pole p, coordinate d) = W(k, p) (w x e_d): w x e_0 = -w.y, w x e_1 = w.x.
    std::array<std::array<double, 8>, 4> grad{};
    std::array<double, 4> value{};
    for (int k = 0; k < 4; ++k) {
      const double hk = std::pow(h, k);  // Bernstein on [0, h] from the scaled a_k h^k
      value[k] = hk * (u[k].x() * c[2].y() - u[k].y() * c[2].x() + v[k].x() * c[3].y() - v[k].y() * c[3].x());
      for (int p = 0; p < 4; ++p) {
        grad[k][2 * p] = hk * (-W(2, p) * u[k].y() - W(3, p) * v[k].y());
        grad[k][2 * p + 1] = hk * (W(2, p) * u[k].x() + W(3, p) * v[k].x());
      }
    }
    // The margin: a curvature of f.margin at the span's middle speed.
    const Eigen::Vector2d mid = c[1] + c[2] * h + 0.75 * c[3] * h * h;
    const double speed3 = std::pow(mid.norm(), 3.0);
    // b_0 = A_0, b_1 = A_0 + A_1 / 3, b_2 = A_0 + 2 A_1 / 3 + A_2 / 3, b_3 = A_0 + A_1 + A_2 + A_3.
    const double B[4][4] = {{1, 0, 0, 0}, {1, 1.0 / 3, 0, 0}, {1, 2.0 / 3, 1.0 / 3, 0}, {1, 1, 1, 1}};
    for (int k = 0; k < 4; ++k) {
      const int s = k == 0 ? s0 : k == 3 ? s1 : (s0 == s1 ? s0 : 0);
      if (s == 0) continue;
      QpRow row = rowFor(j);
      double b = 0.0, norm = 0.0;
      for (int t = 0; t < 4; ++t) b += B[k][t] * value[t];
      for (int c8 = 0; c8 < 8; ++c8) {
        double g = 0.0;
        for (int t = 0; t < 4; ++t) g += B[k][t] * grad[t][c8];
        row.a[c8] = s * g * L;
        if (row.col[c8] >= 0) norm += row.a[c8] * row.a[c8];
      }
      norm = std::sqrt(norm);
      if (!(norm > 0.0)) continue;
      for (double& a : row.a) a /= norm;
      row.b = (f.margin * speed3 - s * b) / norm;
      // Elastic (l1 penalty, the slack's own row keeps it >= 0): a linearisation may have no
      // feasible point where the signs' exact set has one.
      row.col[8] = 2 * nf + slacks, row.a[8] = 1.0;
      slackSpan.push_back(j);
      ++slacks;
      qp.rows.push_back(row);
    }
  }
  // The slacks: unknowns 2 nf .. 2 nf + slacks - 1, each >= 0 with the penalty M.
  {
    const Index nv = 2 * nf + slacks;
    SparseMatrix H(nv, nv);
    Triplets t;
    for (int c = 0; c < qp.H.outerSize(); ++c)
      for (SparseMatrix::InnerIterator it(qp.H, c); it; ++it) t.emplace_back(it.row(), it.col(), it.value());
    for (Index k = 0; k < slacks; ++k) t.emplace_back(2 * nf + k, 2 * nf + k, 1e-9);
    H.setFromTriplets(t.begin(), t.end());
    qp.H = std::move(H);
    const double M = 1e4 * (1.0 + qp.g.lpNorm<Eigen::Infinity>());
    qp.g.conservativeResize(nv);
    qp.g.tail(slacks).setConstant(M);
    for (Index k = 0; k < slacks; ++k) {
      QpRow row{slackSpan[k], {}, {}, 0.0};
      row.col.fill(-1), row.a.fill(0.0);
      row.col[8] = 2 * nf + k, row.a[8] = 1.0;
      qp.rows.push_back(row);
    }
  }
  Eigen::VectorXd x = Eigen::VectorXd::Zero(2 * nf + slacks);
  f.converged = solveQp(qp, x, f.iterations, f.work);
  f.violated.assign(m, 0);
  if (f.converged)
    for (Index k = 0; k < slacks; ++k)
      if (x[2 * nf + k] > 1e-6) f.violated[slackSpan[k]] = 1;
  if (!f.converged || !x.allFinite()) return false;
  for (Index i = 0; i < np; ++i) {
    if (number[i] < 0) continue;
    const Vector3d d = L * (x[2 * number[i]] * e[0] + x[2 * number[i] + 1] * e[1]);
    P.row(i) += d.transpose();
  }
  return true;
}

}  // namespace fairsplines::detail::fairfit
