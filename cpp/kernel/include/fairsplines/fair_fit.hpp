// Fair fit (issue 16): a cubic C2 spline within a tolerance of every sample, with few
// poles and no more curvature sign changes than the data supports. Built on the
// csr-spline of Karčiauskas & Peters, "Curvature-sensitive splines and design with basic
// curves", Section 4, eq. (6), applied to an adaptive subset of noise-smoothed samples.
// The method, what is guaranteed and what is heuristic: docs/FAIR_FIT.md.
#pragma once
#include <optional>
#include <vector>

#include "fairsplines/types.hpp"

namespace fairsplines {

struct FairFitOptions {
  /// The hard bound: every sample lies within this distance of the curve (absolute, in the
  /// samples' units). Must be positive and finite.
  double tolerance = 0.0;
  /// Periodic curve through closed data (the last sample is not repeated).
  bool closed = false;
  /// The samples' noise: the standard deviation of their scatter about the curve, per
  /// coordinate (absolute). Empty: estimated from the residuals of local quadratic fits
  /// (docs/FAIR_FIT.md). 0 means noise-free data (samples are used as they are).
  std::optional<double> noise;
  /// Open data only: unit directions the curve leaves q_0 / arrives at q_{n-1} with
  /// (normalised here; any non-zero length).
  std::optional<Eigen::VectorXd> startTangent, endTangent;
  /// Open data only, with the tangent of the same end: the curvature vector there
  /// (kappa times the unit principal normal; its part along the tangent is ignored).
  /// The zero vector asks for zero curvature.
  std::optional<Eigen::VectorXd> startCurvature, endCurvature;
  /// Thin and fair the fit once it is within the tolerance: remove the knots and then the
  /// third-derivative jumps at the knots that the tolerance allows (fewer poles, fewer
  /// curvature extrema; docs/FAIR_FIT.md, step 10). false gives the csr-spline of the subset
  /// as it is.
  bool fairing = true;
  /// Sharp corners of the data (a turn concentrated at one sample, such as an airfoil's
  /// trailing edge; docs/FAIR_FIT.md, step 1): Refuse throws InputError naming them; Keep
  /// fits each stretch between corners on its own (the pieces meet at the corners); Smooth
  /// fits one smooth curve through them and reports them. Closed data with one corner are
  /// fitted from the corner round to it under every choice: one curve, the corner kept.
  enum class Corners { Refuse, Keep, Smooth };
  Corners corners = Corners::Refuse;
};

/// What fairFitReport learned, for a feature's status line.
struct FairFitResult {
  BSplineCurve curve;
  double maxDeviation = 0.0;          ///< the largest sample-to-curve distance found (an upper bound)
  int signChanges = 0;                ///< curvature sign changes of the curve (0 when not planar)
  int dataSignChanges = 0;            ///< sign changes of the data's smoothed curvature above its noise
  int curvatureExtrema = 0;           ///< interior curvature extrema of the curve
  double noise = 0.0;                 ///< the noise used (given or estimated)
  int iterations = 0;                 ///< refinement passes
  Eigen::Index mergedPoints = 0;      ///< input points merged into a coincident neighbour
  bool closed = false;                ///< the data were fitted as closed (given, or recognised)
  bool recognisedClosed = false;      ///< open data whose last point repeats the first: closed
  std::vector<Eigen::Index> corners;  ///< the input points found to be corners (numbered from 0)
  int pinned = 0;                     ///< samples the curve was made to pass through (step 8)
  /// Corners::Keep: the pieces between corners, in order (curve is the first); else curve alone.
  std::vector<BSplineCurve> pieces;
};

/// The fair fit of samples q (n x 2 or n x 3, in order): a clamped (open) or periodic
/// (closed) cubic C2 B-spline with simple interior knots, whose every sample lies within
/// options.tolerance of the curve (verified by projecting each sample onto the curve
/// before returning), which interpolates q_0 and q_{n-1} of open data (and meets the given
/// end tangents and curvatures), and which is the csr-spline (eq. (6)) of an adaptively
/// chosen subset of noise-smoothed samples, then thinned (knots removed) and faired (pole
/// moves) within the tolerance (options.fairing). Few poles, few curvature extrema, and no
/// more curvature sign changes than the data's smoothed curvature has above its noise, are
/// sought, not proved (docs/FAIR_FIT.md says which parts are heuristic; the result reports
/// both counts).
/// Consecutive points closer than 1e-3 of the tolerance (at most 1e-9 of the data's size)
/// are merged, and open data whose last point repeats the first are closed (without end
/// conditions). Where the csr-spline relaxes beyond the tolerance, the curve is made to pass
/// through the samples (step 8), so any tolerance above the noise is met.
/// Throws InputError for samples validateSamples refuses (fewer than 4 rows, not 2 or 3
/// columns, a coordinate that is not finite, all points coincident), points out of order
/// along the curve (naming them), corners under Corners::Refuse, a tolerance that is not positive and finite, a
/// noise that is negative or not finite, end conditions given for closed data, a tangent
/// that is zero or not finite or of the wrong dimension, a curvature without its tangent,
/// a tolerance that even the csr-spline of all samples does not reach (the message gives
/// the noise), an exhausted work budget, or a curve that is not finite (requireValidCurve).
FairFitResult fairFitReport(PointsRef q, const FairFitOptions& options);

/// fairFitReport(q, options).curve. Throws as fairFitReport.
BSplineCurve fairFit(PointsRef q, const FairFitOptions& options);

}  // namespace fairsplines
