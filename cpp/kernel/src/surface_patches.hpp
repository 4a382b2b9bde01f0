// A B-spline or Bezier face's surface evaluated to second order from its knot spans' patches
// in power form (issue 27, the speed of surfaceCurvature): each span's rational tensor-product
// polynomial about its corner, in homogeneous coordinates with the face's location applied,
// evaluated by Horner's rule. Used by FaceSurface (surface_analysis_detail.hpp) in place of
// OCCT's adaptor, which costs a virtual call, a span search in its cache and a transformation
// of every result per point.
#pragma once
#include <Eigen/Core>
#include <TopoDS_Face.hxx>
#include <cstddef>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>
#include <memory>
#include <vector>

#include "surface_curvature_batch.hpp"

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

  /// The jets of m points (the rows (u, v) of uv, `stride` doubles apart) into the batch's
  /// arrays p, su, sv, suu, svv, suv, each the same bits as d2 gives.
  void jets(const double* uv, std::ptrdiff_t stride, int m, CurvatureBatch& batch) const;

  static constexpr int kMaxDegree = 7;

  /// One direction's knot spans, and a table that finds a parameter's span in a step or two
  /// (a binary search costs a chain of dependent loads a point).
  struct Spans {
    std::vector<double> breaks;  ///< distinct knots (spans + 1)
    std::vector<double> scale;   ///< 1 / each span's width (multiplied, not divided, per point)
    double first = 0.0;          ///< the surface's first parameter
    double period = 0.0;         ///< the period of a periodic direction (0: not periodic)
    /// Buckets of equal width over the knots: a parameter in bucket b lies in a span from
    /// lower[b] to upper[b] (at most one knot apart where the knots are about even).
    double bucketsPerUnit = 0.0;
    std::vector<int> lower, upper;
    void build();  ///< scale and the buckets from breaks
  };

private:
  int p_ = 0, q_ = 0;  ///< degrees in u and v
  Spans u_, v_;
  /// per span (u-major), (p + 1) x (q + 1) homogeneous power coefficients a_kl, 4 doubles each
  std::vector<double> a_;
};

}  // namespace fairsplines::detail
