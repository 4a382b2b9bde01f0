// Internal helpers of the blend complexes (Section 4.2 and Section 5 of Karčiauskas &
// Peters), shared by the C2 (blend_profile.cpp, blend_ring.cpp, blend_surface.cpp, blend_grid.cpp)
// and C1 (blend_c1.cpp) constructions.
#pragma once
#include <Geom_BSplineSurface.hxx>
#include <string>
#include <vector>

#include "fairsplines/blend_shapes.hpp"
#include "fairsplines/types.hpp"

namespace fairsplines::detail {

/// Tensor form of a surface of revolution (docs/READINGS.md, blending paper): circle rows (x w1, y w1, w1) in u
/// times profile rows (rho w2, zeta w2, w2) in v: b_ab = (rho_b x_a, rho_b y_a, zeta_b w_a | omega_b w_a)
/// in the frame; row a * profile.rows() + b. Any numbers of rows (any degrees).
Homogeneous4 revolveRows(const ShapeFrame& f, const Eigen::Ref<const PointMatrix>& circle, const Homogeneous3& profile);

/// Homogeneous Bézier patch of the span [u0,u1] x [v0,v1] of an OCCT B-spline surface, row
/// a (dv + 1) + b; du, dv receive its degrees. Throws InputError if the span is not one
/// Bézier patch (knots inside it).
Homogeneous4 bezierOf(const Handle(Geom_BSplineSurface)& s, double u0, double u1, double v0, double v1, int& du,
                      int& dv);

/// The exact rational Bézier Geom_BSplineSurface over [0,1]^2 of homogeneous rows (w p, w),
/// row a (degreeV + 1) + b holding b_ab. Throws InputError naming `what` for control points
/// that are not finite, for a non-positive weight, or where OpenCASCADE rejects the patch.
Handle(Geom_BSplineSurface) bezierPatchToOcct(const Homogeneous4& bezier, int degreeU, int degreeV,
                                              const std::string& what);

/// The interface data of a straight profile rho = radius0 + slope z over `heights` (checked
/// by checkHeights), for the C2 and the C1 shapes alike: (rho, zeta) at the last and first
/// height, the unit direction leaving each, and the length of the end pieces.
template <class Profile>
void setLineEnds(Profile& p, double radius0, double slope, const Eigen::VectorXd& heights) {
  const Eigen::Index m = heights.size() - 1;
  p.end << radius0 + slope * heights[m], heights[m];
  p.tangent = Eigen::Vector2d(slope, 1.0).normalized();
  p.size = heights[m] - heights[m - 1];
  p.start << radius0 + slope * heights[0], heights[0];
  p.startTangent = -p.tangent;
  p.startSize = heights[1] - heights[0];
}

/// The interface data of a rational cubic profile (issue 32; Bézier pieces of 4 homogeneous
/// rows (w rho, w zeta, w)), for the C2 and the C1 shapes alike: (rho, zeta) at the last and
/// first point, the unit direction leaving each (the projected end derivative), and the
/// length of the end pieces' control polygons.
template <class Profile>
void setCurveEnds(Profile& p, const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>& first,
                  const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>& last) {
  auto point = [](const Eigen::RowVector3d& h) { return Eigen::Vector2d(h[0] / h[2], h[1] / h[2]); };
  auto polygon = [&](const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>& q) {
    double length = 0.0;
    for (Eigen::Index k = 1; k < q.rows(); ++k) length += (point(q.row(k)) - point(q.row(k - 1))).norm();
    return length;
  };
  // The projected derivative at an end b_n leaving towards the direction of b_n - b_{n-1}
  // (the first inner point that differs): (d_xy - d_w p) / w, d = b_n - b_k.
  auto leaving = [&](const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>& q, bool atEnd) {
    const Eigen::Index n = q.rows() - 1;
    const Eigen::RowVector3d b = atEnd ? q.row(n) : q.row(0);
    for (Eigen::Index k = 1; k <= n; ++k) {
      const Eigen::RowVector3d d = b - (atEnd ? q.row(n - k) : q.row(k));
      const Eigen::Vector2d v = (Eigen::Vector2d(d[0], d[1]) - d[2] * point(b)) / b[2];
      if (v.norm() > 1e-14 * (point(b).norm() + polygon(q))) return Eigen::Vector2d(v.normalized());
    }
    return Eigen::Vector2d(0.0, atEnd ? 1.0 : -1.0);
  };
  p.end = point(last.row(last.rows() - 1));
  p.tangent = leaving(last, true);
  p.size = polygon(last);
  p.start = point(first.row(0));
  p.startTangent = leaving(first, false);
  p.startSize = polygon(first);
}

/// Heights of a cylinder or cone profile (radius radius0 + slope z): at least two, finite,
/// increasing, with a positive radius at each. Throws InputError naming the first offender.
void checkHeights(const Eigen::VectorXd& heights, double radius0, double slope);

/// A free-form ring that must have exactly the knots T in u (one period): periodic (closed;
/// else clamped), of the
/// given degree in u and v with simple u knots, clamped in v; returned with `cuts` inserted.
/// Throws InputError "the free-form net does not match the interface: ..." naming the problem.
Handle(Geom_BSplineSurface) matchRingStrict(const Handle(Geom_BSplineSurface)& ring, const Eigen::VectorXd& T,
                                            const Eigen::VectorXd& cuts, int degree, bool closed);

/// A user ring's structure (periodic in u for a full turn of the shape, `turn` = 2 pi, else
/// clamped in u; of `degree` in u and v; clamped in v) and its first row turning about the
/// frame's axis by about `turn` in the direction of u; returns a copy whose u range is mapped
/// affinely onto [0, period] (its first knot to the shape's first angle).
/// Throws InputError "the free-form net does not match the interface: ..." otherwise.
Handle(Geom_BSplineSurface) normalisedRing(const Handle(Geom_BSplineSurface)& ring, const ShapeFrame& frame,
                                           double period, int degree, double turn);

/// The ring with every knot of `knotsU` it lacks inserted (each u-interval one Bézier span).
Handle(Geom_BSplineSurface) withKnots(const Handle(Geom_BSplineSurface)& ring, const Eigen::VectorXd& knotsU);

/// Local cuts (per piece of knotsU) where the ring has u knots inside the pieces.
std::vector<std::vector<double>> ringCuts(const Handle(Geom_BSplineSurface)& ring, const Eigen::VectorXd& knotsU);

/// Local cuts (per piece of knotsU, increasing) at the increasing `values` that fall inside
/// a piece (more than 1e-9 of the span from its ends).
std::vector<std::vector<double>> knotCuts(const Eigen::VectorXd& values, const Eigen::VectorXd& knotsU);

/// Bézier pieces of `order` rows each over `knots`, split at the local cuts: the pieces,
/// their knots, and where each old piece starts (first, one more entry).
struct SplitPieces {
  PointMatrix bezier;
  Eigen::VectorXd knots;
  std::vector<int> first;
};
SplitPieces splitBezierPieces(const PointMatrix& bezier, int order, const Eigen::VectorXd& knots,
                              const std::vector<std::vector<double>>& cuts);

/// The rows of a default ring beyond the interface (issue 15): the first `offset` along the
/// profile's exit tangent, then one every `step`. The full ring (fraction 1) has offset
/// size / 2 and step size / 4. Where the tangent runs towards the axis the whole ring is
/// shortened by one factor, `fraction`, so that its last row keeps 5% of the shape's extent
/// (|coordinates| + size) off the axis.
struct RingRows {
  double offset = 0.0, step = 0.0, fraction = 1.0;
};

/// How much of the full default ring of `rows` rows fits beyond the interface `end`
/// (rho, z) with exit direction `tangent` and last-piece length `size`: 1 when all of it
/// does, less where the ring must be shortened, <= 0 where not even the interface is clear
/// of the axis.
double defaultRingRoom(const Eigen::Vector2d& end, const Eigen::Vector2d& tangent, double size, int rows);

/// The rows of the default ring, shortened to the room there is (defaultRingRoom). Throws
/// InputError naming the room when less than a twentieth of the ring fits ("which": the end of
/// the profile, for the message).
RingRows defaultRingRows(const Eigen::Vector2d& end, const Eigen::Vector2d& tangent, double size, int rows,
                         const char* which);

}  // namespace fairsplines::detail
