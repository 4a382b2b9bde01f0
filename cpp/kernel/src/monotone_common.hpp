// Internal: what the sources of the monotone paper (Karčiauskas & Peters, curves of
// monotone curvature) share: 2D and 3D vectors, numbers for messages, a curve in its
// plane (monotone_certificate.cpp) and the fair location of Fig. 3 (monotone_design.cpp).
#pragma once
#include <Eigen/Core>
#include <iomanip>
#include <sstream>
#include <string>

#include "fairsplines/monotone.hpp"
#include "fairsplines/types.hpp"

namespace fairsplines::detail {

// ---------------------------------------------------------------------------------------
// Vectors and numbers

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
constexpr double kPi = 3.14159265358979323846;

inline double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }
inline double degrees(double radians) { return radians * 180.0 / kPi; }

inline std::string num(double v, int digits = 4) {
  std::ostringstream out;
  out << std::setprecision(digits) << v;
  return out.str();
}

// ---------------------------------------------------------------------------------------
// A curve in its plane, and the certificate on it (monotone_certificate.cpp)

/// Planar data of a curve: 2D poles in the plane basis, weights, flat knots.
struct PlanarCurve {
  PointMatrix poles;  // n x 2
  Eigen::VectorXd weights;
  Eigen::VectorXd flat;
  int degree = 3;
  bool closed = false;  // periodic: the seam is a joint too
  Vec3 normal = Vec3::UnitZ();
  double scale = 1.0;  // poles = (model poles - first pole) / scale, a power of two (exact)
};

/// The planar data of a valid curve: its poles in an orthonormal basis of its plane (the
/// first pole at the origin, divided by `scale`), weights and flat knots; a periodic curve
/// as a non-periodic copy over one period. Throws InputError for an invalid curve
/// (requireValidCurve), a curve that does not move (its poles coincide to double precision)
/// or a 3D curve whose poles do not lie in one plane.
PlanarCurve planarCurve(const BSplineCurve& input);

/// The exact certificate of a planar curve (coefficients of kappa' in Bernstein form and
/// subdivision), relTol as certifyMonotoneCurvature's. Throws InputError if the curve has
/// no non-empty knot span.
MonotonicityCertificate certifyPlanar(const PlanarCurve& curve, double relTol);

// ---------------------------------------------------------------------------------------
// The fair location of Fig. 3 (monotone_design.cpp)

/// Is q in the fair location of A (= C^2_{j-3}) and D (= C^1_{j-2}), up to slack (squared length)?
bool inFairLocation(const Vec2& q, const Vec2& A, const Vec2& D, double slack);

}  // namespace fairsplines::detail

namespace fairsplines {

// The monotone sources use the shared names unqualified.
using detail::cross;
using detail::degrees;
using detail::kPi;
using detail::num;
using detail::Vec2;
using detail::Vec3;

}  // namespace fairsplines
