// Basic shape to biquadratic C1 NURBS with a (4,2) double transition strip: Karčiauskas &
// Peters, "Free-Form Splines Combining NURBS and Basic Shapes", Section 5 ("Combining NURBS
// and G1 splines"), with the quadratic reparameterization eta of Appendix 7.3 (g1_to_c1.hpp).
// Shapes of revolution (sphere zone, cylinder/cone, torus zone) as G1 rational biquadratic
// splines of the [KP11a] kind, joined at the end of their profile over a full turn.
#pragma once
#include <Geom_BSplineSurface.hxx>
#include <vector>

#include "fairsplines/blend_shapes.hpp"
#include "fairsplines/blend_surface.hpp"

namespace fairsplines {

/// A shape of revolution as a G1 rational biquadratic spline ([KP11a]): around the axis the
/// circle partition as rational quadratic arcs (g1Circle: weights 1, cos(alpha/2), 1), along
/// the profile rational quadratic pieces in the (distance from the axis, height) plane
/// (circle arcs for a sphere or torus zone, lines degree-raised to 2 for a cylinder/cone).
/// Patch (i, j) is the tensor product of arc i and profile piece j (revolveRows).
struct G1RevolvedShape {
  ShapeFrame frame;
  Eigen::VectorXd theta;              ///< angles around the axis (arc i: theta[i] .. theta[i+1])
  PointMatrix circle;                 ///< 3 homogeneous rows (x w, y w, w) per arc, unit circle
  Eigen::VectorXd beta;               ///< G1 scalars around the axis (beta[i] between arcs i-1 and i)
  bool closedU = false;               ///< a full turn
  std::vector<Homogeneous3> profile;  ///< 3 rows (rho w, zeta w, w) per profile piece
  Eigen::VectorXd profileBeta;        ///< G1 scalars of the profile (beta[j] between j-1 and j)
  bool profileIsLine = false;         ///< lines: the profile is C1 over profileKnots as it is
  /// a Revolution's rational cubic profile (issue 32): its pieces kept as they are (degree 3
  /// in v, never converted by eq. (12)); profileIsLine tells whether they join C1
  bool profileIsCurve = false;
  Eigen::VectorXd profileKnots;         ///< lines: the heights (from 0); circles: 0, 1, ..., m
  Eigen::Vector2d end, tangent;         ///< (rho, zeta) at the profile's end, unit direction leaving it
  double size = 1.0;                    ///< length of the last profile piece (for the default ring)
  Eigen::Vector2d start, startTangent;  ///< the same at the profile's start (direction leaving it backwards)
  double startSize = 1.0;
  int piecesU() const { return static_cast<int>(circle.rows() / 3); }
  int piecesV() const { return static_cast<int>(profile.size()); }
  /// The biquadratic patch of arc i and profile piece j (role Basic, degree (2,2)).
  /// Throws InputError ("no such patch") unless 0 <= i < piecesU() and 0 <= j < piecesV().
  TaggedPatch patch(int i, int j) const;
};

/// Sphere zone (radius, longitudes around z, latitudes in [-pi/2, pi/2] increasing).
/// Throws InputError for a non-positive radius, non-increasing angles or an arc of pi or more
/// (its weight cos(alpha/2) would not be positive; the message names the arc).
G1RevolvedShape g1SphereZone(const ShapeFrame& frame, double radius, const Eigen::VectorXd& longitudes,
                             const Eigen::VectorXd& latitudes);
/// Cone of radius radius0 + slope z (a cylinder for slope 0) over increasing heights.
/// Throws InputError where the radius is not positive at a height.
G1RevolvedShape g1Cone(const ShapeFrame& frame, double radius0, double slope, const Eigen::VectorXd& angles,
                       const Eigen::VectorXd& heights);
/// Torus zone: major radius R, tube radius r (0 < r < R), anglesV an open range around the
/// tube (0 = outer equator). Throws InputError for radii out of range.
G1RevolvedShape g1Torus(const ShapeFrame& frame, double R, double r, const Eigen::VectorXd& anglesU,
                        const Eigen::VectorXd& anglesV);

/// The same shape with its profile run backwards (pieces, Bézier rows, scalars and knots
/// mirrored), so that its start becomes the end where blendC1 joins (a dome's bottom).
/// Throws nothing.
G1RevolvedShape reversedProfile(const G1RevolvedShape& shape);

/// Choices of the Section 5 construction.
struct C1BlendOptions {
  /// New continuity scalars around the axis (betaT[i] between arcs i-1 and i); empty: beta,
  /// the paper's heuristic betaT = beta. Their product over the full turn must be 1.
  Eigen::VectorXd betaT;
  /// Convert the profile too (eq. (12) along the profile as well): basic patches (4,4), the
  /// whole complex C1 in both directions, so that singleSurface(complex, tol, 1) exists for
  /// sphere and torus zones (lines are C1 along the profile as they are).
  bool quarticInV = false;
  /// Negative control, not for use: the quadratic arcs are only split at their middle and
  /// degree-raised to 4 (no eta of Appendix 7.3). Joins G1 only, across arcs.
  bool withoutEta = false;
};

/// Arc-level knots of eq. (12) around the axis: T_0 = 0, T_1 = 1, intervals in the ratios
/// betaT (T_{i+1} - T_i = betaT_i (T_i - T_{i-1})); each arc is two quartics of half its
/// interval. These are the u knots (one period, or the span of a partial turn) a free-form
/// ring must have. Throws InputError for an arc of pi or more, or betaT that are not
/// positive or (full turn) do not multiply to 1 around the turn.
Eigen::VectorXd ringKnotsC1(const Eigen::VectorXd& angles, const Eigen::VectorXd& betaT = Eigen::VectorXd());

/// The default biquadratic free-form ring continuing the shape beyond its profile's end:
/// periodic in u over `knotsU` (one pole per arc, at the arc's tangent intersection, weights
/// 1; a partial turn: clamped, with end poles on the circle at its first and last angle),
/// clamped in v with one span of 3 rows along the profile's end tangent, starting half
/// the last piece's length beyond the interface, a quarter of it apart. Throws InputError if
/// the ring would reach the axis or knotsU does not have one value per arc plus one.
Handle(Geom_BSplineSurface) defaultRingC1(const G1RevolvedShape& shape, const Eigen::VectorXd& knotsU);

/// Section 5 for a shape of revolution over a full turn or part of one (issue 15), joined at
/// the end of its profile
/// to `ring` (null: defaultRingC1 on ringKnotsC1). Steps:
/// 1. around the axis every quadratic arc becomes the two C1 quartics of eq. (12) (g1ToC1
///    with betaT), so the basic patches are (4,2) (or (4,4), quarticInV) and stay exactly
///    on the shape;
/// 2. the ring (periodic biquadratic in u on the knots of ringKnotsC1, clamped in v, first
///    row where the strip ends) gets the half-arc knots and is raised to degree 4 in u;
/// 3. a double-patch-wide strip of degree (4,2) interpolates the first-order Hermite data
///    (two layers) of both sides: the lower row takes the basic side's, the upper row the
///    ring's, the shared centre line is the average of the two inner layers (the double
///    strip is C1 with equal v-intervals).
/// Output: patches tagged basic / transition / free-form, knotsU (2 pieces per arc),
/// knotsV (basic rows, two strip rows of the top basic row's length, ring rows), smoothness
/// 1, rowsTransition 2. basicC2InV reports whether the basic rows join C1 across v too.
/// Throws InputError for an interface on the axis (a pole), an arc of pi or more, bad betaT,
/// or a ring that does not match ("the free-form net does not match the
/// interface: ...").
BlendComplex blendC1(const G1RevolvedShape& shape, Handle(Geom_BSplineSurface) ring = nullptr,
                     const C1BlendOptions& options = C1BlendOptions());

/// The G1 biquadratic form of a shape of revolution described for the joins.
/// Throws the InputError of g1SphereZone, g1Cone or g1Torus for the shape's kind.
G1RevolvedShape g1Shape(const ShapeOfRevolution& shape);

/// A Revolution (issue 32) in the G1 model: the quadratic arcs of g1Circle around the axis,
/// the profile's rational cubic pieces along it (basic patches (2,3), (4,3) after eq. (12)).
/// Throws InputError for angles g1Circle refuses (an arc of pi or more) or a bad profile.
G1RevolvedShape g1Revolution(const ShapeFrame& frame, const Eigen::VectorXd& angles, const Homogeneous3& cubic,
                             const Eigen::VectorXd& knots);

/// Section 5 for basic shape to basic shape (the C1 counterpart of joinShapes): the end of
/// a's profile joined to the start of b's by a (4,2) double strip; both circles converted by
/// eq. (12) with the averaged scalars betaT_i = sqrt(beta_i^a beta_i^b), so both sides share
/// their knots (two quartics an arc). Shapes with different numbers of arcs (the T-joints of
/// Figs. 14, 15e) keep their own scalars instead: both knot vectors over one period, each
/// side's quartics split at the other's knots (Section 5: "splitting the transversal
/// 1-jets to the finest partition on either side"; the basic rows are split with them, so
/// the complex stays a tensor grid). Full turns or partial ones (both alike). quarticInV:
/// both profiles converted too (C1 across them, one C1 surface). b's patches are tagged
/// Basic and follow the two strip rows (rowsFreeForm counts them). Throws InputError for one
/// full and one partial turn, or an interface on the axis.
BlendComplex joinShapesC1(const G1RevolvedShape& a, const G1RevolvedShape& b, bool quarticInV = true);

}  // namespace fairsplines
