// Fixtures shared by the blending tests (shapes and surfaces).
#pragma once
#include <Eigen/Geometry>
#include <cmath>
#include <initializer_list>

#include <gp_Pnt.hxx>

#include "fairsplines/blend_shapes.hpp"

namespace fairsplines::test::blend {

inline const double kPi = std::acos(-1.0);

inline Eigen::VectorXd vec(std::initializer_list<double> v) {
  Eigen::VectorXd out(static_cast<Eigen::Index>(v.size()));
  Eigen::Index i = 0;
  for (double x : v) out[i++] = x;
  return out;
}

/// A full turn, strongly non-uniform.
inline Eigen::VectorXd nonUniformTurn() { return vec({0.0, 0.4, 1.5, 2.1, 3.9, 4.3, 5.2, 2 * kPi}); }

/// A frame tilted against every coordinate axis.
inline ShapeFrame tilted() {
  ShapeFrame f;
  f.origin << 1.0, -2.0, 0.5;
  f.x = Eigen::Vector3d(1, 1, 0).normalized();
  f.y = Eigen::Vector3d(-1, 1, 1).normalized();
  f.z = f.x.cross(f.y);
  return f;
}

/// A point in the frame's coordinates (x, y across the axis, z along it).
inline Eigen::Vector3d localOf(const ShapeFrame& f, const gp_Pnt& q) {
  const Eigen::Vector3d d = Eigen::Vector3d(q.X(), q.Y(), q.Z()) - f.origin;
  return {d.dot(f.x), d.dot(f.y), d.dot(f.z)};
}

}  // namespace fairsplines::test::blend
