// Internal: the eq. (6) machinery shared by the csr-spline and the quasi-interpolant.
#pragma once
#include <optional>

#include "fairsplines/csr.hpp"

namespace fairsplines::detail {

/// Two implementations of the same poles: one streaming pass with a window of three
/// quadratics (least memory), or three vectorised passes over per-coordinate arrays
/// (fastest while those arrays stay in cache). Tests hold them equal.
enum class CsrStrategy { Streaming, Vectorised };

/// The strategy fitCubic picks for n samples.
CsrStrategy defaultStrategy(Eigen::Index n);

/// Cubic C2 spline with knots t over validated samples q: csr poles of eq. (6), or,
/// with `quasiOnly`, c_i := p_i (the quasi-interpolant). Ends as documented at csrSpline.
/// `size` is the data's bounding-box diagonal (epsilon is relative to it). The vectorised
/// strategy works in windows of `window` points (0: all at once up to 2^18 points, else
/// windows of 4096, as measured fastest).
BSplineCurve fitCubic(PointsRef q, const Eigen::VectorXd& t, bool closed, double size, double epsilon,
                      EpsilonRule rule, bool quasiOnly, std::optional<CsrStrategy> strategy = std::nullopt,
                      Eigen::Index window = 0);

}  // namespace fairsplines::detail
