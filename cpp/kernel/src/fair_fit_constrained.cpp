// Fair fit, the tolerance as a constraint (issue 25). Two tools on the fit's spline space:
// - interpolation pins (step 8's fall-back): where the csr-spline of Karčiauskas & Peters
//   (eq. (6)) relaxes away from samples of high curvature by more than the tolerance, the
//   curve is made to pass through them at their knots, by the smoothest change of its poles;
// - fairing under the tolerance (step 10): the third-derivative jump energy of Sapidis &
//   Farin's fairness criterion ("Automatic fairing algorithm for B-spline curves", CAD 22(2),
//   1990), minimised subject to |C(u_i) - q_i| <= tolerance at every sample, by penalty
//   rounds that never leave the feasible set.
// docs/FAIR_FIT.md, steps 8 and 10.
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>
#include <vector>

#include "fair_fit_detail.hpp"
#include "work_budget.hpp"

namespace fairsplines::detail::fairfit {

// ---------------------------------------------------------------------------------------
// The spline space

double SplineSpace::knot(Index i) const {
  const Index m = spans();
  if (!periodic) return t[std::clamp<Index>(i, 0, m)];
  const Index wraps = i >= 0 ? i / m : -((-i + m - 1) / m);
  return t[i - wraps * m] + static_cast<double>(wraps) * (t[m] - t[0]);
}

std::array<double, 4> SplineSpace::basis(Index j, double x) const {
  // The span is [k_2, k_3] of its six knots k_0 .. k_5 = knot(j - 2 .. j + 3).
  std::array<double, 6> k;
  for (int r = 0; r < 6; ++r) k[r] = knot(j - 2 + r);
  const double u = k[2] + x;
  std::array<double, 4> N{1.0, 0.0, 0.0, 0.0}, left{}, right{};
  for (int p = 1; p <= 3; ++p) {
    left[p] = u - k[3 - p];
    right[p] = k[2 + p] - u;
    double saved = 0.0;
    for (int r = 0; r < p; ++r) {
      const double tmp = N[r] / (right[r + 1] + left[p - r]);
      N[r] = saved + right[r + 1] * tmp;
      saved = left[p - r] * tmp;
    }
    N[p] = saved;
  }
  return N;
}

namespace {

/// The second derivative's two poles on span j (its values at the span's ends; C'' is linear
/// there) as weights of the span's four poles: de Boor's derivative poles, as spanPoly.
std::array<Eigen::Vector4d, 2> secondDerivativePoles(const SplineSpace& S, Index j) {
  std::array<double, 6> k;
  for (int r = 0; r < 6; ++r) k[r] = S.knot(j - 2 + r);
  using V = Eigen::Vector4d;
  const V d[4] = {V::Unit(0), V::Unit(1), V::Unit(2), V::Unit(3)};
  const V d1[3] = {3.0 * (d[1] - d[0]) / (k[3] - k[0]), 3.0 * (d[2] - d[1]) / (k[4] - k[1]),
                   3.0 * (d[3] - d[2]) / (k[5] - k[2])};
  return {V(2.0 * (d1[1] - d1[0]) / (k[3] - k[1])), V(2.0 * (d1[2] - d1[1]) / (k[4] - k[2]))};
}

std::array<double, 4> toArray(const Eigen::Vector4d& v) { return {v[0], v[1], v[2], v[3]}; }

}  // namespace

std::array<std::array<double, 4>, 2> SplineSpace::secondDerivative(Index j) const {
  const auto d2 = secondDerivativePoles(*this, j);
  return {toArray(d2[0]), toArray(d2[1])};
}

std::array<double, 4> SplineSpace::thirdDerivative(Index j) const {
  const auto d2 = secondDerivativePoles(*this, j);
  return toArray((d2[1] - d2[0]) / (knot(j + 1) - knot(j)));
}

Eigen::MatrixX3d polesOf(const BSplineCurve& curve) {
  Eigen::MatrixX3d P = Eigen::MatrixX3d::Zero(curve.poles.rows(), 3);
  P.leftCols(curve.poles.cols()) = curve.poles;
  return P;
}

void setPoles(BSplineCurve& curve, const Eigen::MatrixX3d& P) { curve.poles = P.leftCols(curve.poles.cols()); }

namespace {

using Triplets = std::vector<Eigen::Triplet<double>>;
using SparseMatrix = Eigen::SparseMatrix<double>;

/// The fairness energy E(P) = wB * integral of |C''|^2 + wJ * sum over interior knots t_k of
/// |J_k|^2 hbar_k^3, J_k the jump of C''' at t_k (five poles k - 1 .. k + 3) and hbar_k the
/// mean of the two spans (both terms in 1 / length: the parameter is about arc length).
/// The first is the bending energy of the classic smoothing spline: it straightens what the
/// tolerance lets straighten, so a curve in a band gets no inflection the band does not
/// force. The second is Sapidis & Farin's criterion: zero exactly where the curve is one
/// cubic across the knot, so the curvature humps of neighbouring spans merge.
void energyTriplets(const SplineSpace& S, Triplets& out) {
  const Index m = S.spans();
  constexpr double wJump = 1.0, wBend = 1.0;
  // Bending: C'' is linear on span j, between a = C''(t_j) and b = C''(t_(j+1)) (weights of
  // the span's four poles); its integral is h / 3 (|a|^2 + a . b + |b|^2).
  for (Index j = 0; j < m && wBend > 0.0; ++j) {
    const double h = S.knot(j + 1) - S.knot(j);
    if (!(h > 0.0)) continue;
    const std::array<std::array<double, 4>, 2> ab = S.secondDerivative(j);
    for (int r = 0; r < 4; ++r) {
      for (int c = 0; c < 4; ++c) {
        const double v =
            h / 3.0 * (ab[0][r] * ab[0][c] + 0.5 * (ab[0][r] * ab[1][c] + ab[1][r] * ab[0][c]) + ab[1][r] * ab[1][c]);
        out.emplace_back(S.pole(j, r), S.pole(j, c), wBend * v);
      }
    }
  }
  for (Index k = S.periodic ? 0 : 1; k < m && wJump > 0.0; ++k) {
    const Index left = k > 0 ? k - 1 : m - 1;
    const double hbar = 0.5 * ((S.knot(k + 1) - S.knot(k)) + (S.knot(k) - S.knot(k - 1)));
    if (!(hbar > 0.0)) continue;
    const double weight = wJump * hbar * hbar * hbar;
    const std::array<double, 4> a = S.thirdDerivative(left), b = S.thirdDerivative(k);
    // The jump's weights on its poles (the two spans share three of them).
    std::array<std::pair<Index, double>, 8> w;
    int nw = 0;
    auto add = [&](Index pole, double value) {
      for (int i = 0; i < nw; ++i) {
        if (w[i].first == pole) {
          w[i].second += value;
          return;
        }
      }
      w[nw++] = {pole, value};
    };
    for (int r = 0; r < 4; ++r) add(S.pole(left, r), -a[r]);
    for (int r = 0; r < 4; ++r) add(S.pole(k, r), b[r]);
    for (int i = 0; i < nw; ++i)
      for (int j = 0; j < nw; ++j) out.emplace_back(w[i].first, w[j].first, w[i].second * w[j].second * weight);
  }
}

}  // namespace

SparseMatrix fairnessEnergy(const SplineSpace& S) {
  Triplets t;
  energyTriplets(S, t);
  SparseMatrix E(S.poles(), S.poles());
  E.setFromTriplets(t.begin(), t.end());
  return E;
}

namespace {

double energyOf(const SparseMatrix& E, const Eigen::MatrixX3d& P) { return (P.transpose() * (E * P)).trace(); }

/// Free poles numbered 0 .. nf - 1 (-1 for fixed ones).
std::vector<Index> freeNumbers(const std::vector<char>& fixed, Index& nf) {
  std::vector<Index> f(fixed.size(), -1);
  nf = 0;
  for (std::size_t i = 0; i < fixed.size(); ++i)
    if (!fixed[i]) f[i] = nf++;
  return f;
}

/// A (poles x poles) matrix restricted to the free poles, and its columns of fixed poles
/// times their positions moved to the right-hand side.
SparseMatrix reduce(const SparseMatrix& A, const std::vector<Index>& number, Index nf, const Eigen::MatrixX3d& P,
                    Eigen::MatrixX3d& rhs) {
  Triplets t;
  rhs.setZero(nf, 3);
  for (int c = 0; c < A.outerSize(); ++c) {
    for (SparseMatrix::InnerIterator it(A, c); it; ++it) {
      const Index r = it.row(), fr = number[r], fc = number[c];
      if (fr < 0) continue;
      if (fc >= 0)
        t.emplace_back(fr, fc, it.value());
      else
        rhs.row(fr) -= it.value() * P.row(c);
    }
  }
  SparseMatrix R(nf, nf);
  R.setFromTriplets(t.begin(), t.end());
  return R;
}

}  // namespace

// ---------------------------------------------------------------------------------------
// Interpolation pins (step 8)

bool pinAtKnots(const SplineSpace& S, Eigen::MatrixX3d& P, const std::vector<std::pair<Index, Vector3d>>& pins,
                const std::vector<char>& fixed) {
  if (pins.empty()) return true;
  const Index np = S.poles(), m = S.spans();
  Index nf = 0;
  const std::vector<Index> number = freeNumbers(fixed, nf);
  // min dP^T (E + eps I) dP subject to C_pins (P + dP) = Q: the KKT system
  // [M  C^T; C  0] [dP; mu] = [0; Q - C P] over the free poles. E is scaled to a largest
  // diagonal of 1 (its entries grow as 1 / h^7 on short spans), so that the system's two
  // blocks are of one size.
  Triplets et;
  energyTriplets(S, et);
  SparseMatrix E(np, np);
  E.setFromTriplets(et.begin(), et.end());
  double scale = 0.0;
  for (Index i = 0; i < np; ++i) scale = std::max(scale, E.coeff(i, i));
  if (!(scale > 0.0) || !std::isfinite(scale)) scale = 1.0;
  Triplets t;
  for (int c = 0; c < E.outerSize(); ++c)
    for (SparseMatrix::InnerIterator it(E, c); it; ++it)
      if (number[it.row()] >= 0 && number[c] >= 0) t.emplace_back(number[it.row()], number[c], it.value() / scale);
  for (Index i = 0; i < nf; ++i) t.emplace_back(i, i, 1e-6);
  const Index nc = static_cast<Index>(pins.size());
  std::vector<std::array<double, 4>> N(nc);
  std::vector<Index> span(nc);
  for (Index c = 0; c < nc; ++c) {
    const Index k = pins[c].first;
    // C(t_k): span k at its start (span m - 1 at its end for the last knot of open curves).
    span[c] = k < m ? k : m - 1;
    N[c] = S.basis(span[c], k < m ? 0.0 : S.t[m] - S.t[m - 1]);
    for (int r = 0; r < 4; ++r) {
      const Index p = S.pole(span[c], r);
      if (number[p] >= 0 && N[c][r] != 0.0) {
        t.emplace_back(nf + c, number[p], N[c][r]);
        t.emplace_back(number[p], nf + c, N[c][r]);
      }
    }
  }
  SparseMatrix K(nf + nc, nf + nc);
  K.setFromTriplets(t.begin(), t.end());
  Eigen::SparseLU<SparseMatrix> lu;
  lu.compute(K);
  if (lu.info() != Eigen::Success) return false;
  // Two solves: the second takes up what rounding left of the first (iterative refinement).
  for (int pass = 0; pass < 2; ++pass) {
    Eigen::MatrixX3d rhs = Eigen::MatrixX3d::Zero(nf + nc, 3);
    for (Index c = 0; c < nc; ++c) {
      Vector3d at = Vector3d::Zero();
      for (int r = 0; r < 4; ++r) at += N[c][r] * P.row(S.pole(span[c], r)).transpose();
      rhs.row(nf + c) = (pins[c].second - at).transpose();
    }
    const Eigen::MatrixX3d x = lu.solve(rhs);
    if (lu.info() != Eigen::Success || !x.allFinite()) return false;
    for (Index i = 0; i < np; ++i)
      if (number[i] >= 0) P.row(i) += x.row(number[i]);
  }
  return true;
}

// ---------------------------------------------------------------------------------------
// Fairing under the tolerance (step 10)

void fairUnderTolerance(const SplineSpace& S, Eigen::MatrixX3d& P, ConstrainedFairing& f) {
  const Index np = S.poles(), m = S.spans(), nq = static_cast<Index>(f.feet.size());
  const std::vector<Vector3d>& q = *f.q;
  Triplets et;
  energyTriplets(S, et);
  SparseMatrix E(np, np);
  E.setFromTriplets(et.begin(), et.end());
  f.energyBefore = f.energyAfter = energyOf(E, P);
  Index nf = 0;
  const std::vector<Index> number = freeNumbers(f.fixed, nf);
  if (static_cast<Index>(f.fixed.size()) != np || static_cast<Index>(f.sample.size()) != nq) return;
  if (nf == 0 || nq == 0 || !(f.energyBefore > 0.0)) return;

  // The constraints: each sample's curve point C(u_i) = sum_r N_r P_(span, r) within tau_i of
  // q_i, tau_i the tolerance (or the sample's present distance, if a rounding above it).
  struct Row {
    Index span;
    std::array<double, 4> N;
  };
  auto rowOf = [&](Index i) {
    Row r{std::clamp<Index>(f.feet[i].span, 0, m - 1), {}};
    r.N = S.basis(r.span, f.feet[i].x);
    return r;
  };
  auto pointOf = [&](const Eigen::MatrixX3d& X, const Row& r) {
    Vector3d c = Vector3d::Zero();
    for (int k = 0; k < 4; ++k) c += r.N[k] * X.row(S.pole(r.span, k)).transpose();
    return c;
  };
  double trace = 0.0, dataTrace = 0.0;
  for (Index i = 0; i < np; ++i) trace += E.coeff(i, i);
  // ADMM works on about 4000 samples, every stride-th, and on those already beyond half
  // the tolerance (where the constraints bite), every nearStride-th of them so that they
  // are about 16000 at most (a tight fit of 10^6 samples has a quarter beyond). The step
  // below checks all of them.
  const Index stride = std::max<Index>(1, nq / 4000);
  const double tauMin = f.tolerance * (1.0 - 1e-9);
  auto beyondHalf = [&](Index i) { return (pointOf(P, rowOf(i)) - q[f.sample[i]]).norm() > 0.5 * f.tolerance; };
  Index near = 0;  // samples beyond half the tolerance, counted at every 64th
  for (Index i = 0; i < nq; i += 64) near += beyondHalf(i) ? 64 : 0;
  const Index nearStride = std::max<Index>(1, near / 16000);
  std::vector<Index> act;  // the samples ADMM works on, with their rows and radii
  std::vector<Row> rows;
  std::vector<double> tau;
  for (Index i = 0; i < nq; ++i) {
    const Row r = rowOf(i);
    const double d = (pointOf(P, r) - q[f.sample[i]]).norm();
    if (i % stride != 0 && !(d > 0.5 * f.tolerance && i % nearStride == 0)) continue;
    act.push_back(i);
    rows.push_back(r);
    tau.push_back(std::max(tauMin, d));
    for (int k = 0; k < 4; ++k) dataTrace += r.N[k] * r.N[k];
  }
  const Index na = static_cast<Index>(act.size());
  // ADMM on min E(P) subject to z_i = C(u_i) - q_i, |z_i| <= tau_i (Boyd et al., "Distributed
  // optimization and statistical learning via the alternating direction method of
  // multipliers", 2011, Section 5): the P-step solves (E + rho sum N N^T) P = rho sum N (q_i
  // + z_i - w_i) with one factorisation, the z-step projects onto the balls, w gathers the
  // residuals. rho starts balancing the two terms pole for pole and is adapted to keep the
  // primal and dual residuals within a factor 10 of each other (ibid., 3.4.1).
  double rho = trace / dataTrace;
  Eigen::MatrixX3d fixedRhs;
  Eigen::SimplicialLDLT<SparseMatrix> ldlt;
  // The data term's Gram matrix, span by span: G_j = sum over the samples on span j of N N^T.
  std::vector<Eigen::Matrix4d> G(m, Eigen::Matrix4d::Zero());
  for (const Row& r : rows) {
    const Eigen::Vector4d N(r.N.data());
    G[r.span].noalias() += N * N.transpose();
  }
  auto factor = [&]() {
    Triplets t = et;
    t.reserve(et.size() + 16 * static_cast<std::size_t>(m));
    for (Index j = 0; j < m; ++j)
      for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) t.emplace_back(S.pole(j, r), S.pole(j, c), rho * G[j](r, c));
    SparseMatrix A(np, np);
    A.setFromTriplets(t.begin(), t.end());
    ldlt.compute(reduce(A, number, nf, P, fixedRhs));
    return ldlt.info() == Eigen::Success;
  };
  if (!factor()) return;
  std::vector<Vector3d> z(na), w(na, Vector3d::Zero());
  for (Index a = 0; a < na; ++a) z[a] = pointOf(P, rows[a]) - q[f.sample[act[a]]];
  Eigen::MatrixX3d X = P;
  // At most about 4 10^5 sample updates a pass: 200 iterations up to 2000 samples, fewer
  // (down to 20) on more. An update costs about a sixteenth of a projection (the budget's unit).
  const int rounds = std::clamp(static_cast<int>(4e5 / static_cast<double>(na)), 20, f.rounds);
  for (int it = 0; it < rounds; ++it) {
    detail::WorkBudget::spend(static_cast<double>(na) / 16.0);
    f.roundsUsed = it + 1;
    Eigen::MatrixX3d b = Eigen::MatrixX3d::Zero(np, 3);
    for (Index a = 0; a < na; ++a) {
      const Vector3d target = rho * (q[f.sample[act[a]]] + z[a] - w[a]);
      for (int r = 0; r < 4; ++r) b.row(S.pole(rows[a].span, r)) += rows[a].N[r] * target.transpose();
    }
    Eigen::MatrixX3d rhs = fixedRhs;
    for (Index i = 0; i < np; ++i)
      if (number[i] >= 0) rhs.row(number[i]) += b.row(i);
    const Eigen::MatrixX3d x = ldlt.solve(rhs);
    if (!x.allFinite()) break;
    for (Index i = 0; i < np; ++i)
      if (number[i] >= 0) X.row(i) = x.row(number[i]);
    // The residuals: primal (C(u_i) - q_i leaving its ball) and dual (z moving).
    double primal = 0.0, dual = 0.0;
    for (Index a = 0; a < na; ++a) {
      const Vector3d r = pointOf(X, rows[a]) - q[f.sample[act[a]]], v = r + w[a];
      const double len = v.norm();
      const Vector3d zNew = len > tau[a] ? Vector3d(v * (tau[a] / len)) : v;
      w[a] = v - zNew;
      primal = std::max(primal, (r - zNew).norm());
      dual = std::max(dual, (zNew - z[a]).norm());
      z[a] = zNew;
    }
    // Converged to 1e-2 of the tolerance: the step below keeps the rest feasible. (Both
    // residuals are lengths here, the dual one as the change of z, so the balance below is
    // the same at every size of the data.)
    if (primal <= 1e-2 * f.tolerance && dual <= 1e-2 * f.tolerance) break;
    if (it % 10 == 9 && (primal > 10.0 * dual || dual > 10.0 * primal)) {
      const double grow = primal > dual ? 2.0 : 0.5;
      rho *= grow;
      for (Vector3d& wi : w) wi /= grow;  // w is the multiplier divided by rho
      if (!factor()) break;
    }
  }
  // From the feasible P as far towards the ADMM iterate as every constraint allows: the
  // balls are convex, so |r_i + alpha s_i| <= tau_i holds on [0, alpha_i].
  const Eigen::MatrixX3d D = X - P;
  double alpha = 1.0;
  for (Index i = 0; i < nq; ++i) {
    const Row row = rowOf(i);
    const Vector3d r = pointOf(P, row) - q[f.sample[i]], s = pointOf(D, row);
    const double t = std::max(tauMin, r.norm());
    if ((r + s).norm() <= t) continue;
    const double a = s.squaredNorm(), bb = 2.0 * r.dot(s), c = r.squaredNorm() - t * t;
    const double root = (-bb + std::sqrt(std::max(bb * bb - 4.0 * a * c, 0.0))) / (2.0 * a);
    alpha = std::min(alpha, std::max(root, 0.0));
  }
  if (alpha > 0.0) P += alpha * D;
  f.energyAfter = energyOf(E, P);
}

}  // namespace fairsplines::detail::fairfit
