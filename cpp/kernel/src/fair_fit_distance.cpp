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
  // The four poles Q_0..Q_3 and six knots k_0..k_5 around span j = [k_2, k_3] of a cubic with
  // simple interior knots t_0..t_m: poles j..j+3, clamped (end knots of multiplicity 4) or
  // periodic (pole indices modulo m, knots continued by the period; OCCT's numbering,
  // checked against its evaluation by FairFit.SpanPolynomialsFromPolesAgreeWithOcct). Read
  // directly: OCCT's own evaluation locates the span's first pole by summing the
  // multiplicities before it, O(knots) per point.
  const Index m = static_cast<Index>(t.size()) - 1;
  const bool periodic = occ->IsPeriodic();
  const double period = t[m] - t[0];
  auto knot = [&](Index i) {
    if (!periodic) return t[std::clamp<Index>(i, 0, m)];
    const Index wraps = i >= 0 ? i / m : -((-i + m - 1) / m);
    return t[i - wraps * m] + static_cast<double>(wraps) * period;
  };
  std::array<Vector3d, 4> d;
  std::array<double, 6> k;
  for (int r = 0; r < 4; ++r) {
    const Index i = periodic ? (j + r) % m : j + r;
    const gp_Pnt& x = occ->Pole(static_cast<int>(i) + 1);
    d[r] = Vector3d(x.X(), x.Y(), x.Z());
  }
  for (int r = 0; r < 6; ++r) k[r] = knot(j - 2 + r);
  // Derivative poles (de Boor): degree 2 on k_1..k_4, degree 1 on k_2..k_3, the constant.
  const std::array<Vector3d, 3> d1 = {3.0 * (d[1] - d[0]) / (k[3] - k[0]), 3.0 * (d[2] - d[1]) / (k[4] - k[1]),
                                      3.0 * (d[3] - d[2]) / (k[5] - k[2])};
  const std::array<Vector3d, 2> d2 = {2.0 * (d1[1] - d1[0]) / (k[3] - k[1]), 2.0 * (d1[2] - d1[1]) / (k[4] - k[2])};
  const Vector3d d3 = (d2[1] - d2[0]) / (k[3] - k[2]);
  // At the knot u = k_2: C' from the two quadratic B-splines not zero there, C from de Boor's
  // algorithm (the blossom F[k_1, k_2, k_2] ... reduces to two steps).
  const Vector3d c1 = ((k[3] - k[2]) * d1[0] + (k[2] - k[1]) * d1[1]) / (k[3] - k[1]);
  std::array<Vector3d, 4> b = d;
  const double u = k[2];
  for (int r = 1; r <= 3; ++r) {
    for (int q = 3; q >= r; --q) {
      const double alpha = (u - k[q - 1]) / (k[q + 3 - r] - k[q - 1]);
      b[q] = (1.0 - alpha) * b[q - 1] + alpha * b[q];
    }
  }
  return {b[3], c1, 0.5 * d2[0], d3 / 6.0};
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

CurvatureProfile spanProfile(const SpanPolys& P, const std::optional<Vector3d>& normal, int perSpan) {
  const Index spans = P.spans();
  const Index count = spans * perSpan + 1;
  CurvatureProfile profile;
  profile.isSigned = normal.has_value();
  if (normal) profile.normal = gp_Vec(normal->x(), normal->y(), normal->z());
  profile.u.resize(count), profile.s.resize(count), profile.kappa.resize(count);
  Vector3d last;
  double length = 0.0;
  Index n = 0;
  for (Index j = 0; j < spans; ++j) {
    const auto& c = P.c[j];
    const double h = P.h(j);
    for (int q = 0; q <= perSpan; ++q) {
      if (q == perSpan && j + 1 < spans) break;  // the next span's first sample
      const double x = h * q / perSpan;
      const Vector3d C = ((c[3] * x + c[2]) * x + c[1]) * x + c[0];
      const Vector3d C1 = (3.0 * c[3] * x + 2.0 * c[2]) * x + c[1], C2 = 6.0 * c[3] * x + 2.0 * c[2];
      // kappa = |C' x C''| / |C'|^3, as (T x C'' / v) / v with v = |C'|, T = C' / v: no
      // overflow for data of any size.
      const double v = C1.norm();
      const Vector3d k = (C1 / v).cross(C2 / v) / v;
      double kappa = normal ? k.dot(*normal) : k.norm();
      if (!std::isfinite(kappa)) kappa = 0.0;  // a stationary point: no curvature to count
      if (n > 0) length += (C - last).norm();
      last = C;
      profile.u[n] = P.t[j] + x;
      profile.s[n] = length;
      profile.kappa[n] = kappa;
      ++n;
    }
  }
  return profile;
}

}  // namespace fairsplines::detail::fairfit
