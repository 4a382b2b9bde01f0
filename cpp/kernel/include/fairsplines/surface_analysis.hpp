// Surface fairness analysis on any OCCT face (issue 27): principal curvatures at
// parameters, continuity across the edges of a shape, and a curvature map.
//
// Sign convention (docs/SURFACE_ANALYSIS.md): a curvature is positive where the surface
// is convex as seen from the side its face normal points to, the face's orientation
// included (a sphere solid's face reads +1/R, the same face reversed -1/R). OCCT's
// GeomLProp_SLProps measures against the surface's own normal Su x Sv and calls a convex
// sphere negative; the conversion is made once, in surface_analysis.cpp (faceFrame).
#pragma once
#include <Eigen/Core>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>
#include <cstdint>
#include <string>
#include <vector>

#include "fairsplines/types.hpp"

namespace fairsplines {

/// The shape written as BRep text (BRepTools::Write, as Part's exportBrepToString), read
/// back. Throws InputError if the text is empty or not a BRep shape.
TopoDS_Shape readBrepShape(const std::string& text);

/// The face of a shape that is one face (a face, or a shell or compound of exactly one).
/// Throws InputError naming how many faces the shape has otherwise.
TopoDS_Face singleFace(const TopoDS_Shape& shape);

/// Per-point state of SurfaceCurvature::state.
enum class PointState : int {
  Regular = 0,     ///< two distinct principal curvatures and directions
  Umbilic = 1,     ///< k1 = k2 (a sphere, a plane): dir1 is the unit Su, dir2 = normal x dir1
  Degenerate = 2,  ///< Su x Sv vanishes (a sphere's pole): the limit from inside the face
};

/// The columns of surfaceCurvature's block: one column per scalar quantity, three per vector
/// (x, y, z), one row per point.
namespace curvature_column {
constexpr int k1 = 0, k2 = 1, gaussian = 2, mean = 3;  ///< principal, Gaussian and mean curvatures
constexpr int dir1 = 4, dir2 = 7;                      ///< unit principal directions; dir1 x dir2 = normal
constexpr int normal = 10;                             ///< unit face normal (Face.normalAt's)
constexpr int point = 13;                              ///< the surface point
constexpr int count = 16;
}  // namespace curvature_column

/// n x 16 values, column-major: each quantity's n values contiguous, a vector quantity's
/// three columns one after the other (numpy's C-ordered (16, n) array, whose rows are then the
/// quantities and whose (3, n) slices, transposed, the (n, 3) vectors).
using CurvatureBlock = Eigen::Matrix<double, Eigen::Dynamic, curvature_column::count>;
/// PointState per point.
using PointStates = Eigen::Matrix<std::int8_t, Eigen::Dynamic, 1>;

/// Principal curvatures at n points of one face, in the face's sign convention.
struct SurfaceCurvature {
  CurvatureBlock values;  ///< n x 16 (curvature_column)
  PointStates state;      ///< PointState per point

  auto k1() const { return values.col(curvature_column::k1); }  ///< k1 >= k2
  auto k2() const { return values.col(curvature_column::k2); }
  auto gaussian() const { return values.col(curvature_column::gaussian); }  ///< K = k1 k2
  auto mean() const { return values.col(curvature_column::mean); }          ///< H = (k1 + k2) / 2
  auto dir1() const { return values.middleCols<3>(curvature_column::dir1); }
  auto dir2() const { return values.middleCols<3>(curvature_column::dir2); }
  auto normal() const { return values.middleCols<3>(curvature_column::normal); }
  auto points() const { return values.middleCols<3>(curvature_column::point); }
};

/// Principal curvatures, directions and normal at the rows (u, v) of uv on the face's
/// surface (any OCCT surface: plane, analytic, Bezier, B-spline, rational, offset,
/// extrusion, revolution; the face's location and orientation applied), written into
/// `values` (uv.rows() x 16, see curvature_column) and `state` (uv.rows()): memory the caller
/// owns, such as one numpy array (the binding), so that the results are not copied.
/// At a degenerate point (Su x Sv = 0: a sphere's pole) the values are the limit taken from
/// inside the face; where that limit does not exist (a cone's apex) it throws.
/// Throws InputError if uv is not n x 2, has a NaN or infinite entry, lies outside the
/// face's parameter range by more than 10% of it, if the surface cannot be evaluated there
/// or its curvature is infinite (each naming the point, from 0), if the face is null, or if
/// values or state do not have uv.rows() rows or values' columns overlap (outer stride below
/// uv.rows()) (then nothing is written), or threads < 0.
/// threads: at most this many threads share a large call (0: one a core, at most 8), on
/// B-spline and Bezier faces, each thread taking 16384 points or more; the results do not
/// depend on it.
void surfaceCurvature(const TopoDS_Face& face, const PointsRef& uv, Eigen::Ref<CurvatureBlock> values,
                      Eigen::Ref<PointStates> state, int threads = 0);

/// The same into a SurfaceCurvature of its own.
SurfaceCurvature surfaceCurvature(const TopoDS_Face& face, const PointsRef& uv, int threads = 0);

/// Tolerances of the continuity verdict (docs/SURFACE_ANALYSIS.md).
struct ContinuityOptions {
  int samplesPerSpan = 0;            ///< samples inside each span; 0: adaptive (4, and by turning)
  double gapTolerance = -1.0;        ///< < 0: max(2 x the edge's tolerance, 1e-6 x the shape's size)
  double angleTolerance = 0.1;       ///< degrees
  double curvatureTolerance = 0.02;  ///< relative to the curvature scale along the edge
};

/// The continuity of one edge. Indices count from 1 in TopExp::MapShapes order, which is
/// FreeCAD's (Edge<i>, Face<j>).
struct EdgeContinuity {
  int edge = 0;
  std::vector<int> faces;         ///< the faces meeting at the edge (one for a boundary or a seam)
  std::string kind;               ///< "shared", "seam", "boundary", "degenerate", "non-manifold"
  std::string continuity;         ///< "gap", "G0", "G1", "G2", or "boundary" / "degenerate"
  double gap = 0.0;               ///< largest distance between the sides and the edge
  double angle = 0.0;             ///< largest angle between the normals, degrees
  double curvatureJump = 0.0;     ///< largest normal-curvature jump / curvatureScale
  double curvatureJumpAbs = 0.0;  ///< the same jump, 1/length
  double curvatureScale = 0.0;    ///< the largest normal curvature along the edge (>= 1 / shape size)
  Eigen::Vector3d gapPoint = Eigen::Vector3d::Zero(), anglePoint = Eigen::Vector3d::Zero(),
                  curvaturePoint = Eigen::Vector3d::Zero();                   ///< where each is largest
  double gapParameter = 0.0, angleParameter = 0.0, curvatureParameter = 0.0;  ///< the edge's parameters there
  int samples = 0;                                                            ///< evaluations made along the edge
};

/// One record per edge of the shape (TopExp::MapShapes order).
/// Throws InputError if the shape is null, has no edges, an option is negative or NaN, or an
/// edge's faces give values that are not finite (naming the edge).
std::vector<EdgeContinuity> edgeContinuity(const TopoDS_Shape& shape, const ContinuityOptions& options = {});

/// What curvatureMap colours by.
enum class MapQuantity { Gaussian, Mean, MaxAbs, Min, Max, Radius };

/// Parse "gaussian", "mean", "max_abs", "min", "max", "radius"; InputError otherwise.
MapQuantity parseMapQuantity(const std::string& name);

/// A triangulation of the shape's faces with the quantity at every vertex.
struct CurvatureMap {
  Eigen::MatrixX3d points;
  Eigen::MatrixX3d normals;     ///< the face's unit normal at each vertex, exact (orientation included)
  Eigen::MatrixX3i triangles;   ///< rows of vertex indices (from 0), counter-clockwise about the face normal
  Eigen::VectorXd values;       ///< the quantity at each vertex
  Eigen::VectorXi face;         ///< the face (from 1) of each triangle
  Eigen::MatrixX2d faceRanges;  ///< (min, max) of the values of each face
};

/// The shape meshed by BRepMesh (deflection <= 0: 1e-3 of its size; angle 0.35 rad), each
/// face's triangles split where the quantity changes by more than `fraction` of its range
/// over the shape (at most `levels` times, within a bound on the triangle count).
/// "radius" is 1 / max(|k1|, |k2|), capped at 1e3 x the shape's size where flat. A vertex at
/// a singular point (a cone's apex: no curvature there) takes the mean of its neighbours.
/// Throws InputError if the shape is null or has no faces, if the deflection is below 1e-6 of
/// the shape's size, or if the mesh fails.
CurvatureMap curvatureMap(const TopoDS_Shape& shape, MapQuantity quantity, double deflection = 0.0,
                          double fraction = 0.05, int levels = 3);

}  // namespace fairsplines
