// Surface analysis (issue 27): principal curvatures judged against closed forms and against
// OCCT's GeomLProp_SLProps with the sign convention applied; continuity of a box's edges.
#include <gtest/gtest.h>

#include <BRepAdaptor_Surface.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRepTools.hxx>
#include <GeomLProp_SLProps.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <cmath>

#include "fairsplines/errors.hpp"
#include "fairsplines/surface_analysis.hpp"

using namespace fairsplines;

namespace {

TopoDS_Face firstFace(const TopoDS_Shape& shape) {
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(shape, TopAbs_FACE, faces);
  return TopoDS::Face(faces(1));
}

Eigen::MatrixXd grid(const TopoDS_Face& face, int n) {
  double u0, u1, v0, v1;
  BRepTools::UVBounds(face, u0, u1, v0, v1);
  Eigen::MatrixXd uv(n * n, 2);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      // Interior points, off the construction's own lines.
      uv(i * n + j, 0) = u0 + (u1 - u0) * (i + 0.37) / n;
      uv(i * n + j, 1) = v0 + (v1 - v0) * (j + 0.61) / n;
    }
  }
  return uv;
}

Handle(Geom_BSplineSurface) wavySurface(bool rational) {
  TColgp_Array2OfPnt poles(1, 4, 1, 4);
  TColStd_Array2OfReal weights(1, 4, 1, 4);
  for (int i = 1; i <= 4; ++i) {
    for (int j = 1; j <= 4; ++j) {
      poles(i, j) = gp_Pnt(i, j, 0.3 * std::sin(1.7 * i + 0.9 * j) + 0.1 * i * j);
      weights(i, j) = rational ? 1.0 + 0.2 * ((i + 2 * j) % 3) : 1.0;
    }
  }
  TColStd_Array1OfReal knots(1, 2);
  knots(1) = 0.0;
  knots(2) = 1.0;
  TColStd_Array1OfInteger mults(1, 2);
  mults(1) = mults(2) = 4;
  return rational ? new Geom_BSplineSurface(poles, weights, knots, knots, mults, mults, 3, 3)
                  : new Geom_BSplineSurface(poles, knots, knots, mults, mults, 3, 3);
}

}  // namespace

TEST(SurfaceAnalysis, SphereIsConvexPositiveForwardAndNegativeReversed) {
  const double R = 2.5;
  const TopoDS_Face face = firstFace(BRepPrimAPI_MakeSphere(R).Shape());
  const Eigen::MatrixXd uv = grid(face, 7);
  const SurfaceCurvature c = surfaceCurvature(face, uv);
  for (Eigen::Index i = 0; i < uv.rows(); ++i) {
    EXPECT_NEAR(c.k1[i], 1.0 / R, 1e-10 / R);
    EXPECT_NEAR(c.k2[i], 1.0 / R, 1e-10 / R);
    EXPECT_NEAR(c.normal.row(i).dot(c.points.row(i)) / R, 1.0, 1e-12);  // outward
  }
  const SurfaceCurvature r = surfaceCurvature(TopoDS::Face(face.Reversed()), uv);
  for (Eigen::Index i = 0; i < uv.rows(); ++i) {
    EXPECT_NEAR(r.k1[i], -1.0 / R, 1e-10 / R);
    EXPECT_NEAR(r.normal.row(i).dot(r.points.row(i)) / R, -1.0, 1e-12);
  }
}

TEST(SurfaceAnalysis, SpherePolesAreFiniteUmbilics) {
  const TopoDS_Face face = firstFace(BRepPrimAPI_MakeSphere(3.0).Shape());
  Eigen::MatrixXd uv(2, 2);
  uv << 1.0, M_PI / 2, 2.0, -M_PI / 2;
  const SurfaceCurvature c = surfaceCurvature(face, uv);
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(c.k1[i], 1.0 / 3.0, 1e-9);
    EXPECT_NEAR(c.k2[i], 1.0 / 3.0, 1e-9);
    EXPECT_EQ(c.state[i], static_cast<int>(PointState::Degenerate));
    EXPECT_NEAR(std::abs(c.normal(i, 2)), 1.0, 1e-9);
  }
}

TEST(SurfaceAnalysis, ConeApexIsRefusedNamingThePoint) {
  const TopoDS_Shape cone = BRepPrimAPI_MakeCone(2.0, 0.0, 3.0).Shape();
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(cone, TopAbs_FACE, faces);
  for (int k = 1; k <= faces.Extent(); ++k) {
    const TopoDS_Face face = TopoDS::Face(faces(k));
    double u0, u1, v0, v1;
    BRepTools::UVBounds(face, u0, u1, v0, v1);
    if (BRepAdaptor_Surface(face).GetType() != GeomAbs_Cone) continue;
    Eigen::MatrixXd uv(2, 2);
    uv << 0.5, 0.5 * (v0 + v1), 0.5, v1;  // the apex at the top of the cone (radius 0)
    try {
      surfaceCurvature(face, uv);
      FAIL() << "the apex gave a curvature";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("point 1"), std::string::npos) << e.what();
    }
  }
}

TEST(SurfaceAnalysis, CylinderHasInverseRadiusAcrossAndZeroAlong) {
  const TopoDS_Face face = firstFace(BRepPrimAPI_MakeCylinder(1.5, 4.0).Shape());
  const SurfaceCurvature c = surfaceCurvature(face, grid(face, 5));
  for (Eigen::Index i = 0; i < c.k1.size(); ++i) {
    EXPECT_NEAR(c.k1[i], 1.0 / 1.5, 1e-12);
    EXPECT_NEAR(c.k2[i], 0.0, 1e-12);
    EXPECT_NEAR(std::abs(c.dir2(i, 2)), 1.0, 1e-12);  // the axis
  }
}

TEST(SurfaceAnalysis, BSplineMatchesGeomLPropWithTheSignConvention) {
  for (bool rational : {false, true}) {
    const Handle(Geom_BSplineSurface) s = wavySurface(rational);
    const TopoDS_Face face = BRepBuilderAPI_MakeFace(s, 1e-7).Face();
    for (const TopoDS_Face& f : {face, TopoDS::Face(face.Reversed())}) {
      const Eigen::MatrixXd uv = grid(f, 6);
      const SurfaceCurvature c = surfaceCurvature(f, uv);
      const double sign = f.Orientation() == TopAbs_REVERSED ? 1.0 : -1.0;  // OCCT: convex negative
      for (Eigen::Index i = 0; i < uv.rows(); ++i) {
        GeomLProp_SLProps props(s, uv(i, 0), uv(i, 1), 2, 1e-9);
        ASSERT_TRUE(props.IsCurvatureDefined());
        const double a = sign * props.MaxCurvature(), b = sign * props.MinCurvature();
        const double scale = std::max({std::abs(a), std::abs(b), 1e-3});
        EXPECT_NEAR(c.k1[i], std::max(a, b), 1e-10 * scale);
        EXPECT_NEAR(c.k2[i], std::min(a, b), 1e-10 * scale);
        EXPECT_NEAR(c.gaussian[i], props.GaussianCurvature(), 1e-10 * scale * scale);
        EXPECT_NEAR(c.mean[i], sign * props.MeanCurvature(), 1e-10 * scale);
      }
    }
  }
}

TEST(SurfaceAnalysis, BadUvIsRefused) {
  const TopoDS_Face face = firstFace(BRepPrimAPI_MakeBox(1, 2, 3).Shape());
  Eigen::MatrixXd nan(1, 2);
  nan << std::nan(""), 0.0;
  EXPECT_THROW(surfaceCurvature(face, nan), InputError);
  Eigen::MatrixXd far(1, 2);
  far << 1e6, 0.0;
  EXPECT_THROW(surfaceCurvature(face, far), InputError);
  EXPECT_THROW(surfaceCurvature(face, Eigen::MatrixXd(0, 2)), InputError);
  EXPECT_THROW(surfaceCurvature(face, Eigen::MatrixXd::Zero(2, 3)), InputError);
}

TEST(SurfaceAnalysis, BoxEdgesAreG0AtRightAngles) {
  const std::vector<EdgeContinuity> edges = edgeContinuity(BRepPrimAPI_MakeBox(1, 2, 3).Shape());
  ASSERT_EQ(edges.size(), 12u);
  for (const EdgeContinuity& e : edges) {
    EXPECT_EQ(e.continuity, "G0");
    EXPECT_EQ(e.faces.size(), 2u);
    EXPECT_NEAR(e.angle, 90.0, 1e-9);
    EXPECT_LT(e.gap, 1e-12);
  }
}

TEST(SurfaceAnalysis, CylinderSeamIsG2) {
  const std::vector<EdgeContinuity> edges = edgeContinuity(BRepPrimAPI_MakeCylinder(1.0, 2.0).Shape());
  int seams = 0;
  for (const EdgeContinuity& e : edges) {
    if (e.kind != "seam") continue;
    ++seams;
    EXPECT_EQ(e.continuity, "G2");
    EXPECT_LT(e.angle, 1e-9);
    EXPECT_LT(e.curvatureJump, 1e-9);
  }
  EXPECT_EQ(seams, 1);
}

TEST(SurfaceAnalysis, CurvatureMapOfASphereIsConstant) {
  const CurvatureMap m = curvatureMap(BRepPrimAPI_MakeSphere(2.0).Shape(), MapQuantity::Mean);
  ASSERT_GT(m.triangles.rows(), 0);
  EXPECT_NEAR(m.values.minCoeff(), 0.5, 1e-9);
  EXPECT_NEAR(m.values.maxCoeff(), 0.5, 1e-9);
}
