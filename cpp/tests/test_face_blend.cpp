// Face blends (issue 29): the blend between two cylinders' rims judged by OCCT at 101 points of
// each rim (GeomAPI_ProjectPointOnSurf, GeomLProp_SLProps: position, normal, Gaussian and mean
// curvature), never by the construction's formulas; bad input names the problem.
#include <gtest/gtest.h>

#include <BRepAdaptor_Curve.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRep_Tool.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <GeomLProp_SLProps.hxx>
#include <Geom_CylindricalSurface.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <array>
#include <cmath>
#include <gp_Circ.hxx>
#include <gp_Pln.hxx>

#include "fairsplines/errors.hpp"
#include "fairsplines/face_blend.hpp"

using namespace fairsplines;

namespace {

struct Rim {
  TopoDS_Face face;
  int edge = 0;
};

/// The lateral face of a cylinder and the number of its rim at height z.
Rim cylinderRim(double radius, double z0, double height, double x, double z) {
  const TopoDS_Shape solid = BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(x, 0, z0), gp_Dir(0, 0, 1)), radius, height);
  Rim rim;
  for (TopExp_Explorer e(solid, TopAbs_FACE); e.More(); e.Next()) {
    const TopoDS_Face f = TopoDS::Face(e.Current());
    if (!Handle(Geom_CylindricalSurface)::DownCast(BRep_Tool::Surface(f)).IsNull()) rim.face = f;
  }
  TopTools_IndexedMapOfShape edges;
  TopExp::MapShapes(rim.face, TopAbs_EDGE, edges);
  for (int i = 1; i <= edges.Extent(); ++i) {
    BRepAdaptor_Curve c(TopoDS::Edge(edges(i)));
    if (c.GetType() == GeomAbs_Circle && std::abs(c.Circle().Location().Z() - z) < 1e-12) rim.edge = i;
  }
  return rim;
}

/// The largest differences between the blend's boundary s and the face: distance, angle of the
/// normals (radians), |Gaussian| and |mean| curvature jumps.
std::array<double, 4> compare(const Handle(Geom_BSplineSurface)& blend, double s, const TopoDS_Face& face) {
  const Handle(Geom_Surface) surface = BRep_Tool::Surface(face);
  std::array<double, 4> worst{0, 0, 0, 0};
  for (int i = 0; i <= 100; ++i) {
    const gp_Pnt p = blend->Value(i / 100.0, s);
    GeomAPI_ProjectPointOnSurf projection(p, surface);
    double u, v;
    projection.LowerDistanceParameters(u, v);
    worst[0] = std::max(worst[0], projection.LowerDistance());
    GeomLProp_SLProps a(blend, i / 100.0, s, 2, 1e-12), b(surface, u, v, 2, 1e-12);
    worst[1] = std::max(worst[1], a.Normal().Angle(b.Normal()) > 1.0 ? M_PI - a.Normal().Angle(b.Normal())
                                                                     : a.Normal().Angle(b.Normal()));
    worst[2] = std::max(worst[2], std::abs(a.GaussianCurvature() - b.GaussianCurvature()));
    worst[3] = std::max(worst[3], std::abs(std::abs(a.MeanCurvature()) - std::abs(b.MeanCurvature())));
  }
  return worst;
}

}  // namespace

TEST(FaceBlend, CoaxialCylinders_G2AlongTheWholeRim) {
  const Rim a = cylinderRim(1.0, 0.0, 1.0, 0.0, 1.0), b = cylinderRim(1.5, 2.0, 1.0, 0.0, 2.0);
  ASSERT_GT(a.edge, 0);
  ASSERT_GT(b.edge, 0);
  const FaceBlend blend = blendFaces(a.face, a.edge, b.face, b.edge);
  for (const auto& [s, face] : {std::pair{0.0, a.face}, std::pair{1.0, b.face}}) {
    const auto e = compare(blend.surface, s, face);
    EXPECT_LT(e[0], 1e-12);
    EXPECT_LT(e[1], 1e-10);
    EXPECT_LT(e[2], 1e-9);
    EXPECT_LT(e[3], 1e-9);
  }
  EXPECT_EQ(blend.sides[0].method, "exact");
  EXPECT_TRUE(blend.sides[0].closed && blend.sides[1].closed);
  // Every section the same S between two straight generators: 0, a maximum, 0 (the inflection), a
  // maximum, 0 -- the fewest extrema such ends admit.
  for (const FaceBlendSection& section : blend.sections) EXPECT_EQ(section.curvatureExtrema, 3);
}

TEST(FaceBlend, G1MatchesTheNormalOnly) {
  const Rim a = cylinderRim(1.0, 0.0, 1.0, 0.0, 1.0), b = cylinderRim(1.0, 2.0, 1.0, 0.3, 2.0);
  FaceBlendOptions o;
  o.continuity = 1;
  const FaceBlend blend = blendFaces(a.face, a.edge, b.face, b.edge, o);
  const auto e = compare(blend.surface, 0.0, a.face);
  EXPECT_LT(e[0], 1e-12);
  EXPECT_LT(e[1], 1e-10);
  EXPECT_EQ(blend.surface->VDegree(), 3);
}

TEST(FaceBlend, HoledPlane_FittedG2AlongTheWholeCircle) {
  // A square plane with a round hole: the hole's circle is no isoline of the plane, so that side is
  // fitted; the blend rises from it into a narrower cylinder above.
  BRepBuilderAPI_MakeFace maker(gp_Pln(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), 0.0, 2.0, -1.0, 1.0);
  const TopoDS_Edge circle = BRepBuilderAPI_MakeEdge(gp_Circ(gp_Ax2(gp_Pnt(1, 0, 0), gp_Dir(0, 0, 1)), 0.5));
  TopoDS_Wire inner = BRepBuilderAPI_MakeWire(circle).Wire();
  inner.Reverse();
  maker.Add(inner);
  const TopoDS_Face holed = maker.Face();
  TopTools_IndexedMapOfShape edges;
  TopExp::MapShapes(holed, TopAbs_EDGE, edges);
  int hole = 0;
  for (int i = 1; i <= edges.Extent(); ++i)
    if (BRepAdaptor_Curve(TopoDS::Edge(edges(i))).GetType() == GeomAbs_Circle) hole = i;
  ASSERT_GT(hole, 0);
  const Rim tube = cylinderRim(0.3, 1.0, 1.0, 1.0, 1.0);
  const FaceBlend blend = blendFaces(holed, hole, tube.face, tube.edge);
  EXPECT_EQ(blend.sides[0].method, "fitted");
  EXPECT_EQ(blend.sides[1].method, "exact");
  EXPECT_GE(blend.sides[0].spans, 8);
  // The tolerances: gap 1e-7 of the size, normal 1e-4 degree, curvature 1e-4 of the scale
  // (the tube's 1 / 0.3).
  for (const auto& [s, face] : {std::pair{0.0, holed}, std::pair{1.0, tube.face}}) {
    const auto e = compare(blend.surface, s, face);
    EXPECT_LT(e[0], 1e-7 * blend.size);
    EXPECT_LT(e[1], 1e-4 * M_PI / 180.0);
    EXPECT_LT(e[2], 1e-4 / (0.3 * 0.3));
    EXPECT_LT(e[3], 1e-4 / 0.3);
  }
  // On the plane is not enough: the blend's boundary runs along the hole's circle.
  double offCircle = 0.0;
  for (int i = 0; i <= 100; ++i) {
    const gp_Pnt p = blend.surface->Value(i / 100.0, 0.0);
    offCircle = std::max(offCircle, std::abs(std::hypot(p.X() - 1.0, p.Y()) - 0.5));
  }
  EXPECT_LT(offCircle, 1e-7 * blend.size);
}

TEST(FaceBlend, BadInput_NamesTheProblem) {
  const Rim a = cylinderRim(1.0, 0.0, 1.0, 0.0, 1.0), b = cylinderRim(1.5, 2.0, 1.0, 0.0, 2.0);
  auto message = [&](int edgeA, const TopoDS_Face& faceB, int edgeB) {
    try {
      blendFaces(a.face, edgeA, faceB, edgeB);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message(9, b.face, b.edge).find("edge_a is edge 9"), std::string::npos);
  // The same rim on both sides: the faces touch.
  const Rim touching = cylinderRim(1.0, 1.0, 1.0, 0.0, 1.0);
  EXPECT_NE(message(a.edge, touching.face, touching.edge).find("faces touch"), std::string::npos);
}
