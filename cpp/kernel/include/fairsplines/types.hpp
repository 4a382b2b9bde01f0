// Plain data types shared by every capability of the kernel.
#pragma once
#include <Eigen/Core>

namespace fairsplines {

/// Points stored as rows: an (n x dim) matrix with dim 2 or 3.
using PointMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

/// Read-only view of points (no copy for row-major, row-contiguous data such as a
/// C-ordered numpy array).
using PointsRef = Eigen::Ref<const PointMatrix>;

/// A B-spline curve in OpenCASCADE's layout: distinct knots with multiplicities.
/// For a periodic curve, as in OCCT, the first and last knot bound one period and
/// the number of poles equals the sum of the multiplicities minus the last one.
struct BSplineCurve {
  int degree = 3;
  PointMatrix poles;        ///< n x dim control points
  Eigen::VectorXd weights;  ///< empty for a polynomial curve, else one weight per pole
  Eigen::VectorXd knots;    ///< strictly increasing distinct knots
  Eigen::VectorXi mults;    ///< multiplicity of each knot
  bool periodic = false;

  bool isRational() const { return weights.size() > 0; }
  int dimension() const { return static_cast<int>(poles.cols()); }
};

}  // namespace fairsplines
