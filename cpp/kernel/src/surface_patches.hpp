// A B-spline or Bezier face's surface evaluated to second order from its knot spans' patches
// in power form (issue 27, the speed of surfaceCurvature): each span's rational tensor-product
// polynomial about its corner, in homogeneous coordinates with the face's location applied,
// evaluated by Horner's rule. Used by FaceSurface (surface_analysis_detail.hpp) in place of
// OCCT's adaptor, which costs a virtual call, a span search in its cache and a transformation
// of every result per point.
#pragma once
#include <Eigen/Core>
#include <TopoDS_Face.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>
#include <memory>
#include <vector>

namespace fairsplines::detail {

class PowerPatches {
public:
  /// The patches of a face whose surface is a B-spline or Bezier surface of degree at most
  /// kMaxDegree each way (the power form loses about log10 C(p, p/2) digits: 2 at degree 7);
  /// nullptr for any other face.
  static std::unique_ptr<PowerPatches> of(const TopoDS_Face& face);

  /// S and its first and second partial derivatives at (u, v), as BRepAdaptor_Surface::D2
  /// gives them (location applied; outside the range, the end spans' polynomials continued).
  void d2(double u, double v, gp_Pnt& p, gp_Vec& su, gp_Vec& sv, gp_Vec& suu, gp_Vec& svv, gp_Vec& suv) const;

  static constexpr int kMaxDegree = 7;

private:
  int p_ = 0, q_ = 0;                     ///< degrees in u and v
  double uFirst_ = 0.0, vFirst_ = 0.0;    ///< the surface's first parameters
  double uPeriod_ = 0.0, vPeriod_ = 0.0;  ///< periods of periodic directions (0: not periodic)
  std::vector<double> uBreaks_;           ///< distinct knots in u (spans + 1)
  std::vector<double> vBreaks_;           ///< distinct knots in v
  std::vector<double> uScale_, vScale_;   ///< 1 / each span's width (multiplied, not divided, per point)
  std::vector<Eigen::Vector4d> a_;        ///< per span (u-major), (p + 1) x (q + 1) homogeneous power coefficients a_kl
};

}  // namespace fairsplines::detail
