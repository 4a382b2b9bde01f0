// Curve analysis: curvature samples, sign changes, extrema, distance to data.
#include <gtest/gtest.h>

#include <GeomConvert.hxx>
#include <Geom_Circle.hxx>
#include <Geom_Ellipse.hxx>
#include <gp_Ax2.hxx>

#include "fairsplines/analysis.hpp"
#include "fairsplines/baselines.hpp"
#include "fairsplines/occt.hpp"

using namespace fairsplines;

namespace {
Handle(Geom_BSplineCurve) circle(double r) {
  return GeomConvert::CurveToBSplineCurve(new Geom_Circle(gp_Ax2(gp_Pnt(1, 2, 0), gp_Dir(0, 0, 1)), r));
}
}  // namespace

TEST(Analysis, CircleHasCurvatureInverseRadiusAndArcLength) {
  const CurvatureProfile p = curvatureProfile(circle(2.0), 400);
  ASSERT_TRUE(p.isSigned);
  EXPECT_NEAR(p.normal.Z(), 1.0, 1e-15);
  for (Eigen::Index j = 0; j < p.kappa.size(); ++j) EXPECT_NEAR(p.kappa[j], 0.5, 1e-12);
  EXPECT_NEAR(p.s[p.s.size() - 1], 4 * M_PI, 1e-9);
  EXPECT_EQ(curvatureSignChanges(p), 0);
}

TEST(Analysis, ClockwiseCircleHasNegativeCurvature) {
  Handle(Geom_BSplineCurve) c = circle(1.0);
  c->Reverse();
  const CurvatureProfile p = curvatureProfile(c, 100);
  EXPECT_NEAR(p.kappa.maxCoeff(), -1.0, 1e-12);
}

TEST(Analysis, SCurveHasOneSignChange) {
  PointMatrix q(7, 2);
  q << 0, 0, 1, 1, 2, 1.2, 3, 0, 4, -1.2, 5, -1, 6, 0;
  const Handle(Geom_BSplineCurve) c = toOcct(controlPointSpline(q, false));
  EXPECT_EQ(curvatureSignChanges(curvatureProfile(c, 0, 32)), 1);
}

TEST(Analysis, EllipseExtremaAtVertices) {
  Handle(Geom_BSplineCurve) c =
      GeomConvert::CurveToBSplineCurve(new Geom_Ellipse(gp_Ax2(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), 3.0, 1.0));
  // Start the curve between vertices so all four extrema are interior.
  c->SetPeriodic();
  c->SetOrigin(c->FirstParameter() + 0.3 * (c->LastParameter() - c->FirstParameter()) / 4, 1e-12);
  const std::vector<CurvatureExtremum> ext = curvatureExtrema(curvatureProfile(c, 4000));
  int maxima = 0, minima = 0;
  for (const CurvatureExtremum& e : ext) {
    const gp_Pnt p = c->Value(e.u);
    if (e.maximum) {
      ++maxima;
      EXPECT_NEAR(e.kappa, 3.0, 1e-3);  // a / b^2 at the ends of the major axis
      EXPECT_NEAR(std::abs(p.X()), 3.0, 1e-3);
    } else {
      ++minima;
      EXPECT_NEAR(e.kappa, 1.0 / 9.0, 1e-4);  // b / a^2
      EXPECT_NEAR(std::abs(p.Y()), 1.0, 1e-3);
    }
  }
  EXPECT_EQ(maxima, 2);
  EXPECT_EQ(minima, 2);
}

TEST(Analysis, MaxDistanceOfOffsetPoints) {
  PointMatrix q(5, 3);
  for (int i = 0; i < 5; ++i) {
    const double a = 0.4 + 1.1 * i, r = 2.0 + 0.1 * i;  // the farthest is 0.4 off the circle
    q.row(i) << 1 + r * std::cos(a), 2 + r * std::sin(a), 0.0;
  }
  EXPECT_NEAR(maxDistanceToPoints(circle(2.0), q), 0.4, 1e-10);
}

TEST(Analysis, PlaneNormalOfTiltedPlanarCurveAndNoneFor3D) {
  PointMatrix q(6, 3);
  q << 0, 0, 0, 1, 0, 1, 2, 1, 2, 3, 3, 3, 4, 2, 4, 5, 0, 5;  // in the plane x = z
  auto n = planeNormal(toOcct(controlPointSpline(q, false)));
  ASSERT_TRUE(n.has_value());
  EXPECT_NEAR(std::abs(n->X()), std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(n->Y(), 0.0, 1e-12);
  q(3, 1) += 0.0;
  q(2, 0) += 1.0;  // leaves the plane
  EXPECT_FALSE(planeNormal(toOcct(controlPointSpline(q, false))).has_value());
}
