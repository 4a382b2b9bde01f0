// Internal: the eq. (6) machinery shared by the csr-spline and the quasi-interpolant.
#pragma once
#include <optional>

#include "fairsplines/csr.hpp"

namespace fairsplines::detail {

/// Two implementations of the same poles: one streaming pass with a window of three
/// quadratics (the reference), or vectorised passes over per-coordinate arrays, window
/// by window so that they stay in cache (fastest). Tests hold them equal.
enum class CsrStrategy { Streaming, Vectorised };

/// From this many samples fitCubic picks the vectorised strategy; its window length.
constexpr Eigen::Index kVectorisedFrom = 128, kWindow = 256;

/// The strategy fitCubic picks for n samples.
CsrStrategy defaultStrategy(Eigen::Index n);

/// Cubic C2 spline with knots t over validated samples q: csr poles of eq. (6), or,
/// with `quasiOnly`, c_i := p_i (the quasi-interpolant). Ends as documented at csrSpline.
/// `size` is the data's bounding-box diagonal (epsilon is relative to it). The vectorised
/// strategy works in windows of `window` points (0: kWindow, as measured fastest; at
/// least 8). The parameters t become the curve's knots (moved in when given an rvalue).
BSplineCurve fitCubic(PointsRef q, Eigen::VectorXd t, bool closed, double size, double epsilon, EpsilonRule rule,
                      bool quasiOnly, std::optional<CsrStrategy> strategy = std::nullopt, Eigen::Index window = 0);

/// The poles of fitCubic written to `poles` (contiguous rows of q's width: n + 2 for open
/// data, n for closed data in OCCT's periodic order); t holds n parameters (n + 1 closed).
void cubicPolesInto(PointsRef q, const double* t, bool closed, double size, double epsilon, EpsilonRule rule,
                    bool quasiOnly, std::optional<CsrStrategy> strategy, Eigen::Index window, double* poles);

/// The csr-spline of csrSpline(q, options) into t (its knots: n values, n + 1 closed) and
/// poles (contiguous rows of q's width: n + 2, n closed). Open data of kVectorisedFrom
/// points or more takes one streaming pass (validation, parameters and poles window by
/// window); the values are the same.
void csrSplineInto(PointsRef q, const CsrOptions& options, double* t, double* poles);

}  // namespace fairsplines::detail
