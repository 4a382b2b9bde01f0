// Fair fit (issue 16): the csr-spline of Karčiauskas & Peters, "Curvature-sensitive splines
// and design with basic curves", Section 4, eq. (6), built on an adaptive subset of
// noise-smoothed samples and refined until every sample lies within the tolerance.
// The method, its guarantees and its heuristics: docs/FAIR_FIT.md.
#include "fairsplines/fair_fit.hpp"

#include <Eigen/Dense>
#include <Geom_BSplineCurve.hxx>
#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <vector>

#include "fairsplines/analysis.hpp"
#include "fairsplines/csr.hpp"
#include "fairsplines/errors.hpp"
#include "fairsplines/occt.hpp"
#include "fairsplines/parameters.hpp"
#include "finite.hpp"
#include "work_budget.hpp"

namespace fairsplines {
namespace {

using Eigen::Index;
using Eigen::Vector3d;

// ---------------------------------------------------------------------------------------
// The samples: rows padded to 3D, their cumulative chord length

struct Samples {
  std::vector<Vector3d> p;  // q_i, z = 0 for 2D data
  std::vector<double> s;    // cumulative chord length (n + 1 values when closed)
  Index n = 0;
  bool closed = false;
  double size = 0.0;  // bounding-box diagonal
  Index wrap(Index i) const { return ((i % n) + n) % n; }
  // Chord length up to sample index i, where i may run past n - 1 on closed data.
  double arc(Index i) const { return i < n ? s[i] : s[i - n] + s[n]; }
};

/// Samples with the checks and chords of validateSamples (which throws InputError).
Samples readSamples(PointsRef q, bool closed) {
  Samples S;
  const SampleInfo info = validateSamples(q, closed, 4, "the fair fit");
  S.n = q.rows();
  S.closed = closed;
  S.size = info.size;
  S.p.resize(S.n, Vector3d::Zero());
  for (Index i = 0; i < S.n; ++i) S.p[i].head(q.cols()) = q.row(i).transpose();
  S.s.resize(info.chords.size() + 1);
  S.s[0] = 0.0;
  for (Index i = 0; i < info.chords.size(); ++i) S.s[i + 1] = S.s[i] + info.chords[i];
  return S;
}

// ---------------------------------------------------------------------------------------
// Local least-squares quadratics: the noise-smoothed estimate, curvature and noise residual

struct LocalFit {
  Vector3d point;          // the fitted graph above q_i: q_i moved along the normal(s)
  double kappa = 0.0;      // signed curvature (planar fits), else 0
  double kappaStd = 0.0;   // its standard deviation for noise sigma = 1
  double residual2 = 0.0;  // |q_i - point|^2
  double hat = 0.0;        // the fit's leverage at q_i (its hat-matrix diagonal)
  bool ok = false;
};

/// Fit w(u) = a + b u + c u^2 to the 2k + 1 samples around q_i in the frame of the window's
/// chord (u along it, w the normal offsets; one normal in the plane when `planar`, two in
/// 3D). The window is shifted inside open data and wraps around closed data.
LocalFit localFit(const std::vector<Vector3d>& p, Index n, bool closed, Index i, Index k, bool planar) {
  LocalFit fit;
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
    n1 = Vector3d(-e.y(), e.x(), 0.0);
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

/// The default noise: the median of the squared centre residuals r_i^2 / (1 - h_i) of
/// 7-sample local quadratic fits at up to 4096 samples spread over the data, divided by the
/// median of chi^2 with as many degrees of freedom as normals (0.455 planar, 1.386 in 3D),
/// so that Gaussian noise of standard deviation sigma per coordinate gives sigma.
double estimateNoise(const Samples& S, bool planar) {
  const Index stride = std::max<Index>(1, S.n / 4096);
  std::vector<double> v;
  for (Index i = 0; i < S.n; i += stride) {
    const LocalFit f = localFit(S.p, S.n, S.closed, i, 3, planar);
    if (f.ok && f.hat < 1.0) v.push_back(f.residual2 / (1.0 - f.hat));
  }
  if (v.empty()) return 0.0;
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return std::sqrt(v[v.size() / 2] / (planar ? 0.455 : 1.386));
}

// ---------------------------------------------------------------------------------------
// The plane of the data (for the signs of curvature)

struct Plane {
  bool planar = false;
  Vector3d origin, e1, e2;
};

/// 2D data: the XY plane. 3D data: the least-squares plane when every sample lies within
/// `flatness` of it; otherwise not planar (curvature has no sign).
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

struct StraightRun {
  Index first, last;  // sample indices (open runs only: first <= last)
  Vector3d c, e;      // the least-squares line
};

struct DataShape {
  int signChanges = 0;
  std::vector<StraightRun> straight;
};

/// Signed curvature of local quadratic fits over 2k + 1 samples at every `stride`-th sample
/// (k = kc): positive or negative where it exceeds 5 standard deviations of its noise (and
/// a sagitta of 1e-9 of the size, for noise-free data), else 0. A sign counts only where it
/// holds for kc samples or more. The sign changes of that sequence are those the data
/// supports. Runs of 0 longer than 2 kc whose samples lie within tolerance / 2 of one
/// least-squares line are straight: their estimates are put on that line, so that the
/// csr-spline reproduces the line there (eq. (6) with a vanishing curvature: mu = 0, c_i = p_i).
/// A run that reaches an end of open data has its line through that end point (interpolated).
DataShape dataShape(const Samples& S, const std::vector<Vector3d>& planarPoints, double sigma, double tolerance,
                    Index kc, bool planarFits) {
  DataShape shape;
  const Index stride = std::max<Index>(1, kc / 4);
  std::vector<Index> at;
  std::vector<int> sign;
  for (Index i = 0; i < S.n; i += stride) {
    const LocalFit f = localFit(planarPoints, S.n, S.closed, i, kc, true);
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
      const LocalFit far = localFit(S.p, S.n, S.closed, atStart ? last : first, kc, planarFits);
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

// ---------------------------------------------------------------------------------------
// The curve's spans as cubic polynomials, and the projection of the samples

struct SpanPolys {
  std::vector<double> t;                   // knots t_0 .. t_m (one per subset point; + 1 closed)
  std::vector<std::array<Vector3d, 4>> c;  // C(t_j + x) = c0 + c1 x + c2 x^2 + c3 x^3
  bool closed = false;
  Index spans() const { return static_cast<Index>(c.size()); }
  double h(Index j) const { return t[j + 1] - t[j]; }
};

SpanPolys spanPolys(const BSplineCurve& curve, const Handle(Geom_BSplineCurve)& occ) {
  SpanPolys P;
  P.closed = curve.periodic;
  P.t.assign(curve.knots.data(), curve.knots.data() + curve.knots.size());
  const Index spans = curve.knots.size() - 1;
  P.c.resize(spans);
  for (Index j = 0; j < spans; ++j) {
    gp_Pnt p;
    gp_Vec d1, d2, d3;
    // The right-hand derivatives at t_j, from span j's polynomial (knots numbered from 1).
    occ->LocalD3(P.t[j], static_cast<int>(j + 1), static_cast<int>(j + 2), p, d1, d2, d3);
    P.c[j] = {Vector3d(p.X(), p.Y(), p.Z()), Vector3d(d1.X(), d1.Y(), d1.Z()), 0.5 * Vector3d(d2.X(), d2.Y(), d2.Z()),
              Vector3d(d3.X(), d3.Y(), d3.Z()) / 6.0};
  }
  return P;
}

/// The distance from p to the curve point reached by Newton's method on (C - p) . C' = 0
/// from parameter x in span j (moving to a neighbouring span when it leaves this one). The
/// smallest distance met on the way: a curve point that near exists, so it bounds the true
/// distance from above.
double projectDistance(const SpanPolys& P, const Vector3d& p, Index j, double x) {
  auto eval = [&](Index span, double u, Vector3d& C, Vector3d& C1, Vector3d& C2) {
    const auto& c = P.c[span];
    C = ((c[3] * u + c[2]) * u + c[1]) * u + c[0];
    C1 = (3.0 * c[3] * u + 2.0 * c[2]) * u + c[1];
    C2 = 6.0 * c[3] * u + 2.0 * c[2];
  };
  Vector3d C, C1, C2;
  eval(j, x, C, C1, C2);
  double best = (C - p).norm();
  for (int it = 0; it < 6; ++it) {
    const Vector3d r = C - p;
    const double f = r.dot(C1), fp = C1.squaredNorm() + r.dot(C2);
    if (!(fp > 0.0)) break;
    const double dx = -f / fp;
    x += dx;
    if (x < 0.0) {
      if (j > 0 || P.closed) {
        j = j > 0 ? j - 1 : P.spans() - 1;
        x = std::max(0.0, x + P.h(j));
      } else {
        x = 0.0;
      }
    } else if (x > P.h(j)) {
      if (j + 1 < P.spans() || P.closed) {
        x = std::min(x - P.h(j), 0.0 + P.h(j + 1 < P.spans() ? j + 1 : 0));
        j = j + 1 < P.spans() ? j + 1 : 0;
      } else {
        x = P.h(j);
      }
    }
    eval(j, x, C, C1, C2);
    best = std::min(best, (C - p).norm());
    if (std::abs(dx) <= 1e-13 * P.h(j)) break;
  }
  return best;
}

// ---------------------------------------------------------------------------------------
// The fit

struct Subset {
  std::vector<Index> index;  // sample indices, increasing
  std::vector<char> raw;     // use q_i itself (ends of open data; where smoothing fails)
};

class FairFitter {
public:
  FairFitter(PointsRef q, const FairFitOptions& o) : q_(q), o_(o), S_(readSamples(q, o.closed)), dim_(q.cols()) {
    if (!(o.tolerance > 0.0) || !std::isfinite(o.tolerance)) {
      throw InputError("the fair fit's tolerance must be positive and finite, got " + exactNumber(o.tolerance));
    }
    if (o.noise && (!(*o.noise >= 0.0) || !std::isfinite(*o.noise))) {
      throw InputError("the fair fit's noise must be zero or positive and finite, got " + exactNumber(*o.noise));
    }
    if (o.closed && (o.startTangent || o.endTangent || o.startCurvature || o.endCurvature)) {
      throw InputError("closed data have no ends: end tangents and curvatures are for open data only");
    }
    startT_ = direction(o.startTangent, "the start tangent");
    endT_ = direction(o.endTangent, "the end tangent");
    startK_ = curvatureVector(o.startCurvature, startT_, "the start curvature", "start");
    endK_ = curvatureVector(o.endCurvature, endT_, "the end curvature", "end");
  }

  FairFitResult run() {
    const double tau = o_.tolerance;
    const bool planarFits = dim_ == 2;
    sigma_ = o_.noise ? *o_.noise : estimateNoise(S_, planarFits);
    plane_ = dataPlane(S_, static_cast<int>(dim_), std::max(0.5 * tau, 6.0 * sigma_));
    // Samples whose noise is below 1/100 of the tolerance are used as they are (on noise-free
    // data the "noise" estimated is the local quadratics' model error; smoothing would only
    // add bias). Straight runs are put on their lines either way.
    smooth_ = sigma_ > 0.01 * tau;
    // Position window: the centre estimate of a quadratic fit over M samples has a standard
    // deviation of about 1.5 sigma / sqrt(M); M is chosen so that it is at most tolerance / 8.
    const double M = 2.25 * std::pow(8.0 * sigma_ / tau, 2.0);
    kPos_ = std::clamp<Index>(static_cast<Index>(std::ceil((M - 1.0) / 2.0)), 2, 64);
    // Curvature window: 1/64 of the samples (at least 8, at most 4096 each side).
    kCurv_ = std::clamp<Index>(S_.n / 64, std::max<Index>(8, 2 * kPos_), 4096);
    kCurv_ = std::max<Index>(1, std::min<Index>(kCurv_, (S_.n - 1) / 4));
    // Where the curvature is near 0 the estimates' noise decides its sign, not the tolerance:
    // the position window is widened to a quarter of the curvature window (its noise drops
    // with the square root of its samples; its bias at a curvature jump, quadratic in its
    // length, is bounded by the tolerance check).
    kPos_ = std::max<Index>(kPos_, kCurv_ / 4);

    FairFitResult result;
    result.noise = sigma_;
    if (plane_.planar) {
      planar_.resize(S_.n);
      for (Index i = 0; i < S_.n; ++i) {
        const Vector3d d = S_.p[i] - plane_.origin;
        planar_[i] = Vector3d(d.dot(plane_.e1), d.dot(plane_.e2), 0.0);
      }
      shape_ = dataShape(S_, planar_, sigma_, tau, kCurv_, dim_ == 2);
    }
    result.dataSignChanges = shape_.signChanges;

    detail::WorkBudget budget(400.0 * static_cast<double>(S_.n) + 1e6, "the fair fit of these points",
                              "the tolerance needs more refinement passes than the data's size allows");
    Subset sub = initialSubset();
    BSplineCurve curve;
    double maxDev = 0.0;
    auto fitWithin = [&]() {
      for (;;) {
        ++result.iterations;
        curve = build(sub);
        std::vector<double> dev;
        maxDev = deviations(curve, sub, dev);
        if (maxDev <= tau) break;
        refine(sub, dev);
      }
    };
    fitWithin();
    Handle(Geom_BSplineCurve) occ = toOcct(curve);
    CurvatureProfile profile = curvatureProfile(occ, 0, 16);
    int changes = curvatureSignChanges(profile);
    // Unsupported inflections, first remedy: a csr span depends on the 8 subset points
    // around it (eq. (6): c_i on f_{i-1}, f_i, f_{i+1}), so a straight run with fewer has no
    // exactly straight span, and the small curvatures leaking in from both of its ends may
    // cross 0 in the middle. Runs get 8 points (collinear estimates) and the fit is redone.
    if (changes > shape_.signChanges && densifyStraightRuns(sub)) {
      fitWithin();
      occ = toOcct(curve);
      profile = curvatureProfile(occ, 0, 16);
      changes = curvatureSignChanges(profile);
    }
    // Second remedy: try removing a subset point next to each extra sign change while the
    // tolerance holds (heuristic, bounded).
    for (int attempt = 0; attempt < 24 && changes > shape_.signChanges;) {
      bool improved = false;
      for (double u : signChangeParameters(profile)) {
        for (Index j : nearestInterior(curve, sub, u)) {
          if (++attempt > 24) break;
          Subset fewer = sub;
          fewer.index.erase(fewer.index.begin() + j);
          fewer.raw.erase(fewer.raw.begin() + j);
          const BSplineCurve candidate = build(fewer);
          std::vector<double> dev;
          const double d = deviations(candidate, fewer, dev);
          if (!(d <= tau)) continue;
          const Handle(Geom_BSplineCurve) cOcc = toOcct(candidate);
          const CurvatureProfile cProfile = curvatureProfile(cOcc, 0, 16);
          const int cChanges = curvatureSignChanges(cProfile);
          if (cChanges < changes) {
            sub = std::move(fewer), curve = candidate, occ = cOcc, profile = cProfile, changes = cChanges, maxDev = d;
            improved = true;
            break;
          }
        }
        if (improved) break;
      }
      if (!improved) break;
    }
    requireValidCurve(curve, "the fair fit of these points");
    result.curve = std::move(curve);
    result.maxDeviation = maxDev;
    result.signChanges = changes;
    result.curvatureExtrema = static_cast<int>(curvatureExtrema(profile).size());
    return result;
  }

private:
  static std::optional<Vector3d> unitOf(const Eigen::VectorXd& v, Index dim, const std::string& name) {
    if (v.size() != dim) {
      throw InputError(name + " must have " + std::to_string(dim) + " coordinates, like the points, not " +
                       std::to_string(v.size()));
    }
    requireFiniteInput(v, name);
    Vector3d x = Vector3d::Zero();
    x.head(dim) = v;
    return x;
  }
  std::optional<Vector3d> direction(const std::optional<Eigen::VectorXd>& v, const std::string& name) const {
    if (!v) return std::nullopt;
    Vector3d x = *unitOf(*v, dim_, name);
    const double len = x.norm();
    if (!(len > 0.0) || !std::isfinite(len)) throw InputError(name + " is the zero vector: it needs a direction");
    return x / len;
  }
  std::optional<Vector3d> curvatureVector(const std::optional<Eigen::VectorXd>& v, const std::optional<Vector3d>& t,
                                          const std::string& name, const char* end) const {
    if (!v) return std::nullopt;
    if (!t) throw InputError(name + " needs the " + std::string(end) + " tangent too (G2 is tangent and curvature)");
    const Vector3d k = *unitOf(*v, dim_, name);
    return k - k.dot(*t) * *t;
  }

  Subset initialSubset() const {
    Subset sub;
    const Index m = std::min<Index>(S_.n, S_.closed ? 8 : 9);
    for (Index j = 0; j < m; ++j) {
      const Index i = S_.closed ? (j * S_.n) / m : (j * (S_.n - 1)) / (m - 1);
      if (sub.index.empty() || sub.index.back() != i) sub.index.push_back(i);
    }
    sub.raw.assign(sub.index.size(), 0);
    if (!S_.closed) sub.raw.front() = sub.raw.back() = 1;  // the end points are interpolated
    return sub;
  }

  /// Give every straight run at least 8 subset points (evenly spread over it); whether any
  /// were added.
  bool densifyStraightRuns(Subset& sub) const {
    constexpr Index kPerRun = 8;
    std::vector<Index> extra;
    for (const StraightRun& r : shape_.straight) {
      const Index inside =
          std::count_if(sub.index.begin(), sub.index.end(), [&](Index i) { return i >= r.first && i <= r.last; });
      if (inside >= kPerRun || r.last - r.first < 2 * kPerRun) continue;
      for (Index j = 0; j < kPerRun; ++j) extra.push_back(r.first + (j * (r.last - r.first)) / (kPerRun - 1));
    }
    if (extra.empty()) return false;
    Subset next;
    std::vector<std::pair<Index, char>> all;
    for (std::size_t j = 0; j < sub.index.size(); ++j) all.push_back({sub.index[j], sub.raw[j]});
    for (Index i : extra) all.push_back({i, 0});
    std::sort(all.begin(), all.end(), [](const auto& a, const auto& b) {
      return a.first < b.first || (a.first == b.first && a.second > b.second);
    });
    for (const auto& [i, raw] : all) {
      if (!next.index.empty() && next.index.back() == i) continue;  // keeps the raw flag of the first (raw first)
      next.index.push_back(i);
      next.raw.push_back(raw);
    }
    if (next.index.size() == sub.index.size()) return false;
    sub = std::move(next);
    return true;
  }

  /// The estimate of sample i: itself (raw, or noise-free data), its projection onto the
  /// line of its straight run, or the local quadratic fit over 2 kPos + 1 samples.
  Vector3d estimate(Index i, bool raw) const {
    if (raw) return S_.p[i];
    for (const StraightRun& r : shape_.straight) {
      if (i >= r.first && i <= r.last) {
        const Vector3d xp = S_.p[i] - r.c;
        return r.c + xp.dot(r.e) * r.e;
      }
    }
    if (!smooth_) return S_.p[i];
    const LocalFit f = localFit(S_.p, S_.n, S_.closed, i, kPos_, dim_ == 2);
    return f.ok ? f.point : S_.p[i];
  }

  /// The csr-spline (eq. (6), chordal parameters) of the subset's estimates, with the
  /// end conditions set on its end poles.
  BSplineCurve build(Subset& sub) const {
    const Index m = static_cast<Index>(sub.index.size());
    PointMatrix Q(m, dim_);
    for (int pass = 0; pass < 2; ++pass) {
      for (Index j = 0; j < m; ++j) Q.row(j) = estimate(sub.index[j], sub.raw[j]).head(dim_).transpose();
      // Estimates of neighbouring samples that nearly coincide fall back to the samples.
      bool changed = false;
      for (Index j = 0; j + 1 < m + (S_.closed ? 1 : 0); ++j) {
        const Index jn = (j + 1) % m;
        if ((Q.row(jn) - Q.row(j)).norm() <= 1e-9 * S_.size && !(sub.raw[j] && sub.raw[jn])) {
          sub.raw[j] = sub.raw[jn] = 1;
          changed = true;
        }
      }
      if (!changed) break;
    }
    CsrOptions co;
    co.closed = S_.closed;
    BSplineCurve curve = csrSpline(Q, co);
    if (!S_.closed) endConditions(curve);
    return curve;
  }

  /// Open ends: pole 1 on the given tangent (the leg length kept), pole 2 moved across it
  /// so that the curvature vector is the given one. With knots t_0 (x4), t_1, t_2:
  /// C'(t_0) = 3 (P1 - P0) / h0, C''(t_0) = 6 / h0 ((P2 - P1) / (t_2 - t_0) - (P1 - P0) / h0),
  /// so the curvature vector is (P2 - P1)_perp 6 h0 / (9 a^2 (t_2 - t_0)) with a = |P1 - P0|.
  void endConditions(BSplineCurve& c) const {
    const Index np = c.poles.rows(), nk = c.knots.size();
    auto pole = [&](Index r) {
      Vector3d x = Vector3d::Zero();
      x.head(dim_) = c.poles.row(r).transpose();
      return x;
    };
    auto set = [&](Index r, const Vector3d& x) { c.poles.row(r) = x.head(dim_).transpose(); };
    auto apply = [&](Index i0, Index i1, Index i2, double h0, double h02, const std::optional<Vector3d>& T,
                     const std::optional<Vector3d>& K, double sign) {
      if (!T) return;
      const Vector3d P0 = pole(i0), P2 = pole(i2);
      double a = (pole(i1) - P0).norm();
      if (!(a > 0.0)) a = (P2 - P0).norm() / 2.0;
      const Vector3d P1 = P0 + sign * a * *T;
      set(i1, P1);
      if (K) {
        const Vector3d d = P2 - P1;
        set(i2, P1 + d.dot(*T) * *T + 1.5 * a * a * h02 / h0 * *K);
      }
    };
    apply(0, 1, 2, c.knots[1] - c.knots[0], c.knots[2] - c.knots[0], startT_, startK_, 1.0);
    apply(np - 1, np - 2, np - 3, c.knots[nk - 1] - c.knots[nk - 2], c.knots[nk - 1] - c.knots[nk - 3], endT_, endK_,
          -1.0);
  }

  /// Every sample's distance to the curve (an upper bound, see projectDistance), by
  /// interval of the subset; returns the largest. O(n): each sample is projected from its
  /// chord-length position between the subset samples around it.
  double deviations(const BSplineCurve& curve, const Subset& sub, std::vector<double>& dev) const {
    const Handle(Geom_BSplineCurve) occ = toOcct(curve);
    const SpanPolys P = spanPolys(curve, occ);
    const Index m = static_cast<Index>(sub.index.size()), intervals = S_.closed ? m : m - 1;
    dev.assign(intervals, 0.0);
    double worst = 0.0;
    for (Index j = 0; j < intervals; ++j) {
      const Index a = sub.index[j], b = j + 1 < m ? sub.index[j + 1] : sub.index[0] + S_.n;
      detail::WorkBudget::spend(static_cast<double>(b - a + 1));
      const double sa = S_.arc(a), sb = S_.arc(b), h = P.h(j);
      double d = 0.0;
      for (Index k = a; k <= b; ++k) {
        const double x = sb > sa ? (S_.arc(k) - sa) / (sb - sa) * h : 0.0;
        d = std::max(d, projectDistance(P, S_.p[S_.wrap(k)], j, x));
      }
      if (!std::isfinite(d)) d = HUGE_VAL;
      dev[j] = d;
      worst = std::max(worst, d);
    }
    return worst;
  }

  /// Intervals beyond the tolerance get their middle sample; intervals of neighbouring
  /// samples fall back to the samples themselves, and past that the tolerance is out of reach.
  void refine(Subset& sub, const std::vector<double>& dev) const {
    const Index m = static_cast<Index>(sub.index.size());
    Subset next;
    for (Index j = 0; j < m; ++j) {
      next.index.push_back(sub.index[j]);
      next.raw.push_back(sub.raw[j]);
      if (j >= static_cast<Index>(dev.size()) || dev[j] <= o_.tolerance) continue;
      const Index a = sub.index[j], b = j + 1 < m ? sub.index[j + 1] : sub.index[0] + S_.n;
      if (b - a >= 2) {
        next.index.push_back(S_.wrap((a + b) / 2));
        next.raw.push_back(0);
        continue;
      }
      const Index jn = (j + 1) % m;
      if (sub.raw[j] && sub.raw[jn]) {
        std::ostringstream msg;
        msg << "the fair fit cannot keep within the tolerance " << o_.tolerance << " near sample " << a
            << ": even the csr-spline of the samples themselves is " << dev[j] << " away there (the noise is " << sigma_
            << (o_.noise ? ", as given" : ", estimated")
            << "; a tolerance below about 3 times the noise cannot be met)";
        throw InputError(msg.str());
      }
      next.raw.back() = 1;
      if (jn == 0)
        next.raw.front() = 1;
      else
        sub.raw[jn] = 1;
    }
    // Sort closed subsets whose inserted middle wrapped past the seam.
    if (S_.closed && next.index.size() > 1 && next.index.back() < next.index[next.index.size() - 2]) {
      next.index.insert(next.index.begin(), next.index.back());
      next.raw.insert(next.raw.begin(), next.raw.back());
      next.index.pop_back();
      next.raw.pop_back();
    }
    sub = std::move(next);
  }

  /// Parameters where the curve's signed curvature changes sign (as curvatureSignChanges
  /// counts them: samples of |kappa| <= 1e-6 max |kappa| skipped).
  static std::vector<double> signChangeParameters(const CurvatureProfile& p) {
    std::vector<double> u;
    if (!p.isSigned || p.kappa.size() == 0) return u;
    const double zero = 1e-6 * p.kappa.cwiseAbs().maxCoeff();
    int last = 0;
    for (Index i = 0; i < p.kappa.size(); ++i) {
      const double k = p.kappa[i];
      if (std::abs(k) <= zero) continue;
      const int s = k > 0.0 ? 1 : -1;
      if (last != 0 && s != last) u.push_back(p.u[i]);
      last = s;
    }
    return u;
  }

  /// Interior subset positions whose knots are nearest to u (up to three), nearest first.
  std::vector<Index> nearestInterior(const BSplineCurve& c, const Subset& sub, double u) const {
    const Index m = static_cast<Index>(sub.index.size());
    if (m <= 4) return {};
    std::vector<std::pair<double, Index>> d;
    for (Index j = S_.closed ? 0 : 1; j < (S_.closed ? m : m - 1); ++j) d.push_back({std::abs(c.knots[j] - u), j});
    std::sort(d.begin(), d.end());
    std::vector<Index> out;
    for (std::size_t i = 0; i < d.size() && i < 3; ++i) out.push_back(d[i].second);
    return out;
  }

  PointsRef q_;
  FairFitOptions o_;
  Samples S_;
  Index dim_;
  std::optional<Vector3d> startT_, endT_, startK_, endK_;
  double sigma_ = 0.0;
  bool smooth_ = false;
  Index kPos_ = 2, kCurv_ = 8;
  Plane plane_;
  std::vector<Vector3d> planar_;
  DataShape shape_;
};

}  // namespace

FairFitResult fairFitReport(PointsRef q, const FairFitOptions& options) { return FairFitter(q, options).run(); }

BSplineCurve fairFit(PointsRef q, const FairFitOptions& options) { return fairFitReport(q, options).curve; }

}  // namespace fairsplines
