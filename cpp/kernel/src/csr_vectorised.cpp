// The vectorised strategy of the csr-spline's eq. (6): the same poles as the streaming
// reference (csr.cpp), window by window, in passes without branches over per-coordinate
// arrays; and the open csr-spline in one fused pass. See csr_poles.hpp.
#include <algorithm>
#include <vector>

#include "fairsplines/csr.hpp"
#include "fairsplines/errors.hpp"
#include "csr_detail.hpp"
#include "csr_poles.hpp"
#include "vectorise.hpp"

namespace fairsplines {
namespace detail {

namespace {

template <EpsilonRule rule>
inline double weightOf(double a, double b, double epsilon) {
  if constexpr (rule == EpsilonRule::Additive) {
    return (a + epsilon) / (a + b + 2.0 * epsilon);
  } else {
    // The quotient is formed unconditionally (and discarded below epsilon), so that the
    // choice is a blend, not a branch, and the loops vectorise.
    const double sum = a + b, quotient = a / sum;
    return sum > epsilon ? quotient : 0.5;
  }
}

// The vectorised strategy: the same poles as csrPoles, computed window by window in
// passes over a structure of arrays (one array per coordinate), every pass a loop
// without branches that the compiler vectorises. c_i depends on q_{i-2}..q_{i+2} only,
// so a window of W consecutive points solved as open data gives the global poles of its
// points 2..W-3 (and, where the window touches an end of open data, the end rows too);
// windows overlap by four points. Closed data is read cyclically into the window.

/// Scratch arrays for one window of up to `capacity` points, kept per thread and reused,
/// so that repeated fits neither allocate nor touch fresh pages. Every entry read is
/// written first. Arrays whose distance is a multiple of 4 KiB alias in the caches when
/// a loop streams through several at once: the stride is padded by one cache line.
struct WindowArrays {
  double* dd[3];  // q_{k+1} - q_k of segment k, then (pass A) divided by h_k
  double* D2[3];  // f_k''/2 of the quadratic interpolant f_k about t_k
  double* dv[3];  // f_k'(t_k)
  double* h;      // h_k = t_{k+1} - t_k
  double* kappa;  // |curvature| of f_k at t_k
  static constexpr int kArrays = 11;
};

class Workspace {
public:
  WindowArrays arrays(Eigen::Index capacity) {
    const Eigen::Index stride = (capacity + 7) / 8 * 8 + 8;
    const size_t need = static_cast<size_t>(stride) * WindowArrays::kArrays;
    if (storage_.size() < need) storage_.resize(need);
    double* p = storage_.data();
    WindowArrays a;
    for (int c = 0; c < 3; ++c) a.dd[c] = p + (0 + c) * stride;
    for (int c = 0; c < 3; ++c) a.D2[c] = p + (3 + c) * stride;
    for (int c = 0; c < 3; ++c) a.dv[c] = p + (6 + c) * stride;
    a.h = p + 9 * stride;
    a.kappa = p + 10 * stride;
    return a;
  }

private:
  std::vector<double> storage_;
};

/// Pass 0: the differences q_{k+1} - q_k of the W - 1 segments of a window of contiguous
/// (W x D) points, per coordinate.
template <int D>
inline __attribute__((always_inline)) void differences(const double* __restrict x, Eigen::Index W,
                                                       double* __restrict ddx, double* __restrict ddy,
                                                       double* __restrict ddz) {
  for (Eigen::Index k = 0; k + 1 < W; ++k) {
    ddx[k] = x[D * (k + 1)] - x[D * k];
    ddy[k] = x[D * (k + 1) + 1] - x[D * k + 1];
    if constexpr (D == 3) ddz[k] = x[D * (k + 1) + 2] - x[D * k + 2];
  }
}

/// Pass 0 of the streaming pass over open data, where the window's parameters are made
/// too. tw points at the parameter of the window's first point; t_0..t_{k0} are known,
/// t_{k0+1}..t_{W-1} are new: t_{k+1} = t_k + |q_{k+1} - q_k| (chordal), its square root
/// (centripetal) or 1 (uniform), the additions in order, as parametersInto makes them.
/// Writes the differences to a.dd and h_k = t_{k+1} - t_k to a.h. Returns whether a new
/// chord is at most `tol` (coincident points: the caller names them).
///
/// Eight chords at a time, then their eight additions: the square roots vectorise, the
/// additions stay in order, and the processor can overlap one strip's square roots with
/// the previous strip's additions.
template <int D, Parametrization kind>
inline __attribute__((always_inline)) bool differencesAndParameters(const double* __restrict x, Eigen::Index W,
                                                                    Eigen::Index k0, const WindowArrays& a,
                                                                    double* __restrict tw, double tol) {
  double* __restrict ddx = a.dd[0];
  double* __restrict ddy = a.dd[1];
  double* __restrict ddz = a.dd[2];
  double* __restrict h = a.h;
  auto difference = [&](Eigen::Index k) {
    const double dx = x[D * (k + 1)] - x[D * k], dy = x[D * (k + 1) + 1] - x[D * k + 1];
    ddx[k] = dx;
    ddy[k] = dy;
    double squared = dx * dx + dy * dy;  // the order of validateSamples
    if constexpr (D == 3) {
      const double dz = x[D * (k + 1) + 2] - x[D * k + 2];
      ddz[k] = dz;
      squared += dz * dz;
    }
    return squared;
  };
  auto step = [](double chord) {
    if constexpr (kind == Parametrization::Chordal)
      return chord;
    else if constexpr (kind == Parametrization::Centripetal)
      return std::sqrt(chord);
    else
      return 1.0;
  };
  Eigen::Index k = 0;
  for (; k < k0; ++k) {  // known parameters
    difference(k);
    h[k] = tw[k + 1] - tw[k];
  }
  constexpr int kStrip = 8;
  double shortest[kStrip];  // per lane, the shortest new chord
  for (int j = 0; j < kStrip; ++j) shortest[j] = HUGE_VAL;
  double tk = tw[k];
  for (; k + kStrip < W; k += kStrip) {
    double increment[kStrip];
    for (int j = 0; j < kStrip; ++j) {  // vectorised
      const double chord = std::sqrt(difference(k + j));
      shortest[j] = std::min(shortest[j], chord);
      increment[j] = step(chord);
    }
    for (int j = 0; j < kStrip; ++j) {  // the chain
      const double next = tk + increment[j];
      tw[k + j + 1] = next;
      h[k + j] = next - tk;
      tk = next;
    }
  }
  for (; k + 1 < W; ++k) {
    const double chord = std::sqrt(difference(k));
    shortest[0] = std::min(shortest[0], chord);
    const double next = tk + step(chord);
    tw[k + 1] = next;
    h[k] = next - tk;
    tk = next;
  }
  bool close = false;
  for (int j = 0; j < kStrip; ++j) close |= shortest[j] <= tol;
  return close;
}

/// Pass A: first divided differences (q_{k+1} - q_k) / h_k in place, one reciprocal per
/// segment.
template <int D>
inline __attribute__((always_inline)) void dividedDifferences(const double* __restrict h, Eigen::Index W,
                                                              double* __restrict ddx, double* __restrict ddy,
                                                              double* __restrict ddz) {
  for (Eigen::Index k = 0; k + 1 < W; ++k) {
    const double r = 1.0 / h[k];
    ddx[k] *= r;
    ddy[k] *= r;
    if constexpr (D == 3) ddz[k] *= r;
  }
}

/// Pass B, for the points with two neighbours: the quadratic interpolant f_k of q_{k-1},
/// q_k, q_{k+1} about t_k in Newton form, D2 = f_k''/2 and f_k'(t_k) (one reciprocal for
/// all coordinates), and, with `curvature`, |f_k' x f_k''| / |f_k'|^3 at t_k with a single
/// square root, bounded by boundedCurvature.
template <int D, bool curvature>
inline __attribute__((always_inline)) void quadratics(Eigen::Index W, const double* __restrict h,
                                                      const double* __restrict ddx, const double* __restrict ddy,
                                                      const double* __restrict ddz, double* __restrict D2x,
                                                      double* __restrict D2y, double* __restrict D2z,
                                                      double* __restrict dvx, double* __restrict dvy,
                                                      double* __restrict dvz, double* __restrict kappa) {
  for (Eigen::Index k = 1; k + 1 < W; ++k) {
    const double hm = h[k - 1], r = 1.0 / (h[k - 1] + h[k]);
    const double bx = (ddx[k] - ddx[k - 1]) * r, by = (ddy[k] - ddy[k - 1]) * r;
    const double d1x = ddx[k - 1] + bx * hm, d1y = ddy[k - 1] + by * hm;  // f'(t_k)
    D2x[k] = bx;
    D2y[k] = by;
    dvx[k] = d1x;
    dvy[k] = d1y;
    double bz = 0.0, d1z = 0.0;
    if constexpr (D == 3) {
      bz = (ddz[k] - ddz[k - 1]) * r;
      d1z = ddz[k - 1] + bz * hm;
      D2z[k] = bz;
      dvz[k] = d1z;
    }
    if constexpr (curvature) {
      const double d2x = 2.0 * bx, d2y = 2.0 * by;
      double cross2, speed2;
      if constexpr (D == 2) {
        const double z = d1x * d2y - d1y * d2x;
        cross2 = z * z;
        speed2 = d1x * d1x + d1y * d1y;
      } else {
        const double d2z = 2.0 * bz;
        const double x = d1y * d2z - d1z * d2y, y = d1z * d2x - d1x * d2z, z = d1x * d2y - d1y * d2x;
        cross2 = x * x + y * y + z * z;
        speed2 = d1x * d1x + d1y * d1y + d1z * d1z;
      }
      kappa[k] = boundedCurvature(std::sqrt(cross2 / (speed2 * speed2 * speed2)));
    }
  }
}

/// Pass C: eq. (6) for the poles of points kFrom..kTo of the window, written as rows
/// kFrom + rowShift... of `out`. p_k = F_k[t_{k-1}, t_k, t_{k+1}] is the cubic blossom of
/// f_k; f_{k-1} - f_k vanishes at t_{k-1} and t_k, so it is (D2_{k-1} - D2_k)(t - t_{k-1})
/// (t - t_k), whose blossom at (t_{k-1}, t_k, t_{k+1}) is -(D2_{k-1} - D2_k) h_{k-1}^2 / 3:
/// p_k^L = p_k - (D2_{k-1} - D2_k) h_{k-1}^2 / 3, likewise p_k^R with D2_{k+1} and h_k, and
/// c_k = p_k - (1 - nu_k) mu_k (p_k - p_k^L) - nu_k (1 - mu_{k+1}) (p_k - p_k^R), where
/// mu_k = kappa_k / (kappa_k + kappa_{k-1}) and nu_k = kappa_{k-1} / (kappa_{k-1} +
/// kappa_{k+1}), with the epsilon rule (weightOf).
template <int D, EpsilonRule rule, bool quasiOnly>
inline __attribute__((always_inline)) void poles(const double* __restrict x, const WindowArrays& a, Eigen::Index kFrom,
                                                 Eigen::Index kTo, double epsilon, double* __restrict out) {
  const double* __restrict kappa = a.kappa;
  const double* __restrict h = a.h;
  const double* __restrict D2x = a.D2[0];
  const double* __restrict D2y = a.D2[1];
  const double* __restrict D2z = a.D2[2];
  const double* __restrict dvx = a.dv[0];
  const double* __restrict dvy = a.dv[1];
  const double* __restrict dvz = a.dv[2];
  const double third = 1.0 / 3.0;
  for (Eigen::Index k = kFrom; k <= kTo; ++k) {
    const double hm = h[k - 1], h0 = h[k];
    const double ap = (h0 - hm) * third, bp = -hm * h0 * third;  // p_k = q_k + f'(t_k) ap + D2_k bp
    double* o = out + D * (k - kFrom);
    if constexpr (quasiOnly) {
      o[0] = x[D * k] + dvx[k] * ap + D2x[k] * bp;
      o[1] = x[D * k + 1] + dvy[k] * ap + D2y[k] * bp;
      if constexpr (D == 3) o[2] = x[D * k + 2] + dvz[k] * ap + D2z[k] * bp;
    } else {
      // The weights: mu_k, mu_{k+1} (each pair's is formed twice, by both of its points:
      // cheaper than a pass of its own) and nu_k, times the h^2 / 3 of the differences.
      const double mu0 = weightOf<rule>(kappa[k], kappa[k - 1], epsilon);
      const double mu1 = weightOf<rule>(kappa[k + 1], kappa[k], epsilon);
      const double nu = weightOf<rule>(kappa[k - 1], kappa[k + 1], epsilon);
      const double aL = (1.0 - nu) * mu0 * hm * hm * third, aR = nu * (1.0 - mu1) * h0 * h0 * third;
      o[0] = x[D * k] + dvx[k] * ap + D2x[k] * bp - aL * (D2x[k - 1] - D2x[k]) - aR * (D2x[k + 1] - D2x[k]);
      o[1] = x[D * k + 1] + dvy[k] * ap + D2y[k] * bp - aL * (D2y[k - 1] - D2y[k]) - aR * (D2y[k + 1] - D2y[k]);
      if constexpr (D == 3) {
        o[2] = x[D * k + 2] + dvz[k] * ap + D2z[k] * bp - aL * (D2z[k - 1] - D2z[k]) - aR * (D2z[k + 1] - D2z[k]);
      }
    }
  }
}

/// One window of W >= 3 contiguous points x (W x D) with h_k = t_{k+1} - t_k in a.h and
/// the differences of pass 0 in a.dd, solved as open data: its poles are rows 0..W+1 (row
/// k + 1 for point k; rows 0, 1, W, W + 1 are the clamped ends). Writes rows
/// rowFrom..rowTo to out + D * (row + rowShift).
template <int D, EpsilonRule rule, bool quasiOnly>
inline __attribute__((always_inline)) void windowPolesImpl(const double* x, const WindowArrays& a, Eigen::Index W,
                                                           double epsilon, double* out, Eigen::Index rowShift,
                                                           Eigen::Index rowFrom, Eigen::Index rowTo) {
  dividedDifferences<D>(a.h, W, a.dd[0], a.dd[1], a.dd[2]);
  quadratics<D, !quasiOnly>(W, a.h, a.dd[0], a.dd[1], a.dd[2], a.D2[0], a.D2[1], a.D2[2], a.dv[0], a.dv[1], a.dv[2],
                            a.kappa);
  auto quadratic = [&](Eigen::Index k) {
    Quadratic<D> f;
    for (int c = 0; c < D; ++c) {
      f.q[c] = x[D * k + c];
      f.d[c] = a.dv[c][k];
      f.D2[c] = a.D2[c][k];
    }
    return f;
  };
  // Ends of open data: f_0 := f_1 and f_{W-1} := f_{W-2}; kappa_0 is the curvature of
  // f_1 at q_0 (mirrored at the end).
  const Quadratic<D> first = quadratic(1), last = quadratic(W - 2);
  for (int c = 0; c < D; ++c) {
    a.D2[c][0] = a.D2[c][1];
    a.D2[c][W - 1] = a.D2[c][W - 2];
  }
  if constexpr (!quasiOnly) {
    a.kappa[0] = first.kappaAt(-a.h[0]);
    a.kappa[W - 1] = last.kappaAt(a.h[W - 2]);
  }
  auto row = [&](Eigen::Index r) { return Eigen::Map<Vec<D>>(out + D * (r + rowShift)); };
  // Clamped start: F[t_0,t_0,t_0] = q_0 and F[t_0,t_0,t_1] of f_1.
  if (rowFrom <= 0) row(0) = Eigen::Map<const Vec<D>>(x);
  if (rowFrom <= 1 && rowTo >= 1) row(1) = first.blossom3(-a.h[0], -a.h[0], 0.0);
  const Eigen::Index kFrom = std::max<Eigen::Index>(rowFrom - 1, 1), kTo = std::min<Eigen::Index>(rowTo - 1, W - 2);
  if (kFrom <= kTo) poles<D, rule, quasiOnly>(x, a, kFrom, kTo, epsilon, out + D * (kFrom + 1 + rowShift));
  // Clamped end: F[t_{W-2},t_{W-1},t_{W-1}] of f_{W-2} and q_{W-1}.
  if (rowFrom <= W && rowTo >= W) row(W) = last.blossom3(0.0, a.h[W - 2], a.h[W - 2]);
  if (rowTo >= W + 1) row(W + 1) = Eigen::Map<const Vec<D>>(x + D * (W - 1));
}

/// The instances the strategy runs, each compiled for AVX2 and for the baseline.
using WindowFunction = void (*)(const double*, const WindowArrays&, Eigen::Index, double, double*, Eigen::Index,
                                Eigen::Index, Eigen::Index);
#define FAIRSPLINES_WINDOW(NAME, D, RULE, QUASI)                                                                       \
  FAIRSPLINES_VECTORISE void NAME(const double* x, const WindowArrays& a, Eigen::Index W, double epsilon, double* out, \
                                  Eigen::Index rowShift, Eigen::Index rowFrom, Eigen::Index rowTo) {                   \
    windowPolesImpl<D, RULE, QUASI>(x, a, W, epsilon, out, rowShift, rowFrom, rowTo);                                  \
  }
FAIRSPLINES_WINDOW(window2Case, 2, EpsilonRule::CaseDistinction, false)
FAIRSPLINES_WINDOW(window2Additive, 2, EpsilonRule::Additive, false)
FAIRSPLINES_WINDOW(window2Quasi, 2, EpsilonRule::CaseDistinction, true)
FAIRSPLINES_WINDOW(window3Case, 3, EpsilonRule::CaseDistinction, false)
FAIRSPLINES_WINDOW(window3Additive, 3, EpsilonRule::Additive, false)
FAIRSPLINES_WINDOW(window3Quasi, 3, EpsilonRule::CaseDistinction, true)
#undef FAIRSPLINES_WINDOW

WindowFunction windowFunction(int dim, EpsilonRule rule, bool quasiOnly) {
  if (dim == 2) return quasiOnly ? window2Quasi : rule == EpsilonRule::Additive ? window2Additive : window2Case;
  return quasiOnly ? window3Quasi : rule == EpsilonRule::Additive ? window3Additive : window3Case;
}

/// Pass 0 of a window, compiled likewise.
using DifferencesFunction = void (*)(const double*, const WindowArrays&, Eigen::Index);
#define FAIRSPLINES_DIFFERENCES(NAME, D)                                                    \
  FAIRSPLINES_VECTORISE void NAME(const double* x, const WindowArrays& a, Eigen::Index W) { \
    differences<D>(x, W, a.dd[0], a.dd[1], a.dd[2]);                                        \
  }
FAIRSPLINES_DIFFERENCES(differences2, 2)
FAIRSPLINES_DIFFERENCES(differences3, 3)
#undef FAIRSPLINES_DIFFERENCES

/// differencesAndParameters, compiled likewise.
using ParametersFunction = bool (*)(const double*, Eigen::Index, Eigen::Index, const WindowArrays&, double*, double);
#define FAIRSPLINES_PARAMETERS(NAME, D, KIND)                                                                          \
  FAIRSPLINES_VECTORISE bool NAME(const double* x, Eigen::Index W, Eigen::Index k0, const WindowArrays& a, double* tw, \
                                  double tol) {                                                                        \
    return differencesAndParameters<D, KIND>(x, W, k0, a, tw, tol);                                                    \
  }
FAIRSPLINES_PARAMETERS(parameters2Chordal, 2, Parametrization::Chordal)
FAIRSPLINES_PARAMETERS(parameters2Centripetal, 2, Parametrization::Centripetal)
FAIRSPLINES_PARAMETERS(parameters2Uniform, 2, Parametrization::Uniform)
FAIRSPLINES_PARAMETERS(parameters3Chordal, 3, Parametrization::Chordal)
FAIRSPLINES_PARAMETERS(parameters3Centripetal, 3, Parametrization::Centripetal)
FAIRSPLINES_PARAMETERS(parameters3Uniform, 3, Parametrization::Uniform)
#undef FAIRSPLINES_PARAMETERS

ParametersFunction parametersFunction(int dim, Parametrization kind) {
  switch (kind) {
    case Parametrization::Chordal:
      return dim == 2 ? parameters2Chordal : parameters3Chordal;
    case Parametrization::Centripetal:
      return dim == 2 ? parameters2Centripetal : parameters3Centripetal;
    default:
      return dim == 2 ? parameters2Uniform : parameters3Uniform;
  }
}

/// The window scratch of this thread.
Workspace& threadWorkspace() {
  thread_local Workspace workspace;
  return workspace;
}

}  // namespace

// ---------------------------------------------------------------------------------------
// The strategy over all samples, and the fused open csr-spline

void csrPolesWindowed(PointsRef q, const double* t, bool closed, const Weight& weight, bool quasiOnly,
                      Eigen::Index window, double* out) {
  const Eigen::Index n = q.rows(), dim = q.cols();
  const WindowFunction solve = windowFunction(static_cast<int>(dim), weight.rule, quasiOnly);
  const DifferencesFunction subtract = dim == 2 ? differences2 : differences3;
  Workspace& workspace = threadWorkspace();
  if (!closed) {
    const Eigen::Index W = std::min(n, std::max<Eigen::Index>(window, 8));
    const WindowArrays a = workspace.arrays(W);
    for (Eigen::Index s = 0;; s += W - 4) {
      s = std::min(s, n - W);
      for (Eigen::Index k = 0; k + 1 < W; ++k) a.h[k] = t[s + k + 1] - t[s + k];  // as csrPoles's h
      const bool atStart = s == 0, atEnd = s + W == n;
      subtract(q.data() + dim * s, a, W);
      // Local rows 3..W-2 are the poles of points 2..W-3; global row = s + local row.
      solve(q.data() + dim * s, a, W, weight.epsilon, out, s, atStart ? 0 : 3, atEnd ? W + 1 : W - 2);
      if (atEnd) break;
    }
    return;
  }
  // Closed: points 1..n (point n is point 0) give rows 0..n-1. A window starting at
  // point s holds points s..s+W-1 read cyclically; its local row k + 1 (point s + k) is
  // global row s + k - 1.
  const Eigen::Index W = std::min(std::max<Eigen::Index>(window, 8), n + 4);  // n + 4: all in one
  const WindowArrays a = workspace.arrays(W);
  PointMatrix wq(W, dim);
  auto wrap = [n](Eigen::Index i) { return ((i % n) + n) % n; };
  for (Eigen::Index s = -1; s + 2 <= n; s += W - 4) {
    for (Eigen::Index k = 0; k < W; ++k) {
      const Eigen::Index i = wrap(s + k);
      wq.row(k) = q.row(i);
      if (k + 1 < W) a.h[k] = t[i + 1] - t[i];
    }
    subtract(wq.data(), a, W);
    solve(wq.data(), a, W, weight.epsilon, out, s - 2, 3, std::min(W - 2, n + 1 - s));
  }
}

void csrOpenFusedInto(PointsRef q, const CsrOptions& options, double* t, double* poles) {
  const Eigen::Index n = q.rows(), dim = q.cols();
  // Open data in one streaming pass after the bounding box: each window's differences,
  // chords and parameters are computed just before its poles, while its points are in
  // cache. The checks, their order and every value are those of the path above.
  const double size = openSampleSize(q, 3, "the csr-spline");
  const WindowFunction solve = windowFunction(static_cast<int>(dim), options.rule, false);
  const ParametersFunction prepare = parametersFunction(static_cast<int>(dim), options.parametrization);
  const Eigen::Index W = std::min(n, kWindow);
  const WindowArrays a = threadWorkspace().arrays(W);
  const double tol = 1e-12 * size;  // coincidence, as validateSamples judges it
  t[0] = 0.0;
  Eigen::Index known = 0;  // t[0..known] are computed
  for (Eigen::Index s = 0;; s += W - 4) {
    s = std::min(s, n - W);
    const double* x = q.data() + dim * s;
    // The segments known..s+W-2 are new.
    if (prepare(x, W, known - s, a, t + s, tol)) throwFirstCoincident(q, known, s + W - 1, size);
    known = s + W - 1;
    const bool atStart = s == 0, atEnd = s + W == n;
    solve(x, a, W, options.epsilon / size, poles, s, atStart ? 0 : 3, atEnd ? W + 1 : W - 2);
    if (atEnd) break;
  }
}

}  // namespace detail
}  // namespace fairsplines
