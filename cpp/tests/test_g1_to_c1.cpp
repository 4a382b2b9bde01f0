// G1 to C1 (blending paper, Section 5, eq. (12), Appendix 7.3), judged by OCCT evaluation
// of the homogeneous quartics and of the projected circle.
#include <gtest/gtest.h>

#include <Geom_BSplineCurve.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <cmath>

#include "fairsplines/errors.hpp"
#include "fairsplines/g1_to_c1.hpp"

using namespace fairsplines;

namespace {

const double kPi = std::acos(-1.0);

Eigen::VectorXd partition() {
  Eigen::VectorXd t(9);
  t << 0.0, 0.4, 1.5, 2.1, 3.0, 3.9, 4.3, 5.2, 2 * kPi;
  return t;
}

/// Degree-4 B-spline over knots with ratios beta, interior multiplicity 4 (C0 as assembled).
Handle(Geom_BSplineCurve) toOcct(const C1QuarticSpline& s, bool rational) {
  const int n = s.pieces();
  TColgp_Array1OfPnt poles(1, 4 * n + 1);
  TColStd_Array1OfReal weights(1, 4 * n + 1), knots(1, n + 1);
  TColStd_Array1OfInteger mults(1, n + 1);
  double t = 0.0, h = 1.0;
  for (int k = 0; k <= n; ++k) {
    knots.SetValue(k + 1, t);
    mults.SetValue(k + 1, k == 0 || k == n ? 5 : 4);
    if (k < n) {
      if (k > 0) h *= s.beta[k];
      t += h;
    }
  }
  for (int k = 0; k < n; ++k) {
    for (int j = (k > 0 ? 1 : 0); j <= 4; ++j) {
      const auto q = s.bezier.row(5 * k + j);
      poles.SetValue(4 * k + j + 1, rational ? gp_Pnt(q[0] / q[2], q[1] / q[2], 0) : gp_Pnt(q[0], q[1], q[2]));
      weights.SetValue(4 * k + j + 1, rational ? q[2] : 1.0);
    }
  }
  return new Geom_BSplineCurve(poles, weights, knots, mults, 4);
}

double c1Jump(const C1QuarticSpline& s) {
  const Handle(Geom_BSplineCurve) c = toOcct(s, false);
  double worst = 0.0;
  for (int k = 2; k <= s.pieces(); ++k) {
    const double u = c->Knot(k);
    const gp_Vec l = c->LocalDN(u, k - 1, k, 1), r = c->LocalDN(u, k, k + 1, 1);
    worst = std::max(worst, (l - r).Magnitude() / l.Magnitude());
    worst = std::max(worst, (s.bezier.row(5 * (k - 1) - 1) - s.bezier.row(5 * (k - 1))).norm());
  }
  return worst;
}

}  // namespace

TEST(Eta73, QuarticCircleIsC1AndExactForAnyNewScalars) {
  PointMatrix q;
  Eigen::VectorXd beta;
  bool closed = false;
  g1Circle(partition(), q, beta, closed);
  ASSERT_TRUE(closed);
  for (double scale : {1.0, 1.2, 0.7}) {
    const Eigen::VectorXd betaT = beta * scale;
    const C1QuarticSpline s = g1ToC1(q, beta, betaT, closed);
    EXPECT_EQ(s.pieces(), 16);
    EXPECT_LT(c1Jump(s), 1e-12) << scale;
    Handle(Geom_BSplineCurve) c = toOcct(s, false);
    for (int k = 2; k <= s.pieces(); ++k) EXPECT_TRUE(c->RemoveKnot(k, 3, 1e-10)) << k;  // C1 as a B-spline
    const Handle(Geom_BSplineCurve) projected = toOcct(s, true);
    double off = 0.0;
    for (int j = 0; j <= 2000; ++j) {
      const double u =
          projected->FirstParameter() + (projected->LastParameter() - projected->FirstParameter()) * j / 2000;
      off = std::max(off, std::abs(gp_Vec(projected->Value(u).XYZ()).Magnitude() - 1.0));
    }
    EXPECT_LT(off, 1e-12);
  }
}

TEST(Eta73, PrintedNumeratorsHoldOnlyForUnchangedScalars) {
  // Reading: the printed a_0 = 2 (1 + 1/beta_i) / (...) equals the derived one iff betaT = beta.
  const double wPrev = 0.8, w = 0.9, beta = 1.3;
  const double printed = 2 * (1 + 1 / beta) / (w / beta + wPrev + 1 / beta + 1);
  EXPECT_NEAR(etaStart(wPrev, w, beta, beta), printed, 1e-15);
  EXPECT_GT(std::abs(etaStart(wPrev, w, beta, 1.2 * beta) - printed), 1e-2);
  const double wNext = 0.7;
  const double printedEnd = 2 * (1 + beta) / (w * beta + wNext + beta + 1);
  EXPECT_NEAR(etaEnd(w, wNext, beta, beta), printedEnd, 1e-15);
}

TEST(Eta73, OpenArcAndBadInput) {
  PointMatrix q;
  Eigen::VectorXd beta;
  bool closed = true;
  Eigen::VectorXd t(4);
  t << -0.3, 0.5, 1.1, 2.9;
  g1Circle(t, q, beta, closed);
  EXPECT_FALSE(closed);
  EXPECT_LT(c1Jump(g1ToC1(q, beta, beta, closed)), 1e-12);
  t << 0.0, 3.2, 4.0, 5.0;
  EXPECT_THROW(g1Circle(t, q, beta, closed), InputError);  // an arc of pi or more
  t << 0.0, 1.0, 1.0, 2.0;
  EXPECT_THROW(g1Circle(t, q, beta, closed), InputError);
}
