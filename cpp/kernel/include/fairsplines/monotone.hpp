// Planar cubic B-splines with monotonic curvature: Wang, He, Hou, Cai & Zhao, "Designing
// planar cubic B-spline curves with monotonic curvature for curve interpolation":
// derivative control polygons (eqs. (3), (5)), the per-segment conditions (Lemmas 1-3,
// Theorems 1-2), design (Algorithm 1) and G1 interpolation (Algorithm 2, with the paper's
// grid search kept as a baseline). Beyond the paper: an exact monotonicity certificate for
// any planar polynomial or rational B-spline, and a solver for the fairest curve of the
// family (the analytic centre of its admissible set, see MonotoneMethod::Fairest).
#pragma once
#include <Eigen/Core>
#include <string>
#include <tuple>
#include <vector>
#include "fairsplines/errors.hpp"
#include "fairsplines/types.hpp"

namespace fairsplines {

/// No curve of the family meets the end conditions; the message says why.
class NoMonotoneSolution : public InputError {
public:
  using InputError::InputError;
};

// --- Derivative control polygons, eqs. (3) and (5) ----------------------------------------

/// The knot vector with every knot repeated by its multiplicity (t_0 .. t_{n+p+1}).
/// Throws InputError for a periodic curve, a multiplicity count that is not one per knot, or
/// multiplicities that do not add up to the number of poles + degree + 1.
Eigen::VectorXd flatKnots(const BSplineCurve& curve);

struct DerivativePolygons {
  PointMatrix first;   ///< C^1_i = 3 / (t_{i+4} - t_{i+1}) (C_{i+1} - C_i), eq. (3): one row per control vector
  PointMatrix second;  ///< C^2_i = 2 / (t_{i+4} - t_{i+2}) (C^1_{i+1} - C^1_i), eq. (5)
};

/// Eqs. (3) and (5) for a non-periodic, non-rational cubic B-spline. Throws InputError otherwise.
DerivativePolygons derivativePolygons(const BSplineCurve& cubic);

// --- Per-segment conditions: Lemmas 1-3, Theorems 1 and 2 -----------------------------------

/// The paper's conditions for one segment [t_j, t_{j+1}] of a planar cubic, evaluated in the
/// segment's local frame (origin C_{j-3}, x-axis along C_{j-2} - C_{j-3}). A segment turning
/// right (derivative polygons in the fourth quadrant) is checked as its mirror image.
/// When they hold, |kappa| does not increase along the segment (Theorem 1).
struct SegmentCheck {
  int turn = 0;         ///< +1: first quadrant (left turn), -1: fourth quadrant (right turn), 0: neither
  bool lemma1 = false;  ///< C^1_{j-3..j-1}, C^2_{j-3..j-2} in one quadrant: |P'| does not decrease
  bool lemma2 = false;  ///< angle O C^2_{j-2} C^2_{j-3} >= 90 deg: |P''| does not increase
  bool lemma3 =
      false;  ///< slope(O C^1_{j-2}) <= slope(O C^2_{j-2}) <= slope(O C^2_{j-3}): sin of their angle does not increase
  bool fairLocation = false;  ///< Theorem 2 (i): C^2_{j-2} inside the fair location of Fig. 3
  bool theorem2 =
      false;  ///< Theorem 2: (i) fair location, (ii) slope(O C^1_{j-2}) <= slope(O C^2_{j-3}), (iii) one quadrant
  bool degenerate = false;  ///< the first control vector of the segment is zero: no local frame
  int offQuadrant = -1;     ///< Lemma 1 failure: 0 C^1_{j-2}, 1 C^1_{j-1}, 2 C^2_{j-3}, 3 C^2_{j-2} leaves the quadrant
  int slopeOrder =
      0;  ///< Lemma 3 failure: 1 slope(O C^1_{j-2}) > slope(O C^2_{j-2}), 2 slope(O C^2_{j-2}) > slope(O C^2_{j-3})
  double angle = 0.0;  ///< the angle O C^2_{j-2} C^2_{j-3} in radians (pi when C^2_{j-2} = O)
  bool theorem1() const { return lemma1 && lemma2 && lemma3; }
};

/// Lemmas 1-3 and Theorem 2 for the segment with poles c[0..3] (C_{j-3}..C_j, planar
/// coordinates) and local knots u[0..5] = t_{j-2}..t_{j+3}. Inequalities hold up to `tol`
/// relative to the segment's largest derivative control point. No allocation: the grid search
/// calls it.
/// Throws nothing; the points and knots must be finite (checkSegments validates a curve first).
SegmentCheck checkSegment(const Eigen::Vector2d c[4], const double u[6], double tol = 1e-12);

/// One sentence: which condition fails and by how much, or that Theorem 1 holds.
/// Throws nothing.
std::string describe(const SegmentCheck& check);

struct SegmentReport {
  double u0 = 0.0, u1 = 0.0;  ///< the segment's parameter range
  SegmentCheck check;
};

/// checkSegment for every non-empty span of a planar, non-periodic, non-rational cubic,
/// in the plane of its poles. Throws InputError for other curves.
std::vector<SegmentReport> checkSegments(const BSplineCurve& cubic);

// --- Algorithm 1: design from control vectors ----------------------------------------------

struct MonotoneDesign {
  BSplineCurve curve;       ///< poles C_0 = start, C_{i+1} = C_i + V_i (2 columns)
  PointMatrix differences;  ///< the dV_i used, after clamping (rows)
  Eigen::VectorXd moved;    ///< how far each dV_i was moved to reach its fair location (0: kept)
  int turn = 1;             ///< +1 the curve turns left, -1 right (designed as a mirror image)
};

/// Algorithm 1: V_0 = firstVector, V_{i+1} = V_i + dV_i. dV_0 is moved to the nearest point
/// that puts C^2_0 in the first quadrant of V_0's frame (the fourth, for a right turn, as
/// decided by the sign of dV_0 x V_0), every later dV_i to the nearest point that puts
/// C^2_i in its fair location (Theorem 2), so every segment satisfies Theorem 1.
/// The paper states the conditions on dV_i; they are placed on C^2_i (eqs. (3), (5)),
/// which is the same for uniform knots and right for any knots.
/// flatKnots: t_0..t_{n+4} for n+1 poles (default: clamped, uniform inside).
/// Throws InputError on a zero first vector, non-finite input or unusable knots.
MonotoneDesign designMonotone(const Eigen::Vector2d& firstVector, PointsRef differences,
                              const Eigen::VectorXd& flatKnots = Eigen::VectorXd(),
                              const Eigen::Vector2d& start = Eigen::Vector2d::Zero());

// --- Algorithm 2: two points and tangents to a monotone-curvature cubic --------------------

/// How Algorithm 2 picks the curve among the family's curves that meet the end conditions.
enum class MonotoneMethod {
  /// The analytic centre of the admissible set: the curve maximizing the sum of the
  /// logarithms of the distances of C^2_0 to the two sides of the first quadrant and of
  /// C^2_1, C^2_2 to the four sides of their fair locations (angles in radians; radially
  /// |C^2_j| / |C^2_{j-1}| and cos(delta) minus it, delta the angle between them). It lies
  /// deepest inside Theorem 2's conditions, so its curvature decreases strictly, and it is
  /// unique in our tests.
  /// Newton's method with exact second derivatives; the parabola (the family's boundary)
  /// when the admissible set has no interior.
  Fairest,
  /// The paper's Algorithm 2: the first hit of a grid search with step `gridStep` over
  /// t_1, t_3, t_2x, t_2y (the ranges read as in the README), checked with Lemmas 1-3.
  PaperGrid
};

/// Where the end conditions lie with respect to the family, in the plane of the data.
struct EndConditions {
  bool admissible = false;
  bool straight = false;    ///< collinear, same direction: the straight segment
  bool reversed = false;    ///< curvature must increase from p0 (the curve is solved from p1 back to p0)
  double a = 0.0, b = 0.0;  ///< |M - p0| and |p1 - M|, M the intersection of the tangents
  double turn = 0.0;        ///< angle from t0 to t1 (radians)
  std::string reason;       ///< why not admissible
};

/// Classifies (p0, t0, p1, t1). Admissible: coplanar, the tangents meet at M ahead of p0 and
/// behind p1, the tangent turns by less than 90 degrees, and min(a, b) <= max(a, b) cos(turn)
/// (equality: the parabola from its vertex). Throws InputError on non-finite input, a zero
/// tangent or coincident points.
EndConditions analyzeEndConditions(const Eigen::Vector3d& p0, const Eigen::Vector3d& t0, const Eigen::Vector3d& p1,
                                   const Eigen::Vector3d& t1);

struct MonotoneSpline {
  BSplineCurve curve;     ///< 5 poles (3 columns), knots 0, 1, 2 with multiplicities 4, 1, 4
  bool reversed = false;  ///< curvature increases from p0 (else it decreases)
  bool boundary = false;  ///< on the family's boundary: the parabola (no interior curve exists)
  double margin = 0.0;    ///< smallest of the normalized Theorem 2 slacks (0 on the boundary)
  int iterations = 0;     ///< Newton iterations (Fairest) or grid points tried (PaperGrid)
};

/// Algorithm 2: the cubic B-spline with 5 poles that starts at p0 with tangent direction t0,
/// ends at p1 with direction t1 and has monotone curvature, at any position, orientation and
/// mirror image (the data are normalized to C_0 = 0, T_0 = +x, a left turn, curvature
/// decreasing from C_0). Every result is verified by Theorem 1 and by the exact certificate
/// (collinear ends give the straight segment).
/// Throws NoMonotoneSolution when the family has no such curve (the message says why) or,
/// for PaperGrid, when the grid finds none; InputError on bad input, and for a grid step
/// below kMinGridStep (the grid search's work grows as step^-4).
constexpr double kMinGridStep = 0.01;
MonotoneSpline monotoneCurvatureSpline(const Eigen::Vector3d& p0, const Eigen::Vector3d& t0, const Eigen::Vector3d& p1,
                                       const Eigen::Vector3d& t1, MonotoneMethod method = MonotoneMethod::Fairest,
                                       double gridStep = 0.02);

// --- The exact monotonicity certificate ----------------------------------------------------

enum class CurvatureTrend {
  Increasing,  ///< kappa' >= 0 on the span (signed curvature, about the plane normal)
  Decreasing,  ///< kappa' <= 0
  Constant,    ///< kappa' = 0 (within rounding): a line or a circular arc
  Extremum,    ///< kappa' takes both signs: an interior curvature extremum
  Singular,    ///< the derivative vanishes: curvature undefined
  Undecided    ///< kappa' stays within rounding of 0 near a point, beyond the subdivision depth
};

struct SpanCertificate {
  double u0 = 0.0, u1 = 0.0;          ///< parameter range of the span
  double kappa0 = 0.0, kappa1 = 0.0;  ///< signed curvature at its ends
  CurvatureTrend trend = CurvatureTrend::Undecided;
  int degree = 0;        ///< degree of the polynomial N whose sign is that of kappa'
  int pieces = 1;        ///< Bezier pieces of N examined (1: decided by its coefficients)
  double at = 0.0;       ///< Extremum: parameter of the extremum; Singular/Undecided: where
  double kappaAt = 0.0;  ///< Extremum: curvature there
  bool maximum = false;  ///< Extremum: a maximum (else a minimum)
  std::string reason;
};

struct MonotonicityCertificate {
  bool monotone = false;
  bool increasing = false;                            ///< signed curvature nondecreasing along the parameter
  bool decreasing = false;                            ///< nonincreasing (both: constant curvature)
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  ///< plane normal the curvature sign refers to
  double kappaStart = 0.0, kappaEnd = 0.0;
  std::vector<SpanCertificate> spans;
  std::string reason;  ///< one sentence for the whole curve
};

/// Exact certificate for a planar B-spline of any degree, polynomial or rational (positive
/// weights), periodic or not. Per span, the sign of kappa' is the sign of
///   N = (2 W' (B x B') + W (B x B'')) |B|^2 - 3 W (B x B') (B . B'),  B = X' W - X W',
/// with X the homogeneous numerator and W the weight (for a polynomial curve
/// N = (P' x P''') |P'|^2 - 3 (P' x P'') (P' . P'')). N is built exactly in Bernstein form;
/// its coefficients decide the sign, with subdivision at 1/2 where they disagree (depth 48).
/// Tolerance policy: |N| <= relTol * S counts as 0, S a bound of N's two terms with every
/// derivative factor as large as the span's coordinates allow: rounding of the poles, a line
/// or a circle (N = 0 by cancellation) and a tangency of kappa' to 0 count as "no change";
/// a sign change needs witnesses beyond relTol * S on both sides.
/// Curvature jumps and corners at knots of lower continuity count too.
/// Scale-invariant: the poles are divided by a power of two near their spread (exact), the
/// curvatures reported in the curve's own units.
/// Throws InputError for an invalid curve, a curve that does not move, a non-planar curve,
/// non-positive weights, or curvatures beyond double precision.
MonotonicityCertificate certifyMonotoneCurvature(const BSplineCurve& curve, double relTol = 1e-12);

// ---------------------------------------------------------------------------------------
// Space curves (issue 28; src/monotone_space.cpp, docs/FAIR_BLENDS.md section 8)

struct SpaceSpanCertificate {
  double u0 = 0.0, u1 = 0.0;                         ///< parameter range of the span
  double kappa0 = 0.0, kappa1 = 0.0;                 ///< curvature (>= 0) at its ends
  CurvatureTrend trend = CurvatureTrend::Undecided;  ///< of kappa (equivalently kappa^2)
  int degree = 0;                                    ///< degree of the Bernstein form of N
  double at = 0.0;                                   ///< Extremum: its parameter; Singular/Undecided: where
  double kappaAt = 0.0;                              ///< Extremum: curvature there
  bool maximum = false;                              ///< Extremum: a maximum (else a minimum)
  int torsionSign = 0;                 ///< +1 / -1: det(c', c'', c''') of one sign on the span; 0: zero (a planar span)
  std::vector<double> torsionChanges;  ///< where the torsion changes sign inside the span (rational spans)
  std::string reason;
};

struct SpaceCurvatureCertificate {
  bool monotone = false;    ///< kappa certified monotone along the whole curve
  bool increasing = false;  ///< kappa nondecreasing (both: constant)
  bool decreasing = false;
  bool planar = false;  ///< every span's torsion numerator vanishes (within rounding)
  double kappaStart = 0.0, kappaEnd = 0.0;
  std::vector<SpaceSpanCertificate> spans;
  /// Curvature extrema (u, kappa, is_maximum): inside spans, and at knots where the spans on
  /// the two sides run opposite ways.
  std::vector<std::tuple<double, double, bool>> extrema;
  /// Parameters where the sign of the torsion changes (inside spans, or at the knot between
  /// spans of opposite signs; planar spans between them carry no sign).
  std::vector<double> torsionSignChanges;
  std::string reason;
};

/// Exact certificate of monotone curvature for a space B-spline (3 columns, or 2 read as
/// z = 0), polynomial or rational, per span. kappa^2 = |c' x c''|^2 / |c'|^6, so
///   sign d(kappa^2)/dt = sign N,  N = 2 (c' x c'').(c' x c''') |c'|^2 - 6 |c' x c''|^2 (c'.c'')
/// for a polynomial span (degree 7 for a cubic: c' x c'' has degree 2, not 3), and for a
/// rational span with homogeneous numerator X, weight W, B = X' W - X W', D = B x B':
///   N = 2 W (D.(B x B'')) |B|^2 + 4 W' |D|^2 |B|^2 - 6 W |D|^2 (B.B')
/// (docs/FAIR_BLENDS.md section 8). N is formed exactly in Bernstein form (bernstein.hpp) and
/// signed by its coefficients with subdivision, with the tolerance policy of
/// certifyMonotoneCurvature. The torsion's sign is that of det(B, B', B'') (det(c', c'', c'''),
/// constant on a polynomial cubic span), signed the same way. Scale-invariant.
/// Throws InputError for an invalid curve, a curve that does not move, non-positive weights,
/// or curvatures beyond double precision.
SpaceCurvatureCertificate certifySpaceCurvature(const BSplineCurve& curve, double relTol = 1e-12);

/// Scale-free curvature variation L^3 * integral (dkappa/ds)^2 ds (Gauss quadrature, 16 points
/// per span): 0 for lines and circles. A fairness measure used to compare solvers.
/// Throws InputError for a curve planarCurve refuses (not a valid B-spline, a curve that does
/// not move, or a 3D curve whose poles do not lie in one plane), or a variation that is not
/// finite.
double curvatureVariation(const BSplineCurve& curve);

}  // namespace fairsplines
