// Monotonic-curvature cubic B-splines: eqs. (3), (5), Lemmas 1-3, Theorems 1-2, Algorithms 1-2,
// the exact certificate. OCCT's evaluation of the curves is the referee.
#include <gtest/gtest.h>

#include <GC_MakeArcOfCircle.hxx>
#include <GC_MakeArcOfEllipse.hxx>
#include <GeomConvert.hxx>
#include <Geom_Circle.hxx>
#include <Geom_Ellipse.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <gp_Ax2.hxx>
#include <gp_Elips.hxx>
#include <random>

#include "fairsplines/monotone.hpp"
#include "fairsplines/occt.hpp"
#include "monotone_detail.hpp"
#include "test_support.hpp"

using namespace fairsplines;
using Eigen::Vector2d;
using Eigen::Vector3d;

namespace {

BSplineCurve curveOf(const PointMatrix& poles, std::vector<double> knots, std::vector<int> mults, int degree = 3) {
  BSplineCurve c;
  c.degree = degree;
  c.poles = poles;
  c.knots = Eigen::Map<Eigen::VectorXd>(knots.data(), knots.size());
  c.mults = Eigen::Map<Eigen::VectorXi>(mults.data(), mults.size());
  return c;
}

/// The cubic Bezier of y = x^3 (or any cubic polynomial graph) over [x0, x1].
BSplineCurve cubicGraph(double x0, double x1) {
  // Blossom of f(x) = x^3 is x y z; of x is (x + y + z) / 3.
  PointMatrix p(4, 2);
  const double a = x0, b = x1;
  const double xs[4][3] = {{a, a, a}, {a, a, b}, {a, b, b}, {b, b, b}};
  for (int i = 0; i < 4; ++i) p.row(i) << (xs[i][0] + xs[i][1] + xs[i][2]) / 3.0, xs[i][0] * xs[i][1] * xs[i][2];
  return curveOf(p, {x0, x1}, {4, 4});
}

/// |kappa| of the OCCT curve at n + 1 equally spaced parameters.
std::vector<double> occtCurvature(const Handle(Geom_BSplineCurve)& c, int n) {
  std::vector<double> k;
  for (int i = 0; i <= n; ++i) {
    const double u = c->FirstParameter() + (c->LastParameter() - c->FirstParameter()) * i / n;
    gp_Pnt p;
    gp_Vec d1, d2;
    c->D2(u, p, d1, d2);
    k.push_back(d1.Crossed(d2).Magnitude() / std::pow(d1.Magnitude(), 3));
  }
  return k;
}

/// +1 nondecreasing, -1 nonincreasing (within tol of the largest value), 0 neither.
int monotoneDirection(const std::vector<double>& k, double relTol = 1e-9) {
  const double tol = relTol * *std::max_element(k.begin(), k.end());
  bool up = true, down = true;
  for (size_t i = 1; i < k.size(); ++i) {
    up = up && k[i] >= k[i - 1] - tol;
    down = down && k[i] <= k[i - 1] + tol;
  }
  return up ? 1 : (down ? -1 : 0);
}

double relError(const gp_Pnt& p, const Vector3d& q, double size) {
  return (Vector3d(p.X(), p.Y(), p.Z()) - q).norm() / size;
}

}  // namespace

// --- eqs. (3), (5) ------------------------------------------------------------------------

TEST(Monotone, DerivativePolygons_AreTheControlPolygonsOfOcctsDerivatives) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  PointMatrix poles(7, 2);
  for (int i = 0; i < 7; ++i) poles.row(i) << 10 * unit(rng), 10 * unit(rng);
  const BSplineCurve c = curveOf(poles, {0.0, 0.7, 1.1, 2.9, 4.0}, {4, 1, 1, 1, 4});  // non-uniform
  const DerivativePolygons d = derivativePolygons(c);
  ASSERT_EQ(d.first.rows(), 6);
  ASSERT_EQ(d.second.rows(), 5);
  // P' is the quadratic B-spline on t_1..t_{m-1} with poles C^1_i; P'' the linear one on t_2..t_{m-2}.
  const BSplineCurve first = curveOf(d.first, {0.0, 0.7, 1.1, 2.9, 4.0}, {3, 1, 1, 1, 3}, 2);
  const BSplineCurve second = curveOf(d.second, {0.0, 0.7, 1.1, 2.9, 4.0}, {2, 1, 1, 1, 2}, 1);
  const Handle(Geom_BSplineCurve) C = toOcct(c), D1 = toOcct(first), D2 = toOcct(second);
  for (int i = 0; i <= 40; ++i) {
    const double u = 4.0 * i / 40;
    gp_Pnt p;
    gp_Vec v1, v2;
    C->D2(u, p, v1, v2);
    EXPECT_NEAR(D1->Value(u).Distance(gp_Pnt(v1.XYZ())), 0.0, 1e-11) << u;
    EXPECT_NEAR(D2->Value(u).Distance(gp_Pnt(v2.XYZ())), 0.0, 1e-10) << u;
  }
  EXPECT_THROW(derivativePolygons(curveOf(poles.topRows(3), {0, 1}, {3, 3}, 2)), InputError);
}

// --- Lemmas 1-3, Theorems 1-2 ----------------------------------------------------------------

TEST(Monotone, Segment_ParabolaFromItsVertexMeetsTheorem1OnItsBoundary) {
  // x = u, y = u^2 on [0, 2] as a clamped cubic with knots (0,0,0,0,1,2,2,2,2): P'' is constant.
  // Poles: blossoms of (u, u^2) at (0,0,0), (0,0,1), (0,1,2), (1,2,2), (2,2,2).
  PointMatrix p(5, 2);
  p << 0, 0, 1.0 / 3, 0, 1, 2.0 / 3, 5.0 / 3, 8.0 / 3, 2, 4;
  const std::vector<SegmentReport> r = checkSegments(curveOf(p, {0, 1, 2}, {4, 1, 4}));
  ASSERT_EQ(r.size(), 2u);
  for (const SegmentReport& s : r) {
    EXPECT_TRUE(s.check.theorem1()) << describe(s.check);
    EXPECT_TRUE(s.check.theorem2) << describe(s.check);
    EXPECT_EQ(s.check.turn, 1);
    EXPECT_NEAR(s.check.angle, M_PI / 2, 1e-9);  // C^2 constant: on the circle of Lemma 2
  }
}

TEST(Monotone, Segment_EachLemmaFailsWithItsReason) {
  const double u[6] = {0, 0, 0, 1, 2, 2};  // the first span of (0,0,0,0,1,2,2,2,2)
  auto check = [&](std::vector<Vector2d> c) { return checkSegment(c.data(), u); };
  // Lemma 1: an S-shape, the second derivatives on both sides of the first control vector.
  SegmentCheck s = check({{0, 0}, {1, 0}, {3, 1}, {4, 0}});
  EXPECT_FALSE(s.lemma1);
  EXPECT_NE(describe(s).find("Lemma 1 fails"), std::string::npos) << describe(s);
  // Lemma 2: |C^2| grows (C^2_1 outside the circle with diameter O C^2_0): the second derivative grows.
  s = check({{0, 0}, {1, 0}, {3, 0.2}, {5.5, 3}});
  EXPECT_TRUE(s.lemma1) << describe(s);
  EXPECT_FALSE(s.lemma2);
  EXPECT_NE(describe(s).find("Lemma 2 fails"), std::string::npos) << describe(s);
  EXPECT_LT(s.angle, M_PI / 2);
  // Lemma 3: C^2_1 = (0.5, 0.5) turns further left than C^2_0 = (2, 0.4), inside its circle.
  s = check({{0, 0}, {1, 0}, {11.0 / 3, 2.0 / 15}, {20.0 / 3, 0.6}});
  EXPECT_TRUE(s.lemma1) << describe(s);
  EXPECT_FALSE(s.lemma3);
  EXPECT_NE(describe(s).find("Lemma 3 fails"), std::string::npos) << describe(s);
  // The mirror image of a right turn is checked as a left turn.
  // C^2_0 = (1, 1), C^2_1 = (0.5, 0.4): in the fair location.
  SegmentCheck left = check({{0, 0}, {1, 0}, {10.0 / 3, 1.0 / 3}, {6, 14.0 / 15}});
  SegmentCheck right = check({{0, 0}, {1, 0}, {10.0 / 3, -1.0 / 3}, {6, -14.0 / 15}});
  EXPECT_TRUE(left.theorem1()) << describe(left);
  EXPECT_TRUE(right.theorem1()) << describe(right);
  EXPECT_EQ(left.turn, 1);
  EXPECT_EQ(right.turn, -1);
  // No frame without a first control vector.
  EXPECT_TRUE(check({{0, 0}, {0, 0}, {1, 1}, {2, 3}}).degenerate);
}

// --- Algorithm 1 ------------------------------------------------------------------------------

TEST(Monotone, Algorithm1_RandomControlVectorsAreClampedIntoMonotoneCurves) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    const int m = 2 + trial % 6;
    PointMatrix dv(m, 2);
    for (int i = 0; i < m; ++i) dv.row(i) << unit(rng), unit(rng);
    const Vector2d v0(2 * unit(rng), 2 * unit(rng));
    const MonotoneDesign d = designMonotone(v0, dv);
    const MonotonicityCertificate cert = certifyMonotoneCurvature(d.curve);
    const std::vector<SegmentReport> segments = checkSegments(d.curve);
    for (size_t k = 0; k < segments.size(); ++k) {
      ASSERT_TRUE(segments[k].check.theorem2) << trial << ": " << describe(segments[k].check);
      const bool straight = cert.spans[k].trend == CurvatureTrend::Constant;
      if (!straight) ASSERT_EQ(segments[k].check.turn, d.turn) << trial;  // a straight piece turns neither way
    }
    // The referee: OCCT's curvature decreases in magnitude, and the certificate agrees.
    const Handle(Geom_BSplineCurve) c = toOcct(d.curve);
    ASSERT_EQ(monotoneDirection(occtCurvature(c, 2000)), -1) << trial;
    ASSERT_TRUE(cert.monotone) << cert.reason;
    EXPECT_EQ(d.turn > 0 ? cert.decreasing : cert.increasing, true) << cert.reason;
    // The poles are the running sums of the vectors used.
    Vector2d V = v0, C = Vector2d::Zero();
    for (int i = 0; i <= m; ++i) {
      C += V;
      ASSERT_NEAR((d.curve.poles.row(i + 1).transpose() - C).norm(), 0.0, 1e-12);
      if (i < m) V += d.differences.row(i).transpose();
    }
  }
}

TEST(Monotone, Algorithm1_KeepsDifferencesAlreadyInTheirFairLocation) {
  // Knots (0,0,0,0,1,2,2,2,2): C^2_0 = (0, 1.5) in the quadrant, C^2_1 = (0.45, 0.675) and
  // C^2_2 = (0.25, 0.25) in their fair locations (the clamped end asks V_3 near V_2 / 2).
  PointMatrix dv(3, 2);
  dv << 1.0, 0.5, 0.3, 0.45, -133.0 / 120, -13.0 / 30;
  const MonotoneDesign d = designMonotone(Vector2d(1, 0), dv);
  EXPECT_EQ(d.moved.maxCoeff(), 0.0);
  EXPECT_EQ((d.differences - dv).cwiseAbs().maxCoeff(), 0.0);
  // A growing difference is pulled back onto its circle, and the curve stays monotone.
  dv.row(2) << 1.0, 2.0;
  const MonotoneDesign e = designMonotone(Vector2d(1, 0), dv);
  EXPECT_GT(e.moved[2], 0.1);
  EXPECT_EQ(e.moved[0], 0.0);
  EXPECT_EQ(e.moved[1], 0.0);
  EXPECT_TRUE(certifyMonotoneCurvature(e.curve).decreasing);
  // Given back, the clamped differences stay put (on the circle, up to rounding).
  const MonotoneDesign again = designMonotone(Vector2d(1, 0), e.differences);
  EXPECT_EQ(again.moved.maxCoeff(), 0.0);
  EXPECT_EQ((again.differences - e.differences).cwiseAbs().maxCoeff(), 0.0);
}

TEST(Monotone, Algorithm1_RejectsBadInput) {
  PointMatrix dv(2, 2);
  dv << 1, 1, 0.5, 0.5;
  EXPECT_THROW(designMonotone(Vector2d(0, 0), dv), InputError);
  EXPECT_THROW(designMonotone(Vector2d(1, NAN), dv), InputError);
  EXPECT_THROW(designMonotone(Vector2d(1, 0), dv.topRows(1)), InputError);
  Eigen::VectorXd knots(7);
  knots << 0, 0, 0, 0, 1, 1, 1;  // one short
  EXPECT_THROW(designMonotone(Vector2d(1, 0), dv, knots), InputError);
}

// --- Algorithm 2 ------------------------------------------------------------------------------

TEST(Monotone, Algorithm2_ThousandRandomAdmissibleEndsGiveVerifiedMonotoneCurves) {
  const std::vector<test::EndCondition> ends = test::randomAdmissibleEnds(1000, 7);
  int boundary = 0;
  for (size_t k = 0; k < ends.size(); ++k) {
    const test::EndCondition& e = ends[k];
    const MonotoneSpline s = monotoneCurvatureSpline(e.p0, e.t0, e.p1, e.t1);
    boundary += s.boundary;
    EXPECT_EQ(s.reversed, e.reversed) << k;
    const Handle(Geom_BSplineCurve) c = toOcct(s.curve);
    const double size = (e.p1 - e.p0).norm();
    EXPECT_LE(relError(c->Value(c->FirstParameter()), e.p0, size), 1e-12) << k;
    EXPECT_LE(relError(c->Value(c->LastParameter()), e.p1, size), 1e-12) << k;
    gp_Pnt p;
    gp_Vec d0, d1;
    c->D1(c->FirstParameter(), p, d0);
    c->D1(c->LastParameter(), p, d1);
    const Vector3d a(d0.X(), d0.Y(), d0.Z()), b(d1.X(), d1.Y(), d1.Z());
    // The direction of a short end leg between two large coordinates is known to about
    // eps * |coordinates| / |leg|: that, or 1e-12, bounds the angle to t0 and t1.
    const double coords = s.curve.poles.cwiseAbs().maxCoeff();
    const double leg0 = (s.curve.poles.row(1) - s.curve.poles.row(0)).norm();
    const double leg1 = (s.curve.poles.row(4) - s.curve.poles.row(3)).norm();
    EXPECT_LE(a.normalized().cross(e.t0.normalized()).norm(), 1e-12 + 8e-16 * coords / leg0) << k;
    EXPECT_GT(a.dot(e.t0), 0.0) << k;
    EXPECT_LE(b.normalized().cross(e.t1.normalized()).norm(), 1e-12 + 8e-16 * coords / leg1) << k;
    EXPECT_GT(b.dot(e.t1), 0.0) << k;
    // Curvature magnitude decreases from p0, or increases when the ends ask for it.
    EXPECT_EQ(monotoneDirection(occtCurvature(c, 400)), e.reversed ? 1 : -1) << k;
    const MonotonicityCertificate cert = certifyMonotoneCurvature(s.curve);
    EXPECT_TRUE(cert.monotone) << k << ": " << cert.reason;
  }
  EXPECT_LT(boundary, 5);  // the parabola only where the admissible set is (nearly) empty inside
}

TEST(Monotone, Algorithm2_IsInvariantUnderSimilarities) {
  // The same ends moved, turned, scaled and mirrored give the same curve moved likewise.
  const Vector3d p0(0, 0, 0), t0(1, 0, 0), p1(1.0, 0.5, 0), t1(0.8, 0.6, 0);
  const MonotoneSpline s = monotoneCurvatureSpline(p0, t0, p1, t1);
  const double angle = 2.1, scale = 37.0;
  Eigen::Matrix3d R = Eigen::AngleAxisd(angle, Vector3d::UnitZ()).toRotationMatrix() * scale;
  R.col(1) *= -1.0;  // mirror
  const Vector3d shift(5, -3, 2);
  const MonotoneSpline m = monotoneCurvatureSpline(R * p0 + shift, R * t0, R * p1 + shift, R * t1);
  for (int i = 0; i < 5; ++i) {
    const Vector3d expected = R * s.curve.poles.row(i).transpose() + shift;
    EXPECT_NEAR((m.curve.poles.row(i).transpose() - expected).norm() / scale, 0.0, 1e-9) << i;
  }
  // Reversing the data reverses the curve.
  const MonotoneSpline r = monotoneCurvatureSpline(p1, -t1, p0, -t0);
  EXPECT_TRUE(r.reversed);
  for (int i = 0; i < 5; ++i) EXPECT_NEAR((r.curve.poles.row(i) - s.curve.poles.row(4 - i)).norm(), 0.0, 1e-12);
}

TEST(Monotone, Algorithm2_FairestLiesStrictlyInsideTheorem2) {
  const MonotoneSpline s = monotoneCurvatureSpline({0, 0, 0}, {1, 0, 0}, {1.0, 0.5, 0}, {0.8, 0.6, 0});
  EXPECT_FALSE(s.boundary);
  EXPECT_GT(s.margin, 0.05);
  for (const SegmentReport& r : checkSegments(s.curve)) EXPECT_TRUE(r.check.theorem2) << describe(r.check);
  const MonotonicityCertificate cert = certifyMonotoneCurvature(s.curve);
  ASSERT_TRUE(cert.decreasing) << cert.reason;
  for (const SpanCertificate& span : cert.spans) EXPECT_EQ(span.trend, CurvatureTrend::Decreasing);
  EXPECT_GT(cert.kappaStart, 1.5 * cert.kappaEnd);
}

TEST(Monotone, Algorithm2_OnTheBoundaryReturnsTheParabolaFromItsVertex) {
  // a = b cos(turn): M = (0.5, 0), p1 = (1, 1) with t1 = (1, 2): the parabola y = x^2.
  const MonotoneSpline s = monotoneCurvatureSpline({0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {1, 2, 0});
  EXPECT_TRUE(s.boundary);
  const Handle(Geom_BSplineCurve) c = toOcct(s.curve);
  for (int i = 0; i <= 20; ++i) {
    const gp_Pnt p = c->Value(2.0 * i / 20);
    EXPECT_NEAR(p.Y(), p.X() * p.X(), 1e-12);
  }
  EXPECT_TRUE(certifyMonotoneCurvature(s.curve).decreasing);
}

TEST(Monotone, Algorithm2_StraightEndsGiveTheSegment) {
  const MonotoneSpline s = monotoneCurvatureSpline({1, 1, 1}, {2, 2, 2}, {4, 4, 4}, {1, 1, 1});
  const MonotonicityCertificate cert = certifyMonotoneCurvature(s.curve);
  EXPECT_TRUE(cert.increasing && cert.decreasing) << cert.reason;
  EXPECT_NEAR(toOcct(s.curve)->Value(1.0).Distance(gp_Pnt(2.5, 2.5, 2.5)), 0.0, 1e-14);
}

TEST(Monotone, Algorithm2_InadmissibleEndsSayWhy) {
  auto reason = [](Vector3d p0, Vector3d t0, Vector3d p1, Vector3d t1) {
    try {
      monotoneCurvatureSpline(p0, t0, p1, t1);
    } catch (const NoMonotoneSolution& e) {
      return std::string(e.what());
    }
    return std::string("solved");
  };
  const Vector3d o(0, 0, 0), x(1, 0, 0);
  EXPECT_NE(reason(o, x, {1, 1, 0}, {0, 1, 0}).find("turns by 90 deg"), std::string::npos);
  EXPECT_NE(reason(o, x, {1, 1, 0}, {1, 0.5, 0}).find("behind p0 along t0"), std::string::npos);
  EXPECT_NE(reason(o, x, {1, 1, 0}, {1, -0.2, 0}).find("outside the admissible wedge"), std::string::npos);  // S-curve
  EXPECT_NE(reason(o, x, {-1, 1, 0}, {-1, 0.1, 0}).find("turns by"), std::string::npos);
  EXPECT_NE(reason(o, x, {1, 1, 0}, {0.2, 1, 0}).find("too central"), std::string::npos);  // a = 0.8, b = 1.02
  EXPECT_NE(reason(o, x, {1, 1, 0}, {-0.1, 1, 0}).find("turns by"), std::string::npos);
  EXPECT_EQ(reason(o, x, {2, 1, 0}, {1, 1, 0}), "solved");  // a = b cos(turn): the parabola from its vertex
  EXPECT_NE(reason(o, x, {2, 1, 0}, {1, 0, 0}).find("parallel"), std::string::npos);
  EXPECT_NE(reason(o, x, {2, 1, 0}, {1, 1, 1}).find("not planar"), std::string::npos);
  EXPECT_NE(reason(o, x, {2, 0, 0}, {1, 1, 0}).find("start tangent"), std::string::npos);
  EXPECT_NE(reason(o, x, {-2, 0, 0}, {-1, 0, 0}).find("behind p0"), std::string::npos);
  // NoMonotoneSolution is an InputError; bad input is an InputError naming the problem.
  EXPECT_THROW(monotoneCurvatureSpline(o, x, {2, 1, 0}, {1, 0, 0}), InputError);
  auto inputError = [](Vector3d p0, Vector3d t0, Vector3d p1, Vector3d t1) {
    try {
      monotoneCurvatureSpline(p0, t0, p1, t1);
    } catch (const NoMonotoneSolution&) {
      return std::string("NoMonotoneSolution");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("solved");
  };
  EXPECT_EQ(inputError(o, {0, 0, 0}, {1, 1, 0}, x), "t0 is zero: give the start tangent direction");
  EXPECT_EQ(inputError(o, x, {1, 1, 0}, {0, 0, 0}), "t1 is zero: give the end tangent direction");
  EXPECT_EQ(inputError(o, x, o, x), "p0 and p1 coincide");
  EXPECT_EQ(inputError(o, x, {NAN, 1, 0}, x), "p1 is not finite");
}

TEST(Monotone, Algorithm2_TooCentralEndsFailJustBeyondTheParabola) {
  // a <= b cos(turn) is the exact limit: just inside solvable, just outside not (both orientations fail).
  const double turn = 0.7, b = 1.0;
  const Vector3d t1(std::cos(turn), std::sin(turn), 0);
  for (double f : {0.999, 1.001}) {
    const double a = f * b * std::cos(turn);
    const Vector3d p1 = Vector3d(a, 0, 0) + b * t1;
    bool solved = true;
    try {
      monotoneCurvatureSpline({0, 0, 0}, {1, 0, 0}, p1, t1);
    } catch (const NoMonotoneSolution& e) {
      solved = false;
      EXPECT_NE(std::string(e.what()).find("too central"), std::string::npos) << e.what();
    }
    EXPECT_EQ(solved, f < 1.0) << f;
  }
}

TEST(Monotone, Algorithm2_GridAgreesOnFeasibilityWhereverItFindsACurve) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int gridSolved = 0, inadmissible = 0;
  for (int k = 0; k < 300; ++k) {
    // Anywhere in the first quadrant, any tangent turning up to 120 deg: admissible or not.
    const Vector3d p1(0.2 + unit(rng), 1.2 * unit(rng), 0);
    const double turn = 2.1 * unit(rng);
    const Vector3d t1(std::cos(turn), std::sin(turn), 0);
    const EndConditions ec = analyzeEndConditions({0, 0, 0}, {1, 0, 0}, p1, t1);
    inadmissible += !ec.admissible;
    try {
      const MonotoneSpline g = monotoneCurvatureSpline({0, 0, 0}, {1, 0, 0}, p1, t1, MonotoneMethod::PaperGrid);
      ++gridSolved;
      ASSERT_TRUE(ec.admissible) << k;
      ASSERT_TRUE(certifyMonotoneCurvature(g.curve).monotone);
      ASSERT_NO_THROW(monotoneCurvatureSpline({0, 0, 0}, {1, 0, 0}, p1, t1)) << k;
    } catch (const NoMonotoneSolution&) {
    }
  }
  EXPECT_GT(gridSolved, 20);
  EXPECT_GT(inadmissible, 100);
}

TEST(Monotone, Algorithm2_ReadingC1AsT1TimesMFindsNothingInThePapersRange) {
  // docs/READINGS.md reads "C_1 = t_1 P" as C_1 = t_1 M. With the paper's 0 < t_1 < 1/6 (step 0.02)
  // no candidate of 50 random admissible ends passes Lemmas 1-3: the bounds are in units of
  // C4.x (README), which the kernel's grid uses.
  const double knots[9] = {0, 0, 0, 0, 1, 2, 2, 2, 2};
  int found = 0;
  for (const test::EndCondition& e : test::randomAdmissibleEnds(50, 9)) {
    const EndConditions ec = analyzeEndConditions(e.p0, e.t0, e.p1, e.t1);
    const double L = (e.p1 - e.p0).norm(), a = (ec.reversed ? ec.b : ec.a) / L, b = (ec.reversed ? ec.a : ec.b) / L;
    const Vector2d M(a, 0), T(std::cos(ec.turn), std::abs(std::sin(ec.turn))), P = M + b * T;
    for (int i1 = 1; i1 * 0.02 < 1.0 / 6; ++i1) {
      for (int i3 = 1; i3 * 0.02 < 0.8; ++i3) {
        const Vector2d C1 = i1 * 0.02 * M, C3 = (1 - i3 * 0.02) * M + i3 * 0.02 * P;
        for (double tx = 3 * i1 * 0.02 + 0.02; tx < C3.x() / P.x(); tx += 0.02) {
          for (double ty = 0.02; ty < i3 * 0.01; ty += 0.02) {
            const Vector2d c[5] = {{0, 0}, C1, {tx * P.x(), ty * P.y()}, C3, P};
            found += checkSegment(c, knots + 1).theorem1() && checkSegment(c + 1, knots + 2).theorem1();
          }
        }
      }
    }
  }
  EXPECT_EQ(found, 0);
}

TEST(Monotone, Algorithm2_GridResultsAreVerifiedAndOfTheFamily) {
  const MonotoneSpline g =
      monotoneCurvatureSpline({0, 0, 0}, {1, 0, 0}, {1.0, 0.5, 0}, {0.8, 0.6, 0}, MonotoneMethod::PaperGrid);
  EXPECT_GT(g.iterations, 1);
  for (const SegmentReport& r : checkSegments(g.curve)) EXPECT_TRUE(r.check.theorem1()) << describe(r.check);
  EXPECT_EQ(monotoneDirection(occtCurvature(toOcct(g.curve), 1000)), -1);
}

// --- The certificate ----------------------------------------------------------------------------

TEST(Monotone, Certificate_FindsTheCurvatureMaximumOfXCubed) {
  // y = x^3 has kappa' = 0 at x = 45^(-1/4) = 0.3861: a maximum.
  const BSplineCurve c = cubicGraph(0.2, 0.6);
  const MonotonicityCertificate cert = certifyMonotoneCurvature(c);
  EXPECT_FALSE(cert.monotone);
  ASSERT_EQ(cert.spans.size(), 1u);
  const SpanCertificate& s = cert.spans[0];
  EXPECT_EQ(s.trend, CurvatureTrend::Extremum);
  EXPECT_TRUE(s.maximum);
  const double x = toOcct(c)->Value(s.at).X();
  EXPECT_NEAR(x, std::pow(45.0, -0.25), 1e-9);
  EXPECT_NEAR(s.kappaAt, 6 * x / std::pow(1 + 9 * std::pow(x, 4), 1.5), 1e-9);
  EXPECT_NE(cert.reason.find("maximum"), std::string::npos) << cert.reason;
  EXPECT_EQ(s.degree, 6);
}

TEST(Monotone, Certificate_AcceptsKnownMonotoneCurves) {
  // y = x^3 on [0, 0.3]: curvature rises; the parabola from its vertex: curvature falls.
  MonotonicityCertificate cert = certifyMonotoneCurvature(cubicGraph(0.0, 0.3));
  EXPECT_TRUE(cert.monotone && cert.increasing && !cert.decreasing) << cert.reason;
  EXPECT_NEAR(cert.kappaStart, 0.0, 1e-15);
  PointMatrix parabola(3, 2);  // y = x^2 over [0, 1] as a quadratic Bezier
  parabola << 0, 0, 0.5, 0, 1, 1;
  cert = certifyMonotoneCurvature(curveOf(parabola, {0, 1}, {3, 3}, 2));
  EXPECT_TRUE(cert.decreasing && !cert.increasing) << cert.reason;
  EXPECT_NEAR(cert.kappaStart, 2.0, 1e-12);
  // Its reverse (in another plane): increasing.
  PointMatrix tilted(3, 3);
  tilted << 1, 1, 1, 0.5, 0, 0.5, 0, 0, 0;
  cert = certifyMonotoneCurvature(curveOf(tilted, {0, 1}, {3, 3}, 2));
  EXPECT_TRUE(cert.monotone) << cert.reason;
  // A line and a circular arc (rational): constant.
  PointMatrix line(4, 2);
  line << 0, 0, 1, 1, 2, 2, 3, 3;
  cert = certifyMonotoneCurvature(curveOf(line, {0, 1}, {4, 4}));
  EXPECT_TRUE(cert.increasing && cert.decreasing) << cert.reason;
  const Handle(Geom_TrimmedCurve) arc = GC_MakeArcOfCircle(gp_Pnt(2, 0, 0), gp_Pnt(0, 2, 0), gp_Pnt(-2, 0, 0)).Value();
  cert = certifyMonotoneCurvature(fromOcct(GeomConvert::CurveToBSplineCurve(arc)));
  EXPECT_TRUE(cert.increasing && cert.decreasing) << cert.reason;
  EXPECT_NEAR(cert.kappaStart, 0.5, 1e-12);
}

TEST(Monotone, Certificate_RejectsConstructedExtrema) {
  // The parabola through its vertex (y = x^2, x in [-0.5, 1]): a maximum at the vertex.
  PointMatrix p(3, 2);
  p << -0.5, 0.25, 0.25, -0.5, 1, 1;
  MonotonicityCertificate cert = certifyMonotoneCurvature(curveOf(p, {0, 1}, {3, 3}, 2));
  ASSERT_FALSE(cert.monotone);
  EXPECT_EQ(cert.spans[0].trend, CurvatureTrend::Extremum);
  EXPECT_NEAR(toOcct(curveOf(p, {0, 1}, {3, 3}, 2))->Value(cert.spans[0].at).X(), 0.0, 1e-12);
  EXPECT_NEAR(cert.spans[0].kappaAt, 2.0, 1e-9);
  // A symmetric cubic arch: maximum in the middle.
  PointMatrix arch(4, 2);
  arch << 0, 0, 1, 1, 2, 1, 3, 0;
  cert = certifyMonotoneCurvature(curveOf(arch, {0, 1}, {4, 4}));
  ASSERT_FALSE(cert.monotone);
  EXPECT_NEAR(cert.spans[0].at, 0.5, 1e-12);
  EXPECT_FALSE(cert.spans[0].maximum);  // signed curvature of a clockwise arch: its minimum
  // An ellipse arc across the end of its major axis (rational).
  const Handle(Geom_TrimmedCurve) e =
      GC_MakeArcOfEllipse(gp_Elips(gp_Ax2(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), 3.0, 1.0), -0.5, 0.3, true).Value();
  cert = certifyMonotoneCurvature(fromOcct(GeomConvert::CurveToBSplineCurve(e)));
  ASSERT_FALSE(cert.monotone) << cert.reason;
  bool found = false;
  for (const SpanCertificate& s : cert.spans) {
    if (s.trend == CurvatureTrend::Extremum) {
      found = true;
      EXPECT_NEAR(s.kappaAt, 3.0, 1e-9);  // a / b^2
    }
  }
  EXPECT_TRUE(found) << cert.reason;
}

TEST(Monotone, Certificate_AgreesWithDenseOcctSamplingOnRandomCurves) {
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int monotone = 0, extremum = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const int degree = 2 + trial % 4;
    PointMatrix p(degree + 1, 2);
    for (int i = 0; i <= degree; ++i) p.row(i) << i + 0.6 * unit(rng), 0.8 * i * i * unit(rng) / degree;
    const BSplineCurve c = curveOf(p, {0, 1}, {degree + 1, degree + 1}, degree);
    const MonotonicityCertificate cert = certifyMonotoneCurvature(c);
    const Handle(Geom_BSplineCurve) occt = toOcct(c);
    std::vector<double> signedKappa;
    for (int i = 0; i <= 4000; ++i) signedKappa.push_back(test::signedKappa(occt, i / 4000.0));
    const int direction = monotoneDirection(signedKappa, 1e-7);
    if (cert.monotone) {
      ++monotone;
      EXPECT_NE(direction, 0) << trial << ": " << cert.reason;
      if (direction != 0 && !(cert.increasing && cert.decreasing)) EXPECT_EQ(direction, cert.increasing ? 1 : -1);
    } else {
      ASSERT_EQ(cert.spans[0].trend, CurvatureTrend::Extremum) << trial << ": " << cert.reason;
      ++extremum;
      // OCCT's samples turn around at the extremum.
      const double at = cert.spans[0].at, h = 1e-3;
      const double k0 = test::signedKappa(occt, std::max(0.0, at - h)), k1 = test::signedKappa(occt, at);
      const double k2 = test::signedKappa(occt, std::min(1.0, at + h));
      if (cert.spans[0].maximum) {
        EXPECT_GE(k1, std::max(k0, k2) - 1e-12) << trial;
      } else {
        EXPECT_LE(k1, std::min(k0, k2) + 1e-12) << trial;
      }
    }
  }
  EXPECT_GT(monotone, 30);
  EXPECT_GT(extremum, 30);
}

TEST(Monotone, Certificate_SeesJumpsAndCornersAtKnots) {
  // A corner: a polyline.
  PointMatrix q(3, 2);
  q << 0, 0, 1, 0, 2, 1;
  MonotonicityCertificate cert = certifyMonotoneCurvature(curveOf(q, {0, 1, 2}, {2, 1, 2}, 1));
  EXPECT_FALSE(cert.monotone);
  EXPECT_NE(cert.reason.find("corner at u = 1"), std::string::npos) << cert.reason;
  // A curvature jump: a straight piece, then a parabola from its vertex, joined G1 at a triple knot.
  PointMatrix r(7, 2);
  r << 0, 0, 1, 0, 2, 0, 3, 0, 11.0 / 3, 0, 13.0 / 3, 1.0 / 3, 5, 1;
  cert = certifyMonotoneCurvature(curveOf(r, {0, 1, 2}, {4, 3, 4}));
  EXPECT_FALSE(cert.monotone);
  EXPECT_EQ(cert.spans[0].trend, CurvatureTrend::Constant);
  EXPECT_EQ(cert.spans[1].trend, CurvatureTrend::Decreasing);
  EXPECT_NE(cert.reason.find("jumps up from 0 to 0.5 at u = 1"), std::string::npos) << cert.reason;
  // The parabola alone, and the straight piece alone, are monotone.
  EXPECT_TRUE(certifyMonotoneCurvature(curveOf(r.bottomRows(4), {0, 1}, {4, 4})).decreasing);
}

TEST(Monotone, Certificate_PeriodicCurvesAndSingularAndNonPlanar) {
  Handle(Geom_BSplineCurve) circle = GeomConvert::CurveToBSplineCurve(new Geom_Circle(gp_Ax2(), 2.0));
  circle->SetPeriodic();
  MonotonicityCertificate cert = certifyMonotoneCurvature(fromOcct(circle));
  EXPECT_TRUE(cert.increasing && cert.decreasing) << cert.reason;
  Handle(Geom_BSplineCurve) ellipse = GeomConvert::CurveToBSplineCurve(new Geom_Ellipse(gp_Ax2(), 3.0, 1.0));
  ellipse->SetPeriodic();
  EXPECT_FALSE(certifyMonotoneCurvature(fromOcct(ellipse)).monotone);
  PointMatrix cusp(4, 2);  // first two poles equal: P'(0) = 0
  cusp << 0, 0, 0, 0, 1, 1, 2, 0;
  cert = certifyMonotoneCurvature(curveOf(cusp, {0, 1}, {4, 4}));
  EXPECT_FALSE(cert.monotone);
  EXPECT_EQ(cert.spans[0].trend, CurvatureTrend::Singular) << cert.reason;
  PointMatrix helix(4, 3);
  helix << 1, 0, 0, 1, 1, 0.3, -1, 1, 0.6, -1, 0, 0.9;
  EXPECT_THROW(certifyMonotoneCurvature(curveOf(helix, {0, 1}, {4, 4})), InputError);
}

TEST(Monotone, CurvatureVariation_IsZeroForLinesAndCirclesOnly) {
  PointMatrix line(4, 2);
  line << 0, 0, 1, 1, 2, 2, 3, 3;
  EXPECT_NEAR(curvatureVariation(curveOf(line, {0, 1}, {4, 4})), 0.0, 1e-20);
  const Handle(Geom_TrimmedCurve) arc = GC_MakeArcOfCircle(gp_Pnt(2, 0, 0), gp_Pnt(0, 2, 0), gp_Pnt(-2, 0, 0)).Value();
  EXPECT_NEAR(curvatureVariation(fromOcct(GeomConvert::CurveToBSplineCurve(arc))), 0.0, 1e-15);
  EXPECT_GT(curvatureVariation(cubicGraph(0.0, 0.3)), 1e-3);
}

TEST(Monotone, Fairest_NewtonReachesTheSameStationaryCentreFromEveryStart) {
  // Normalized ends (C0 = 0, T0 = +x, |C4| = 1): the analytic centre does not depend on where
  // Newton starts, and the barrier's gradient vanishes there (central differences).
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int compared = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const double turn = 0.05 + 1.45 * unit(rng), limit = std::cos(turn) / (1 + std::cos(turn));
    const double r = (0.05 + 0.9 * unit(rng)) * limit;
    const Vector2d T(std::cos(turn), std::sin(turn));
    const Vector2d C4 = Vector2d(r, 0) + (1 - r) * T;
    const double L = C4.norm();
    const Vector2d P = C4 / L;
    std::vector<Eigen::Vector4d> centres;
    for (double k : {0.8, 0.95, 0.99, 0.999}) {
      for (double theta : {0.1, 0.01, 0.001}) {
        if (const auto start = detail::geometricStart(P, T, k, theta)) {
          int iterations = 0;
          centres.push_back(detail::analyticCentre(*start, P, T, iterations));
          EXPECT_LT(iterations, 60);
        }
      }
    }
    ASSERT_FALSE(centres.empty()) << trial;
    for (const Eigen::Vector4d& c : centres) EXPECT_LE((c - centres[0]).norm(), 1e-7) << trial;
    compared += static_cast<int>(centres.size()) - 1;
    const Eigen::Vector4d& x = centres[0];
    EXPECT_GT(detail::margin(x, P, T), 0.0);
    for (int i = 0; i < 4; ++i) {  // stationary: the Newton correction along each axis is below 1e-8
      const double h = 1e-5, f0 = detail::barrier(x, P, T);
      auto at = [&](double d) {
        Eigen::Vector4d y = x;
        y[i] += d;
        return detail::barrier(y, P, T);
      };
      auto slope = [&](double d) { return (at(d) - at(-d)) / (2 * d); };
      const double first = (4 * slope(h / 2) - slope(h)) / 3;  // Richardson-extrapolated
      const double second = (at(h) - 2 * f0 + at(-h)) / (h * h);
      EXPECT_GT(second, 0.0) << trial << " " << i;
      EXPECT_LE(std::abs(first / second), 1e-8) << trial << " " << i;
    }
  }
  EXPECT_GT(compared, 100);
}
