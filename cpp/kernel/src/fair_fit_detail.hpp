// Internal: the parts of the fair fit (fair_fit.cpp) that read the data (fair_fit_data.cpp:
// samples, local quadratics, noise, plane, curvature signs and straight runs) and measure
// the curve against it (fair_fit_distance.cpp: span polynomials, sample projection).
#pragma once
#include <Eigen/SparseCore>
#include <Geom_BSplineCurve.hxx>
#include <array>
#include <cmath>
#include <functional>
#include <optional>
#include <vector>

#include "fairsplines/analysis.hpp"
#include "fairsplines/types.hpp"

namespace fairsplines::detail::fairfit {

using Eigen::Index;
using Eigen::Vector3d;

// ---------------------------------------------------------------------------------------
// The samples: rows padded to 3D, their cumulative chord length

struct Samples {
  std::vector<Vector3d> p;  // q_i, z = 0 for 2D data
  std::vector<double> s;    // cumulative chord length (n + 1 values when closed)
  Index n = 0;
  bool closed = false;
  double size = 0.0;  // bounding-box diagonal
  Index wrap(Index i) const { return ((i % n) + n) % n; }
  // Chord length up to sample index i, where i may run past n - 1 on closed data.
  double arc(Index i) const { return i < n ? s[i] : s[i - n] + s[n]; }
};

/// Samples with the checks and chords of validateSamples (which throws InputError).
Samples readSamples(PointsRef q, bool closed);

// ---------------------------------------------------------------------------------------
// Real input (fair_fit_input.cpp): coincident points merged, closed data recognised, the
// order along the curve checked, corners found

/// The samples as the fit takes them: runs of consecutive points within `mergeDistance` of
/// the run's first point are that one point; data whose last point repeats the first
/// (within it) are closed, when `mayClose` (open data without end conditions) or closed.
struct MergedInput {
  PointMatrix kept;           // the kept rows, when a point other than a closing repeat was dropped
  Index rows = 0;             // the number of kept samples
  std::vector<Index> origin;  // the input row of each kept sample (empty: sample i is row i)
  Index merged = 0;           // input points dropped
  double offset = 0.0;        // the largest distance from a dropped point to the one kept
  bool closed = false;
  bool recognisedClosed = false;  // open data whose last point repeats the first
  /// The samples to fit: `input` itself (or its first rows) when nothing inside it was merged,
  /// so that 10^6 clean samples are not copied.
  PointsRef samples(PointsRef input) const {
    return kept.rows() > 0 ? PointsRef(kept) : PointsRef(input.topRows(rows));
  }
  Index inputRow(Index i) const { return origin.empty() ? i : origin[static_cast<std::size_t>(i)]; }
};

/// Merge coincident and near-coincident neighbours: the merge distance is 1e-3 of the
/// tolerance, at most 1e-9 of the data's size, at least 2e-12 of it (what validateSamples
/// calls coincident). Throws as validateSamples for rows, columns and non-finite values.
MergedInput mergeCoincident(PointsRef q, bool closed, double tolerance, bool mayClose);

/// Where the data turn sharply at one sample: a corner (a tangent discontinuity: the
/// trailing edge of an airfoil, the corner of a profile). Samples i whose turn, the angle
/// between the chords into and out of it at a stride where chords are at least 20 noise
/// deviations long, is at least 30 degrees and at least 5 times the turns at both its
/// stride neighbours. Throws InputError naming the samples (in the input's numbering,
/// `origin`) where the data run back along themselves: two consecutive turns beyond 135
/// degrees, as a pair of points out of order makes.
std::vector<Index> findCorners(const Samples& S, double sigma, const MergedInput& M);

// ---------------------------------------------------------------------------------------
// Local least-squares quadratics: the noise-smoothed estimate, curvature and noise residual

struct LocalFit {
  Vector3d point;          // the fitted graph above q_i: q_i moved along the normal(s)
  double kappa = 0.0;      // signed curvature (planar fits), else 0
  double kappaStd = 0.0;   // its standard deviation for noise sigma = 1
  double residual2 = 0.0;  // |q_i - point|^2
  double hat = 0.0;        // the fit's leverage at q_i (its hat-matrix diagonal)
  bool ok = false;
};

/// Fit w(u) = a + b u + c u^2 to the 2k + 1 samples around q_i in the frame of the window's
/// chord (u along it, w the normal offsets; with a plane's unit `normal` nu the one normal
/// nu x e in that plane, the curvature signed about nu; without, two normals in 3D). The
/// window is shifted inside open data and wraps around closed data.
LocalFit localFit(const std::vector<Vector3d>& p, Index n, bool closed, Index i, Index k, const Vector3d* normal);
inline const Vector3d kPlaneZ = Vector3d::UnitZ();  // the plane of 2D data and of planar coordinates

/// The default noise: the median of the squared centre residuals r_i^2 / (1 - h_i) of
/// 7-sample local quadratic fits at up to 4096 samples spread over the data, divided by the
/// median of chi^2 with as many degrees of freedom as normals (0.455 planar, 1.386 in 3D),
/// so that Gaussian noise of standard deviation sigma per coordinate gives sigma. 3D data
/// that lie in a plane to rounding (1e-9 of their size: a road given with z = 0) have one
/// normal, as 2D data do (with two, their noise would read 0.57 of itself).
double estimateNoise(const Samples& S, int dim);

// ---------------------------------------------------------------------------------------
// The plane of the data (for the signs of curvature)

struct Plane {
  bool planar = false;
  Vector3d origin, e1, e2;
};

/// 2D data: the XY plane. 3D data: the least-squares plane when every sample lies within
/// `flatness` of it; otherwise not planar (curvature has no sign).
Plane dataPlane(const Samples& S, int dim, double flatness);

// ---------------------------------------------------------------------------------------
// The data's curvature signs above the noise, and its straight runs

struct StraightRun {
  Index first, last;  // sample indices (open runs only: first <= last)
  Vector3d c, e;      // the least-squares line
};

struct DataShape {
  int signChanges = 0;
  std::vector<StraightRun> straight;
};

/// Signed curvature of local quadratic fits over 2k + 1 samples at every `stride`-th sample
/// (k = kc): positive or negative where it exceeds 5 standard deviations of its noise (and
/// a sagitta of 1e-9 of the size, for noise-free data), else 0. A sign counts only where it
/// holds for kc samples or more. The sign changes of that sequence are those the data
/// supports. Runs of 0 longer than 2 kc whose samples lie within tolerance / 2 of one
/// least-squares line are straight: their estimates are put on that line, so that the
/// csr-spline reproduces the line there (eq. (6) with a vanishing curvature: mu = 0, c_i = p_i).
/// A run that reaches an end of open data has its line through that end point (interpolated).
DataShape dataShape(const Samples& S, const std::vector<Vector3d>& planarPoints, double sigma, double tolerance,
                    Index kc, bool planarFits);

// ---------------------------------------------------------------------------------------
// The curve's spans as cubic polynomials, and the projection of the samples

struct SpanPolys {
  std::vector<double> t;                   // knots t_0 .. t_m (one per subset point; + 1 closed)
  std::vector<std::array<Vector3d, 4>> c;  // C(t_j + x) = c0 + c1 x + c2 x^2 + c3 x^3
  bool closed = false;
  Index spans() const { return static_cast<Index>(c.size()); }
  double h(Index j) const { return t[j + 1] - t[j]; }
};

/// Span j of `occ` (a cubic with simple interior knots, clamped or periodic; knots t, as
/// SpanPolys::t) as its cubic polynomial about t_j, from the four poles and six knots around
/// it (O(1); OCCT's own evaluation costs O(knots) per point on such a curve).
std::array<Vector3d, 4> spanPoly(const Handle(Geom_BSplineCurve)& occ, const std::vector<double>& t, Index j);

/// Every span of `curve` (its OCCT twin `occ`) as its cubic polynomial about its start
/// knot, from OCCT's right-hand derivatives there.
SpanPolys spanPolys(const BSplineCurve& curve, const Handle(Geom_BSplineCurve)& occ);

/// The distance from p to the curve point reached by Newton's method on (C - p) . C' = 0
/// from parameter x in span j (moving to a neighbouring span when it leaves this one). The
/// smallest distance met on the way: a curve point that near exists, so it bounds the true
/// distance from above.
double projectDistance(const SpanPolys& P, const Vector3d& p, Index j, double x);

/// A curve point near a sample: span, parameter in it (from the span's start) and distance.
struct Foot {
  Index span = 0;
  double x = 0.0, d = 0.0;
};

/// projectDistance with the curve point it found.
Foot projectFoot(const SpanPolys& P, const Vector3d& p, Index j, double x);

/// The curvature of the curve of P at perSpan + 1 points per span (spans sharing their ends),
/// signed about `normal` when given, else its magnitude; arc length by chords. For
/// curvatureSignChanges and curvatureExtrema (analysis.hpp) in O(spans), where
/// curvatureProfile's OCCT evaluation costs O(knots) per point.
CurvatureProfile spanProfile(const SpanPolys& P, const std::optional<Vector3d>& normal, int perSpan);

/// Sign changes of the curvature about `normal` over the given spans of P in that order (16
/// samples a span; curvatures of at most zeroKappa have no sign).
int signChangesOver(const SpanPolys& P, const std::vector<Index>& spans, const Vector3d& normal, double zeroKappa);

// ---------------------------------------------------------------------------------------
// Step 10: thinning (fair_fit_thinning.cpp) and fairing (fair_fit_fairing.cpp)

/// What step 10 may change and must keep.
struct Polishing {
  double tolerance = 0.0;
  /// The samples, and the sample index at each knot (the subset: m + 1 values, the last past
  /// n - 1 when closed): span j's samples are at[j] .. at[j + 1].
  const Samples* samples = nullptr;
  std::vector<Index> at;
  /// Each sample's curve point (at sample index - at[0]), from the last distance check.
  std::vector<Foot> feet;
  /// Open curves: poles 0 .. fixedStart - 1 and the last fixedEnd poles, and the knots their
  /// end conditions depend on, do not change (2: end point and tangent leg; 3 with an end
  /// curvature).
  Index fixedStart = 2, fixedEnd = 2;
  /// Planar curves: the plane's normal, for the signs of curvature (kept from increasing).
  std::optional<Vector3d> normal;
  /// Curvatures of at most this size have no sign.
  double zeroKappa = 0.0;
  /// Out, when the curve changed: the largest distance of the samples to it (an upper
  /// bound, verified over every sample on the final curve).
  double maxDeviation = HUGE_VAL;
};

/// Fairing: `feet` may be empty (then the samples are projected here).
struct Fairing : Polishing {
  /// At most this many pole moves.
  Index maxMoves = 0;
};

/// Fair `occ` and its span polynomials P in place: knot by knot, largest jump first, the
/// pole centred on a knot is moved to make the curve C3 there (or half or a quarter of the
/// way), when every sample of the spans it changes stays within the tolerance and their
/// curvature sign changes do not increase. Returns the moves made.
Index fairThirdDerivativeJumps(const Handle(Geom_BSplineCurve)& occ, SpanPolys& P, Fairing& f);

/// Thinning: `feet` required; out: `at` and `feet` of the thinned curve.
using Thinning = Polishing;

/// Remove interior knots of `occ` (a cubic with simple knots) one at a time, in order of
/// their estimated removal error, by OCCT's knot removal, when every sample near the changed
/// spans stays within the tolerance and their curvature sign changes do not increase; up to
/// three passes, within a work budget of about 20 sample evaluations per sample. Returns the
/// thinned curve (a new one), or `occ` itself: when no knot was removed (then `t` is as
/// given) or the final check over all samples failed (then `t.at` is as given and `t.feet`
/// is empty).
Handle(Geom_BSplineCurve) removeKnots(const Handle(Geom_BSplineCurve)& occ, Thinning& t);

// ---------------------------------------------------------------------------------------
// The tolerance as a constraint (fair_fit_constrained.cpp): interpolation pins where the
// csr-spline relaxes beyond the tolerance, and fairing under the tolerance constraints

/// The cubic spline space of a fit: simple knots t_0 .. t_m, clamped (m + 3 poles; span j
/// depends on poles j .. j + 3) or periodic (m poles; span j on poles j .. j + 3 modulo m),
/// OCCT's numbering as in spanPoly.
struct SplineSpace {
  std::vector<double> t;
  bool periodic = false;
  Index spans() const { return static_cast<Index>(t.size()) - 1; }
  Index poles() const { return periodic ? spans() : spans() + 3; }
  /// Knot i of the span's six-knot window, continued past the ends (clamped: repeated;
  /// periodic: by the period).
  double knot(Index i) const;
  /// The index of the r-th pole of span j (r = 0 .. 3).
  Index pole(Index j, int r) const { return periodic ? (j + r) % spans() : j + r; }
  /// The values of the four B-splines of span j at t_j + x (Cox-de Boor; The NURBS Book, A2.2).
  std::array<double, 4> basis(Index j, double x) const;
  /// The second derivative at the start and at the end of span j (it is linear there) as
  /// weights of the span's four poles.
  std::array<std::array<double, 4>, 2> secondDerivative(Index j) const;
  /// The third derivative on span j (a constant) as weights of its four poles (de Boor's
  /// derivative poles, as spanPoly).
  std::array<double, 4> thirdDerivative(Index j) const;
};

/// Poles as an (poles x 3) matrix, and back into `curve` (dim columns kept).
Eigen::MatrixX3d polesOf(const BSplineCurve& curve);
void setPoles(BSplineCurve& curve, const Eigen::MatrixX3d& P);

/// Step 8's fall-back where the csr-spline of the samples themselves stays beyond the
/// tolerance: the poles move by the smoothest change (least third-derivative jump energy,
/// see fairUnderTolerance) that puts the curve through each pin's point at its knot,
/// C(t_j) = Q_j, the poles marked `fixed` kept. Pins at distinct knots: the constraint rows
/// have full rank (Schoenberg-Whitney: every site a knot, fewer sites than poles). Returns
/// false when the system is singular (the poles are then unchanged).
bool pinAtKnots(const SplineSpace& S, Eigen::MatrixX3d& P, const std::vector<std::pair<Index, Vector3d>>& pins,
                const std::vector<char>& fixed);

/// Fairing under the tolerance (step 10): the poles P of a curve whose samples q_i lie within
/// `tolerance` of their curve points C(u_i) (feet) are moved towards the minimum of the
/// fairness energy E(P) = integral of |C''|^2 + sum_k |J_k|^2 hbar_k^3 (J_k the jump of C'''
/// at knot t_k) subject to |C(u_i) - q_i| <= tolerance for every sample, found by ADMM on
/// about 4000 of the samples and at most about 16000 of those beyond half the tolerance. P moves from the feasible start towards it as far as every
/// constraint allows (they are convex in P, so the segment from a feasible P stays feasible
/// up to the first one met): every sample stays within the tolerance at its own foot, and
/// the result's distances do too (an upper bound). Returns the energy before and after.
/// The samples a constrained fairing holds within the tolerance at their feet, and the poles it keeps.
struct HeldSamples {
  double tolerance = 0.0;
  const std::vector<Vector3d>* q = nullptr;  // the samples
  std::vector<Index> sample;                 // per foot: its sample index
  std::vector<Foot> feet;                    // span and parameter of each constrained point
  std::vector<char> fixed;                   // per pole
};
struct ConstrainedFairing : HeldSamples {
  int rounds = 200;  // ADMM iterations at most (fewer, down to 20, above 2000 samples)
  double energyBefore = 0.0, energyAfter = 0.0;
  int roundsUsed = 0;
};
void fairUnderTolerance(const SplineSpace& S, Eigen::MatrixX3d& P, ConstrainedFairing& f);

/// The fairness energy E of fairUnderTolerance as a (poles x poles) matrix: E(P) = sum over
/// the coordinates of P_c^T E P_c.
Eigen::SparseMatrix<double> fairnessEnergy(const SplineSpace& S);

// ---------------------------------------------------------------------------------------
// The data's curvature signs imposed (fair_fit_signs.cpp, step 11)

/// Where the data's curvature takes a sign: from sample `at` on (-1: from the start), `sign`.
struct SignSwitch {
  Index at;
  int sign;
};

/// The data's sign pattern (open planar data, in-plane coordinates `planar`, cumulative
/// chord lengths `s`, noise sigma): the headings of chords k samples long (k: the least whose
/// mean is 100 sigma) starting every ceil(k / 2) samples (independent neighbours), scanned
/// with hysteresis: a turn counts when the heading moves away
/// from its running extreme by more than 5 deviations of the two headings' noise (sqrt(2)
/// sigma / chord each). The first move gives the first sign (at = -1); each reversal a
/// switch at the heading's extreme (the inflection), in the middle of the stretch whose
/// headings stay within the noise of it (a straight between opposite turns). Empty when the
/// heading never moves beyond its noise. Its size - 1 is the number of sign changes.
std::vector<SignSwitch> turningPattern(const std::vector<Vector3d>& planar, const std::vector<double>& s, double sigma);

/// Span j's polynomial C(t_j + x) = sum_k c_k x^k as weights of its four poles: c_k = sum_r
/// W(k, r) P_(pole(j, r)).
using SpanWeights = Eigen::Matrix4d;
SpanWeights spanWeights(const SplineSpace& S, Index j);

/// One linearisation of the sign-constrained fairing (step 11): the poles P move to the least
/// fairness energy (fairnessEnergy) such that every sample's curve point lies within its
/// tolerance rows (sliding along the present tangent, or the 16-gon inscribed in its disc,
/// in the plane e1, e2; the poles' normal coordinates stay), and the four Bernstein
/// coefficients of T x C'' on each span (T the present tangent, C'' of the new poles; about
/// e1 x e2) exceed the margin times the span's speed cubed with the signs of spanSign: the
/// first the start's, the last the end's, the middle ones both when they agree. The sign rows
/// are elastic: `violated` names the spans whose rows could not be met. False (P unchanged)
/// when the QP did not converge within `iterations` or `work`.
struct SignedFairing : HeldSamples {
  std::vector<std::array<int, 2>> spanSign;  // per span: the sign at its start and at its end (0: free)
  Vector3d e1 = Vector3d::UnitX(), e2 = Vector3d::UnitY();
  int iterations = 200;  // interior point iterations at most
  double work = 0.0;     // rows times iterations left to spend (in and out); the QP fails past it
  /// Let each curve point slide along the present tangent (up to 4 tolerances, less where the
  /// curve bends), held within 0.95 of the tolerance across it: the distance is then only
  /// about within the tolerance, and the caller verifies it. Otherwise the 16-gon.
  bool slide = true;
  /// Per foot: how often its slide went beyond the tolerance (each time the slide is 0.3 times
  /// shorter and the bound across 0.05 tighter, down to 0.8).
  std::vector<char> hold;
  double margin = 0.0;  // the signed curvature asked for at least (Bernstein coefficients over speed^3)
  bool converged = false;
  std::vector<char> violated;  // out, per span: its signs could not be met (elastic slack used)
};
bool fairWithSigns(const SplineSpace& S, Eigen::MatrixX3d& P, SignedFairing& f);

}  // namespace fairsplines::detail::fairfit
