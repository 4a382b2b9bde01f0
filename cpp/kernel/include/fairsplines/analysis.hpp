// Curve analysis shared by every capability: curvature samples, sign changes,
// extrema, distance to data. Works on any OCCT B-spline curve.
#pragma once
#include <Eigen/Core>
#include <Geom_BSplineCurve.hxx>
#include <gp_Vec.hxx>
#include <optional>
#include <vector>
#include "fairsplines/types.hpp"

namespace fairsplines {

/// Curvature from first and second derivative in 3D: |C' x C''| / |C'|^3.
/// Throws nothing: d1 = 0 gives NaN (0/0) or infinity.
double curvature3D(const gp_Vec& d1, const gp_Vec& d2);

/// Signed curvature of a planar curve with unit plane normal n: (C' x C'') . n / |C'|^3.
/// Throws nothing: d1 = 0 gives NaN (0/0) or infinity.
double signedCurvature(const gp_Vec& d1, const gp_Vec& d2, const gp_Vec& n);

/// Unit normal of the plane holding all poles, oriented with a non-negative z (then y,
/// then x) component; empty when the poles do not lie in one plane (relative tolerance).
/// Scale-invariant (the poles are measured divided by a power of two near their spread).
/// Throws InputError if the curve does not move (its poles coincide to double precision);
/// the curve must not be null (not checked).
std::optional<gp_Vec> planeNormal(const Handle(Geom_BSplineCurve)& curve, double relTol = 1e-9);

struct CurvatureProfile {
  Eigen::VectorXd u;      ///< parameters, increasing
  Eigen::VectorXd s;      ///< arc length from the start
  Eigen::VectorXd kappa;  ///< curvature, signed when `isSigned`
  bool isSigned = false;
  gp_Vec normal;  ///< plane normal the sign refers to (when isSigned)
};

/// Curvature at n parameters spread over the curve: every knot span gets samples in
/// proportion to its parameter length and at least `minPerSpan`, span ends included.
/// Measured on the curve scaled to size about 1 and scaled back, so a curve 1e300 or
/// 1e-300 in size gets its curvature. Throws InputError if the curve does not move, if its
/// derivative vanishes at a sample (the curvature is undefined there, named by u), or if a
/// curvature or length is beyond double precision; the curve must not be null and n,
/// minPerSpan should be >= 1 (not checked).
CurvatureProfile curvatureProfile(const Handle(Geom_BSplineCurve)& curve, int n, int minPerSpan = 8);

/// Sign changes of the signed curvature along the profile; samples with
/// |kappa| <= zeroTol * max|kappa| (or numerically zero for the curve's size) are skipped.
/// A non-planar curve has unsigned curvature: 0.
/// Throws nothing.
int curvatureSignChanges(const CurvatureProfile& profile, double zeroTol = 1e-6);

struct CurvatureExtremum {
  double u, s, kappa;
  bool maximum;  ///< true: local maximum of kappa, false: local minimum
};

/// Interior local extrema of kappa along the profile, refined by a parabola through
/// the three samples around each one.
/// Throws nothing (fewer than 3 samples: no extrema).
std::vector<CurvatureExtremum> curvatureExtrema(const CurvatureProfile& profile);

/// Largest distance from the points to the curve (rows of q, 2 or 3 columns),
/// by projection (sampling followed by Newton refinement).
/// Throws nothing; the curve must not be null and the points finite (not checked).
double maxDistanceToPoints(const Handle(Geom_BSplineCurve)& curve, PointsRef q);

}  // namespace fairsplines
