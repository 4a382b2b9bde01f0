// Internal: the eq. (6) machinery shared by the csr-spline and the quasi-interpolant.
#pragma once
#include "fairsplines/csr.hpp"

namespace fairsplines::detail {

/// Cubic C2 spline with knots t over validated samples q: csr poles of eq. (6), or,
/// with `quasiOnly`, c_i := p_i (the quasi-interpolant). Ends as documented at csrSpline.
/// `size` is the data's bounding-box diagonal (epsilon is relative to it).
BSplineCurve fitCubic(PointsRef q, const Eigen::VectorXd& t, bool closed, double size, double epsilon,
                      EpsilonRule rule, bool quasiOnly);

}  // namespace fairsplines::detail
