// Internal: the parts of the C2 blends of shapes of revolution (Section 4.2 of Karčiauskas &
// Peters) that several sources share: the profiles (blend_profile.cpp), the default ring
// (blend_ring.cpp), the transition strip and the assembly of a complex (blend_surface.cpp),
// on which the joins and the edited structures (blend_join.cpp) build.
#pragma once
#include <Geom_BSplineSurface.hxx>
#include <string>
#include <vector>

#include "fairsplines/blend_surface.hpp"
#include "fairsplines/g2_to_c2.hpp"

namespace fairsplines::detail {

// ---------------------------------------------------------------------------------------
// Profiles of the shapes of revolution (blend_profile.cpp)

/// The profile of a shape of revolution in the (distance from the axis, height) plane, as
/// G2 cubic pieces (eq. (2) for circles, degree-raised lines) and as C2 sextic pieces
/// (Section 4.1), with the interface at its end.
struct RevolvedProfile {
  std::vector<Homogeneous3> cubic;      ///< 4 homogeneous rows (rho w, zeta w, w) per piece
  std::vector<Homogeneous3> sextic;     ///< 7 rows per piece, C2 in homogeneous space
  Eigen::VectorXd sexticKnots;          ///< pieces + 1 knots of the sextic pieces
  Eigen::Vector2d end, tangent;         ///< (rho, zeta) at the interface and the unit direction leaving it
  double size = 1.0;                    ///< length scale of the last piece (for the default ring)
  Eigen::Vector2d start, startTangent;  ///< the same at the profile's start (direction leaving it backwards)
  double startSize = 1.0;
};

/// The profile run backwards, so that its start becomes the interface at its end. Pieces and
/// their Bézier rows in reverse order; the knots mirrored.
RevolvedProfile reversedProfile(const RevolvedProfile& p);

/// A circle profile: centre (rhoOffset, 0), radius r, partition `angles` (the circle's
/// pieces (x, y, w) map to (rhoOffset w + r x, r y, w)).
RevolvedProfile circleProfile(double rhoOffset, double r, const Eigen::VectorXd& angles, CircleReparam method);

/// A straight profile rho = radius0 + slope z over increasing heights: degree-raised
/// lines (beta_j = h_j / h_{j-1}, gamma_j = 0), which are already C2 over the heights.
RevolvedProfile lineProfile(double radius0, double slope, const Eigen::VectorXd& heights);

/// The sphere's profile: the circle of `radius` about the origin over `latitudes` (in
/// [-pi/2, pi/2]). Throws InputError for a radius that is not positive and finite, or a
/// latitude outside that range.
RevolvedProfile sphereProfile(double radius, const Eigen::VectorXd& latitudes, CircleReparam method);

/// The torus's profile: the circle of radius r about (R, 0) over `anglesV`. Throws
/// InputError unless 0 < r < R, R finite.
RevolvedProfile torusProfile(double R, double r, const Eigen::VectorXd& anglesV, CircleReparam method);

/// Whether cubic pieces a (over an interval of length h0) and b (h1 after it) join C^order
/// (1 or 2) in homogeneous space: their derivatives in the curve's parameter at the knot
/// agree within 1e-9 of the pieces' homogeneous size (eqs. (3)-(4) with beta = h1 / h0,
/// gamma = 0). Throws nothing.
bool joinsHomogeneousC(int order, const Homogeneous3& a, const Homogeneous3& b, double h0, double h1);

/// A Revolution's profile (issue 32): the rational cubic pieces as they are and, for the C2
/// rows, each raised to degree 6 over the curve's knots (the identity map of Section 4.1). At
/// a join that is not C2 in homogeneous space (a multiple knot: the profile G2 or less there)
/// the two sextics are made C2 by eq. (11) with beta = the knot ratio; `adjusted` receives
/// the indices of those joins. Throws InputError for fewer than one piece or knots that do
/// not increase.
RevolvedProfile curveProfile(const Homogeneous3& cubic, const Eigen::VectorXd& knots,
                             std::vector<int>* adjusted = nullptr);

/// The profile with the interface at its end: as it is (Interface::End) or reversed.
/// Throws InputError where that end (the interface) lies on the axis.
/// Interface::Auto picks the end unless it lies on the axis, or, with `defaultRing`, unless
/// the start leaves the default ring more room (detail::defaultRingRoom).
RevolvedProfile atInterface(const RevolvedProfile& p, Interface at, bool defaultRing = false);

/// The G2 circle of the longitudes around the frame's axis: a full turn (closed in u) or a
/// partial one (open). Throws InputError for a frame that is not orthonormal or longitudes
/// g2Circle refuses.
G2CircleSpline checkedLongitudes(const ShapeFrame& frame, const Eigen::VectorXd& longitudes);

// ---------------------------------------------------------------------------------------
// The default free-form ring (blend_ring.cpp)

/// The default free-form ring after a profile's end: 4 rows along the end tangent, the
/// first half the last piece's length beyond the interface, a quarter apart; in u one
/// pole per longitude (Boehm's form: pole i centred on knot u_i), periodic cubic.
/// `which` names the interface in the message of defaultRingRows.
Handle(Geom_BSplineSurface) defaultRing(const ShapeFrame& frame, const G2CircleSpline& lon, const RevolvedProfile& p,
                                        const Eigen::VectorXd& knotsU, const char* which = "interface");

// ---------------------------------------------------------------------------------------
// The transition strip and the assembly of a complex (blend_surface.cpp)

/// The transition patch of u-piece k (row vPiece, degree (degreeU, 5)) from the Hermite data
/// of the patch below (`lower`, degree dvLower in v) and the one above (`upper`).
TaggedPatch stripPatch(int k, int vPiece, int degreeU, const Homogeneous4& lower, int dvLower,
                       const Homogeneous4& upper, int dvUpper);

/// The basic side of a blend along u: one C2 sextic spline per control layer of the basic
/// rows (layer J (dv + 1) + s holds Bézier index s in v of row J), all on the same pieces.
struct BasicLayers {
  std::vector<C2SexticSpline> layers;
  int rows = 0, dv = 3;
  Eigen::VectorXd knotsV;  ///< rows + 1 values
  bool c2InV = false;
};

/// The layers of a shape of revolution: the C2 sextic circle `c2` times each profile point
/// (the sextic profile pieces with sexticInV, else the cubic ones).
BasicLayers revolvedLayers(const ShapeFrame& frame, const C2SexticSpline& c2, const RevolvedProfile& profile,
                           bool sexticInV);

/// Section 4.2 from the basic side's layers (C2 along u): the ring (default, or a user's
/// with its period mapped onto the circle's and the pieces split at its knots), then the
/// patches and the (6,5) strip from three layers on each side.
BlendComplex assembleBlend(const ShapeFrame& frame, const G2CircleSpline& lon, const RevolvedProfile& profile,
                           BasicLayers basic, Handle(Geom_BSplineSurface) ring);

// ---------------------------------------------------------------------------------------
// Shapes in a join and edited control structures (blend_join.cpp)

/// One shape of a join or a chain: its frame, the circle around the axis and the profile in
/// its own direction (v increasing).
struct JoinSide {
  ShapeFrame frame;
  G2CircleSpline lon;
  RevolvedProfile profile;
};

/// The side of a shape. Throws the InputError of the shape's profile and longitudes, and
/// "a cone needs a finite radius and slope".
JoinSide joinSide(const ShapeOfRevolution& shape, CircleReparam method);

/// Throws InputError unless the profile's end (Interface::End) or start is off the axis
/// ("the <name> shape's profile meets the axis (a pole) at the join").
void checkJoinOffAxis(const JoinSide& side, Interface at, const std::string& name);

/// Section 4.1 on every control layer of an edited structure of the side's shape (G2 cubic
/// rows along the profile), with the scalars betaT around the axis (empty: beta), every
/// arc-to-arc join then made C2 by eq. (11). Throws InputError for a structure of another
/// size, a non-finite point or a non-positive weight.
BasicLayers editedLayers(const JoinSide& side, const G2Surface& edited, CircleReparam method,
                         const Eigen::VectorXd& betaT = Eigen::VectorXd());

}  // namespace fairsplines::detail
