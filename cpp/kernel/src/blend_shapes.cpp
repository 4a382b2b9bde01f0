#include "fairsplines/blend_shapes.hpp"

#include "blend_detail.hpp"

#include <Standard_Failure.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <cmath>
#include <limits>
#include <sstream>

#include "fairsplines/errors.hpp"
#include "finite.hpp"

namespace fairsplines {

namespace detail {

void checkHeights(const Eigen::VectorXd& heights, double radius0, double slope) {
  const int m = static_cast<int>(heights.size()) - 1;
  if (m < 1) throw InputError("a profile needs at least two heights");
  for (int j = 0; j <= m; ++j) {
    if (!std::isfinite(heights[j])) {
      std::ostringstream os;
      os << "non-finite height at index " << j;
      throw InputError(os.str());
    }
    if (j > 0 && !(heights[j] > heights[j - 1])) {
      std::ostringstream os;
      os << "heights must increase: height " << j << " (" << heights[j] << ") is not greater than height " << j - 1;
      throw InputError(os.str());
    }
    if (!(radius0 + slope * heights[j] > 0)) {
      std::ostringstream os;
      os << "the radius at height " << j << " (z = " << heights[j] << ") is not positive";
      throw InputError(os.str());
    }
  }
  requireSeparateKnots(heights, "the profile's heights");
}

}  // namespace detail

namespace {

const double kPi = std::acos(-1.0);

std::string angleList(const char* what, int index) {
  std::ostringstream os;
  os << what << " " << index;
  return os.str();
}

}  // namespace

void circleScalars(double alphaPrev, double alpha, double& beta, double& gamma) {
  // Eqs. (3)-(4) for the pieces of eq. (2); checked by evaluation in the tests.
  beta = std::sin(alpha / 2) / std::sin(alphaPrev / 2);
  gamma = 2 * beta * (std::tan(alphaPrev / 4) + std::tan(alpha / 4)) * std::sin(alpha / 2);
}

Homogeneous3 G2CircleSpline::quadratic(int i) const {
  const double t0 = theta[i], a = alpha[i], c = std::cos(a / 2);
  Homogeneous3 q(3, 3);
  q.row(0) << std::cos(t0), std::sin(t0), 1.0;
  q.row(1) << std::cos(t0 + a / 2), std::sin(t0 + a / 2), c;  // c * (tangent intersection, 1)
  q.row(2) << std::cos(t0 + a), std::sin(t0 + a), 1.0;
  return q;
}

G2CircleSpline g2Circle(const Eigen::VectorXd& theta) {
  const int n = static_cast<int>(theta.size()) - 1;
  if (n < 1) throw InputError("a circle partition needs at least two angles");
  for (int i = 0; i <= n; ++i) {
    if (!std::isfinite(theta[i])) throw InputError(angleList("the partition has a non-finite angle at index", i));
  }
  for (int i = 1; i <= n; ++i) {
    if (!(theta[i] > theta[i - 1])) {
      std::ostringstream os;
      os << "angles must increase: angle " << i << " (" << theta[i] << ") is not greater than angle " << i - 1 << " ("
         << theta[i - 1] << ")";
      throw InputError(os.str());
    }
    if (theta[i] - theta[i - 1] >= 4 * kPi / 3 - 1e-12) {
      std::ostringstream os;
      os << "the arc from angle " << i - 1 << " to " << i << " opens " << theta[i] - theta[i - 1]
         << " rad: eq. (2) needs less than 4 pi / 3 for a positive weight w = 1/3 + 2/3 cos(alpha/2); split it";
      throw InputError(os.str());
    }
  }
  requireSeparateKnots(theta, "the circle partition's angles");
  const double span = theta[n] - theta[0];
  if (span > 2 * kPi + 1e-12) throw InputError("the partition spans more than a full turn (2 pi)");
  G2CircleSpline c;
  c.theta = theta;
  c.closed = std::abs(span - 2 * kPi) <= 1e-12;
  if (c.closed) c.theta[n] = theta[0] + 2 * kPi;
  c.alpha = c.theta.tail(n) - c.theta.head(n);
  c.w.resize(n);
  c.beta = Eigen::VectorXd::Ones(n);
  c.gamma = Eigen::VectorXd::Zero(n);
  c.cubic.resize(4 * n, 3);
  for (int i = 0; i < n; ++i) {
    // Eq. (2): w = 1/3 + 2/3 cos(alpha/2); the cubic is the degree raise of the conic
    // (1, c, 1), so b_1 = (b_0 + 2 c m) / (1 + 2 c) with m the tangents' intersection.
    c.w[i] = 1.0 / 3 + 2.0 / 3 * std::cos(c.alpha[i] / 2);
    const Homogeneous3 q = c.quadratic(i);
    c.cubic.row(4 * i) = q.row(0);
    c.cubic.row(4 * i + 1) = (q.row(0) + 2 * q.row(1)) / 3;
    c.cubic.row(4 * i + 2) = (2 * q.row(1) + q.row(2)) / 3;
    c.cubic.row(4 * i + 3) = q.row(2);
    if (i > 0) circleScalars(c.alpha[i - 1], c.alpha[i], c.beta[i], c.gamma[i]);
  }
  if (c.closed) circleScalars(c.alpha[n - 1], c.alpha[0], c.beta[0], c.gamma[0]);
  return c;
}

void ShapeFrame::check() const {
  auto bad = [](double v, double target) { return !(std::abs(v - target) <= 1e-9); };
  if (!origin.allFinite() || bad(x.norm(), 1) || bad(y.norm(), 1) || bad(z.norm(), 1) || bad(x.dot(y), 0) ||
      bad(x.dot(z), 0) || bad(y.dot(z), 0) || bad(x.cross(y).dot(z), 1)) {
    throw InputError("a shape frame needs a finite origin and right-handed orthonormal axes x, y, z");
  }
}

void G2Surface::setControl(int I, int J, int r, int s, const Eigen::Vector3d& p, double weight) {
  if (I < 0 || I >= nu || J < 0 || J >= nv || r < 0 || r > 3 || s < 0 || s > 3) {
    throw InputError("control point index out of range");
  }
  if (!(weight > 0) || !p.allFinite())
    throw InputError("a control point needs finite coordinates and a positive weight");
  const Eigen::Vector3d weighted = weight * p;
  if (!weighted.allFinite()) {
    throw InputError("the control point's weight " + exactNumber(weight) +
                     " is too large for its coordinates: the homogeneous point would overflow");
  }
  point(I, J, r, s) << weighted.transpose(), weight;
}

G2Surface revolveG2(const ShapeFrame& frame, const Homogeneous3& profile, const Eigen::VectorXd& profileBeta,
                    const Eigen::VectorXd& profileGamma, bool profileClosed, const G2CircleSpline& circle) {
  frame.check();
  const int m = static_cast<int>(profile.rows() / 4);
  if (m < 1 || profile.rows() != 4 * m) throw InputError("a G2 profile needs 4 homogeneous Bézier points per piece");
  if (profileBeta.size() != m || profileGamma.size() != m)
    throw InputError("a G2 profile needs one beta and gamma per piece");
  for (Eigen::Index k = 0; k < profile.rows(); ++k) {
    if (!(profile(k, 2) > 0))
      throw InputError(angleList("the profile has a non-positive weight at point", static_cast<int>(k)));
  }
  G2Surface s;
  s.nu = circle.pieces();
  s.nv = m;
  s.closedU = circle.closed;
  s.closedV = profileClosed;
  s.betaU = circle.beta;
  s.gammaU = circle.gamma;
  s.betaV = profileBeta;
  s.gammaV = profileGamma;
  s.bezier.resize(16 * s.nu * s.nv, 4);
  for (int I = 0; I < s.nu; ++I) {
    for (int J = 0; J < s.nv; ++J) {
      for (int r = 0; r < 4; ++r) {
        const auto c = circle.cubic.row(4 * I + r);  // (x w1, y w1, w1)
        for (int q = 0; q < 4; ++q) {
          const auto p = profile.row(4 * J + q);  // (rho w2, zeta w2, w2)
          // Tensor form (docs/READINGS.md, blending paper): (rho x1, rho y1, zeta w1 | omega w1) in the frame.
          const Eigen::Vector3d local = p[0] * c[0] * frame.x + p[0] * c[1] * frame.y + p[1] * c[2] * frame.z;
          const double weight = p[2] * c[2];
          s.point(I, J, r, q) << (local + weight * frame.origin).transpose(), weight;
        }
      }
    }
  }
  // The boundary rule: sizes whose surface overflows are refused here, by name.
  requireFinite(s.bezier, "the surface of revolution (its sizes are too large for double precision)",
                "homogeneous control points");
  return s;
}

namespace {

/// The latitude profile of a sphere: G2 circle pieces of eq. (2) scaled by the radius,
/// read as (distance from the axis, height).
void circleProfile(const G2CircleSpline& c, double radius, double rhoOffset, Homogeneous3& profile) {
  profile.resize(c.cubic.rows(), 3);
  for (Eigen::Index k = 0; k < c.cubic.rows(); ++k) {
    profile.row(k) << rhoOffset * c.cubic(k, 2) + radius * c.cubic(k, 0), radius * c.cubic(k, 1), c.cubic(k, 2);
  }
}

/// A straight profile from (rho0, z0) to (rho1, z1) over increasing heights: the linear
/// pieces degree-raised to cubics (weights 1); beta_j = h_j / h_{j-1}, gamma_j = 0.
void lineProfile(const Eigen::VectorXd& heights, double radius0, double slope, Homogeneous3& profile,
                 Eigen::VectorXd& beta, Eigen::VectorXd& gamma) {
  detail::checkHeights(heights, radius0, slope);
  const int m = static_cast<int>(heights.size()) - 1;
  profile.resize(4 * m, 3);
  beta = Eigen::VectorXd::Ones(m);
  gamma = Eigen::VectorXd::Zero(m);
  for (int j = 0; j < m; ++j) {
    for (int q = 0; q < 4; ++q) {
      const double z = heights[j] + (heights[j + 1] - heights[j]) * q / 3.0;
      profile.row(4 * j + q) << radius0 + slope * z, z, 1.0;
    }
    if (j > 0) beta[j] = (heights[j + 1] - heights[j]) / (heights[j] - heights[j - 1]);
  }
}

}  // namespace

G2Surface sphereZone(const ShapeFrame& frame, double radius, const Eigen::VectorXd& longitudes,
                     const Eigen::VectorXd& latitudes) {
  if (!(radius > 0) || !std::isfinite(radius)) throw InputError("a sphere needs a positive radius");
  // Its patches' affine poles reach a few radii out (the middle weights are cos(alpha/2)):
  // beyond DBL_MAX / 64 they overflow.
  if (!(radius < std::numeric_limits<double>::max() / 64.0)) {
    throw InputError("radius " + exactNumber(radius) + " is too large: the sphere's points would overflow");
  }
  for (Eigen::Index j = 0; j < latitudes.size(); ++j) {
    if (!(std::abs(latitudes[j]) <= kPi / 2 + 1e-15)) {
      throw InputError(angleList("latitudes must lie in [-pi/2, pi/2]; not so at index", static_cast<int>(j)));
    }
  }
  const G2CircleSpline lon = g2Circle(longitudes), lat = g2Circle(latitudes);
  Homogeneous3 profile;
  circleProfile(lat, radius, 0.0, profile);
  return revolveG2(frame, profile, lat.beta, lat.gamma, false, lon);
}

G2Surface cylinder(const ShapeFrame& frame, double radius, const Eigen::VectorXd& angles,
                   const Eigen::VectorXd& heights) {
  if (!(radius > 0) || !std::isfinite(radius)) throw InputError("a cylinder needs a positive radius");
  return cone(frame, radius, 0.0, angles, heights);
}

G2Surface cone(const ShapeFrame& frame, double radius0, double slope, const Eigen::VectorXd& angles,
               const Eigen::VectorXd& heights) {
  if (!std::isfinite(radius0) || !std::isfinite(slope)) throw InputError("a cone needs a finite radius and slope");
  // As for the sphere: the patches' affine poles reach a few radii out; the largest radius
  // over the heights must stay below DBL_MAX / 64 (a fuzz finding: radius0 = DBL_MAX).
  double reach = std::abs(radius0);
  for (Eigen::Index j = 0; j < heights.size(); ++j) reach = std::max(reach, std::abs(radius0 + slope * heights[j]));
  if (!(reach < std::numeric_limits<double>::max() / 64.0)) {
    throw InputError("the cone's radius reaches " + exactNumber(reach) +
                     " over its heights: too large, its points "
                     "would overflow");
  }
  const G2CircleSpline c = g2Circle(angles);
  Homogeneous3 profile;
  Eigen::VectorXd beta, gamma;
  lineProfile(heights, radius0, slope, profile, beta, gamma);
  return revolveG2(frame, profile, beta, gamma, false, c);
}

G2Surface torus(const ShapeFrame& frame, double R, double r, const Eigen::VectorXd& anglesU,
                const Eigen::VectorXd& anglesV) {
  if (!(r > 0) || !(R > r) || !std::isfinite(R)) throw InputError("a torus needs radii 0 < r < R");
  if (!(r > 1e-12 * R)) {
    throw InputError("the torus's tube radius " + exactNumber(r) + " is below the precision of its radius " +
                     exactNumber(R) + " (less than 1e-12 of it)");
  }
  const G2CircleSpline cu = g2Circle(anglesU), cv = g2Circle(anglesV);
  Homogeneous3 profile;
  circleProfile(cv, r, R, profile);  // (R + r cos v, r sin v)
  return revolveG2(frame, profile, cv.beta, cv.gamma, cv.closed, cu);
}

namespace detail {

Handle(Geom_BSplineSurface) bezierPatchToOcct(const Homogeneous4& bezier, int degreeU, int degreeV,
                                              const std::string& what) {
  const int nu = degreeU + 1, nv = degreeV + 1;
  TColgp_Array2OfPnt poles(1, nu, 1, nv);
  TColStd_Array2OfReal weights(1, nu, 1, nv);
  for (int a = 0; a < nu; ++a) {
    for (int b = 0; b < nv; ++b) {
      const auto h = bezier.row(a * nv + b);
      requireFinite(h, what, "homogeneous control points");
      if (!(h[3] > 0)) throw InputError("a patch has a non-positive weight");
      const gp_Pnt pole(h[0] / h[3], h[1] / h[3], h[2] / h[3]);
      if (!std::isfinite(pole.X()) || !std::isfinite(pole.Y()) || !std::isfinite(pole.Z())) {
        throw InputError(what +
                         ": its poles are not finite (a small weight divides a large homogeneous point): "
                         "the input is too large for double precision");
      }
      poles.SetValue(a + 1, b + 1, pole);
      weights.SetValue(a + 1, b + 1, h[3]);
    }
  }
  TColStd_Array1OfReal knots(1, 2);
  knots.SetValue(1, 0.0);
  knots.SetValue(2, 1.0);
  TColStd_Array1OfInteger multsU(1, 2), multsV(1, 2);
  multsU.Init(nu);
  multsV.Init(nv);
  try {
    return new Geom_BSplineSurface(poles, weights, knots, knots, multsU, multsV, degreeU, degreeV);
  } catch (const Standard_Failure& failure) {
    throw InputError(std::string("OpenCASCADE rejected the patch: ") + failure.GetMessageString());
  }
}

}  // namespace detail

Handle(Geom_BSplineSurface) patchToOcct(const G2Surface& surface, int I, int J) {
  if (I < 0 || I >= surface.nu || J < 0 || J >= surface.nv) throw InputError("patch index out of range");
  // Row 4 r + s of the patch's 16 rows is b_rs: degree (3, 3) in the layout of bezierPatchToOcct.
  return detail::bezierPatchToOcct(
      surface.bezier.middleRows((I * surface.nv + J) * 16, 16), 3, 3,
      "the patch (" + std::to_string(I + 1) + ", " + std::to_string(J + 1) + ") of the shape");
}

}  // namespace fairsplines
