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
#include <string>
#include <vector>

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

/// n x 3 rows (row-major: numpy's layout).
using Rows3d = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;

/// Principal curvatures at n points of one face, in the face's sign convention.
struct SurfaceCurvature {
  Eigen::VectorXd k1, k2;       ///< principal curvatures, k1 >= k2
  Eigen::VectorXd gaussian;     ///< K = k1 k2
  Eigen::VectorXd mean;         ///< H = (k1 + k2) / 2
  Eigen::MatrixX3d dir1, dir2;  ///< unit principal directions; dir1 x dir2 = normal
  Eigen::MatrixX3d normal;      ///< unit face normal (Face.normalAt's)
  Eigen::MatrixX3d points;      ///< the surface points
  Eigen::VectorXi state;        ///< PointState per point
};

/// Principal curvatures, directions and normal at the rows (u, v) of uv on the face's
/// surface (any OCCT surface: plane, analytic, Bezier, B-spline, rational, offset,
/// extrusion, revolution; the face's location and orientation applied).
/// At a degenerate point (Su x Sv = 0: a sphere's pole) the values are the limit taken from
/// inside the face; where that limit does not exist (a cone's apex) it throws.
/// Throws InputError if uv is not n x 2, has a NaN or infinite entry, lies outside the
/// face's parameter range by more than 10% of it, if the surface cannot be evaluated there
/// or its curvature is infinite (each naming the point, from 0), or if the face is null.
SurfaceCurvature surfaceCurvature(const TopoDS_Face& face, const Eigen::Ref<const Eigen::MatrixXd>& uv);

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
