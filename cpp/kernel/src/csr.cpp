// csr-spline, Section 4, eq. (6), and quadratic design, Section 7, eq. (12), of
// Karčiauskas & Peters, "Curvature-sensitive splines and design with basic curves".
#include "fairsplines/csr.hpp"

#include <Eigen/Geometry>
#include <cmath>
#include <memory>
#include <vector>

#include "fairsplines/bspline.hpp"
#include "fairsplines/csr_detail.hpp"
#include "fairsplines/errors.hpp"

namespace fairsplines {
namespace detail {

namespace {

template <int D>
using Vec = Eigen::Matrix<double, D, 1>;

/// |d1 x d2| / |d1|^3, with a single square root.
template <int D>
inline double curvatureOf(const Vec<D>& d1, const Vec<D>& d2) {
  double cross2;
  if constexpr (D == 2) {
    const double z = d1[0] * d2[1] - d1[1] * d2[0];
    cross2 = z * z;
  } else {
    cross2 = d1.cross(d2).squaredNorm();
  }
  const double speed2 = d1.squaredNorm();
  return std::sqrt(cross2 / (speed2 * speed2 * speed2));
}

/// The quadratic interpolant f_i of q_{i-1}, q_i, q_{i+1} at t_{i-1}, t_i, t_{i+1},
/// written about its middle node: f_i(t) = q_i + d (t - t_i) + D (t - t_i)^2.
template <int D>
struct Quadratic {
  Vec<D> q, d, D2;  // D2 = f''/2
  /// Cubic blossom F[x, y, z] of the quadratic (degree-raised), given the arguments
  /// relative to the expansion point: (X + Y + Z)/3 and (XY + XZ + YZ)/3.
  Vec<D> blossom3(double X, double Y, double Z) const {
    return q + d * ((X + Y + Z) / 3.0) + D2 * ((X * Y + X * Z + Y * Z) / 3.0);
  }
  /// Quadratic blossom f[x, y].
  Vec<D> blossom2(double X, double Y) const { return q + d * ((X + Y) / 2.0) + D2 * (X * Y); }
  /// |curvature| at parameter offset X from the expansion point.
  double kappaAt(double X) const { return curvatureOf<D>(d + 2.0 * X * D2, 2.0 * D2); }
};

template <int D>
Vec<D> row(PointsRef q, Eigen::Index i) {
  return q.row(i).transpose().template head<D>();
}

template <int D>
Quadratic<D> interpolant(const Vec<D>& qm, const Vec<D>& q0, const Vec<D>& qp, double hm, double h0) {
  // Newton form about t_i: first divided differences on either side, then the second.
  const Vec<D> dm = (q0 - qm) / hm, d0 = (qp - q0) / h0;
  Quadratic<D> f;
  f.D2 = (d0 - dm) / (hm + h0);
  f.d = dm + f.D2 * hm;  // f'(t_i)
  f.q = q0;
  return f;
}

/// mu, nu of eq. (6): a / (a + b), with the epsilon rule.
struct Weight {
  double epsilon;  // already divided by the data size: units of curvature
  EpsilonRule rule;
  double operator()(double a, double b) const {
    if (rule == EpsilonRule::Additive) return (a + epsilon) / (a + b + 2.0 * epsilon);
    const double sum = a + b;
    return sum > epsilon ? a / sum : 0.5;
  }
};

template <int D>
void csrPoles(PointsRef q, const Eigen::VectorXd& h, bool closed, const Weight& weight, bool quasiOnly,
              PointMatrix& out) {
  // One streaming pass over the samples with a window of three quadratics
  // f_{i-1}, f_i, f_{i+1}; each first divided difference, curvature and mu is computed
  // once and carried along. Indices wrap only for closed data.
  const Eigen::Index n = q.rows(), segments = h.size();
  auto P = [&](Eigen::Index i) { return Eigen::Map<const Vec<D>>(q.data() + D * i); };
  // First divided difference (q_{s+1} - q_s) / h_s of segment s.
  // (One reciprocal each: Eigen would divide every coordinate.)
  auto divided = [&](Eigen::Index s) -> Vec<D> { return (P(s + 1 == n ? 0 : s + 1) - P(s)) * (1.0 / h[s]); };
  auto hBefore = [&](Eigen::Index i) { return i == 0 ? h[segments - 1] : h[i - 1]; };  // t_i - t_{i-1}
  // f_i about t_i from the divided differences of the segments before and after q_i.
  auto quadratic = [&](Eigen::Index i, const Vec<D>& dm, const Vec<D>& d0) {
    const double hm = hBefore(i);
    Quadratic<D> f;
    f.D2 = (d0 - dm) * (1.0 / (hm + h[i]));
    f.d = dm + f.D2 * hm;  // f'(t_i)
    f.q = P(i);
    return f;
  };

  const Eigen::Index first = closed ? 0 : 1, last = closed ? n - 1 : n - 2;
  const Eigen::Index offset = closed ? 0 : 1;  // open curves start with q_0 and F[t_0,t_0,t_1]
  out.resize(closed ? n : n + 2, D);
  auto outRow = [&](Eigen::Index r) { return Eigen::Map<Vec<D>>(out.data() + D * r); };

  Vec<D> dCur = divided(first);  // segment i
  const Vec<D> dBefore = divided(first == 0 ? segments - 1 : first - 1);
  Quadratic<D> f0 = quadratic(first, dBefore, dCur), fm, fp;
  double k0 = f0.kappaAt(0.0), km, kp;
  if (closed) {
    fm = quadratic(n - 1, divided(n - 2), dBefore);
    km = fm.kappaAt(0.0);
  } else {
    // Ends of open data: the end quadratics continue outwards, f_0 := f_1 and
    // f_{n-1} := f_{n-2}; kappa_0 is the curvature of f_1 at q_0 (mirrored at the end).
    fm = f0;
    km = f0.kappaAt(-h[0]);
  }
  double mu_i = weight(k0, km);
  for (Eigen::Index i = first; i <= last; ++i) {
    const bool leftIsSelf = !closed && i == 1, rightIsSelf = !closed && i == n - 2;
    if (rightIsSelf) {
      fp = f0;
      kp = f0.kappaAt(h[n - 2]);
    } else {
      const Eigen::Index ip = i + 1 == n ? 0 : i + 1;
      const Vec<D> dNext = divided(ip);
      fp = quadratic(ip, dCur, dNext);
      kp = fp.kappaAt(0.0);
      dCur = dNext;
    }
    const double hm = hBefore(i), h0 = h[i];
    // p_i: the cubic blossom of f_i at (t_{i-1}, t_i, t_{i+1}).
    const Vec<D> p = f0.blossom3(-hm, 0.0, h0);
    const double mu_ip = weight(kp, k0);
    if (quasiOnly) {
      outRow(i + offset) = p;
    } else {
      // Eq. (6) with its three blossoms. f_{i-1} - f_i vanishes at t_{i-1} and t_i, so it is
      // (D2_{i-1} - D2_i)(t - t_{i-1})(t - t_i), whose cubic blossom at (t_{i-1}, t_i, t_{i+1})
      // is -(D2_{i-1} - D2_i) h_{i-1}^2 / 3: p_i^L = p_i - (D2_{i-1} - D2_i) h_{i-1}^2 / 3, and
      // likewise p_i^R = p_i - (D2_{i+1} - D2_i) h_i^2 / 3. (At the open ends f_{i-1} = f_i.)
      const double nu_i = weight(km, kp);
      const double aL = (1.0 - nu_i) * mu_i;    // weight of p_i^L
      const double aR = nu_i * (1.0 - mu_ip);   // weight of p_i^R
      outRow(i + offset) = p - ((aL * hm * hm / 3.0) * (fm.D2 - f0.D2) + (aR * h0 * h0 / 3.0) * (fp.D2 - f0.D2));
    }
    if (i == first && !closed) {
      // Clamped start: F[t_0,t_0,t_0] = q_0 and F[t_0,t_0,t_1] of f_1.
      outRow(0) = P(0);
      outRow(1) = f0.blossom3(-h[0], -h[0], 0.0);
    }
    if (i == last && !closed) {
      // Clamped end: F[t_{n-2},t_{n-1},t_{n-1}] of f_{n-2} and q_{n-1}.
      outRow(n) = f0.blossom3(0.0, h[n - 2], h[n - 2]);
      outRow(n + 1) = P(n - 1);
    }
    fm = f0;
    km = k0;
    f0 = fp;
    k0 = kp;
    mu_i = mu_ip;
  }
}

template <EpsilonRule rule>
inline double weightOf(double a, double b, double epsilon) {
  if constexpr (rule == EpsilonRule::Additive) {
    return (a + epsilon) / (a + b + 2.0 * epsilon);
  } else {
    const double sum = a + b;
    return sum > epsilon ? a / sum : 0.5;
  }
}

/// The same poles as csrPoles, computed in passes over a structure of arrays (one array
/// per coordinate, padded by one point at each end so closed data wraps without
/// branches), so that every loop vectorises.
/// Scratch memory for csrPolesSoa on up to n points, reused across windows.
/// Uninitialised on purpose: every entry read is written first. Arrays m doubles long
/// would sit a multiple of 4 KiB apart for round n, and the loops that stream through
/// several of them at once would alias in the caches: the stride is padded.
template <int D>
struct SoaWorkspace {
  explicit SoaWorkspace(Eigen::Index n) : stride(n + 2 + 37), storage(new double[static_cast<size_t>(stride) * (4 * D + 3)]) {}
  Eigen::Index stride;
  std::unique_ptr<double[]> storage;
};

template <int D, EpsilonRule rule, bool quasiOnly>
void csrPolesSoa(PointsRef q, const Eigen::VectorXd& h, bool closed, double epsilon, SoaWorkspace<D>& workspace,
                 PointMatrix& out) {
  const Eigen::Index n = q.rows(), segments = h.size();  // padded index j = i + 1
  const Eigen::Index stride = workspace.stride;
  double* const bufferData = workspace.storage.get();
  double* X[D];
  double* dd[D];
  double* D2[D];
  double* dv[D];
  for (int c = 0; c < D; ++c) {
    X[c] = bufferData + (0 * D + c) * stride;
    dd[c] = bufferData + (1 * D + c) * stride;
    D2[c] = bufferData + (2 * D + c) * stride;
    dv[c] = bufferData + (3 * D + c) * stride;
  }
  double* H = bufferData + 4 * D * stride;  // H[j]: t_{i+1} - t_i (segment after point i)
  double* kappa = H + stride;
  double* hb = kappa + stride;  // t_i - t_{i-1}
  const double* qd = q.data();
  for (Eigen::Index i = 0; i < n; ++i) {
    for (int c = 0; c < D; ++c) X[c][i + 1] = qd[D * i + c];
  }
  for (int c = 0; c < D; ++c) {
    X[c][0] = X[c][n];      // point -1 = point n-1 (closed)
    X[c][n + 1] = X[c][1];  // point n = point 0 (closed)
  }
  for (Eigen::Index i = 0; i < segments; ++i) H[i + 1] = h[i];
  H[0] = h[segments - 1];
  if (!closed) H[n] = h[segments - 1];  // unused by open data
  H[n + 1] = h[0];
  // Pass A: first divided differences of segment i (point i to i + 1), j = i + 1.
  const Eigen::Index jLast = closed ? n : n - 1;  // last segment's j
  const Eigen::Index jFirst = closed ? 0 : 1;
  for (int c = 0; c < D; ++c) {
    double* __restrict out_c = dd[c];
    const double* __restrict x = X[c];
    for (Eigen::Index j = jFirst; j <= jLast; ++j) out_c[j] = (x[j + 1] - x[j]) * (1.0 / H[j]);
  }
  // Pass B: f_i about t_i for every point with two neighbours: D2 = f''/2, d = f'(t_i), kappa.
  const Eigen::Index first = closed ? 0 : 1, last = closed ? n - 1 : n - 2;
  for (Eigen::Index j = first + 1; j <= last + 1; ++j) {
    const double hm = H[j - 1], h0 = H[j], r = 1.0 / (hm + h0);
    hb[j] = hm;
    double d1[D], d2[D];
    for (int c = 0; c < D; ++c) {
      D2[c][j] = (dd[c][j] - dd[c][j - 1]) * r;
      dv[c][j] = dd[c][j - 1] + D2[c][j] * hm;
      d1[c] = dv[c][j];
      d2[c] = 2.0 * D2[c][j];
    }
    double cross2, speed2 = 0.0;
    if constexpr (D == 2) {
      const double z = d1[0] * d2[1] - d1[1] * d2[0];
      cross2 = z * z;
    } else {
      const double x = d1[1] * d2[2] - d1[2] * d2[1], y = d1[2] * d2[0] - d1[0] * d2[2],
                   z = d1[0] * d2[1] - d1[1] * d2[0];
      cross2 = x * x + y * y + z * z;
    }
    for (int c = 0; c < D; ++c) speed2 += d1[c] * d1[c];
    kappa[j] = std::sqrt(cross2 / (speed2 * speed2 * speed2));
  }
  auto curvatureAt = [&](Eigen::Index j, double X0) {  // f of point j at offset X0 from its t
    Vec<D> a, b;
    for (int c = 0; c < D; ++c) {
      a[c] = dv[c][j] + 2.0 * X0 * D2[c][j];
      b[c] = 2.0 * D2[c][j];
    }
    return curvatureOf<D>(a, b);
  };
  if (closed) {
    for (int c = 0; c < D; ++c) {
      D2[c][0] = D2[c][n];
      D2[c][n + 1] = D2[c][1];
    }
    kappa[0] = kappa[n];
    kappa[n + 1] = kappa[1];
  } else {
    // Ends of open data: f_0 := f_1 and f_{n-1} := f_{n-2}; kappa_0 is the curvature of
    // f_1 at q_0 (mirrored at the end).
    for (int c = 0; c < D; ++c) {
      D2[c][1] = D2[c][2];
      D2[c][n] = D2[c][n - 1];
    }
    kappa[1] = curvatureAt(2, -h[0]);
    kappa[n] = curvatureAt(n - 1, h[n - 2]);
  }
  // Pass C: eq. (6) for every c_i (see csrPoles for the closed form of p_i^L, p_i^R).
  const Eigen::Index offset = closed ? 0 : 1;
  out.resize(closed ? n : n + 2, D);
  double* o = out.data();
  const double third = 1.0 / 3.0;
  for (Eigen::Index j = first + 1; j <= last + 1; ++j) {
    const double hm = hb[j], h0 = H[j];
    const double ap = (h0 - hm) * third, bp = -hm * h0 * third;
    double aL = 0.0, aR = 0.0;
    if constexpr (!quasiOnly) {
      const double km = kappa[j - 1], k0 = kappa[j], kp = kappa[j + 1];
      const double mu_i = weightOf<rule>(k0, km, epsilon);
      const double mu_ip = weightOf<rule>(kp, k0, epsilon);
      const double nu_i = weightOf<rule>(km, kp, epsilon);
      aL = (1.0 - nu_i) * mu_i * hm * hm * third;
      aR = nu_i * (1.0 - mu_ip) * h0 * h0 * third;
    }
    for (int c = 0; c < D; ++c) {
      o[D * (j - 1 + offset) + c] = X[c][j] + dv[c][j] * ap + D2[c][j] * bp - aL * (D2[c][j - 1] - D2[c][j]) -
                                    aR * (D2[c][j + 1] - D2[c][j]);
    }
  }
  if (!closed) {
    auto blossom = [&](Eigen::Index j, double x, double y, double z) {
      Quadratic<D> f;
      for (int c = 0; c < D; ++c) {
        f.q[c] = X[c][j];
        f.d[c] = dv[c][j];
        f.D2[c] = D2[c][j];
      }
      return f.blossom3(x, y, z);
    };
    out.row(0) = q.row(0);
    out.row(1) = blossom(2, -h[0], -h[0], 0.0).transpose();
    out.row(n) = blossom(n - 1, 0.0, h[n - 2], h[n - 2]).transpose();
    out.row(n + 1) = q.row(n - 1);
  }
}

template <int D>
void csrPolesSoaDispatch(PointsRef q, const Eigen::VectorXd& h, bool closed, const Weight& weight, bool quasiOnly,
                         SoaWorkspace<D>& workspace, PointMatrix& out) {
  if (quasiOnly) {
    csrPolesSoa<D, EpsilonRule::CaseDistinction, true>(q, h, closed, weight.epsilon, workspace, out);
  } else if (weight.rule == EpsilonRule::Additive) {
    csrPolesSoa<D, EpsilonRule::Additive, false>(q, h, closed, weight.epsilon, workspace, out);
  } else {
    csrPolesSoa<D, EpsilonRule::CaseDistinction, false>(q, h, closed, weight.epsilon, workspace, out);
  }
}

/// The vectorised passes window by window, so that their arrays stay in cache. c_i
/// depends on q_{i-2}..q_{i+2} only, so a window of W points solved as open data gives
/// the global poles for its points 2..W-3 (and, where a window touches an end of open
/// data, for the end rows too); windows overlap by four points. Closed data is read
/// cyclically.
template <int D>
void csrPolesFast(PointsRef q, const Eigen::VectorXd& h, bool closed, const Weight& weight, bool quasiOnly,
                  PointMatrix& out, Eigen::Index window) {
  const Eigen::Index n = q.rows(), W = std::max<Eigen::Index>(window, 8);
  SoaWorkspace<D> workspace(std::min(n, W));
  if (n <= W) {
    csrPolesSoaDispatch<D>(q, h, closed, weight, quasiOnly, workspace, out);
    return;
  }
  out.resize(closed ? n : n + 2, D);
  PointMatrix local;
  if (!closed) {
    for (Eigen::Index s = 0;; s += W - 4) {
      s = std::min(s, n - W);
      csrPolesSoaDispatch<D>(q.middleRows(s, W), h.segment(s, W - 1), false, weight, quasiOnly, workspace, local);
      const bool atStart = s == 0, atEnd = s + W == n;
      const Eigen::Index from = atStart ? 0 : 3, to = atEnd ? W + 1 : W - 2;  // local rows (c_i is row i + 1)
      out.middleRows(s + from, to - from + 1) = local.middleRows(from, to - from + 1);
      if (atEnd) break;
    }
    return;
  }
  PointMatrix wq(W, D);
  Eigen::VectorXd wh(W - 1);
  auto wrap = [n](Eigen::Index i) { return ((i % n) + n) % n; };
  for (Eigen::Index s = -2; s + 2 < n; s += W - 4) {
    for (Eigen::Index k = 0; k < W; ++k) wq.row(k) = q.row(wrap(s + k));
    for (Eigen::Index k = 0; k + 1 < W; ++k) wh[k] = h[wrap(s + k)];
    csrPolesSoaDispatch<D>(wq, wh, false, weight, quasiOnly, workspace, local);
    for (Eigen::Index i = 2; i <= W - 3 && s + i < n; ++i) out.row(s + i) = local.row(i + 1);
  }
}

}  // namespace

CsrStrategy defaultStrategy(Eigen::Index n) {
  // Measured with bench/bench_csr: the vectorised passes win from a few thousand points;
  // below, their allocation costs more than they save.
  return n >= 2048 ? CsrStrategy::Vectorised : CsrStrategy::Streaming;
}

BSplineCurve fitCubic(PointsRef q, const Eigen::VectorXd& t, bool closed, double size, double epsilon,
                      EpsilonRule rule, bool quasiOnly, std::optional<CsrStrategy> strategy, Eigen::Index window) {
  const Weight weight{epsilon / size, rule};
  const Eigen::VectorXd h = t.tail(t.size() - 1) - t.head(t.size() - 1);
  PointMatrix poles;
  if (window <= 0) window = q.rows() <= (1 << 18) ? q.rows() : 4096;
  if (strategy.value_or(defaultStrategy(q.rows())) == CsrStrategy::Vectorised) {
    if (q.cols() == 2) csrPolesFast<2>(q, h, closed, weight, quasiOnly, poles, window);
    else csrPolesFast<3>(q, h, closed, weight, quasiOnly, poles, window);
  } else {
    if (q.cols() == 2) csrPoles<2>(q, h, closed, weight, quasiOnly, poles);
    else csrPoles<3>(q, h, closed, weight, quasiOnly, poles);
  }
  return closed ? periodicCubic(std::move(poles), t) : clampedCubic(std::move(poles), t);
}

template <int D>
PointMatrix quadraticHandles(PointsRef q, const Eigen::VectorXd& t, bool closed, const Weight& weight) {
  const Eigen::Index n = q.rows();
  const Eigen::Index segments = closed ? n : n - 1;
  Eigen::VectorXd h(segments);
  for (Eigen::Index i = 0; i < segments; ++i) h[i] = t[i + 1] - t[i];
  auto H = [&](Eigen::Index i) { return h[(i + segments) % segments]; };
  std::vector<Quadratic<D>> f(n);
  Eigen::VectorXd kappa(n);
  const Eigen::Index first = closed ? 0 : 1, last = closed ? n - 1 : n - 2;
  for (Eigen::Index i = first; i <= last; ++i) {
    f[i] = interpolant<D>(row<D>(q, (i + n - 1) % n), row<D>(q, i), row<D>(q, (i + 1) % n), H(i - 1), H(i));
    kappa[i] = f[i].kappaAt(0.0);
  }
  PointMatrix m(segments, q.cols());
  for (Eigen::Index i = 0; i < segments; ++i) {
    const Eigen::Index ip = (i + 1) % n;
    const bool hasLeft = closed || i >= 1, hasRight = closed || i + 1 <= n - 2;
    Vec<D> mi;
    // m_i^L: middle coefficient of f_i on [t_i, t_{i+1}]; m_i^R: that of f_{i+1}.
    const Vec<D> mL = hasLeft ? f[i].blossom2(0.0, H(i)) : Vec<D>();
    const Vec<D> mR = hasRight ? f[ip].blossom2(-H(i), 0.0) : Vec<D>();
    if (hasLeft && hasRight) {
      const double mu_ip = weight(kappa[ip], kappa[i]);  // eq. (12), mu_{i+1} as in eq. (6)
      mi = mu_ip * mL + (1.0 - mu_ip) * mR;
    } else {
      mi = hasLeft ? mL : mR;
    }
    m.row(i).head<D>() = mi.transpose();
  }
  return m;
}

}  // namespace detail

BSplineCurve csrSpline(PointsRef q, const CsrOptions& options) {
  const SampleInfo info = validateSamples(q, options.closed, 3, "the csr-spline");
  const Eigen::VectorXd t = options.parameters.size() > 0
                                ? validatedParameters(options.parameters, q.rows(), options.closed)
                                : parameters(info.chords, options.parametrization);
  if (!(options.epsilon > 0.0)) throw InputError("epsilon must be positive");
  return detail::fitCubic(q, t, options.closed, info.size, options.epsilon, options.rule, false);
}

BSplineCurve quadraticDesign(PointsRef q, Parametrization parametrization, bool closed, double epsilon) {
  const SampleInfo info = validateSamples(q, closed, 3, "the quadratic design");
  if (!(epsilon > 0.0)) throw InputError("epsilon must be positive");
  const Eigen::VectorXd t = parameters(info.chords, parametrization);
  const detail::Weight weight{epsilon / info.size, EpsilonRule::CaseDistinction};
  const PointMatrix m = q.cols() == 2 ? detail::quadraticHandles<2>(q, t, closed, weight)
                                      : detail::quadraticHandles<3>(q, t, closed, weight);
  const Eigen::Index n = q.rows(), segments = m.rows();
  // Piecewise quadratic Bézier {q_i, m_i, q_{i+1}} as a degree-2 B-spline with double
  // knots; a closed design ends where it starts (it is only C0 at the q_i anyway).
  BSplineCurve curve;
  curve.degree = 2;
  curve.poles.resize(2 * segments + 1, q.cols());
  for (Eigen::Index i = 0; i < segments; ++i) {
    curve.poles.row(2 * i) = q.row(i);
    curve.poles.row(2 * i + 1) = m.row(i);
  }
  curve.poles.row(2 * segments) = q.row(segments % n);
  curve.knots = t;
  curve.mults = Eigen::VectorXi::Constant(t.size(), 2);
  curve.mults[0] = curve.mults[t.size() - 1] = 3;
  return curve;
}

}  // namespace fairsplines
