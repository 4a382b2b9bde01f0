// Basic shapes as G2 rational bi-cubic splines: Karčiauskas & Peters, "Free-Form Splines
// Combining NURBS and Basic Shapes", Section 2, eqs. (1)-(4). Every shape is a tensor
// product, in homogeneous form, of the G2 rational cubic circle pieces of eq. (2) (around
// the axis) with a rational cubic profile (docs/READINGS.md, "blending paper").
#pragma once
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Geom_BSplineSurface.hxx>

#include "fairsplines/types.hpp"

namespace fairsplines {

/// Homogeneous points of a plane curve: rows (w x, w y, w).
using Homogeneous3 = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;
/// Homogeneous points in space: rows (w x, w y, w z, w).
using Homogeneous4 = Eigen::Matrix<double, Eigen::Dynamic, 4, Eigen::RowMajor>;

/// The unit circle (or an arc of it) as G2-joined rational cubic pieces, eq. (2): piece i
/// runs from angle theta_i to theta_{i+1}, opening alpha_i = theta_{i+1} - theta_i, with
/// weights 1, w_i, w_i, 1 and w_i = 1/3 + 2/3 cos(alpha_i / 2) (the degree-raised conic).
struct G2CircleSpline {
  Eigen::VectorXd theta;  ///< theta_0 < ... < theta_n (radians)
  Eigen::VectorXd alpha;  ///< alpha_i, n values
  Eigen::VectorXd w;      ///< w_i of eq. (2), n values
  /// beta_i, gamma_i of eqs. (3)-(4) between piece i-1 and piece i, index i = 0..n-1;
  /// index 0 is the closing join (last piece to first) of a closed circle, else beta 1, gamma 0.
  Eigen::VectorXd beta, gamma;
  bool closed = false;  ///< theta_n - theta_0 = 2 pi
  Homogeneous3 cubic;   ///< 4 n rows: homogeneous Bézier points of piece i at rows 4 i .. 4 i + 3

  int pieces() const { return static_cast<int>(alpha.size()); }
  /// The rational quadratic (conic) of piece i, 3 homogeneous rows (weights 1, cos(alpha_i/2), 1);
  /// piece i is its exact degree raise.
  /// Throws nothing; i must be a piece (0 <= i < pieces(), not checked).
  Homogeneous3 quadratic(int i) const;
};

/// Eq. (2) for a partition theta_0 < ... < theta_n of (part of) the unit circle. The circle
/// is closed when theta_n - theta_0 = 2 pi (within 1e-12). Throws InputError for fewer
/// than two angles, non-finite or non-increasing angles (naming the index), an arc that
/// is 4 pi / 3 or more (its weight w would not be positive), or a span above 2 pi.
G2CircleSpline g2Circle(const Eigen::VectorXd& theta);

/// Eqs. (3)-(4): beta_i = sin(alpha_i/2) / sin(alpha_{i-1}/2),
/// gamma_i = 2 beta_i (tan(alpha_{i-1}/4) + tan(alpha_i/4)) sin(alpha_i/2).
/// Throws nothing; expects openings 0 < alpha < 4 pi / 3 (as g2Circle checks).
void circleScalars(double alphaPrev, double alpha, double& beta, double& gamma);

/// Orthonormal frame of a shape: origin and axes; z is the axis of revolution.
struct ShapeFrame {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d x = Eigen::Vector3d::UnitX(), y = Eigen::Vector3d::UnitY(), z = Eigen::Vector3d::UnitZ();
  /// Throws InputError unless the axes are unit and pairwise orthogonal (1e-9) and right-handed.
  void check() const;
};

/// A rational bi-cubic G2 spline surface: nu x nv Bézier patches in homogeneous form, with
/// the scalars of geometric continuity across the seams. This is the editable control
/// structure (points, weights, scalars): change `bezier` rows (w p, w);
/// the scalars then describe the intended joins (the tests check them by OCCT evaluation).
struct G2Surface {
  int nu = 0, nv = 0;  ///< patches in u (around the axis) and in v (along the profile)
  /// 16 nu nv rows: homogeneous Bézier point b_rs (r in u, s in v) of patch (I, J) at row
  /// (I nv + J) 16 + 4 r + s.
  Homogeneous4 bezier;
  /// Seam scalars of eqs. (3)-(4) in u: index I is the seam at the start of patch column I
  /// (I = 0: the closing seam of a closed surface, else 1 and 0). Likewise in v.
  Eigen::VectorXd betaU, gammaU, betaV, gammaV;
  bool closedU = false, closedV = false;

  auto point(int I, int J, int r, int s) { return bezier.row((I * nv + J) * 16 + 4 * r + s); }
  auto point(int I, int J, int r, int s) const { return bezier.row((I * nv + J) * 16 + 4 * r + s); }
  /// Sets b_rs of patch (I, J) from a point and its weight. Throws InputError for a
  /// non-positive weight or an index out of range.
  void setControl(int I, int J, int r, int s, const Eigen::Vector3d& p, double weight);
};

/// Surface of revolution of a G2 rational cubic profile (homogeneous rows (w rho, w zeta, w):
/// distance from the axis and height) about frame.z, with the circle partition in u. The
/// tensor form of docs/READINGS.md: b_rs = (rho_s x_r, rho_s y_r, zeta_s w_r, omega_s w_r) in the
/// frame. `profileBeta`/`profileGamma` follow the layout of G2Surface::betaV.
/// Throws InputError for a frame ShapeFrame::check refuses, a profile that is not 4 rows per
/// piece (at least one piece), profileBeta or profileGamma not one per piece, a profile weight
/// that is not positive, or a surface whose points are not finite.
G2Surface revolveG2(const ShapeFrame& frame, const Homogeneous3& profile, const Eigen::VectorXd& profileBeta,
                    const Eigen::VectorXd& profileGamma, bool profileClosed, const G2CircleSpline& circle);

/// Sphere zone or dome: longitudes (u, around frame.z) and latitudes (v, in [-pi/2, pi/2],
/// increasing; a latitude of +-pi/2 gives a dome with a pole). Throws InputError for a
/// non-positive radius or latitudes outside [-pi/2, pi/2] (besides g2Circle's checks).
G2Surface sphereZone(const ShapeFrame& frame, double radius, const Eigen::VectorXd& longitudes,
                     const Eigen::VectorXd& latitudes);
/// Circular cylinder of the given radius, angles in u and increasing heights z_j in v.
/// Throws InputError for a radius that is not positive and finite, and as cone does (heights,
/// angles, frame).
G2Surface cylinder(const ShapeFrame& frame, double radius, const Eigen::VectorXd& angles,
                   const Eigen::VectorXd& heights);
/// Cone with radius r(z) = radius0 + slope z at height z (frame coordinates), heights in v.
/// Throws InputError where r(z) <= 0 at a height (the apex is excluded).
G2Surface cone(const ShapeFrame& frame, double radius0, double slope, const Eigen::VectorXd& angles,
               const Eigen::VectorXd& heights);
/// Torus with major radius R and minor radius r < R: angles u about frame.z, angles v
/// around the tube (0 = outer equator). Throws InputError unless 0 < r < R.
G2Surface torus(const ShapeFrame& frame, double R, double r, const Eigen::VectorXd& anglesU,
                const Eigen::VectorXd& anglesV);

/// The profile of a surface of revolution of any designed curve (issue 32): a rational cubic
/// spline (a B-spline of degree <= 3, rational or not: a design spline, a conic arc, a
/// quadratic spline raised to cubic) in a half-plane bounded by the axis.
struct RevolutionProfile {
  /// origin on the axis, z the axis, x the direction of the profile's half-plane (angle 0)
  ShapeFrame frame;
  /// 4 homogeneous Bézier rows per piece, (w rho, w zeta, w): distance from the axis and
  /// height; the B-spline's own weights, so that its joins keep their homogeneous continuity
  Homogeneous3 cubic;
  Eigen::VectorXd knots;  ///< pieces + 1 increasing parameters (the curve's distinct knots)
  int pieces() const { return static_cast<int>(cubic.rows() / 4); }
};

/// The profile of a curve about the axis through `origin` along `axis`: raised to degree 3,
/// the parameters `splits` (inside its range) inserted as knots, split into its Bézier
/// pieces exactly (knot insertion). Throws InputError naming the
/// problem for a curve OCCT would refuse (poles, weights or knots not finite, ...), a degree
/// above 3, a periodic (closed) curve, an axis that is not a finite non-zero direction, a
/// curve not in one plane through the axis (naming the pole off it), a curve that touches
/// or crosses the axis (naming where), or a split outside the curve's range.
RevolutionProfile revolutionProfile(const BSplineCurve& curve, const Eigen::Vector3d& origin,
                                    const Eigen::Vector3d& axis, const Eigen::VectorXd& splits = {});

/// The profile revolved about its frame's z (eq. (2) around the axis, the profile's pieces
/// along it): patches exactly on the surface of revolution. Profile scalars beta_j = the knot
/// ratios h_j / h_{j-1}, gamma_j = 0 (exact at the profile's homogeneous C2 joins).
/// Throws InputError for angles g2Circle refuses, or as revolveG2.
G2Surface revolution(const RevolutionProfile& profile, const Eigen::VectorXd& angles);

/// Dupin ring cyclide (the paper's "generalized tori", Section 2) in the frame's coordinates:
///   x = (mu (c - a cos u cos v) + b^2 cos u) / D, y = b sin u (a - mu cos v) / D,
///   z = b sin v (c cos u - mu) / D, D = a - c cos u cos v, b^2 = a^2 - c^2,
/// implicitly (x^2 + y^2 + z^2 - mu^2 + b^2)^2 = 4 (a x - c mu)^2 + 4 b^2 y^2 (c = 0: the
/// torus of radii a and mu about the frame's z). Both families of curvature lines (u and v
/// constant) are circles; bilinear in the two circles' homogeneous points, so patch (I, J)
/// is the exact bicubic of the eq. (2) pieces of anglesU[I..I+1] and anglesV[J..J+1]. Seam
/// scalars: the circles' beta (exact after the linear map); gamma: the circles' (the
/// cyclide's projected gamma differ). Throws InputError for parameters that are not finite,
/// a > c >= 0 failing (no real surface), mu outside (c, a) (singular: spindle or horn
/// cyclide), a control weight that is not positive (arcs too wide for c / a near 1), or the
/// angle checks of g2Circle.
G2Surface dupinCyclide(const ShapeFrame& frame, double a, double c, double mu, const Eigen::VectorXd& anglesU,
                       const Eigen::VectorXd& anglesV);

/// The homogeneous rows (w p, w) under the affine map p -> A p + t: (A (w p) + w t, w). Every
/// construction of the blends is linear in homogeneous coordinates, so it commutes with this
/// map (docs/BLENDING.md): the image of a sphere zone is an ellipsoid zone, exactly.
/// Throws InputError for a map that is not finite or not invertible.
Homogeneous4 affineImage(const Homogeneous4& rows, const Eigen::Matrix3d& A, const Eigen::Vector3d& t);

/// The homogeneous rows under the projective map (w p, w) -> M (w p, w) (a linear map of
/// homogeneous space, so the blends commute with it as with affine maps). The paper's
/// recipe of Section 2 in one line: the hyperbolic cylinder x^2/a^2 - y^2/b^2 = 1 is
/// (a, b sin t | cos t) = M (cos t, sin t | 1) times the heights, i.e. the image of a
/// circular cylinder's partial turn (|t| < pi/2) under (X, Y, Z, W) -> (a W, b Y, Z, X).
/// Throws InputError for a map that is not finite or not invertible, or a row whose weight
/// becomes <= 0 (the row's point would go to infinity or beyond), naming the row.
Homogeneous4 projectiveImage(const Homogeneous4& rows, const Eigen::Matrix4d& M);

/// Patch (I, J) as an exact rational Bézier Geom_BSplineSurface over [0,1]^2.
Handle(Geom_BSplineSurface) patchToOcct(const G2Surface& surface, int I, int J);

}  // namespace fairsplines
