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

template <int D>
double curvatureOf(const Vec<D>& d1, const Vec<D>& d2) {
  double cross2;
  if constexpr (D == 2) {
    const double z = d1[0] * d2[1] - d1[1] * d2[0];
    cross2 = z * z;
  } else {
    cross2 = d1.cross(d2).squaredNorm();
  }
  const double speed2 = d1.squaredNorm();
  return std::sqrt(cross2) / (speed2 * std::sqrt(speed2));
}

/// The quadratic interpolant f_i of q_{i-1}, q_i, q_{i+1} at t_{i-1}, t_i, t_{i+1},
/// written about its middle node: f_i(t) = q_i + d (t - t_i) + D (t - t_i)^2.
template <int D>
struct Quadratic {
  Vec<D> q, d, D2;  // D2 is the paper-free name for f''/2
  double ta;        // t_i, the expansion point
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
Vec<D> row(const PointMatrix& q, Eigen::Index i) {
  return q.row(i).transpose().template head<D>();
}

template <int D>
Quadratic<D> interpolant(const Vec<D>& qm, const Vec<D>& q0, const Vec<D>& qp, double hm, double h0, double t0) {
  // Newton form about t_i: first divided differences on either side, then the second.
  const Vec<D> dm = (q0 - qm) / hm, d0 = (qp - q0) / h0;
  Quadratic<D> f;
  f.D2 = (d0 - dm) / (hm + h0);
  f.d = dm + f.D2 * hm;  // f'(t_i)
  f.q = q0;
  f.ta = t0;
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
void csrPoles(const PointMatrix& q, const Eigen::VectorXd& t, bool closed, const Weight& weight, bool quasiOnly,
              PointMatrix& out) {
  const Eigen::Index n = q.rows();
  const Eigen::Index segments = closed ? n : n - 1;
  Eigen::VectorXd h(segments);
  for (Eigen::Index i = 0; i < segments; ++i) h[i] = t[i + 1] - t[i];
  auto H = [&](Eigen::Index i) { return h[(i + segments) % segments]; };  // cyclic for closed data

  // f_i and kappa_i for every sample that has two neighbours.
  std::vector<Quadratic<D>> f(n);
  Eigen::VectorXd kappa(n);
  const Eigen::Index first = closed ? 0 : 1, last = closed ? n - 1 : n - 2;
  for (Eigen::Index i = first; i <= last; ++i) {
    const Eigen::Index im = (i + n - 1) % n, ip = (i + 1) % n;
    f[i] = interpolant<D>(row<D>(q, im), row<D>(q, i), row<D>(q, ip), H(i - 1), H(i), t[i]);
    kappa[i] = f[i].kappaAt(0.0);
  }
  if (!closed) {
    // Ends of open data: the end quadratics continue outwards, f_0 := f_1, f_{n-1} := f_{n-2};
    // kappa_0 is the curvature of f_1 at q_0 (mirrored at the other end).
    f[0] = f[1];
    f[n - 1] = f[n - 2];
    kappa[0] = f[1].kappaAt(-h[0]);
    kappa[n - 1] = f[n - 2].kappaAt(h[n - 2]);
  }

  const Eigen::Index offset = closed ? 0 : 1;  // open curves start with q_0 and F[t_0,t_0,t_1]
  out.resize(closed ? n : n + 2, q.cols());
  for (Eigen::Index i = first; i <= last; ++i) {
    const Eigen::Index im = (i + n - 1) % n, ip = (i + 1) % n;
    const double hm = H(i - 1), h0 = H(i);
    // Cubic blossoms at (t_{i-1}, t_i, t_{i+1}) of f_i, f_{i-1}, f_{i+1}, each written
    // relative to that quadratic's own expansion point.
    const Vec<D> p = f[i].blossom3(-hm, 0.0, h0);
    Vec<D> c;
    if (quasiOnly) {
      c = p;
    } else {
      // For the open ends f_{i-1} or f_{i+1} is f_i itself, expanded about t_i.
      const bool leftIsSelf = !closed && i == 1, rightIsSelf = !closed && i == n - 2;
      const double hmm = leftIsSelf ? 0.0 : H(i - 1);  // t_i - t_{expansion of f_{i-1}}
      const double hpp = rightIsSelf ? 0.0 : H(i);     // t_{expansion of f_{i+1}} - t_i
      const Vec<D> pL = f[im].blossom3(-hm + hmm, hmm, h0 + hmm);
      const Vec<D> pR = f[ip].blossom3(-hm - hpp, -hpp, h0 - hpp);
      // Eq. (6).
      const double mu_i = weight(kappa[i], kappa[im]);
      const double mu_ip = weight(kappa[ip], kappa[i]);
      const double nu_i = weight(kappa[im], kappa[ip]);
      c = (1.0 - nu_i) * (mu_i * pL + (1.0 - mu_i) * p) + nu_i * ((1.0 - mu_ip) * pR + mu_ip * p);
    }
    out.row(i + offset).head<D>() = c.transpose();
  }
  if (!closed) {
    // Clamped ends: F[t_0,t_0,t_0] = q_0 and F[t_0,t_0,t_1] of f_1; mirrored at the end.
    out.row(0) = q.row(0);
    out.row(1).head<D>() = f[1].blossom3(-h[0], -h[0], 0.0).transpose();
    out.row(n).head<D>() = f[n - 2].blossom3(0.0, h[n - 2], h[n - 2]).transpose();
    out.row(n + 1) = q.row(n - 1);
  }
}

}  // namespace

BSplineCurve fitCubic(const PointMatrix& q, const Eigen::VectorXd& t, bool closed, double epsilon,
                      EpsilonRule rule, bool quasiOnly) {
  const double size = (q.colwise().maxCoeff() - q.colwise().minCoeff()).norm();
  const Weight weight{epsilon / size, rule};
  PointMatrix poles;
  if (q.cols() == 2) csrPoles<2>(q, t, closed, weight, quasiOnly, poles);
  else csrPoles<3>(q, t, closed, weight, quasiOnly, poles);
  return closed ? periodicCubic(std::move(poles), t) : clampedCubic(std::move(poles), t);
}

template <int D>
PointMatrix quadraticHandles(const PointMatrix& q, const Eigen::VectorXd& t, bool closed, const Weight& weight) {
  const Eigen::Index n = q.rows();
  const Eigen::Index segments = closed ? n : n - 1;
  Eigen::VectorXd h(segments);
  for (Eigen::Index i = 0; i < segments; ++i) h[i] = t[i + 1] - t[i];
  auto H = [&](Eigen::Index i) { return h[(i + segments) % segments]; };
  std::vector<Quadratic<D>> f(n);
  Eigen::VectorXd kappa(n);
  const Eigen::Index first = closed ? 0 : 1, last = closed ? n - 1 : n - 2;
  for (Eigen::Index i = first; i <= last; ++i) {
    f[i] = interpolant<D>(row<D>(q, (i + n - 1) % n), row<D>(q, i), row<D>(q, (i + 1) % n), H(i - 1), H(i), t[i]);
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

BSplineCurve csrSpline(const PointMatrix& q, const CsrOptions& options) {
  validateSamples(q, options.closed, 3, "the csr-spline");
  const Eigen::VectorXd t = options.parameters.size() > 0
                                ? validatedParameters(options.parameters, q.rows(), options.closed)
                                : parameters(q, options.parametrization, options.closed);
  if (!(options.epsilon > 0.0)) throw InputError("epsilon must be positive");
  return detail::fitCubic(q, t, options.closed, options.epsilon, options.rule, false);
}

BSplineCurve quadraticDesign(const PointMatrix& q, Parametrization parametrization, bool closed, double epsilon) {
  validateSamples(q, closed, 3, "the quadratic design");
  if (!(epsilon > 0.0)) throw InputError("epsilon must be positive");
  const Eigen::VectorXd t = parameters(q, parametrization, closed);
  const double size = (q.colwise().maxCoeff() - q.colwise().minCoeff()).norm();
  const detail::Weight weight{epsilon / size, EpsilonRule::CaseDistinction};
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
