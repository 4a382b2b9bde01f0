// The unifying spline (Section 1, Fig. 1 of Karčiauskas & Peters, "Curvature-sensitive
// splines and design with basic curves"): samples enter the design with basic curves as
// a piece whose control polygon is their csr-spline (Section 4, eq. (6)).
#include "fairsplines/design_samples.hpp"

#include "fairsplines/errors.hpp"
#include "finite.hpp"

namespace fairsplines {

PiecePolygon samplesPolygon(PointsRef q, const CsrOptions& options) {
  if (options.closed) throw InputError("a sampled piece of a design is open: closed samples cannot be one piece");
  // Section 4: the csr-spline, a clamped cubic C2 B-spline with a simple knot at every
  // t_i and the poles q_0, F[t_0,t_0,t_1], c_1..c_{n-2} (eq. (6)), F[t_{n-2},t_{n-1},t_{n-1}],
  // q_{n-1}. It validates the samples (and names what is wrong with them).
  const BSplineCurve csr = csrSpline(q, options);
  const Eigen::Index n = csr.knots.size();  // one knot per sample
  if (n < 3 || csr.poles.rows() != n + 2 || csr.isRational()) {
    throw InputError("the csr-spline of the samples is not a clamped cubic with a knot per sample");
  }
  PiecePolygon p;
  p.exact = false;
  // The marks u_i: the samples' parameters t_i mapped onto [0, 1] (u_0 = 0, u_m = 1,
  // m = n - 1). An affine map keeps every beta_i = (t_{i+1} - t_i) / (t_i - t_{i-1}) of
  // eq. (1), hence the csr-spline's G2 form.
  const Eigen::VectorXd& t = csr.knots;
  p.marks = (t.array() - t[0]) / (t[n - 1] - t[0]);
  p.marks[0] = 0.0;
  p.marks[n - 1] = 1.0;
  requireSeparateKnots(p.marks, "the samples' parameters mapped onto [0, 1]");
  // Homogeneous rows (x, y, z, 1): the csr-spline is polynomial; planar samples get z = 0.
  HomogeneousPoints h = HomogeneousPoints::Zero(n + 2, 4);
  h.leftCols(csr.poles.cols()) = csr.poles;
  h.col(3).setOnes();
  requireFinite(h, "the csr-spline of the samples", "control points");
  p.start = h.topRows(2);
  p.inner = h.middleRows(2, n - 2);
  p.end = h.bottomRows(2);
  return p;
}

}  // namespace fairsplines
