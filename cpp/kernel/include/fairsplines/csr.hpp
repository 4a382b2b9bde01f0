// Curvature-sensitive relaxed spline (csr-spline) and the quadratic design,
// Karčiauskas & Peters, "Curvature-sensitive splines and design with basic curves",
// Section 4, eq. (6), and Section 7, eq. (12).
#pragma once
#include "fairsplines/parameters.hpp"
#include "fairsplines/types.hpp"

namespace fairsplines {

/// How eq. (6) avoids dividing by a vanishing curvature sum.
enum class EpsilonRule {
  CaseDistinction,  ///< mu, nu := 1/2 where the curvature sum is <= epsilon (the paper's main form)
  Additive          ///< epsilon added to every curvature, no case distinction (the paper's alternative)
};

struct CsrOptions {
  Parametrization parametrization = Parametrization::Chordal;
  bool closed = false;
  /// Tolerance of eq. (6), relative to the data: curvatures are compared after
  /// multiplying by the diagonal of the samples' bounding box.
  double epsilon = 1e-9;
  EpsilonRule rule = EpsilonRule::CaseDistinction;
  /// Explicit parameters t_i (n values, n + 1 for closed data), strictly increasing;
  /// when given they replace `parametrization`.
  Eigen::VectorXd parameters;
};

/// csr-spline of eq. (6): a cubic C2 B-spline with simple knots at the samples'
/// parameters t_i; control point c_i is the curvature-weighted average of the cubic
/// blossoms, at (t_{i-1}, t_i, t_{i+1}), of the quadratic interpolants f_{i-1}, f_i, f_{i+1}.
///
/// Ends of open data (the paper is silent): the end quadratics continue outwards,
/// f_0 := f_1 and f_{n-1} := f_{n-2}. The curve is clamped, so it interpolates q_0 and
/// q_{n-1}; its end poles are the blossoms F[t_0,t_0,t_0] = q_0 and F[t_0,t_0,t_1] of f_1
/// (mirrored at the other end). It is C2 throughout, reproduces quadratic data exactly
/// and adds no turn at the ends that f_1 / f_{n-2} do not have.
/// Closed data give a periodic curve. Points whose squared distances leave double precision
/// (sizes of about 1e154 and more, or 1e-300 and less) are fitted divided by a power of two
/// and the poles multiplied back: the unit fit, scaled.
/// Throws InputError for samples validateSamples refuses (fewer than 3 rows, not 2 or 3
/// columns, a coordinate that is not finite, all points coincident, two consecutive points
/// (cyclically, when closed) coincident), an epsilon that is not positive and finite, given
/// parameters that are not n (n + 1 closed) finite, strictly increasing values or span more
/// than double precision holds, or a curve whose poles or knots are not finite
/// (requireValidCurve).
BSplineCurve csrSpline(PointsRef q, const CsrOptions& options = {});

/// Quadratic design of eq. (12): sparse samples to the quadratic Bézier pieces
/// {q_i, m_i, q_{i+1}} with shape handles m_i = mu_{i+1} m_i^L + (1 - mu_{i+1}) m_i^R.
/// Returned as a degree-2 B-spline with double interior knots at t_i (poles q_0, m_0,
/// q_1, m_1, ..., q_{n-1}); at the ends of open data the one available handle is used.
/// Points of extreme size are fitted as by csrSpline (scaled by a power of two and back).
/// Throws InputError for samples validateSamples refuses (fewer than 3 rows, not 2 or 3
/// columns, a coordinate that is not finite, all points coincident, two consecutive points
/// (cyclically, when closed) coincident), an epsilon that is not positive and finite, or a
/// curve that is not finite.
BSplineCurve quadraticDesign(PointsRef q, Parametrization parametrization = Parametrization::Chordal,
                             bool closed = false, double epsilon = 1e-9);

}  // namespace fairsplines
