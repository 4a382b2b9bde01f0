// Random space curves as blend end conditions (issue 28), shared by the space fair-blend
// tests and bench/bench_fair_blend.cpp: curvature linear in arc length (0.2 to 2.5, so
// positive), torsion linear (-1.5 to 1.5), length 3, integrated independently of the kernel
// (exact rotations of the frame about the Darboux vector, 3000 steps). The first and last
// thirds are approximated by OCCT (GeomAPI_PointsToBSpline, C2, 1e-7) and the ends are what
// OCCT evaluates on those edges, at random scale, placement, orientation and mirror image.
#pragma once
#include <Eigen/Geometry>
#include <GeomAPI_PointsToBSpline.hxx>
#include <Geom_BSplineCurve.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "fairsplines/fair_blend.hpp"

namespace fairsplines::test {

using Eigen::Vector3d;

struct SpaceCase {
  SpaceBlendEnds ends;             // G2 ends (drop K0, K1 for G1)
  Handle(Geom_BSplineCurve) a, b;  // the two edges: the blend leaves a's end, enters b's start
  double kappa0 = 0, kappa1 = 0;   // the generating curve's curvature at the start and end
  double tau0 = 0, tau1 = 0;       // and torsion
};

/// The point, unit tangent and curvature vector (d1 x d2) x d1 / |d1|^4 of an OCCT curve at u.
inline void jetOf(const Handle(Geom_BSplineCurve)& c, double u, Vector3d& p, Vector3d& t, Vector3d& K) {
  gp_Pnt x;
  gp_Vec d1, d2;
  c->D2(u, x, d1, d2);
  const Vector3d v1(d1.X(), d1.Y(), d1.Z()), v2(d2.X(), d2.Y(), d2.Z());
  p = Vector3d(x.X(), x.Y(), x.Z());
  t = v1.normalized();
  K = v1.cross(v2).cross(v1) / std::pow(v1.norm(), 4);
}

inline SpaceCase randomSpaceCase(std::mt19937& rng) {
  std::uniform_real_distribution<double> U(0.0, 1.0);
  SpaceCase sc;
  sc.kappa0 = 0.2 + 2.3 * U(rng);
  sc.kappa1 = 0.2 + 2.3 * U(rng);
  sc.tau0 = -1.5 + 3.0 * U(rng);
  sc.tau1 = -1.5 + 3.0 * U(rng);
  const double L = 3.0;
  const int steps = 3000;
  std::vector<Vector3d> pts(steps + 1);
  Eigen::Matrix3d F = Eigen::Matrix3d::Identity();  // columns T, N, B
  Vector3d x = Vector3d::Zero();
  pts[0] = x;
  const double h = L / steps;
  for (int i = 0; i < steps; ++i) {
    const double s = (i + 0.5) * h, f = s / L;
    const double k = sc.kappa0 + (sc.kappa1 - sc.kappa0) * f, tau = sc.tau0 + (sc.tau1 - sc.tau0) * f;
    // The Darboux vector tau T + kappa B in the frame's own coordinates: (tau, 0, kappa).
    const Vector3d w(tau, 0.0, k);
    const Eigen::Matrix3d R = Eigen::AngleAxisd(w.norm() * h, w.normalized()).toRotationMatrix();
    const Eigen::Matrix3d Fn = F * R;
    // Position: the tangent of the rotation's midpoint (second order).
    const Eigen::Matrix3d Rh = Eigen::AngleAxisd(0.5 * w.norm() * h, w.normalized()).toRotationMatrix();
    x += h * (F * Rh).col(0);
    F = Fn;
    pts[i + 1] = x;
  }
  // Random similarity: scale, rotation, mirror, placement.
  const double scale = std::pow(10.0, -2.0 + 4.0 * U(rng));
  Eigen::Quaterniond q(U(rng) - 0.5, U(rng) - 0.5, U(rng) - 0.5, U(rng) - 0.5);
  q.normalize();
  Eigen::Matrix3d M = q.toRotationMatrix();
  if (U(rng) < 0.5) M.col(0) *= -1.0;
  const Vector3d offset = scale * 20.0 * Vector3d(U(rng) - 0.5, U(rng) - 0.5, U(rng) - 0.5);
  auto edge = [&](int from, int to) {
    const int n = 40;
    TColgp_Array1OfPnt arr(1, n + 1);
    for (int i = 0; i <= n; ++i) {
      const Vector3d p = offset + scale * (M * pts[from + (to - from) * i / n]);
      arr(i + 1) = gp_Pnt(p.x(), p.y(), p.z());
    }
    return GeomAPI_PointsToBSpline(arr, 3, 8, GeomAbs_C2, 1e-7 * scale).Curve();
  };
  sc.a = edge(0, steps / 3);
  sc.b = edge(2 * steps / 3, steps);
  jetOf(sc.a, sc.a->LastParameter(), sc.ends.p0, sc.ends.t0, sc.ends.K0);
  jetOf(sc.b, sc.b->FirstParameter(), sc.ends.p1, sc.ends.t1, sc.ends.K1);
  return sc;
}

}  // namespace fairsplines::test
