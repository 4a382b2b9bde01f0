// Quadratic design, Section 7, eq. (12), of Karčiauskas & Peters, "Curvature-sensitive
// splines and design with basic curves": the middle coefficients m_i of the quadratic
// pieces blended with the csr-spline's weights.
#include <vector>

#include "fairsplines/csr.hpp"
#include "fairsplines/errors.hpp"
#include "fairsplines/parameters.hpp"
#include "csr_poles.hpp"
#include "finite.hpp"

namespace fairsplines {
namespace detail {

namespace {

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

}  // namespace

}  // namespace detail

namespace {

BSplineCurve quadraticDesignAsGiven(PointsRef q, Parametrization parametrization, bool closed, double epsilon) {
  const SampleInfo info = validateSamples(q, closed, 3, "the quadratic design");
  if (!detail::validEpsilon(epsilon)) throw InputError(detail::kEpsilonMessage);
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
  requireValidCurve(curve, "the quadratic design of these points");
  return curve;
}

}  // namespace

BSplineCurve quadraticDesign(PointsRef q, Parametrization parametrization, bool closed, double epsilon) {
  try {
    return quadraticDesignAsGiven(q, parametrization, closed, epsilon);
  } catch (const detail::ExtremeScale& e) {
    // Scale-free, as the csr-spline (csrSplineInto): fitted divided by a power of two, the
    // poles multiplied back.
    const double scale = powerOfTwoScale(e.largest);
    BSplineCurve curve = quadraticDesignAsGiven(q / scale, parametrization, closed, epsilon);
    curve.poles *= scale;
    requireValidCurve(curve, "the quadratic design of these points");
    return curve;
  }
}

}  // namespace fairsplines
