// csr-spline, Section 4, eq. (6), and quadratic design, Section 7, eq. (12), of
// Karčiauskas & Peters, "Curvature-sensitive splines and design with basic curves".
#include "fairsplines/csr.hpp"

#include <Eigen/Geometry>
#include <cmath>

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

}  // namespace

BSplineCurve fitCubic(PointsRef q, const Eigen::VectorXd& t, bool closed, double size, double epsilon,
                      EpsilonRule rule, bool quasiOnly) {
  const Weight weight{epsilon / size, rule};
  const Eigen::VectorXd h = t.tail(t.size() - 1) - t.head(t.size() - 1);
  PointMatrix poles;
  if (q.cols() == 2) csrPoles<2>(q, h, closed, weight, quasiOnly, poles);
  else csrPoles<3>(q, h, closed, weight, quasiOnly, poles);
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
