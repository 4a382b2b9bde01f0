// Fair fit, measuring the curve against the data (issue 16): every span as its cubic
// polynomial, and the projection of a sample that bounds its distance from above.
// docs/FAIR_FIT.md, step 7.
#include "fair_fit_detail.hpp"

#include <Eigen/Dense>
#include <Geom_BSplineCurve.hxx>
#include <algorithm>
#include <cmath>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>
#include <vector>

namespace fairsplines::detail::fairfit {

// ---------------------------------------------------------------------------------------
// The curve's spans as cubic polynomials, and the projection of the samples

std::array<Vector3d, 4> spanPoly(const Handle(Geom_BSplineCurve)& occ, const std::vector<double>& t, Index j) {
  gp_Pnt p;
  gp_Vec d1, d2, d3;
  // The right-hand derivatives at t_j, from span j's polynomial (knots numbered from 1).
  occ->LocalD3(t[j], static_cast<int>(j + 1), static_cast<int>(j + 2), p, d1, d2, d3);
  return {Vector3d(p.X(), p.Y(), p.Z()), Vector3d(d1.X(), d1.Y(), d1.Z()), 0.5 * Vector3d(d2.X(), d2.Y(), d2.Z()),
          Vector3d(d3.X(), d3.Y(), d3.Z()) / 6.0};
}

SpanPolys spanPolys(const BSplineCurve& curve, const Handle(Geom_BSplineCurve)& occ) {
  SpanPolys P;
  P.closed = curve.periodic;
  P.t.assign(curve.knots.data(), curve.knots.data() + curve.knots.size());
  const Index spans = curve.knots.size() - 1;
  P.c.resize(spans);
  for (Index j = 0; j < spans; ++j) P.c[j] = spanPoly(occ, P.t, j);
  return P;
}

Foot projectFoot(const SpanPolys& P, const Vector3d& p, Index j, double x) {
  auto eval = [&](Index span, double u, Vector3d& C, Vector3d& C1, Vector3d& C2) {
    const auto& c = P.c[span];
    C = ((c[3] * u + c[2]) * u + c[1]) * u + c[0];
    C1 = (3.0 * c[3] * u + 2.0 * c[2]) * u + c[1];
    C2 = 6.0 * c[3] * u + 2.0 * c[2];
  };
  Vector3d C, C1, C2;
  eval(j, x, C, C1, C2);
  Foot best{j, x, (C - p).norm()};
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
    if (const double d = (C - p).norm(); d < best.d) best = {j, x, d};
    if (std::abs(dx) <= 1e-13 * P.h(j)) break;
  }
  return best;
}

double projectDistance(const SpanPolys& P, const Vector3d& p, Index j, double x) { return projectFoot(P, p, j, x).d; }

int signChangesOver(const SpanPolys& P, const std::vector<Index>& spans, const Vector3d& normal, double zeroKappa) {
  int changes = 0, last = 0;
  for (Index j : spans) {
    const auto& c = P.c[j];
    const double h = P.h(j);
    for (int s = 0; s < 16; ++s) {
      const double u = h * s / 16.0;
      const Vector3d C1 = (3.0 * c[3] * u + 2.0 * c[2]) * u + c[1], C2 = 6.0 * c[3] * u + 2.0 * c[2];
      const double speed = C1.norm();
      if (!(speed > 0.0)) continue;
      const double kappa = C1.cross(C2).dot(normal) / (speed * speed * speed);
      if (!(std::abs(kappa) > zeroKappa)) continue;
      const int sign = kappa > 0.0 ? 1 : -1;
      if (last != 0 && sign != last) ++changes;
      last = sign;
    }
  }
  return changes;
}

}  // namespace fairsplines::detail::fairfit
