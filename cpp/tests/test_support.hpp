// Helpers for the kernel tests: OCCT evaluation is the referee.
#pragma once
#include <Geom_BSplineCurve.hxx>
#include <cmath>
#include <random>

#include "fairsplines/types.hpp"

namespace fairsplines::test {

inline PointMatrix circleSamples(int n, double r, double a0, double a1, bool endpoint = true) {
  PointMatrix q(n, 2);
  for (int i = 0; i < n; ++i) {
    const double a = a0 + (a1 - a0) * i / (endpoint ? n - 1 : n);
    q.row(i) << r * std::cos(a), r * std::sin(a);
  }
  return q;
}

/// Fig. 2 of the csr paper: a half circle (radius 1, counter-clockwise from (1,0) to
/// (-1,0)) continued tangentially by an almost flat parabola (curvature 0.04 at the
/// joint), sampled at equal spacing h along the circle and in y along the parabola.
inline PointMatrix fig2Samples(int perHalfCircle = 12, int parabolaSamples = 19) {
  const double pi = std::acos(-1.0), h = pi / perHalfCircle;
  PointMatrix q(perHalfCircle + 1 + parabolaSamples, 2);
  for (int i = 0; i <= perHalfCircle; ++i) q.row(i) << std::cos(i * h), std::sin(i * h);
  for (int j = 1; j <= parabolaSamples; ++j) {
    const double s = j * h;
    q.row(perHalfCircle + j) << -1.0 + 0.02 * s * s, -s;
  }
  return q;
}

/// Signed curvature (z component) of the OCCT curve at u.
inline double signedKappa(const Handle(Geom_BSplineCurve)& c, double u) {
  gp_Pnt p;
  gp_Vec d1, d2;
  c->D2(u, p, d1, d2);
  return d1.Crossed(d2).Z() / std::pow(d1.Magnitude(), 3);
}

/// Sign changes of the OCCT-evaluated signed curvature, `perSpan` samples per knot span.
inline int signChanges(const Handle(Geom_BSplineCurve)& c, int perSpan = 32) {
  int changes = 0, last = 0;
  for (int k = 1; k < c->NbKnots(); ++k) {
    for (int j = 0; j < perSpan; ++j) {
      const double u = c->Knot(k) + (c->Knot(k + 1) - c->Knot(k)) * j / perSpan;
      const double kappa = signedKappa(c, u);
      if (std::abs(kappa) < 1e-9) continue;
      const int sign = kappa > 0 ? 1 : -1;
      if (last && sign != last) ++changes;
      last = sign;
    }
  }
  return changes;
}

}  // namespace fairsplines::test
