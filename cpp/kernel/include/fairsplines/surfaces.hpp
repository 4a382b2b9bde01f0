// Tensor-product constructions: eq. (11) of Karčiauskas & Peters, "Curvature-sensitive
// splines and design with basic curves", and exact surfaces of revolution of designed
// profiles (the paper's "profile test").
#pragma once
#include <Geom_BSplineSurface.hxx>
#include <TopoDS_Face.hxx>
#include <string>

#include "fairsplines/types.hpp"

namespace fairsplines {

/// A B-spline surface in OpenCASCADE's layout; pole (i, j) is row i * nv + j.
struct BSplineSurface {
  int degreeU = 3, degreeV = 3;
  int nu = 0, nv = 0;
  PointMatrix poles;        ///< nu * nv rows, 3 columns
  Eigen::VectorXd weights;  ///< empty, or nu * nv
  Eigen::VectorXd knotsU, knotsV;
  Eigen::VectorXi multsU, multsV;
  bool periodicU = false, periodicV = false;
};

/// Eq. (11): the bicubic control points c_ij (i = 1..nI, j = 1..nJ) from the interior
/// Bézier points b_11, b_12, b_21, b_22 of patch (i-1, j-1), with the geometric continuity
/// scalars betaU_i, betaV_j (sizes nI + 1 and nJ + 1: index i, j). `bezier` holds the
/// patches' 4 x 4 points: row ((I * nJ + J) * 16 + 4 r + s) is b_rs of patch (I, J).
/// Returns nI * nJ rows (row (i-1) * nJ + (j-1)). Works coordinate-wise (3 or 4 columns).
/// Throws InputError unless bezier holds 16 points per patch of the nI x nJ grid (nI, nJ >= 1)
/// and betaU, betaV one per control row (nI + 1, nJ + 1).
PointMatrix tensorControlNet(const PointMatrix& bezier, int nI, int nJ, const Eigen::VectorXd& betaU,
                             const Eigen::VectorXd& betaV);

/// The exact surface of revolution of a profile curve about an axis: the profile's
/// (rational) B-spline in u, times the rational quadratic circle (four quarter arcs) in v.
/// Any profile works (each pole turns about the axis). Throws InputError for a zero axis
/// direction or a profile that lies on the axis.
BSplineSurface revolve(const BSplineCurve& profile, const Eigen::Vector3d& axisPoint,
                       const Eigen::Vector3d& axisDirection);

/// Exact conversion; throws InputError when OCCT rejects the data.
Handle(Geom_BSplineSurface) toOcct(const BSplineSurface& surface);

/// Exact conversion back (weights always filled); throws nothing, the handle must not be null.
BSplineSurface fromOcct(const Handle(Geom_BSplineSurface)& surface);

/// The face bounded by the surface's own boundary (BRepBuilderAPI_MakeFace), as it leaves the
/// kernel: throws InputError naming `what` when OCCT's check (BRepCheck_Analyzer) calls it not
/// valid, e.g. a surface 1e12 from the origin and 1 across, or of denormal size.
TopoDS_Face validFace(const Handle(Geom_BSplineSurface)& surface, const std::string& what);

}  // namespace fairsplines
