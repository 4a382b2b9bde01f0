// Fair fit, reading the data (issue 16): the samples, local least-squares quadratics, the
// noise estimate, the data's plane, its curvature signs above the noise and its straight
// runs. docs/FAIR_FIT.md, steps 2 to 5.
#include "fair_fit_detail.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "fairsplines/errors.hpp"
#include "fairsplines/parameters.hpp"

namespace fairsplines::detail::fairfit {

// ---------------------------------------------------------------------------------------
// The samples: rows padded to 3D, their cumulative chord length

Samples readSamples(PointsRef q, bool closed) {
  Samples S;
  S.n = q.rows();
  S.closed = closed;
  // The chords land in s_1.. and are summed in place (no second array of n values).
  S.s.resize(std::max<Index>(closed ? S.n : S.n - 1, 0) + 1);
  S.size = validateSamplesInto(q, closed, 4, "the fair fit", S.s.data() + 1);
  S.s[0] = 0.0;
  for (std::size_t i = 1; i < S.s.size(); ++i) S.s[i] += S.s[i - 1];
  S.p.resize(S.n, Vector3d::Zero());
  for (Index i = 0; i < S.n; ++i) S.p[i].head(q.cols()) = q.row(i).transpose();
  return S;
}

// ---------------------------------------------------------------------------------------
// Local least-squares quadratics: the noise-smoothed estimate, curvature and noise residual

LocalFit localFit(const std::vector<Vector3d>& p, Index n, bool closed, Index i, Index k, const Vector3d* normal) {
  LocalFit fit;
  const bool planar = normal != nullptr;
  k = std::min<Index>(k, closed ? (n - 1) / 2 : (n - 1) / 2);
  if (k < 1) return fit;
  Index lo = i - k, hi = i + k;
  if (!closed) {
    if (lo < 0) hi -= lo, lo = 0;
    if (hi > n - 1) lo -= hi - (n - 1), hi = n - 1;
    lo = std::max<Index>(lo, 0);
  }
  auto at = [&](Index j) -> const Vector3d& { return p[((j % n) + n) % n]; };
  const Vector3d& qi = at(i);
  Vector3d e = at(hi) - at(lo);
  const double L = 0.5 * e.norm();
  if (!(L > 0.0)) return fit;
  e /= 2.0 * L;
  Vector3d n1, n2;
  if (planar) {
    n1 = normal->cross(e);  // (-e_y, e_x, 0) in the plane z = 0
  } else {
    n1 = e.unitOrthogonal();
    n2 = e.cross(n1);
  }
  Eigen::Matrix3d M = Eigen::Matrix3d::Zero();
  Eigen::Matrix<double, 3, 2> rhs = Eigen::Matrix<double, 3, 2>::Zero();
  for (Index j = lo; j <= hi; ++j) {
    const Vector3d d = at(j) - qi;
    const double u = d.dot(e) / L;  // scaled to about [-1, 1] for conditioning
    const Eigen::Vector3d basis(1.0, u, u * u);
    M.noalias() += basis * basis.transpose();
    rhs.col(0) += basis * d.dot(n1);
    if (!planar) rhs.col(1) += basis * d.dot(n2);
  }
  Eigen::FullPivLU<Eigen::Matrix3d> lu(M);
  if (!lu.isInvertible()) return fit;
  const Eigen::Matrix3d Minv = lu.inverse();
  const Eigen::Matrix<double, 3, 2> coef = Minv * rhs;
  fit.point = qi + coef(0, 0) * n1 + (planar ? 0.0 : coef(0, 1)) * (planar ? Vector3d::Zero() : n2);
  fit.residual2 = coef(0, 0) * coef(0, 0) + (planar ? 0.0 : coef(0, 1) * coef(0, 1));
  fit.hat = Minv(0, 0);
  if (planar) {
    const double b = coef(1, 0) / L, c = coef(2, 0) / (L * L);
    const double g = std::pow(1.0 + b * b, 1.5);
    fit.kappa = 2.0 * c / g;
    fit.kappaStd = 2.0 * std::sqrt(std::max(Minv(2, 2), 0.0)) / (L * L) / g;
  }
  fit.ok = std::isfinite(fit.point.squaredNorm()) && std::isfinite(fit.kappa);
  return fit;
}

double estimateNoise(const Samples& S, int dim) {
  std::optional<Vector3d> normal;
  if (dim == 2) {
    normal = kPlaneZ;
  } else if (const Plane P = dataPlane(S, 3, 1e-9 * S.size); P.planar) {
    normal = P.e1.cross(P.e2).normalized();
  }
  const bool planar = normal.has_value();
  const Index stride = std::max<Index>(1, S.n / 4096);
  std::vector<double> v;
  for (Index i = 0; i < S.n; i += stride) {
    const LocalFit f = localFit(S.p, S.n, S.closed, i, 3, planar ? &*normal : nullptr);
    if (f.ok && f.hat < 1.0) v.push_back(f.residual2 / (1.0 - f.hat));
  }
  if (v.empty()) return 0.0;
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return std::sqrt(v[v.size() / 2] / (planar ? 0.455 : 1.386));
}

// ---------------------------------------------------------------------------------------
// The plane of the data (for the signs of curvature)

Plane dataPlane(const Samples& S, int dim, double flatness) {
  Plane P;
  if (dim == 2) {
    P.planar = true;
    P.origin = Vector3d::Zero(), P.e1 = Vector3d::UnitX(), P.e2 = Vector3d::UnitY();
    return P;
  }
  Vector3d c = Vector3d::Zero();
  for (const Vector3d& x : S.p) c += x;
  c /= static_cast<double>(S.n);
  Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
  for (const Vector3d& x : S.p) C.noalias() += (x - c) * (x - c).transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(C);
  const Vector3d normal = eig.eigenvectors().col(0);
  double off = 0.0;
  for (const Vector3d& x : S.p) off = std::max(off, std::abs((x - c).dot(normal)));
  if (!(off <= flatness)) return P;
  P.planar = true;
  P.origin = c, P.e1 = eig.eigenvectors().col(2), P.e2 = normal.cross(P.e1);
  return P;
}

// ---------------------------------------------------------------------------------------
// The data's curvature signs above the noise, and its straight runs

DataShape dataShape(const Samples& S, const std::vector<Vector3d>& planarPoints, double sigma, double tolerance,
                    Index kc, bool planarFits) {
  DataShape shape;
  const Index stride = std::max<Index>(1, kc / 4);
  std::vector<Index> at;
  std::vector<int> sign;
  for (Index i = 0; i < S.n; i += stride) {
    const LocalFit f = localFit(planarPoints, S.n, S.closed, i, kc, &kPlaneZ);
    int sgn = 0;
    if (f.ok) {
      const Index lo = std::max<Index>(0, i - kc), hi = std::min<Index>(S.n - 1, i + kc);
      const double L = 0.5 * (S.s[hi] - S.s[lo]);
      const double floorKappa = L > 0.0 ? 2e-9 * S.size / (L * L) : 0.0;
      if (std::abs(f.kappa) > std::max(5.0 * sigma * f.kappaStd, floorKappa)) sgn = f.kappa > 0.0 ? 1 : -1;
    }
    at.push_back(i);
    sign.push_back(sgn);
  }
  // Runs of one class; signs held for fewer than kc samples become 0.
  struct Run {
    std::size_t from, to;
    int sign;
  };
  std::vector<Run> runs;
  for (std::size_t j = 0; j < sign.size(); ++j) {
    if (runs.empty() || runs.back().sign != sign[j])
      runs.push_back({j, j, sign[j]});
    else
      runs.back().to = j;
  }
  for (Run& r : runs) {
    if (r.sign != 0 && static_cast<Index>(r.to - r.from + 1) * stride < kc) r.sign = 0;
  }
  std::vector<int> held;
  for (const Run& r : runs)
    if (r.sign != 0 && (held.empty() || held.back() != r.sign)) held.push_back(r.sign);
  if (S.closed && held.size() > 1 && held.front() == held.back()) held.pop_back();
  shape.signChanges = held.size() > 1 ? static_cast<int>(S.closed ? held.size() : held.size() - 1) : 0;

  // Straight runs: merge neighbouring runs of 0 (open data; a run across the seam of closed
  // data is left to the quadratic fits).
  for (std::size_t r = 0; r < runs.size();) {
    if (runs[r].sign != 0) {
      ++r;
      continue;
    }
    std::size_t e = r;
    while (e + 1 < runs.size() && runs[e + 1].sign == 0) ++e;
    const Index first = at[runs[r].from], last = std::min<Index>(S.n - 1, at[runs[e].to] + stride - 1);
    r = e + 1;
    if (last - first < 2 * kc) continue;
    // A run that reaches an end of open data keeps its line through that end point, which
    // the curve interpolates (so the end stays collinear with the run's estimates).
    const bool atStart = !S.closed && first == 0, atEnd = !S.closed && last == S.n - 1;
    Vector3d c = Vector3d::Zero(), dir;
    if (atStart && atEnd) {
      c = S.p[0];
      dir = (S.p[S.n - 1] - S.p[0]).normalized();
    } else if (atStart || atEnd) {
      // Through the end point and the wide-window estimate at the run's other end, so that
      // the line meets the estimates beyond the run to a fraction of the noise (a least-
      // squares line pinned at a noisy end point would be tilted by that point's noise and
      // leave a kink of the noise's size, hence a false inflection, where the run ends).
      c = atStart ? S.p[0] : S.p[S.n - 1];
      const LocalFit far = localFit(S.p, S.n, S.closed, atStart ? last : first, kc, planarFits ? &kPlaneZ : nullptr);
      dir = ((far.ok ? far.point : S.p[atStart ? last : first]) - c).normalized();
      if (atEnd) dir = -dir;
    } else {
      for (Index i = first; i <= last; ++i) c += S.p[i];
      c /= static_cast<double>(last - first + 1);
      Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
      for (Index i = first; i <= last; ++i) C.noalias() += (S.p[i] - c) * (S.p[i] - c).transpose();
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(C);
      dir = eig.eigenvectors().col(2);
    }
    auto offLine = [&](Index from, Index to) {
      double off = 0.0;
      for (Index i = from; i <= to; ++i) {
        const Vector3d d = S.p[i] - c;
        off = std::max(off, (d - d.dot(dir) * dir).norm());
      }
      return off;
    };
    if (!(offLine(first, last) <= 0.5 * tolerance)) continue;
    // The signs' window smears the run's ends by up to kc samples, where the data are
    // still straight: there the estimates' remaining noise against the line would decide
    // the curvature's sign at the run's ends. The run is extended by the longest of kc,
    // kc / 2, kc / 4 samples whose samples stay within tolerance / 2 of its line; where it
    // reaches into a curved piece, the kink it leaves bends the piece's way.
    Index from = first, to = last;
    for (Index ext : {kc, kc / 2, kc / 4}) {
      if (ext < 1 || atEnd) break;
      const Index end = std::min<Index>(S.n - 1, last + ext);
      if (end > last && offLine(last + 1, end) <= 0.5 * tolerance) {
        to = end;
        break;
      }
    }
    for (Index ext : {kc, kc / 2, kc / 4}) {
      if (ext < 1 || atStart) break;
      const Index begin = std::max<Index>(0, first - ext);
      if (begin < first && offLine(begin, first - 1) <= 0.5 * tolerance) {
        from = begin;
        break;
      }
    }
    // Runs stay apart (a curved piece between two runs keeps its samples).
    if (!shape.straight.empty()) from = std::max(from, shape.straight.back().last + 1);
    shape.straight.push_back({from, to, c, dir});
  }
  return shape;
}

}  // namespace fairsplines::detail::fairfit
