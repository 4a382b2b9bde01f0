// Baselines the csr-spline is compared with (paper, Fig. 2 and Fig. 15).
#pragma once
#include <Geom_BSplineCurve.hxx>
#include "fairsplines/parameters.hpp"
#include "fairsplines/types.hpp"

namespace fairsplines {

/// Classic C2 cubic interpolation (OCCT GeomAPI_Interpolate) at the same parameters
/// as the other constructions. Needs at least 2 samples (3 when closed).
Handle(Geom_BSplineCurve) classicInterpolation(PointsRef q, Parametrization parametrization, bool closed);

/// The cubic quasi-interpolant: c_i := p_i, the blossom of f_i at (t_{i-1}, t_i, t_{i+1}),
/// i.e. (-1, 8, -1)/6 for uniform parameters. Same knots and ends as csrSpline.
/// Throws InputError for samples validateSamples refuses (fewer than 3 rows, not 2 or 3
/// columns, a coordinate that is not finite, all points coincident, two consecutive points
/// (cyclically, when closed) coincident), or a curve that is not finite.
BSplineCurve quasiInterpolant(PointsRef q, Parametrization parametrization, bool closed);

/// The "data as control points" cubic B-spline, uniform knots, clamped when open,
/// periodic when closed. Needs at least 4 samples (3 when closed).
/// Throws InputError for samples validateSamples refuses (fewer than 4 (3 closed) rows, not 2
/// or 3 columns, a coordinate that is not finite, all points coincident, two consecutive points
/// (cyclically, when closed) coincident).
BSplineCurve controlPointSpline(PointsRef q, bool closed);

}  // namespace fairsplines
