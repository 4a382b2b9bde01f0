// Fair blends: planar cubic B-splines between two end conditions (G1: points and tangent
// directions; G2: also signed end curvatures) whose curvature is monotone, certified by the
// exact Bernstein certificate (monotone.hpp), with as many spans as the ends need.
//
// Beyond the monotone-curvature paper, whose single short cubic covers turns under 90
// degrees without inflection: every G1 problem with distinct points has a clothoid
// solution (Bertolazzi & Frego 2015), whose curvature is linear in arc length. The blend
// is the C2 cubic spline that follows that clothoid: exact end points, tangents and
// curvatures, the clothoid's points at the interior knots, more spans until the
// certificate proves its curvature monotone. The criterion it optimizes is closeness to
// the clothoid of the same ends, the fairest monotone curve (its curvature varies at one
// constant rate). For G2 ends it follows the spiral of least scale-free variation
// L^3 int (dkappa/ds)^2 ds whose curvature runs monotonically between the end curvatures;
// the report gives that variation for every result. docs/FAIR_BLENDS.md has the
// derivation, the refusals and the measured coverage.
#pragma once
#include <Eigen/Core>
#include <limits>
#include <string>
#include "fairsplines/monotone.hpp"
#include "fairsplines/types.hpp"

namespace fairsplines {

/// The two ends of a blend. Curvatures are signed about the plane normal: positive turns
/// counter-clockwise seen from the normal's tip. NaN curvature: not prescribed (G1 at that
/// end). A zero normal: derived from the data (+Z for data in the XY plane; else the plane
/// of the tangents and the chord, oriented to make the first turn counter-clockwise, which
/// is refused when curvatures are prescribed, since their sign would be ambiguous).
struct BlendEnds {
  Eigen::Vector3d p0 = Eigen::Vector3d::Zero(), t0 = Eigen::Vector3d::UnitX();
  Eigen::Vector3d p1 = Eigen::Vector3d::UnitX(), t1 = Eigen::Vector3d::UnitX();
  double k0 = std::numeric_limits<double>::quiet_NaN(), k1 = std::numeric_limits<double>::quiet_NaN();
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
};

struct FairBlend {
  BSplineCurve curve;                                 ///< planar cubic, 3 columns, clamped, C2 inside
  MonotonicityCertificate certificate;                ///< the exact certificate of `curve`
  bool monotone = false;                              ///< certificate.monotone
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  ///< the plane normal curvatures refer to
  double kappa0 = 0.0, kappa1 = 0.0;                  ///< end curvatures of `curve`, signed about `normal`
  double turning = 0.0;                               ///< total tangent turning, radians, signed about `normal`
  double length = 0.0;                                ///< arc length of the clothoid followed
  double variation = 0.0;                             ///< L^3 int (dkappa/ds)^2 ds of `curve` (curvatureVariation)
  int spans = 0;
  std::string reason;  ///< how it was found, or why it is not monotone
};

/// The fair blend of two ends, never NaN geometry.
/// - G1 (k0, k1 NaN): the C2 cubic through p0 with direction t0 and p1 with direction t1
///   that follows the G1 Hermite clothoid of those ends (of the clothoids turning less than
///   a full turn, the one whose curvature varies least), its end curvatures the clothoid's.
///   Every pair of distinct points is solved; the curve is certified monotone.
/// - G2 (k0, k1 given): the cubic also meets the end curvatures. It follows the fairest
///   spiral whose curvature is a cubic of arc length running monotonically from k0 to k1
///   (spiral.hpp), over the turnings of less than a full turn that meet the tangents. Where none
///   exists, `monotone` is false and `reason` says why: a necessary condition that fails
///   (equal curvatures off a common circle; osculating circles not nested, or overlapping
///   across an inflection, by the Tait-Kneser theorem), or that no such spiral was found.
///   The curve is then the fairest non-monotone spiral found, or the G1 clothoid with the
///   given end curvatures.
/// Straight ends (collinear, same direction, zero curvatures) give the segment.
/// Throws InputError on non-finite input, a zero tangent or normal, coincident points, a
/// tangent or the chord out of the plane of `normal`, no plane at all, only one of k0 and
/// k1, or curvatures with data outside the XY plane and no normal.
FairBlend fairBlend(const BlendEnds& ends);

// ---------------------------------------------------------------------------------------
// Fair blends in space (issue 28; src/fair_blend_space.cpp, docs/FAIR_BLENDS.md sections 8-10)

/// The ends of a blend in space: points, tangent directions and (G2) curvature vectors
/// kappa N, as OCCT evaluates an edge's end ((d1 x d2) x d1 / |d1|^4). NaN curvature vectors:
/// G1 at both ends.
struct SpaceBlendEnds {
  Eigen::Vector3d p0 = Eigen::Vector3d::Zero(), t0 = Eigen::Vector3d::UnitX();
  Eigen::Vector3d p1 = Eigen::Vector3d::UnitX(), t1 = Eigen::Vector3d::UnitX();
  Eigen::Vector3d K0 = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  Eigen::Vector3d K1 = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
};

struct SpaceFairBlend {
  BSplineCurve curve;                     ///< cubic, 3 columns, clamped, C2 inside
  SpaceCurvatureCertificate certificate;  ///< certifySpaceCurvature(curve)
  bool monotone = false;                  ///< the curvature is certified monotone (planar: signed, as fairBlend)
  bool planar = false;                    ///< the ends are coplanar: fairBlend's result, in their plane
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();  ///< the plane's normal where planar
  int curvatureExtrema = 0;                          ///< certificate.extrema.size()
  int torsionSignChanges = 0;                        ///< certificate.torsionSignChanges.size()
  double length = 0.0;                               ///< arc length of the guide curve followed
  double variation = 0.0;                            ///< L^3 int (dkappa/ds)^2 ds of `curve`
  int spans = 0;
  std::string reason;  ///< how it was found, or why it is not monotone
};

/// The fair blend of two ends anywhere in space, never NaN geometry.
/// - Coplanar ends (the chord, tangents and curvature vectors in one plane to 1e-12) are
///   fairBlend's, in that plane: the planar result.
/// - Otherwise the C2 cubic that follows a space spiral (space_spiral.hpp): curvature a cubic
///   of arc length (linear for G1), torsion quadratic (linear for G1), solved for the ends;
///   of the solutions found, monotone curvature first, then the fewest torsion sign changes,
///   then the least variation. Spans are halved until certifySpaceCurvature proves the cubic's
///   curvature monotone where the spiral's is. Points and tangents are exact (first and last
///   poles, neighbours on the tangent lines); G2 curvature vectors to rounding (the third
///   poles are placed for them).
/// Where nothing monotone is found, `monotone` is false and `reason` says why.
/// Throws InputError on non-finite input, zero tangents, coincident points, only one of the
/// curvature vectors, a curvature vector along its tangent, or a solve past its work budget.
SpaceFairBlend fairBlendSpace(const SpaceBlendEnds& ends);

}  // namespace fairsplines
