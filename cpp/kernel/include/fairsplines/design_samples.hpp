// The unifying spline: a sampled-data piece for the design with basic curves,
// Karčiauskas & Peters, "Curvature-sensitive splines and design with basic curves",
// Section 1 and Fig. 1 (one cubic C2 spline for all three scenarios), Section 4 (the
// csr-spline, eq. (6)) and Fig. 9 (the merge). docs/READINGS.md, "The unifying spline".
#pragma once
#include "fairsplines/csr.hpp"
#include "fairsplines/design.hpp"

namespace fairsplines {

/// The csr-spline of samples q_0..q_{n-1} (Section 4, eq. (6); open data, n >= 3) as one
/// piece of a design: its control polygon over the marks u_i = (t_i - t_0) / (t_{n-1} - t_0),
/// the samples' parameters (chordal by default) mapped onto [0, 1], so m = n - 1. The
/// polygon is the csr-spline's own: start = (q_0, F[t_0,t_0,t_1] of f_1), inner = the
/// eq. (6) control points c_1..c_{n-2} (c_i belongs to the knot t_i), end =
/// (F[t_{n-2},t_{n-1},t_{n-1}] of f_{n-2}, q_{n-1}), every weight 1. mergePieces then joins
/// it to its neighbours by the rules of Fig. 9 like any basic piece: beta := 1 at the new
/// control point(s), the knot intervals of the piece scaled to continue the previous
/// piece's, so the piece keeps the csr-spline's own beta_i = h_i / h_{i-1} inside and the
/// design equals the csr-spline on [u_2, u_{m-2}] of the piece. `exact` is false.
/// Throws InputError as csrSpline does (fewer than 3 samples, samples not finite,
/// consecutive samples that coincide, all samples coincident, wrong shapes) and for
/// closed options (a piece is open).
PiecePolygon samplesPolygon(PointsRef q, const CsrOptions& options = {});

}  // namespace fairsplines
