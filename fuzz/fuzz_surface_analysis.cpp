// Surface analysis (issue 27): principal curvatures at any (u, v), continuity across the
// face's edges and the curvature map, on B-spline faces of degree 1 to 3 in each direction,
// rational or not, forward or reversed, with any heights and scale (NaN, 1e300, 1e-300).
#include <BRepBuilderAPI_MakeFace.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopoDS.hxx>

#include "fairsplines/surface_analysis.hpp"
#include "fuzz_check.hpp"
#include "fuzz_input.hpp"

using namespace fairsplines;
using namespace fairsplines::fuzz;

namespace {

/// Clamped uniform knots for n poles of degree p.
void clampedKnots(int n, int p, TColStd_Array1OfReal& knots, TColStd_Array1OfInteger& mults) {
  const int distinct = n - p + 1;
  knots.Resize(1, distinct, false);
  mults.Resize(1, distinct, false);
  for (int i = 1; i <= distinct; ++i) {
    knots(i) = i - 1;
    mults(i) = (i == 1 || i == distinct) ? p + 1 : 1;
  }
}

}  // namespace

int fuzzOne(FuzzInput& in) {
  const int du = in.count(1, 3), dv = in.count(1, 3);
  const int nu = du + 1 + in.count(0, 3), nv = dv + 1 + in.count(0, 3);
  const bool rational = in.flag();
  const double scale = in.flag() ? in.number() : 1.0;
  TColgp_Array2OfPnt poles(1, nu, 1, nv);
  TColStd_Array2OfReal weights(1, nu, 1, nv);
  Eigen::MatrixXd heights(nu, nv);
  for (int i = 1; i <= nu; ++i) {
    for (int j = 1; j <= nv; ++j) {
      heights(i - 1, j - 1) = in.number();
      poles(i, j) = gp_Pnt(scale * i, scale * j, scale * heights(i - 1, j - 1));
    }
  }
  for (int i = 1; i <= nu; ++i) {
    for (int j = 1; j <= nv; ++j) weights(i, j) = rational ? in.positive() : 1.0;
  }
  const bool reversed = in.flag();
  const PointMatrix uv = samplePoints(in, 16);
  const int quantity = in.choice(6);
  const double angleTolerance = in.flag() ? in.number() : 0.1;
  note("degrees", Eigen::Vector2d(du, dv));
  note("scale", scale);
  note("heights", heights);
  note("rational", rational);
  note("reversed", reversed);
  note("uv", uv);
  note("quantity", quantity);
  note("angle tolerance", angleTolerance);

  // The face is the input, made by OCCT: data OCCT refuses is not the kernel's to judge.
  TopoDS_Face face;
  try {
    TColStd_Array1OfReal uKnots(1, 1), vKnots(1, 1);
    TColStd_Array1OfInteger uMults(1, 1), vMults(1, 1);
    clampedKnots(nu, du, uKnots, uMults);
    clampedKnots(nv, dv, vKnots, vMults);
    Handle(Geom_BSplineSurface) s =
        rational ? new Geom_BSplineSurface(poles, weights, uKnots, vKnots, uMults, vMults, du, dv)
                 : new Geom_BSplineSurface(poles, uKnots, vKnots, uMults, vMults, du, dv);
    BRepBuilderAPI_MakeFace make(s, 1e-7);
    if (!make.IsDone()) return 0;
    face = make.Face();
  } catch (const Standard_Failure&) {
    return 0;
  }
  if (reversed) face = TopoDS::Face(face.Reversed());

  SurfaceCurvature c;
  if (guarded("surfaceCurvature", [&] { c = surfaceCurvature(face, uv); })) {
    requireFinite("surfaceCurvature", "k1", c.k1());
    requireFinite("surfaceCurvature", "k2", c.k2());
    requireFinite("surfaceCurvature", "direction", c.dir1());
    requireFinite("surfaceCurvature", "direction", c.dir2());
    requireFinite("surfaceCurvature", "normal", c.normal());
    for (Eigen::Index i = 0; i < c.k1().size(); ++i) {
      if (c.k1()[i] < c.k2()[i]) fail("surfaceCurvature", "k1 < k2 at point " + std::to_string(i));
    }
  }
  ContinuityOptions options;
  options.angleTolerance = angleTolerance;
  std::vector<EdgeContinuity> edges;
  if (guarded("edgeContinuity", [&] { edges = edgeContinuity(face, options); })) {
    for (const EdgeContinuity& e : edges) {
      requireFinite("edgeContinuity", "gap", e.gap);
      requireFinite("edgeContinuity", "angle", e.angle);
      requireFinite("edgeContinuity", "curvature jump", e.curvatureJump);
    }
  }
  CurvatureMap m;
  if (guarded("curvatureMap", [&] { m = curvatureMap(face, static_cast<MapQuantity>(quantity)); })) {
    requireFinite("curvatureMap", "point", m.points);
    requireFinite("curvatureMap", "value", m.values);
  }
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) { return runOne(data, size, fuzzOne); }
