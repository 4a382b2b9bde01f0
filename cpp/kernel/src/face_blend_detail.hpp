// Internal: what face_blend.cpp (the sides and the surface) and face_blend_fairness.cpp (the
// cross sections and the search of their magnitudes) and face_blend_fitted.cpp (the fitted
// boundary data) share (issue 29; docs/FACE_BLENDS.md).
#pragma once
#include <Eigen/Core>
#include <Geom2d_Curve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_Surface.hxx>
#include <array>
#include <string>
#include <vector>

#include "fairsplines/face_blend.hpp"

namespace fairsplines::face_blend_detail {

using Vec3 = Eigen::Vector3d;
using Vec4 = Eigen::Vector4d;
using Rows = Eigen::Matrix<double, Eigen::Dynamic, 4>;  // homogeneous poles (w x, w y, w z, w)
using Net = Eigen::Matrix<double, Eigen::Dynamic, 4>;   // a section's homogeneous Bezier points

/// Homogeneous boundary rows of one side: position, first and second cross-boundary derivative.
struct Boundary {
  Rows r0, d1, d2;  // nu x 4 each, in the common u-basis
};

// ---------------------------------------------------------------------------------------
// The blend's rows across: docs/FACE_BLENDS.md eq. (2.3)

struct Magnitudes {
  double alpha = 1.0, beta = 0.0;
};

/// Rows 0, 1 (, 2) of a Bezier of degree n in s matching the side to first (second) order under
/// v(s) = v0 - alpha s + beta s^2 / 2:  B_s = -alpha P_v,  B_ss = alpha^2 P_vv + beta P_v. A side
/// of continuity k (1: G1, 2: G2) sets rows 0 .. k; the degree across is n = kA + kB + 1.
template <class R>
std::array<R, 3> sideRows(const R& r0, const R& d1, const R& d2, const Magnitudes& m, int n) {
  const R r1 = r0 - (m.alpha / n) * d1;
  const R r2 = 2.0 * r1 - r0 + (m.alpha * m.alpha * d2 + m.beta * d1) / (n * (n - 1.0));
  return {r0, r1, r2};
}

// ---------------------------------------------------------------------------------------
// Cross sections: rational Bezier curves in s (face_blend_fairness.cpp)

struct SectionData {
  double u = 0.0;
  Vec4 a0, a1, a2, b0, b1, b2;  // the boundary rows of both sides at u
};

struct Sampled {
  int extrema = 0;
  double variation = 0.0, kappaMin = 0.0, kappaMax = 0.0;
  bool folded = false;
};

constexpr int kSamples = 96;        // per section in the report
constexpr int kSearchSamples = 48;  // per section in the fairness search

/// The Bezier points of the section at d.u with the sides' magnitudes: rows 0 .. kA of side A,
/// rows n - kB .. n of side B, degree n = kA + kB + 1 (3, 4 or 5).
Net sectionNet(const SectionData& d, const Magnitudes& ma, const Magnitudes& mb, int kA, int kB);

/// Value and first two derivatives of a Bezier of degree n <= 5 at s.
std::array<Vec4, 3> bezierJet(const Net& c, double s);

/// Curvature of the rational section at samples + 1 points (samples <= kSamples): sign changes
/// of dkappa/ds, the scale-free variation L^3 int kappa_s^2 ds, and (selfApproach) whether the
/// section comes back near itself.
Sampled sampleSection(const Net& c, int samples, bool selfApproach);

// ---------------------------------------------------------------------------------------
// The fairness search (docs/FACE_BLENDS.md section 3)

struct Search {
  const std::vector<SectionData>& sections;
  const Boundary& A;
  const Boundary& B;
  double alpha0A, alpha0B;
  int kA, kB;  ///< each side's continuity (1: G1, 2: G2); the degree across is kA + kB + 1
  int evaluations = 0;

  /// Every weight of the blend's rows stays above 1e-3 of the boundary's smallest (the rows'
  /// weights are those of eq. (2.3), column 3).
  bool positiveWeights(const Boundary& side, const Magnitudes& m, int k) const {
    const double floor = 1e-3 * side.r0.col(3).minCoeff();
    const auto rows = sideRows<Eigen::VectorXd>(side.r0.col(3), side.d1.col(3), side.d2.col(3), m, kA + kB + 1);
    return rows[1].minCoeff() > floor && (k == 1 || rows[2].minCoeff() > floor);
  }

  Magnitudes magnitudes(double scale, double bend, double alpha0) const {
    return Magnitudes{scale * alpha0, bend * scale * alpha0};
  }
  /// Fewest extrema first (1000 per extremum), then the least variation; folds and weights that
  /// would turn negative are refused (infinite cost).
  double cost(const std::array<double, 4>& x);
};

// ---------------------------------------------------------------------------------------
// Fitted sides (face_blend_fitted.cpp; docs/FACE_BLENDS.md section 1b)

// The tolerances: position over the blend's size, normal angle in degrees, normal
// curvature over the curvature scale.
constexpr double kGapTolerance = 1e-7, kAngleTolerance = 1e-4, kCurvatureTolerance = 1e-4;

/// An edge on its face that is not an isoparametric boundary: the face's surface, the edge's
/// pcurve on it over [from, to] (u = 0 and u = 1), and the side the face lies on.
struct FittedEdge {
  Handle(Geom_Surface) surface;
  Handle(Geom2d_Curve) pcurve;
  double from = 0.0, to = 1.0;
  double inward = 1.0;  ///< +1: the face lies left of the pcurve's direction in the parameter plane; -1: right
  std::string edgeName, faceName;
};

/// The fitted side: a B-spline surface of v-degree 2 whose rows are C, T, K (u in [0, 1]), and
/// how the fit went (its spans, the rounds of halving, the samples, the worst misfit at the check
/// points: gap over the size, angle in degrees, curvature over the curvature scale).
struct FittedSide {
  Handle(Geom_BSplineSurface) surface;
  int spans = 0, refinements = 0, samples = 0;
  double gap = 0.0, angle = 0.0, curvature = 0.0;
};

/// Samples the face along the edge, fits C, T, K and refines until the fit meets a tenth of the
/// tolerances between its samples (continuity 1: position and normal; 2: also normal curvature).
/// Throws InputError naming the edge when the budget is spent, or where the face is singular.
FittedSide fitSide(const FittedEdge& edge, int continuity, double size);

/// Normal curvature II(d, d) / I(d, d) of the tangent direction d of a surface with derivatives
/// Xu, Xv, Xuu, Xuv, Xvv, against the unit normal N (d is written a Xu + b Xv by least squares).
double normalCurvature(const Vec3& Xu, const Vec3& Xv, const Vec3& Xuu, const Vec3& Xuv, const Vec3& Xvv, const Vec3& N,
                       const Vec3& d);

/// The scalars (scale_a, bend_a, scale_b, bend_b) of the fairest sections: a grid of the scales,
/// then a pattern search. Throws InputError when every candidate folds.
std::array<double, 4> searchMagnitudes(Search& search, const FaceBlendOptions& o);

}  // namespace fairsplines::face_blend_detail
