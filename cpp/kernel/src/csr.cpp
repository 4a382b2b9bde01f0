// csr-spline, Section 4, eq. (6), of Karčiauskas & Peters, "Curvature-sensitive splines
// and design with basic curves": the streaming strategy (the reference) and the entry
// points that pick a strategy. The vectorised strategy is in csr_vectorised.cpp, the
// quadratic design of Section 7, eq. (12), in quadratic_design.cpp.
#include "fairsplines/csr.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "fairsplines/bspline.hpp"
#include "fairsplines/errors.hpp"
#include "csr_detail.hpp"
#include "csr_poles.hpp"
#include "finite.hpp"

namespace fairsplines {
namespace detail {

// ---------------------------------------------------------------------------------------
// The streaming strategy: one pass with a window of three quadratics (the reference)

namespace {

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
    const bool rightIsSelf = !closed && i == n - 2;
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
      const double aL = (1.0 - nu_i) * mu_i;   // weight of p_i^L
      const double aR = nu_i * (1.0 - mu_ip);  // weight of p_i^R
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

}  // namespace

// ---------------------------------------------------------------------------------------
// The poles and the curve, by either strategy

CsrStrategy defaultStrategy(Eigen::Index n) {
  // Measured: the vectorised passes are about 3x faster from 100 points on (their scratch
  // memory is reused, so it costs nothing per call); the streaming pass stays the
  // reference for small data.
  return n >= kVectorisedFrom ? CsrStrategy::Vectorised : CsrStrategy::Streaming;
}

void cubicPolesInto(PointsRef q, const double* t, bool closed, double size, double epsilon, EpsilonRule rule,
                    bool quasiOnly, std::optional<CsrStrategy> strategy, Eigen::Index window, double* poles) {
  if (q.outerStride() != q.cols()) {  // the passes read rows as one contiguous block
    cubicPolesInto(PointMatrix(q), t, closed, size, epsilon, rule, quasiOnly, strategy, window, poles);
    return;
  }
  const Weight weight{epsilon / size, rule};
  const Eigen::Index n = q.rows();
  if (strategy.value_or(defaultStrategy(n)) == CsrStrategy::Vectorised) {
    csrPolesWindowed(q, t, closed, weight, quasiOnly, window <= 0 ? kWindow : window, poles);
    return;
  }
  const Eigen::Map<const Eigen::VectorXd> tv(t, closed ? n + 1 : n);
  const Eigen::VectorXd h = tv.tail(tv.size() - 1) - tv.head(tv.size() - 1);
  PointMatrix p;
  if (q.cols() == 2)
    csrPoles<2>(q, h, closed, weight, quasiOnly, p);
  else
    csrPoles<3>(q, h, closed, weight, quasiOnly, p);
  Eigen::Map<PointMatrix> out(poles, p.rows(), p.cols());
  if (closed) {
    // OCCT's periodic pole j belongs to the basis function starting at knot j - 1: row
    // j holds c_{j+1} (see periodicCubic).
    for (Eigen::Index j = 0; j < n; ++j) out.row(j) = p.row((j + 1) % n);
  } else {
    out = p;
  }
}

BSplineCurve fitCubic(PointsRef q, Eigen::VectorXd t, bool closed, double size, double epsilon, EpsilonRule rule,
                      bool quasiOnly, std::optional<CsrStrategy> strategy, Eigen::Index window) {
  // The curve is built in place: poles written where they stay, the parameters moved
  // into the knots (clampedCubic / periodicCubic's layout).
  const Eigen::Index n = q.rows();
  BSplineCurve curve;
  curve.degree = 3;
  curve.periodic = closed;
  curve.poles.resize(closed ? n : n + 2, q.cols());
  cubicPolesInto(q, t.data(), closed, size, epsilon, rule, quasiOnly, strategy, window, curve.poles.data());
  curve.mults = Eigen::VectorXi::Ones(t.size());
  if (!closed) curve.mults[0] = curve.mults[t.size() - 1] = 4;
  curve.knots = std::move(t);
  requireValidCurve(curve, "the cubic fit of these points");
  return curve;
}

namespace {

void csrSplineAsGiven(PointsRef q, const CsrOptions& options, double* t, double* poles) {
  const Eigen::Index n = q.rows(), dim = q.cols();
  const bool fused = !options.closed && options.parameters.size() == 0 && validEpsilon(options.epsilon) &&
                     (dim == 2 || dim == 3) && q.outerStride() == dim && n >= kVectorisedFrom;
  if (!fused) {
    const Eigen::Index segments = options.closed ? n : n - 1;
    // The chords are written where the parameters go and turned into them in place.
    const double size = validateSamplesInto(q, options.closed, 3, "the csr-spline", t + 1);
    if (!validEpsilon(options.epsilon)) throw InputError(kEpsilonMessage);
    if (options.parameters.size() > 0) {
      const Eigen::VectorXd given = validatedParameters(options.parameters, n, options.closed);
      // Scale-free: a B-spline's poles do not change under an affine map of its knots, so
      // they are computed on the parameters mapped onto [0, 1] (parameters 1e-300 or 1e200
      // apart mean the same curve), and the knots are the parameters as given.
      const double t0 = given[0], span = given[given.size() - 1] - t0;
      if (!std::isfinite(span)) {
        std::ostringstream msg;
        msg << "the parameters run from " << t0 << " to " << given[given.size() - 1]
            << ": their span is more than double precision holds";
        throw InputError(msg.str());
      }
      requireSeparateParameters(given.data(), given.size(), n, true, "the csr-spline");
      const Eigen::VectorXd unit = (given.array() - t0) / span;
      cubicPolesInto(q, unit.data(), options.closed, size, options.epsilon, options.rule, false, std::nullopt, 0,
                     poles);
      std::copy(given.data(), given.data() + given.size(), t);
      return;
    }
    parametersInto(t + 1, segments, options.parametrization, t);
    requireSeparateParameters(t, segments + 1, n, false, "the csr-spline");
    cubicPolesInto(q, t, options.closed, size, options.epsilon, options.rule, false, std::nullopt, 0, poles);
    return;
  }
  csrOpenFusedInto(q, options, t, poles);
  requireSeparateParameters(t, n, n, false, "the csr-spline");  // the knots, before they leave
}

}  // namespace

void csrSplineInto(PointsRef q, const CsrOptions& options, double* t, double* poles) {
  try {
    csrSplineAsGiven(q, options, t, poles);
  } catch (const ExtremeScale& e) {
    // Scale-free: points whose squared distances leave double precision (1e300, 1e-300) are
    // fitted divided by a power of two near their largest coordinate (exact: the same digits
    // as at that size) and the poles multiplied back; the knots are the parameters of the
    // scaled points (chordal and centripetal ones scale with them) or the given ones.
    const double scale = powerOfTwoScale(e.largest);
    const PointMatrix unit = q / scale;
    csrSplineAsGiven(unit, options, t, poles);
    const Eigen::Index count = (options.closed ? q.rows() : q.rows() + 2) * q.cols();
    for (Eigen::Index i = 0; i < count; ++i) poles[i] *= scale;
  }
}

}  // namespace detail

BSplineCurve csrSpline(PointsRef q, const CsrOptions& options) {
  // The curve is built in place (clampedCubic / periodicCubic's layout).
  const Eigen::Index n = q.rows(), knots = std::max<Eigen::Index>(options.closed ? n + 1 : n, 1);
  BSplineCurve curve;
  curve.degree = 3;
  curve.periodic = options.closed;
  curve.knots.resize(knots);
  curve.poles.resize(std::max<Eigen::Index>(options.closed ? n : n + 2, 0), q.cols());
  detail::csrSplineInto(q, options, curve.knots.data(), curve.poles.data());
  curve.mults = Eigen::VectorXi::Ones(knots);
  if (!options.closed) curve.mults[0] = curve.mults[knots - 1] = 4;
  requireValidCurve(curve, "the csr-spline of these points and parameters");
  return curve;
}

}  // namespace fairsplines
