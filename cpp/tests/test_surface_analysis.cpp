// Surface analysis (issue 27): principal curvatures judged against closed forms and against
// OCCT's GeomLProp_SLProps with the sign convention applied; continuity of a box's edges.
#include <gtest/gtest.h>

#include <BRepAdaptor_Surface.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_NurbsConvert.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <GeomConvert.hxx>
#include <GeomLProp_SLProps.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_BezierSurface.hxx>
#include <Geom_SphericalSurface.hxx>
#include <Geom_ToroidalSurface.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopExp.hxx>
#include <TopLoc_Location.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <cmath>
#include <cstring>
#include <random>
#include <tuple>
#include <utility>
#include <vector>

#include "fairsplines/errors.hpp"
#include "fairsplines/surface_analysis.hpp"
#include "surface_analysis_detail.hpp"
#include "surface_patches.hpp"

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

/// A rational B-spline of degrees (3, 3) whose u knots crowd near 0 (many spans in one of the
/// span table's buckets) and are even in v, moved by a location.
TopoDS_Face crowdedKnotsFace() {
  TColgp_Array2OfPnt poles(1, 9, 1, 5);
  TColStd_Array2OfReal weights(1, 9, 1, 5);
  for (int i = 1; i <= 9; ++i) {
    for (int j = 1; j <= 5; ++j) {
      poles(i, j) = gp_Pnt(i, 1.2 * j, 0.5 * std::sin(1.1 * i + 0.8 * j));
      weights(i, j) = 1.0 + 0.25 * ((i + j) % 3);
    }
  }
  TColStd_Array1OfReal uKnots(1, 7), vKnots(1, 3);
  TColStd_Array1OfInteger uMults(1, 7), vMults(1, 3);
  const double u[] = {0.0, 1e-4, 2e-4, 3e-4, 4e-4, 0.6, 1.0};  // 4 + 5 + 4 - 3 - 1 = 9 poles
  for (int i = 1; i <= 7; ++i) uKnots(i) = u[i - 1], uMults(i) = (i == 1 || i == 7) ? 4 : 1;
  vKnots(1) = 0.0, vKnots(2) = 0.5, vKnots(3) = 1.0;  // 4 + 1 + 4 - 3 - 1 = 5 poles
  vMults(1) = 4, vMults(2) = 1, vMults(3) = 4;
  gp_Trsf move;
  move.SetRotation(gp_Ax1(gp_Pnt(0, 1, 0), gp_Dir(0, 1, 1)), 0.4);
  return TopoDS::Face(
      BRepBuilderAPI_MakeFace(new Geom_BSplineSurface(poles, weights, uKnots, vKnots, uMults, vMults, 3, 3), 1e-7)
          .Face()
          .Moved(TopLoc_Location(move)));
}

/// n points spread over the face's parameter box: random, with every 7th on a u knot line and
/// every 11th on a v one (the knots of crowdedKnotsFace; others land between).
Eigen::MatrixXd scattered(const TopoDS_Face& face, Eigen::Index n, unsigned seed) {
  double u0, u1, v0, v1;
  BRepTools::UVBounds(face, u0, u1, v0, v1);
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double uKnots[] = {0.0, 1e-4, 2e-4, 3e-4, 4e-4, 0.6, 1.0};
  Eigen::MatrixXd uv(n, 2);
  for (Eigen::Index i = 0; i < n; ++i) {
    uv(i, 0) = i % 7 == 0 ? u0 + (u1 - u0) * uKnots[i % 49 / 7] : u0 + (u1 - u0) * unit(random);
    uv(i, 1) = i % 11 == 0 ? v0 + (v1 - v0) * 0.5 : v0 + (v1 - v0) * unit(random);
  }
  return uv;
}

}  // namespace

TEST(SurfaceAnalysis, SphereIsConvexPositiveForwardAndNegativeReversed) {
  const double R = 2.5;
  const TopoDS_Face face = firstFace(BRepPrimAPI_MakeSphere(R).Shape());
  const Eigen::MatrixXd uv = grid(face, 7);
  const SurfaceCurvature c = surfaceCurvature(face, uv);
  for (Eigen::Index i = 0; i < uv.rows(); ++i) {
    EXPECT_NEAR(c.k1()[i], 1.0 / R, 1e-10 / R);
    EXPECT_NEAR(c.k2()[i], 1.0 / R, 1e-10 / R);
    EXPECT_NEAR(c.normal().row(i).dot(c.points().row(i)) / R, 1.0, 1e-12);  // outward
  }
  const SurfaceCurvature r = surfaceCurvature(TopoDS::Face(face.Reversed()), uv);
  for (Eigen::Index i = 0; i < uv.rows(); ++i) {
    EXPECT_NEAR(r.k1()[i], -1.0 / R, 1e-10 / R);
    EXPECT_NEAR(r.normal().row(i).dot(r.points().row(i)) / R, -1.0, 1e-12);
  }
}

TEST(SurfaceAnalysis, SpherePolesAreFiniteUmbilics) {
  const TopoDS_Face face = firstFace(BRepPrimAPI_MakeSphere(3.0).Shape());
  Eigen::MatrixXd uv(2, 2);
  uv << 1.0, M_PI / 2, 2.0, -M_PI / 2;
  const SurfaceCurvature c = surfaceCurvature(face, uv);
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(c.k1()[i], 1.0 / 3.0, 1e-9);
    EXPECT_NEAR(c.k2()[i], 1.0 / 3.0, 1e-9);
    EXPECT_EQ(c.state[i], static_cast<int>(PointState::Degenerate));
    EXPECT_NEAR(std::abs(c.normal()(i, 2)), 1.0, 1e-9);
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
  for (Eigen::Index i = 0; i < c.k1().size(); ++i) {
    EXPECT_NEAR(c.k1()[i], 1.0 / 1.5, 1e-12);
    EXPECT_NEAR(c.k2()[i], 0.0, 1e-12);
    EXPECT_NEAR(std::abs(c.dir2()(i, 2)), 1.0, 1e-12);  // the axis
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
        EXPECT_NEAR(c.k1()[i], std::max(a, b), 1e-10 * scale);
        EXPECT_NEAR(c.k2()[i], std::min(a, b), 1e-10 * scale);
        EXPECT_NEAR(c.gaussian()[i], props.GaussianCurvature(), 1e-10 * scale * scale);
        EXPECT_NEAR(c.mean()[i], sign * props.MeanCurvature(), 1e-10 * scale);
      }
    }
  }
}

// The spans in power form (surface_patches.cpp) against OCCT's own D2 of the face, to rounding:
// a rational B-spline of degrees (3, 2) on non-uniform knots moved by a location, the same
// reversed, a sphere converted to a rational B-spline made periodic in u (points beyond its
// range wrap), and a Bezier face; points inside, on knots and up to 10% outside the range.
TEST(SurfaceAnalysis, PowerPatchesMatchOcctD2) {
  TColgp_Array2OfPnt poles(1, 6, 1, 5);
  TColStd_Array2OfReal weights(1, 6, 1, 5);
  for (int i = 1; i <= 6; ++i) {
    for (int j = 1; j <= 5; ++j) {
      poles(i, j) = gp_Pnt(1.5 * i, j + 0.2 * i, 0.4 * std::sin(1.3 * i + 0.7 * j));
      weights(i, j) = 1.0 + 0.3 * ((2 * i + j) % 4);
    }
  }
  TColStd_Array1OfReal uKnots(1, 4), vKnots(1, 3);
  TColStd_Array1OfInteger uMults(1, 4), vMults(1, 3);
  uKnots(1) = 0.0, uKnots(2) = 0.3, uKnots(3) = 1.1, uKnots(4) = 2.0;  // 4 + 1 + 1 + 4 - 3 - 1 = 6 poles
  uMults(1) = 4, uMults(2) = 1, uMults(3) = 1, uMults(4) = 4;
  vKnots(1) = -1.0, vKnots(2) = 0.5, vKnots(3) = 3.0;  // 3 + 2 + 3 - 2 - 1 = 5 poles
  vMults(1) = 3, vMults(2) = 2, vMults(3) = 3;
  const Handle(Geom_BSplineSurface) rational =
      new Geom_BSplineSurface(poles, weights, uKnots, vKnots, uMults, vMults, 3, 2);
  gp_Trsf move;
  move.SetRotation(gp_Ax1(gp_Pnt(1, 2, 3), gp_Dir(1, 1, 0)), 0.7);
  move.SetTranslationPart(gp_Vec(5, -4, 2));
  const TopoDS_Face moved = TopoDS::Face(BRepBuilderAPI_MakeFace(rational, 1e-7).Face().Moved(TopLoc_Location(move)));

  Handle(Geom_BSplineSurface) sphere = GeomConvert::SurfaceToBSplineSurface(new Geom_SphericalSurface(gp_Ax3(), 2.0));
  if (!sphere->IsUPeriodic()) sphere->SetUPeriodic();
  ASSERT_TRUE(sphere->IsUPeriodic());
  TColgp_Array2OfPnt bezierPoles(1, 3, 1, 4);
  for (int i = 1; i <= 3; ++i)
    for (int j = 1; j <= 4; ++j) bezierPoles(i, j) = gp_Pnt(i, j, 0.5 * ((i * j) % 3));
  const Handle(Geom_BezierSurface) bezier = new Geom_BezierSurface(bezierPoles);

  int checked = 0;
  for (const TopoDS_Face& face : {moved, TopoDS::Face(moved.Reversed()), BRepBuilderAPI_MakeFace(sphere, 1e-7).Face(),
                                  BRepBuilderAPI_MakeFace(bezier, 1e-7).Face()}) {
    const std::unique_ptr<detail::PowerPatches> patches = detail::PowerPatches::of(face);
    ASSERT_NE(patches, nullptr);
    BRepAdaptor_Surface occt(face, false);
    double u0, u1, v0, v1;
    BRepTools::UVBounds(face, u0, u1, v0, v1);
    for (int i = -1; i <= 11; ++i) {
      for (int j = 0; j <= 10; ++j) {
        // u from 10% before the range to 10% past it (a periodic surface wraps there); v
        // inside, its knots included.
        const double u = u0 + (u1 - u0) * (i + 0.05 * (i % 3)) / 10.0, v = v0 + (v1 - v0) * j / 10.0;
        gp_Pnt p, q;
        gp_Vec d[5], e[5];
        patches->d2(u, v, p, d[0], d[1], d[2], d[3], d[4]);
        occt.D2(u, v, q, e[0], e[1], e[2], e[3], e[4]);
        double scale = gp_Vec(q.XYZ()).Magnitude() + 1.0;
        for (const gp_Vec& x : e) scale = std::max(scale, x.Magnitude());
        ASSERT_LT(p.Distance(q), 1e-12 * scale) << u << " " << v;
        for (int k = 0; k < 5; ++k)
          ASSERT_LT((d[k] - e[k]).Magnitude(), 1e-11 * scale) << k << " at " << u << ", " << v;
        ++checked;
      }
    }
  }
  EXPECT_EQ(checked, 4 * 13 * 11);
  // Degrees past kMaxDegree are left to OCCT.
  TColgp_Array2OfPnt high(1, detail::PowerPatches::kMaxDegree + 2, 1, 2);
  for (int i = 1; i <= high.UpperRow(); ++i) high(i, 1) = gp_Pnt(i, 0, i % 2), high(i, 2) = gp_Pnt(i, 1, 0);
  EXPECT_EQ(detail::PowerPatches::of(BRepBuilderAPI_MakeFace(new Geom_BezierSurface(high), 1e-7).Face()), nullptr);
}

// The span table (surface_patches.cpp, Spans) and the jets against OCCT's own D2, on and one
// ulp either side of every knot, and halfway between: crowded knots (many spans a bucket:
// the binary search among a bucket's candidates) on a C2 cubic and on a face of degrees (1, 2)
// that is C0 at its u knots (its derivative in u jumps there, so a span one off shows; its
// knot 0.51 lies in the first half of its bucket, where the bucket's first candidate matters). Both the single-point path (d2) and the batch's points
// and normals (surfaceCurvature, against OCCT's D1).
TEST(SurfaceAnalysis, PowerPatchesMatchOcctD2OnEveryKnot) {
  TColgp_Array2OfPnt poles(1, 6, 1, 4);
  for (int i = 1; i <= 6; ++i)
    for (int j = 1; j <= 4; ++j) poles(i, j) = gp_Pnt(i + 0.1 * j, j, 0.3 * std::cos(0.9 * i + 1.3 * j));
  TColStd_Array1OfReal uKnots(1, 6), vKnots(1, 3);
  TColStd_Array1OfInteger uMults(1, 6), vMults(1, 3);
  const double linearKnots[] = {0.0, 1e-3, 2e-3, 3e-3, 0.51, 1.0};  // degree 1: 2 + 4 + 2 - 1 - 1 = 6 poles
  for (int i = 1; i <= 6; ++i) uKnots(i) = linearKnots[i - 1], uMults(i) = (i == 1 || i == 6) ? 2 : 1;
  vKnots(1) = -2.0, vKnots(2) = 1.0, vKnots(3) = 2.5;  // degree 2: 3 + 1 + 3 - 2 - 1 = 4 poles
  vMults(1) = 3, vMults(2) = 1, vMults(3) = 3;
  const TopoDS_Face linear =
      BRepBuilderAPI_MakeFace(new Geom_BSplineSurface(poles, uKnots, vKnots, uMults, vMults, 1, 2), 1e-7).Face();
  const std::vector<double> crowdedU = {0.0, 1e-4, 2e-4, 3e-4, 4e-4, 0.6, 1.0}, crowdedV = {0.0, 0.5, 1.0};
  const std::vector<double> linearU(std::begin(linearKnots), std::end(linearKnots)), linearV = {-2.0, 1.0, 2.5};
  int checked = 0;
  // The power form about a span's corner loses about log10(1 / h^k) digits in the k-th
  // derivative on a span of width h (here 1e-4 in the crowded cubic's u, a C2 face: a span
  // taken one off changes its values only at rounding there, so it is judged to these widths);
  // the linear face's derivative in u jumps at every knot, so a wrong span shows at 1e-11.
  for (const auto& [face, us, vs, h] : {std::make_tuple(crowdedKnotsFace(), crowdedU, crowdedV, 1e-4),
                                        std::make_tuple(linear, linearU, linearV, 1.0)}) {
    const std::unique_ptr<detail::PowerPatches> patches = detail::PowerPatches::of(face);
    ASSERT_NE(patches, nullptr);
    // The referee: OCCT's LocalD2 on the span a plain scan names (the last knot <= x, the last
    // span past the end). OCCT's D2 would snap a parameter within its tolerance of a knot to
    // the knot, and take the other side of a knot where the surface is not C2.
    const auto surface = Handle(Geom_BSplineSurface)::DownCast(BRep_Tool::Surface(face));  // location applied
    ASSERT_FALSE(surface.IsNull());
    const auto spanOf = [](const std::vector<double>& knots, double x) {
      int span = 0;
      for (std::size_t k = 1; k + 1 < knots.size(); ++k) span += knots[k] <= x;
      return span + 1;  // OCCT counts knots from 1
    };
    std::vector<double> u, v;  // each knot, one ulp either side, and midpoints
    for (const auto& [knots, out] : {std::make_pair(us, &u), std::make_pair(vs, &v)}) {
      for (std::size_t k = 0; k < knots.size(); ++k) {
        out->push_back(knots[k]);
        if (k > 0) out->push_back(std::nextafter(knots[k], -1e300));
        if (k + 1 < knots.size()) {
          out->push_back(std::nextafter(knots[k], 1e300));
          out->push_back(0.5 * (knots[k] + knots[k + 1]));
        }
      }
    }
    Eigen::MatrixXd uv(u.size() * v.size(), 2);
    Eigen::Index row = 0;
    std::vector<gp_Pnt> points;
    std::vector<gp_Vec> normals;
    for (double x : u) {
      for (double y : v) {
        gp_Pnt p, q;
        gp_Vec d[5], e[5];
        patches->d2(x, y, p, d[0], d[1], d[2], d[3], d[4]);
        const int i = spanOf(us, x), j = spanOf(vs, y);
        surface->LocalD2(x, y, i, i + 1, j, j + 1, q, e[0], e[1], e[2], e[3], e[4]);
        double scale = gp_Vec(q.XYZ()).Magnitude() + 1.0;
        for (const gp_Vec& w : e) scale = std::max(scale, w.Magnitude());
        ASSERT_LT(p.Distance(q), 1e-12 * scale) << x << " " << y;
        for (int k = 0; k < 5; ++k) {
          const double order = k < 2 ? 1 : 2;  // Su, Sv; Suu, Svv, Suv
          ASSERT_LT((d[k] - e[k]).Magnitude(), 1e-11 * scale / std::pow(h, order)) << k << " at " << x << ", " << y;
        }
        uv(row, 0) = x;
        uv(row++, 1) = y;
        points.push_back(q);
        normals.push_back(e[0].Crossed(e[1]).Normalized() * (face.Orientation() == TopAbs_REVERSED ? -1.0 : 1.0));
        ++checked;
      }
    }
    // The batch: its points and normals on the same spans.
    const SurfaceCurvature c = surfaceCurvature(face, uv, 1);
    for (Eigen::Index i = 0; i < uv.rows(); ++i) {
      const gp_Pnt& q = points[i];
      const gp_Vec& n = normals[i];
      EXPECT_LT((c.points().row(i) - Eigen::RowVector3d(q.X(), q.Y(), q.Z())).norm(),
                1e-12 * (1.0 + gp_Vec(q.XYZ()).Magnitude()))
          << i;
      EXPECT_LT((c.normal().row(i) - Eigen::RowVector3d(n.X(), n.Y(), n.Z())).norm(), 1e-12 / h) << i;
    }
  }
  EXPECT_EQ(checked, (7 + 6 + 6 + 6) * (3 + 2 + 2 + 2) + (6 + 5 + 5 + 5) * (3 + 2 + 2 + 2));
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

// ---- the batch, the threads and the scalar path (surface_curvature_batch.cpp)

// The batch's vectorised loop and jets against the scalar path (FaceSurface::frame and
// principalCurvatures, one point at a time): the same bits, at every point, on B-spline faces
// (the batch's own patches: rational, moved, reversed, crowded knots, a periodic sphere whose
// points are all umbilic), on faces OCCT evaluates (a torus, a sphere), and with 1, 2, 3 and
// automatic threads. The block starts as NaN, so that a row no thread wrote shows.
TEST(SurfaceAnalysis, BatchesAndThreadsGiveTheScalarPathsBits) {
  Handle(Geom_BSplineSurface) sphere = GeomConvert::SurfaceToBSplineSurface(new Geom_SphericalSurface(gp_Ax3(), 2.0));
  if (!sphere->IsUPeriodic()) sphere->SetUPeriodic();
  const TopoDS_Face crowded = crowdedKnotsFace();
  const TopoDS_Face torus =
      BRepBuilderAPI_MakeFace(new Geom_ToroidalSurface(gp_Ax3(gp_Pnt(1, 2, 3), gp_Dir(0, 1, 1)), 4.0, 1.5), 0.0,
                              2 * M_PI, 0.0, 2 * M_PI, 1e-7)
          .Face();
  const struct {
    TopoDS_Face face;
    bool patches;
  } cases[] = {{crowded, true},
               {TopoDS::Face(crowded.Reversed()), true},
               {BRepBuilderAPI_MakeFace(sphere, 1e-7).Face(), true},
               {torus, false},
               {firstFace(BRepPrimAPI_MakeSphere(3.0).Shape()), false}};
  const Eigen::Index n = 50000;  // 3 ranges of 16384 points or more
  int umbilics = 0;
  for (const auto& c : cases) {
    ASSERT_EQ(detail::PowerPatches::of(c.face) != nullptr, c.patches);
    const Eigen::MatrixXd uv = scattered(c.face, n, 27);
    SurfaceCurvature one;
    one.values.setConstant(n, curvature_column::count, std::nan(""));
    one.state.setConstant(n, -1);
    surfaceCurvature(c.face, uv, one.values, one.state, 1);
    // The scalar path at every point.
    const detail::FaceSurface surface(c.face);
    for (Eigen::Index i = 0; i < n; ++i) {
      detail::SurfaceFrame f;
      ASSERT_TRUE(surface.frame(uv(i, 0), uv(i, 1), f)) << i;
      const detail::Principal k = detail::principalCurvatures(f);
      const double expected[curvature_column::count] = {k.k1,       k.k2,       k.k1 * k.k2, 0.5 * (k.k1 + k.k2),
                                                        k.dir1.X(), k.dir1.Y(), k.dir1.Z(),  k.dir2.X(),
                                                        k.dir2.Y(), k.dir2.Z(), f.n.X(),     f.n.Y(),
                                                        f.n.Z(),    f.p.X(),    f.p.Y(),     f.p.Z()};
      for (int col = 0; col < curvature_column::count; ++col) {
        ASSERT_EQ(one.values(i, col), expected[col]) << "point " << i << ", column " << col;
      }
      ASSERT_EQ(one.state[i], static_cast<int>(k.state)) << i;
      umbilics += k.state == PointState::Umbilic;
    }
    for (int threads : {0, 2, 3}) {
      SurfaceCurvature shared;
      shared.values.setConstant(n, curvature_column::count, std::nan(""));
      shared.state.setConstant(n, -1);
      surfaceCurvature(c.face, uv, shared.values, shared.state, threads);
      ASSERT_EQ(std::memcmp(shared.values.data(), one.values.data(), sizeof(double) * n * curvature_column::count), 0)
          << threads << " threads";
      ASSERT_EQ(shared.state, one.state) << threads << " threads";
    }
  }
  EXPECT_GE(umbilics, 2 * n - 20);  // both spheres' points (but a few near their poles, where rounding parts k1, k2)
  EXPECT_THROW(surfaceCurvature(crowded, scattered(crowded, 10, 1), -1), InputError);
}

// With threads, a refusal still names the first point that fails: a B-spline cone (its apex
// has no curvature) with apex points in the first and the last of three ranges, and in the
// last only.
TEST(SurfaceAnalysis, ThreadsReportTheFirstRefusedPoint) {
  const TopoDS_Shape cone = BRepBuilderAPI_NurbsConvert(BRepPrimAPI_MakeCone(2.0, 0.0, 3.0).Shape()).Shape();
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(cone, TopAbs_FACE, faces);
  int checked = 0;
  for (int k = 1; k <= faces.Extent(); ++k) {
    const TopoDS_Face face = TopoDS::Face(faces(k));
    if (!detail::PowerPatches::of(face)) continue;
    double u0, u1, v0, v1;
    BRepTools::UVBounds(face, u0, u1, v0, v1);
    Eigen::MatrixXd uv = scattered(face, 50000, 5);
    detail::SurfaceFrame f;
    const detail::FaceSurface surface(face);
    // The apex: the end of v where the frame degenerates (radius 0).
    const double apex = surface.frame(0.5 * (u0 + u1), v1, f) ? v0 : v1;
    if (surface.frame(0.5 * (u0 + u1), apex, f)) continue;  // the base disc
    for (Eigen::Index i = 0; i < uv.rows(); ++i) uv(i, 1) = v0 + (v1 - v0) * (0.1 + 0.8 * (uv(i, 1) - v0) / (v1 - v0));
    const auto refusal = [&](const Eigen::MatrixXd& points, int threads) {
      try {
        surfaceCurvature(face, points, threads);
      } catch (const InputError& e) {
        return std::string(e.what());
      }
      return std::string("no refusal");
    };
    Eigen::MatrixXd both = uv;
    both(123, 1) = apex;
    both(45678, 1) = apex;
    Eigen::MatrixXd last = uv;
    last(45678, 1) = apex;
    for (int threads : {1, 3}) {
      EXPECT_NE(refusal(both, threads).find("point 123 "), std::string::npos) << refusal(both, threads);
      EXPECT_NE(refusal(last, threads).find("point 45678 "), std::string::npos) << refusal(last, threads);
    }
    EXPECT_EQ(refusal(uv, 3), "no refusal");
    ++checked;
  }
  EXPECT_EQ(checked, 1);
}
