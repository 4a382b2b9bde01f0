// Helpers for the kernel tests: OCCT evaluation is the referee.
#pragma once
#include <Eigen/Geometry>
#include <Geom_BSplineCurve.hxx>
#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "fairsplines/errors.hpp"
#include "fairsplines/types.hpp"

namespace fairsplines::test {

/// The message of the InputError `call` throws ("" if it returns; any other exception
/// escapes and fails the test).
inline std::string refusal(const std::function<void()>& call) {
  try {
    call();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

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

/// G1 end conditions p0, t0, p1, t1 (3D vectors).
struct EndCondition {
  Eigen::Vector3d p0, t0, p1, t1;
  bool reversed = false;  ///< built so that the curvature must increase from p0
};

/// Random end conditions the monotone-curvature family can meet: turn in (0.5, 89.5) deg, legs
/// a = |M - p0|, b = |p1 - M| with a/(a+b) uniform in (0.001, 0.999) of its limit cos/(1+cos)
/// (or the reverse), in random positions, orientations, scales (1e-2 .. 1e3) and mirror
/// images, half of them in random planes of 3D space; tangents of random length.
inline std::vector<EndCondition> randomAdmissibleEnds(int count, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double pi = std::acos(-1.0);
  std::vector<EndCondition> out;
  for (int k = 0; k < count; ++k) {
    const double turn = (0.5 + 89.0 * unit(rng)) * pi / 180.0;
    const double rmax = std::cos(turn) / (1.0 + std::cos(turn));
    const double r = (0.001 + 0.998 * unit(rng)) * rmax;
    Eigen::Vector2d q0(0, 0), d0(1, 0), d1(std::cos(turn), std::sin(turn));
    Eigen::Vector2d q1 = Eigen::Vector2d(r, 0) + (1 - r) * d1;
    EndCondition e;
    if (unit(rng) < 0.5) {  // curvature increasing from p0: the same curve run backwards
      std::swap(q0, q1);
      const Eigen::Vector2d back0 = -d1, back1 = -d0;
      d0 = back0;
      d1 = back1;
      e.reversed = true;
    }
    const double mirror = unit(rng) < 0.5 ? -1.0 : 1.0;
    const double scale = std::pow(10.0, -2.0 + 5.0 * unit(rng)), angle = 2 * pi * unit(rng);
    const Eigen::Rotation2Dd rot(angle);
    auto place = [&](const Eigen::Vector2d& v, bool point) {
      Eigen::Vector2d w = rot * Eigen::Vector2d(v.x(), mirror * v.y());
      return point ? Eigen::Vector2d(scale * w) : w;
    };
    Eigen::Vector3d origin(200 * unit(rng) - 100, 200 * unit(rng) - 100, 0), e1(1, 0, 0), e2(0, 1, 0);
    if (k % 2 == 1) {  // a random plane of space
      origin.z() = 200 * unit(rng) - 100;
      std::normal_distribution<double> normal;
      const Eigen::Quaterniond qr = Eigen::Quaterniond(normal(rng), normal(rng), normal(rng), normal(rng)).normalized();
      e1 = qr * e1;
      e2 = qr * e2;
    }
    auto lift = [&](const Eigen::Vector2d& v) { return Eigen::Vector3d(v.x() * e1 + v.y() * e2); };
    e.p0 = origin + lift(place(q0, true));
    e.p1 = origin + lift(place(q1, true));
    e.t0 = (0.1 + 10 * unit(rng)) * lift(place(d0, false));
    e.t1 = (0.1 + 10 * unit(rng)) * lift(place(d1, false));
    out.push_back(e);
  }
  return out;
}

}  // namespace fairsplines::test
