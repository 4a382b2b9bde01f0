// Design with basic curves: marks on basic curves to one non-uniform cubic C2 NURBS,
// Karčiauskas & Peters, "Curvature-sensitive splines and design with basic curves",
// Section 5 (eqs. (7), (8), (3)), Section 6 (eqs. (9), (10)) and Fig. 9 (merging).
#pragma once
#include <vector>

#include "fairsplines/basic_curves.hpp"
#include "fairsplines/types.hpp"

namespace fairsplines {

/// Homogeneous points: rows (w x, w y, w z, w).
using HomogeneousPoints = Eigen::Matrix<double, Eigen::Dynamic, 4, Eigen::RowMajor>;

/// One basic piece of a design, as control polygon of a clamped rational cubic C2 spline
/// over its marks u_0 = 0 < u_1 < ... < u_m = 1.
struct PiecePolygon {
  Eigen::VectorXd marks;    ///< u_0 .. u_m (m + 1 values)
  HomogeneousPoints start;  ///< F[0,0,0], F[0,0,u_1]: the end extension (10) at u = 0
  HomogeneousPoints inner;  ///< c_i for i = 1..m-1, corresponding to the knot u_i
  HomogeneousPoints end;    ///< F[u_{m-1},1,1], F[1,1,1]: the end extension at u = 1
  bool exact = false;       ///< Section 6 (exact) or Section 5 (approximation)
  int marksAdded = 0;       ///< marks inserted to keep every weight positive
};

/// Checks marks given by a designer: finite, inside [0, 1], strictly increasing. Marks
/// at 0 or 1 (within 1e-12) are the ends and are dropped. Returns u_0 = 0, marks, u_m = 1.
/// Throws InputError for a mark that is not finite, outside [0, 1], not increasing, or too
/// close to its neighbour to be a knot (requireSeparateKnots).
Eigen::VectorXd completeMarks(const Eigen::VectorXd& marks);

/// Section 6: the exact rational C2 cubic of a homogeneous cubic with marks. Eq. (9):
/// c_i = f^h[u_{i-1}, u_i, u_{i+1}] (the blossom), and the end extension (10):
/// F[0,0,0], F[0,0,u_1] (mirrored at u = 1). Where a control weight would not be
/// positive (circle arcs of large sweep), marks are added at the middle of the widest
/// interval next to it until every weight is positive ("split just enough").
/// Throws InputError unless the cubic has 4 rows, for marks completeMarks refuses, or when 64
/// added marks cannot make every weight positive.
PiecePolygon exactPolygon(const HomogeneousBezier& cubic, const Eigen::VectorXd& marks);

/// Section 5 from the 2-jets of a curve at u_0..u_m (rows of f, df, d2f: derivatives in
/// u; 3 columns, or 4 for homogeneous jets of a rational curve). Per segment i the
/// quintic of eq. (7) is formed with h f', h^2 f'' (h = u_{i+1} - u_i), its 2-jet is
/// converted to degree 3 by eq. (8), and c_i follows from eq. (3). The ends use the
/// cubic 2-jets at u_0 and u_m (which is eq. (10) for those jets).
/// Throws InputError unless the 2-jets are given at every mark (ends included) with 3 (or 4,
/// homogeneous) coordinates, for jets that are not finite, or a curve that does not move.
PiecePolygon polygonFromJets(const PointMatrix& f, const PointMatrix& df, const PointMatrix& d2f,
                             const Eigen::VectorXd& marks);

/// Section 6 for rational curves of degree <= 3, Section 5 for the others.
/// Throws InputError as completeMarks, exactPolygon or polygonFromJets, or for jets or a
/// polygon that are not finite.
PiecePolygon piecePolygon(const BasicCurve& curve, const Eigen::VectorXd& marks);

/// The quintic pieces of eq. (7) over the segments of `marks` (6 rows per segment).
/// Throws InputError as piecePolygon, or for Bézier points that are not finite.
PointMatrix quinticPieces(const BasicCurve& curve, const Eigen::VectorXd& marks);

enum class JoinKind {
  Agree,     ///< end points equal: one shared control point
  Averaged,  ///< end points within the join tolerance: their average
  Edge       ///< end points apart: both, with the edge between them
};

struct PieceRange {
  double t0 = 0.0, scale = 1.0;  ///< the piece's u maps to the spline's t = t0 + scale u
};

struct Design {
  BSplineCurve curve;              ///< rational (or polynomial) clamped cubic, C2
  std::vector<JoinKind> joins;     ///< one per consecutive pair of pieces
  std::vector<PieceRange> ranges;  ///< one per piece
};

/// Fig. 9: one C2 cubic NURBS from the pieces' polygons. Between pieces the end points
/// agree, are averaged (closer than `joinTolerance`) or are joined by an edge; every new
/// control point gets beta := 1, the knot intervals of each piece are scaled to continue
/// the previous one, and each piece's homogeneous points are scaled so that the weights
/// meet at the joins. The interior of each piece, [u_2, u_{m-2}], stays exact (all of it
/// up to the free ends for the first and last piece). Throws InputError for no pieces or
/// a negative tolerance.
Design mergePieces(const std::vector<PiecePolygon>& pieces, double joinTolerance);

}  // namespace fairsplines
