// Basic shapes of revolution from fuzz bytes, shared by fuzz_blend_shapes and
// fuzz_blend_surface: frames, angle partitions (mostly a full turn: the blends need one),
// latitudes, heights and tube angles.
#pragma once
#include <Eigen/Geometry>

#include "fairsplines/blend_shapes.hpp"
#include "fairsplines/blend_surface.hpp"
#include "fuzz_check.hpp"
#include "fuzz_input.hpp"

namespace fairsplines::fuzz {

/// Mostly a rotated right-handed orthonormal frame at any origin; sometimes raw axes
/// (ShapeFrame::check must refuse them).
inline ShapeFrame shapeFrame(FuzzInput& in) {
  ShapeFrame f;
  if (in.byte() < 64) f.origin = in.vector3();
  if (in.byte() < 224) {
    if (in.byte() < 128) {
      const Eigen::Vector3d axis = in.vector3().normalized();
      const double angle = in.number();
      const Eigen::Matrix3d rotation = Eigen::Matrix3d(Eigen::AngleAxisd(angle, axis));
      if (rotation.allFinite()) {
        f.x = rotation.col(0);
        f.y = rotation.col(1);
        f.z = f.x.cross(f.y);  // as the bindings do
      }
    }
  } else {
    f.x = in.vector3();
    f.y = in.vector3();
    f.z = in.byte() < 128 ? f.x.cross(f.y) : in.vector3();
  }
  return f;
}

/// Angles theta_0 < ... < theta_n: mostly a full turn from any start in 1..maxArcs arcs of
/// any relative sizes (theta_n = theta_0 + 2 pi exactly), sometimes a partial range or any
/// numbers.
inline Eigen::VectorXd turnAngles(FuzzInput& in, int maxArcs) {
  const int arcs = in.count(1, maxArcs);
  const double start = in.byte() < 160 ? 0.0 : in.number();
  const int how = in.byte();
  if (how < 200) {  // a full turn
    Eigen::VectorXd theta(arcs + 1);
    Eigen::VectorXd cumulative = Eigen::VectorXd::LinSpaced(arcs + 1, 0.0, 1.0);
    if (in.flag()) cumulative = in.increasing(arcs + 1);  // arcs of any relative sizes
    for (int i = 0; i <= arcs; ++i) theta[i] = start + 2 * M_PI * cumulative[i] / cumulative[arcs];
    theta[arcs] = start + 2 * M_PI;
    return theta;
  }
  if (how < 240) return in.increasing(arcs + 1, start);  // a partial range, maybe more than a turn
  return in.numbers(arcs + 1);
}

/// Latitudes in [-pi/2, pi/2], increasing, 2..maxValues of them (sometimes reaching a pole),
/// or any numbers.
inline Eigen::VectorXd latitudes(FuzzInput& in, int maxValues) {
  const int n = in.count(2, maxValues);
  if (in.byte() < 224) {
    const double lo = in.byte() < 32 ? -M_PI / 2 : -M_PI / 2 + M_PI * in.unit();
    const double hi = in.byte() < 32 ? M_PI / 2 : lo + (M_PI / 2 - lo) * in.unit();
    const Eigen::VectorXd c = in.increasing(n);
    Eigen::VectorXd v(n);
    for (int i = 0; i < n; ++i) v[i] = lo + (hi - lo) * c[i] / c[n - 1];
    v[n - 1] = hi;
    return v;
  }
  return in.numbers(n);
}

/// Increasing values (heights, tube angles) from any start, 2..maxValues of them.
inline Eigen::VectorXd profileValues(FuzzInput& in, int maxValues) {
  const int n = in.count(2, maxValues);
  if (in.byte() < 224) {
    const double start = in.byte() < 128 ? 0.0 : in.number();
    const double scale = in.byte() < 192 ? 0.25 : in.number();
    Eigen::VectorXd v = in.increasing(n) * scale;
    v.array() += start;
    return v;
  }
  return in.numbers(n);
}

inline CircleReparam reparam(FuzzInput& in) { return static_cast<CircleReparam>(in.choice(3)); }

/// A shape of revolution for the joins: a sphere zone, cone (cylinder) or torus zone.
inline ShapeOfRevolution shapeOfRevolution(FuzzInput& in, int maxArcs, const Eigen::VectorXd* around = nullptr) {
  ShapeOfRevolution s;
  s.kind = static_cast<ShapeOfRevolution::Kind>(in.choice(3));
  s.frame = shapeFrame(in);
  s.around = around && in.byte() < 224 ? *around : turnAngles(in, maxArcs);
  switch (s.kind) {
    case ShapeOfRevolution::Kind::SphereZone:
      s.size0 = in.positive();
      s.profile = latitudes(in, 4);
      break;
    case ShapeOfRevolution::Kind::Cone:
      s.size0 = in.positive();
      s.size1 = in.byte() < 96 ? 0.0 : in.number() / 4;
      s.profile = profileValues(in, 4);
      break;
    case ShapeOfRevolution::Kind::Torus:
      s.size0 = in.positive() + 1.0;
      s.size1 = in.byte() < 192 ? s.size0 * in.unit() : in.number();
      s.profile = profileValues(in, 4);
      break;
  }
  return s;
}

inline void noteShape(const char* name, const ShapeOfRevolution& s) {
  note(name, std::string(s.kind == ShapeOfRevolution::Kind::SphereZone ? "sphere zone"
                         : s.kind == ShapeOfRevolution::Kind::Cone     ? "cone"
                                                                       : "torus"));
  note("  frame origin", s.frame.origin);
  note("  frame x", s.frame.x);
  note("  frame y", s.frame.y);
  note("  frame z", s.frame.z);
  note("  size0", s.size0);
  note("  size1", s.size1);
  note("  around", s.around);
  note("  profile", s.profile);
}

inline void requireFiniteComplex(const char* call, const BlendComplex& c) {
  requireFinite(call, "u knot", c.knotsU);
  requireFinite(call, "v knot", c.knotsV);
  for (const TaggedPatch& p : c.patches) requireFinite(call, "patch control point", p.bezier);
  if (c.patches.empty()) fail(call, "a blend complex without patches");
}

}  // namespace fairsplines::fuzz
