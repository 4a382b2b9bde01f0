// Basic shape to NURBS with a curvature-continuous transition strip of degree (6,5):
// Karčiauskas & Peters, "Free-Form Splines Combining NURBS and Basic Shapes", Section 4.2
// ("Algorithm for combining NURBS and G2 splines"), and the naive baseline of Fig. 2a.
// First shape: the sphere zone, joined at its top latitude to a bicubic ring.
#pragma once
#include <Geom_BSplineSurface.hxx>
#include <TopoDS_Shape.hxx>
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
  int rowsTransition = 1;   ///< transition rows between them: 1 (Section 4.2) or 2 (the double strip of Section 5)
  bool closedU = true;
  bool basicC2InV = false;  ///< basic rows converted to C2 sextics across the interface too
  int smoothness = 2;       ///< the continuity the complex is built for: 2 (Section 4.2) or 1 (Section 5)
};

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
Eigen::VectorXd arcKnots(const C2SexticSpline& c2);

/// Section 4.2 for a sphere zone over a full turn of longitudes (closed in u), joined at its
/// top latitude (below pi/2) to `ring` (null: defaultSphereRing). The ring must be periodic
/// in u with the arc knots of the C2 circle (arcKnots; betaT = the circle's beta, the
/// heuristic of Section 3) and clamped in v, its first row at the interface. Steps: the
/// longitude circle becomes the C2 sextic of Section 4.1 (method), giving basic patches of
/// degree (6,3) that stay on the sphere; the second-order Hermite data (three layers of
/// Bézier coefficients) of the sphere at its top and of the ring at its first row are
/// degree-raised to (6,5) and fill one transition row (scalar 1 across both seams).
/// Throws InputError for an open longitude partition, a top latitude of pi/2, or a ring
/// whose structure does not match the interface.
/// With sexticInV the latitudes are converted too ("or in both" directions, Section 4.2):
/// basic patches of degree (6,6), the whole complex C2 and a tensor grid (singleSurface).
BlendComplex blendSphereZone(const ShapeFrame& frame, double radius, const Eigen::VectorXd& longitudes,
                             const Eigen::VectorXd& latitudes, CircleReparam method = CircleReparam::Rho,
                             Handle(Geom_BSplineSurface) ring = nullptr, bool sexticInV = false);

/// Section 4.2 for a cone (a cylinder with slope 0): radius radius0 + slope z, angles over a
/// full turn, increasing heights; the interface is the top height. naive: the Fig. 2a
/// baseline instead (method and sexticInV unused). Ring rules as blendSphereZone; the
/// default ring continues along the cone's generator.
BlendComplex blendCone(const ShapeFrame& frame, double radius0, double slope, const Eigen::VectorXd& angles,
                       const Eigen::VectorXd& heights, CircleReparam method = CircleReparam::Rho,
                       Handle(Geom_BSplineSurface) ring = nullptr, bool sexticInV = false, bool naive = false);

/// Section 4.2 for a torus zone: anglesU over a full turn, anglesV an open range around the
/// tube (0 = outer equator); the interface is the last v angle. Throws InputError for a
/// closed tube range (no boundary to join).
BlendComplex blendTorus(const ShapeFrame& frame, double R, double r, const Eigen::VectorXd& anglesU,
                        const Eigen::VectorXd& anglesV, CircleReparam method = CircleReparam::Rho,
                        Handle(Geom_BSplineSurface) ring = nullptr, bool sexticInV = false, bool naive = false);

/// The u knots (one period) a free-form ring must have: arcKnots of the C2 circle.
Eigen::VectorXd ringKnots(const Eigen::VectorXd& longitudes, CircleReparam method = CircleReparam::Rho);

/// Degree raise of a homogeneous Bézier patch to (du, dv) (not below its degrees).
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
BlendComplex blendSphereZoneNaive(const ShapeFrame& frame, double radius, const Eigen::VectorXd& longitudes,
                                  const Eigen::VectorXd& latitudes, Handle(Geom_BSplineSurface) ring = nullptr);

/// Every patch as a face, sewn into one shell (BRepBuilderAPI_Sewing, tolerance relative
/// to the complex's size). Throws InputError if sewing does not give a single shell.
TopoDS_Shape sewnShell(const BlendComplex& complex, double tolerance = 1e-7);

}  // namespace fairsplines
