// Basic curves from fuzz bytes, shared by fuzz_basic_curves and fuzz_design: every kind
// of basic_curves.hpp (line, circle, ellipse, parabola, hyperbola, rational Bézier,
// Archimedean spiral, involute) and a ParametricCurve of a cubic polynomial (any curve the
// Python API accepts as a function). The constructors may throw InputError (the caller
// guards them).
#pragma once
#include <memory>
#include <string>

#include <Eigen/Geometry>

#include "fairsplines/basic_curves.hpp"
#include "fuzz_check.hpp"
#include "fuzz_input.hpp"

namespace fairsplines::fuzz {

/// A placement: mostly a rotation of the standard frame (orthonormal) at any origin,
/// sometimes raw directions (which Frame::check must refuse or accept).
inline Frame basicFrame(FuzzInput& in) {
  Frame f;
  if (in.byte() < 64) f.origin = in.vector3();
  if (in.byte() < 200) {
    const double a = in.number(), b = in.number();  // rotation about z, then about x
    const Eigen::Matrix3d rotation =
        (Eigen::AngleAxisd(b, Eigen::Vector3d::UnitX()) * Eigen::AngleAxisd(a, Eigen::Vector3d::UnitZ()))
            .toRotationMatrix();
    if (rotation.allFinite()) {
      f.x = rotation.col(0);
      f.y = rotation.col(1);
    }
  } else {
    f.x = in.vector3();
    f.y = in.vector3();
  }
  return f;
}

/// One basic curve; `kind` receives its name for the report.
inline std::unique_ptr<BasicCurve> basicCurve(FuzzInput& in, std::string& kind) {
  const int which = in.choice(9);
  const Frame f = basicFrame(in);
  const double a = in.number(), b = in.number(), c = in.number(), d = in.number();
  note("curve frame origin", f.origin);
  note("curve frame x", f.x);
  note("curve frame y", f.y);
  note("curve numbers (a, b, c, d)", Eigen::Vector4d(a, b, c, d));
  switch (which) {
    case 0: {
      kind = "lineSegment(p0, p1)";
      const Eigen::Vector3d p0 = in.vector3(), p1 = in.vector3();
      note("p0", p0);
      note("p1", p1);
      return lineSegment(p0, p1);
    }
    case 1:
      kind = "CircleArc(frame, radius a, start b, sweep c)";
      return std::make_unique<CircleArc>(f, a, b, c);
    case 2:
      kind = "ellipseArc(frame, a, b, start c, sweep d)";
      return ellipseArc(f, a, b, c, d);
    case 3:
      kind = "parabolaArc(frame, focal a, t0 b, t1 c)";
      return parabolaArc(f, a, b, c);
    case 4:
      kind = "hyperbolaArc(frame, a, b, t0 c, t1 d)";
      return hyperbolaArc(f, a, b, c, d);
    case 5:
      kind = "archimedeanSpiral(frame, a, b, theta0 c, theta1 d)";
      return archimedeanSpiral(f, a, b, c, d);
    case 6:
      kind = "circleInvolute(frame, r a, t0 b, t1 c)";
      return circleInvolute(f, a, b, c);
    case 7: {
      kind = "RationalBezierCurve(homogeneous)";
      HomogeneousBezier h(in.count(1, 5), 4);
      for (Eigen::Index i = 0; i < h.rows(); ++i) {
        for (int j = 0; j < 3; ++j) h(i, j) = in.number();
        h(i, 3) = in.byte() < 128 ? 1.0 : in.number();
        if (h(i, 3) != 1.0) h.row(i).head<3>() *= h(i, 3);  // mostly w p, w for points p
      }
      note("homogeneous", h);
      return std::make_unique<RationalBezierCurve>(h);
    }
    default: {
      kind = "ParametricCurve(cubic polynomial, s0 a, s1 b)";
      Eigen::Matrix<double, 4, 3> coefficients;  // f(s) = sum_k coefficients.row(k) s^k
      for (int k = 0; k < 4; ++k)
        for (int j = 0; j < 3; ++j) coefficients(k, j) = in.byte() < 96 ? 0.0 : in.number();
      note("polynomial coefficients (row k: s^k)", coefficients);
      auto jet = [coefficients](double s, Eigen::Vector3d& p, Eigen::Vector3d& dp, Eigen::Vector3d& d2p) {
        p = coefficients.row(0).transpose() +
            s * (coefficients.row(1).transpose() +
                 s * (coefficients.row(2).transpose() + s * coefficients.row(3).transpose()));
        dp = coefficients.row(1).transpose() +
             s * (2 * coefficients.row(2).transpose() + 3 * s * coefficients.row(3).transpose());
        d2p = 2 * coefficients.row(2).transpose() + 6 * s * coefficients.row(3).transpose();
      };
      return std::make_unique<ParametricCurve>(jet, a, b);
    }
  }
}

}  // namespace fairsplines::fuzz
