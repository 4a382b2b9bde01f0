// Basic shape to NURBS with a curvature-continuous transition strip of degree (6,5):
// Karčiauskas & Peters, "Free-Form Splines Combining NURBS and Basic Shapes", Section 4.2
// ("Algorithm for combining NURBS and G2 splines"), and the naive baseline of Fig. 2a.
// First shape: the sphere zone, joined at its top latitude to a bicubic ring.
#pragma once
#include <Geom_BSplineSurface.hxx>
#include <TopoDS_Shape.hxx>
#include <TopoDS_Shell.hxx>
#include <optional>
#include <vector>

#include "fairsplines/blend_shapes.hpp"
#include "fairsplines/g2_to_c2.hpp"

namespace fairsplines {

/// One Bézier patch of a blend complex, in homogeneous form: (degreeU + 1) (degreeV + 1)
/// rows (w p, w), row a (degreeV + 1) + b holding b_ab.
struct TaggedPatch {
  enum class Role { Basic, Transition, FreeForm };
  Role role = Role::Basic;
  int degreeU = 3, degreeV = 3;
  int uPiece = 0;  ///< index of the u-interval [knotsU[uPiece], knotsU[uPiece + 1]]
  int vPiece = 0;  ///< row of the complex, counted from the basic shape's first row
  Homogeneous4 bezier;
};

/// The patches of a blend, all over the same u-intervals (a closed ring in u). In v the rows
/// are: the basic shape's pieces, one transition row, the free-form rows. Every patch is
/// parameterised over [0,1]^2; in u, patch k stands for the interval of length
/// knotsU[k+1] - knotsU[k] of the shared parameterization.
struct BlendComplex {
  std::vector<TaggedPatch> patches;
  Eigen::VectorXd knotsU;  ///< piecesU + 1 values
  /// rowsBasic + 1 + rowsFreeForm + 1 values: the shared v parameterization of the rows
  /// (the strip joins both neighbours with scalar 1, so it has the length of the basic
  /// shape's top row, and the ring's first span that length again).
  Eigen::VectorXd knotsV;
  int piecesU = 0, rowsBasic = 0, rowsFreeForm = 0;
  int rowsTransition = 1;  ///< transition rows between them: 1 (Section 4.2) or 2 (the double strip of Section 5)
  bool closedU = true;
  bool basicC2InV = false;  ///< basic rows converted to C2 sextics across the interface too
  int smoothness = 2;       ///< the continuity the complex is built for: 2 (Section 4.2) or 1 (Section 5)
};

/// Where a shape of revolution meets the free-form side: the end of its profile (top
/// latitude, top height, last tube angle) or its start (bottom), e.g. for a dome whose top
/// is a pole. At the start the profile is run backwards (v reversed). Auto: the end, unless
/// it is a pole, or, for the default ring, the start has more room for it (issue 15).
enum class Interface { End, Start, Auto };

/// Exact rational Bézier Geom_BSplineSurface of a patch over [0,1]^2. Throws InputError for
/// a non-positive weight.
Handle(Geom_BSplineSurface) patchToOcct(const TaggedPatch& patch);

/// The default free-form ring that continues a sphere zone beyond its top latitude: a
/// periodic bicubic B-spline (weights 1), one span in v with 4 control rows along the
/// tangent cone of the sphere, starting half the top piece's length beyond the interface,
/// a quarter of it apart; in u, one
/// control point per longitude (Boehm's form: pole i centred on knot u_i), knots `knotsU`
/// (n + 1 values for n longitude arcs, periodic). Throws InputError if the ring would
/// cross the axis.
Handle(Geom_BSplineSurface) defaultSphereRing(const ShapeFrame& frame, double radius, const Eigen::VectorXd& longitudes,
                                              const Eigen::VectorXd& latitudes, const Eigen::VectorXd& knotsU);

/// Arc-level knots of the C2 conversion of a circle with scalars betaT: u_0 = 0, intervals
/// with ratio betaT (the knots of C2SexticSpline::knots() at the arcs' first pieces).
/// Throws nothing; c2 must come from circleToC2 (firstPiece has one entry per arc and one
/// more).
Eigen::VectorXd arcKnots(const C2SexticSpline& c2);

/// Section 4.2 for a sphere zone over a full turn of longitudes (closed in u), joined at its
/// top latitude (below pi/2) to `ring` (null: defaultSphereRing). The ring must be periodic
/// in u with the arc knots of the C2 circle (arcKnots; betaT = the circle's beta, the
/// heuristic of Section 3) and clamped in v, its first row at the interface. Steps: the
/// longitude circle becomes the C2 sextic of Section 4.1 (method), giving basic patches of
/// degree (6,3) that stay on the sphere; the second-order Hermite data (three layers of
/// Bézier coefficients) of the sphere at its top and of the ring at its first row are
/// degree-raised to (6,5) and fill one transition row (scalar 1 across both seams).
/// `at`: the interface at the top latitude (End) or the bottom one (Start, e.g. a dome whose
/// top is the pole). Throws InputError for an open longitude partition, an interface at a
/// pole (latitude +-pi/2), or a ring
/// whose structure does not match the interface.
/// With sexticInV the latitudes are converted too ("or in both" directions, Section 4.2):
/// basic patches of degree (6,6), the whole complex C2 and a tensor grid (singleSurface).
BlendComplex blendSphereZone(const ShapeFrame& frame, double radius, const Eigen::VectorXd& longitudes,
                             const Eigen::VectorXd& latitudes, CircleReparam method = CircleReparam::Rho,
                             Handle(Geom_BSplineSurface) ring = nullptr, bool sexticInV = false,
                             Interface at = Interface::End);

/// Section 4.2 for a cone (a cylinder with slope 0): radius radius0 + slope z, angles over a
/// full turn, increasing heights; the interface is the top height. naive: the Fig. 2a
/// baseline instead (method and sexticInV unused). Ring rules as blendSphereZone; the
/// default ring continues along the cone's generator.
/// Throws InputError for a non-finite radius0 or slope, heights detail::checkHeights refuses
/// (fewer than two, not finite, not increasing, or a radius that is not positive at one),
/// angles g2Circle refuses, an interface on the axis, or a ring whose structure does not match
/// the interface.
BlendComplex blendCone(const ShapeFrame& frame, double radius0, double slope, const Eigen::VectorXd& angles,
                       const Eigen::VectorXd& heights, CircleReparam method = CircleReparam::Rho,
                       Handle(Geom_BSplineSurface) ring = nullptr, bool sexticInV = false, bool naive = false,
                       Interface at = Interface::End);

/// Section 4.2 for a torus zone: anglesU over a full turn, anglesV an open range around the
/// tube (0 = outer equator); the interface is the last v angle. Throws InputError for a
/// closed tube range (no boundary to join).
BlendComplex blendTorus(const ShapeFrame& frame, double R, double r, const Eigen::VectorXd& anglesU,
                        const Eigen::VectorXd& anglesV, CircleReparam method = CircleReparam::Rho,
                        Handle(Geom_BSplineSurface) ring = nullptr, bool sexticInV = false, bool naive = false,
                        Interface at = Interface::End);

/// The u knots (one period) a free-form ring must have: arcKnots of the C2 circle.
/// Throws the InputError of g2Circle and circleToC2 for the longitudes.
Eigen::VectorXd ringKnots(const Eigen::VectorXd& longitudes, CircleReparam method = CircleReparam::Rho);

/// Degree raise of a homogeneous Bézier patch to (du, dv) (not below its degrees).
/// Throws nothing; the patch must have (degreeU + 1) (degreeV + 1) rows (not checked).
TaggedPatch raisePatch(const TaggedPatch& patch, int du, int dv);

/// The complex as one Geom_BSplineSurface: every patch raised to the largest degrees
/// (d, e), assembled over knotsU x knotsV, then every interior knot removed down to
/// multiplicity d - smoothness (e - smoothness) within `tolerance` (relative to the largest
/// homogeneous coordinate) so that the multiplicities give C^smoothness (2 for the C2
/// complexes, 1 for the C1 ones of Section 5). Throws InputError where a knot does not
/// come down (the complex is not that smooth there, e.g. basic rows that are only G2). The
/// closing u seam is kept as the surface's boundary (not periodic).
Handle(Geom_BSplineSurface) singleSurface(const BlendComplex& complex, double tolerance = 1e-9, int smoothness = 2);

/// The naive baseline of Fig. 2a: the G2 bicubic sphere patches as they are, the ring, and a
/// transition row of degree (3,5) that Hermite-interpolates both 2-jets without
/// reparameterization (u-intervals: the arcs). Same ring rules as blendSphereZone.
/// Throws InputError as blendSphereZone for the sphere (radius, latitudes, an interface at a
/// pole), for longitudes g2Circle refuses, or for a ring that does not match the arc knots
/// exactly ("the free-form net does not match the interface: ...").
BlendComplex blendSphereZoneNaive(const ShapeFrame& frame, double radius, const Eigen::VectorXd& longitudes,
                                  const Eigen::VectorXd& latitudes, Handle(Geom_BSplineSurface) ring = nullptr,
                                  Interface at = Interface::End);

/// A basic shape of revolution, described for the shape-to-shape join: kind, frame (z the
/// axis), its two size parameters and its angle lists (radians; heights for cylinder/cone).
struct ShapeOfRevolution {
  /// a cylinder is a cone with slope 0; Revolution: any rational cubic profile (issue 32)
  enum class Kind { SphereZone, Cone, Torus, Revolution };
  Kind kind = Kind::SphereZone;
  ShapeFrame frame;
  double size0 = 1.0;       ///< sphere: radius; cone: radius0 (at height 0); torus: major radius R
  double size1 = 0.0;       ///< sphere: unused; cone: slope; torus: minor radius r
  Eigen::VectorXd around;   ///< angles around the axis (a full turn)
  Eigen::VectorXd profile;  ///< latitudes, heights or tube angles; Revolution: the curve's knots
  Homogeneous3 curve;       ///< Revolution: RevolutionProfile::cubic (frame: RevolutionProfile::frame)
  /// A Revolution of `p` over the angles `around`. Throws nothing (the blends check it).
  static ShapeOfRevolution of(const RevolutionProfile& p, const Eigen::VectorXd& around);
};

/// Section 4.2 for a Dupin ring cyclide (dupinCyclide; anglesU a full turn, anglesV an open
/// range): both circles converted to C2 sextics (Section 4.1; the cyclide is bilinear in their
/// homogeneous points, so it stays exact and the basic rows are C2 in homogeneous space), the
/// default ring in the same tensor form (the revolution's default ring on the unit circles,
/// mapped by the cyclide's bilinear form: rational), one (6,5) strip at the last v angle.
/// Throws InputError as dupinCyclide, for a partial turn, or a ring weight that is not positive.
BlendComplex blendCyclide(const ShapeFrame& frame, double a, double c, double mu, const Eigen::VectorXd& anglesU,
                          const Eigen::VectorXd& anglesV, CircleReparam method = CircleReparam::Rho);

/// The naive baseline of Fig. 2a for a Dupin ring cyclide (for comparison): the exact G2
/// patches joined to the same default ring by a direct Hermite strip of degree (3,5), no
/// reparameterization; not C2 where the arcs differ. Throws InputError as blendCyclide.
BlendComplex blendCyclideNaive(const ShapeFrame& frame, double a, double c, double mu, const Eigen::VectorXd& anglesU,
                               const Eigen::VectorXd& anglesV);

/// Section 4.2 for any shape of revolution (a Revolution's profile included): as blendCone,
/// the interface at the end or start of its profile. A profile join that is only G2 (not C2
/// in homogeneous space, e.g. a double knot) is made C2 by eq. (11) in the sextic rows
/// (docs/BLENDING.md). naive: the Fig. 2a baseline. Throws InputError as the shape's checks,
/// for an interface on the axis, or a ring that does not match.
BlendComplex blendShape(const ShapeOfRevolution& shape, CircleReparam method = CircleReparam::Rho,
                        Handle(Geom_BSplineSurface) ring = nullptr, bool sexticInV = true, bool naive = false,
                        Interface at = Interface::End);

/// Basic shape to basic shape (Figs. 9, 11, 12): the end of a's profile joined to the start
/// of b's by one (6,5) transition row, both kept exact. Both angle lists around the axes need
/// the same number of arcs; across the transition the scalars are averaged,
/// betaT_i = sqrt(beta_i^a beta_i^b) (Fig. 11), both circles converted to C2 sextics with
/// these betaT (Section 4.1; arcs where one side has one piece and the other three are split
/// into thirds, exactly), so the two sides share their u knots without knot insertion
/// (Fig. 12). sexticInV: both profiles converted too (C2 everywhere, singleSurface works).
/// The strip joins both sides with scalar 1: the second shape's first v interval is made as
/// long as the first shape's last. The patches of b are tagged Basic too; they are the rows
/// after the strip (rowsFreeForm counts them). naive: the Fig. 2a baseline between the two
/// G2 complexes (cubic in u, a (3,5) strip, no reparameterization). Throws InputError for
/// different arc counts, partial turns, an interface on the axis or the other checks of the
/// shapes.
BlendComplex joinShapes(const ShapeOfRevolution& a, const ShapeOfRevolution& b,
                        CircleReparam method = CircleReparam::Rho, bool sexticInV = true, bool naive = false);

/// One shape of a chain (blendChain): a shape of revolution, joined as it is or, with
/// `edited` (its G2Surface with control points changed, Figs. 1c/d), as edited.
struct ChainShape {
  ShapeOfRevolution shape;
  std::optional<G2Surface> edited;
};

/// What closes one end of a chain: nothing (the profile's end is a boundary of the complex)
/// or a free-form ring, the user's (`net`: bicubic, periodic in u for a full turn, clamped in
/// v, its first row at the shape's profile end, leaving the shape) or, with `net` null, the
/// default ring continuing the shape (detail::defaultRingRows gives its room).
struct ChainEnd {
  bool ring = false;
  Handle(Geom_BSplineSurface) net;
  static ChainEnd open() { return ChainEnd(); }
  static ChainEnd freeForm(Handle(Geom_BSplineSurface) net = nullptr) { return ChainEnd{true, std::move(net)}; }
};

/// Several interfaces on one complex (issue 15): shapes of revolution in order along their
/// profiles, the end of each joined to the start of the next by one (6,5) transition row as
/// joinShapes does (Figs. 9, 11, 12), and a free-form ring (Section 4.2) at the first shape's
/// start and at the last one's end where `start` / `end` ask for one: a ball joint's
/// spherical band with free-form on both sides, a cylinder joined at both ends, a post and a
/// dome with free-form below the post. One circle conversion serves every strip: the scalars
/// around the axis are the geometric mean over the shapes, betaT_i = (prod_s beta_i^s)^(1/S)
/// (Fig. 11's average sqrt(beta^top beta^bottom) for two), every arc is split into the
/// least common multiple of the pieces the shapes give it (Fig. 12), and the pieces are split
/// at a user ring's u knots (exactly, de Casteljau). Every strip has the v length of the basic
/// row before it, and the next shape or ring is scaled to start with that length (scalar 1
/// across both seams). Rows in v: the start ring (its rows reversed, so v increases towards
/// the shapes), strip, shape 1, strip, shape 2, ..., strip, end ring. Edited shapes give G2
/// cubic rows along their profile (no single surface); otherwise sexticInV gives one C2
/// tensor grid (singleSurface). rowsBasic, rowsTransition and rowsFreeForm count all rows of
/// each role. Throws InputError for no shapes, one shape with no ring, shapes with different
/// arc counts or closedness, an interface on the axis (naming the shape and its end), a ring
/// that does not match or has no room, or the checks of the shapes.
BlendComplex blendChain(const std::vector<ChainShape>& shapes, const ChainEnd& start, const ChainEnd& end,
                        CircleReparam method = CircleReparam::Rho, bool sexticInV = true);

/// Section 4.2 for an edited control structure (Figs. 1c/d, 4a): `edited` is the shape's
/// G2Surface (sphereZone, cylinder, cone, torus of the same angles) with control points and
/// weights changed (G2Surface::setControl). Along u every control layer is converted with
/// the circle partition's maps (Section 4.1) and every arc-to-arc join made C2 by eq. (11),
/// which leaves the joins that are already C2 unchanged: unedited arcs not next to an edit
/// stay on the shape. Across the profile the rows stay G2 cubics (no single C2 surface).
/// The ring (default: the unedited shape's) joins at the end of the profile. Throws
/// InputError for a structure of another size, non-finite points or weights <= 0.
BlendComplex blendEdited(const ShapeOfRevolution& shape, const G2Surface& edited,
                         CircleReparam method = CircleReparam::Rho, Handle(Geom_BSplineSurface) ring = nullptr);

/// Splits arc i of a C2 sextic spline into parts[i] equal pieces (a multiple of the pieces it
/// has) by de Casteljau: the curve and its C2 joins are unchanged; the scalars follow the new
/// interval lengths. Throws InputError for a count that is not a multiple.
C2SexticSpline refineArcs(const C2SexticSpline& c2, const std::vector<int>& parts);

/// Splits piece k of a C2 sextic spline at the local parameters cuts[k] (increasing, inside
/// (0, 1)) by de Casteljau: the curve and its C2 joins are unchanged; the scalars follow the
/// new interval lengths and firstPiece the arcs. Throws InputError for cuts out of order.
C2SexticSpline splitPieces(const C2SexticSpline& c2, const std::vector<std::vector<double>>& cuts);

/// The shell of a complex and what building it measured (blendShell).
struct BlendShell {
  TopoDS_Shell shell;
  double maxGap = 0.0;     ///< largest distance between two patches along a shared edge or at a shared corner
  double tolerance = 0.0;  ///< the edges' least tolerance (Precision::Confusion(), more for huge coordinates)
  double allowedGap =
      0.0;              ///< the largest gap accepted: 1e-9 of the complex's size plus 1e-13 of its largest coordinate
  int freeEdges = 0;    ///< edges on one face only, degenerated ones not counted (0: the shell is closed)
  int degenerated = 0;  ///< patch sides collapsed to a point (a pole row)
};

/// The complex's patches as one shell with the topology of its grid, without sewing: one
/// TopoDS_Vertex per grid corner (one per pole where a row collapses), one TopoDS_Edge per
/// patch side, shared by the two patches it bounds (its 3D curve the first patch's
/// boundary iso-curve, a straight pcurve on each face in the face's [0,1]^2), closed around
/// the axis where the complex is (closedU), every face oriented like its patch (du x dv),
/// so shared edges run opposite ways in their two faces. An edge's tolerance is the largest
/// deviation measured between its two patches' boundary curves (at least
/// BlendShell::tolerance). Throws InputError naming the patch, the edge and the deviation
/// where two patches that share a side or a corner are more than allowedGap apart, where a
/// patch has numbers that are not finite or a weight <= 0, and where the patches are not a
/// tensor grid (every u piece in every row exactly once).
BlendShell blendShell(const BlendComplex& complex);

}  // namespace fairsplines
