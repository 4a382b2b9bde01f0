// Eqs. (1)-(3): the G2 (beta) form of non-uniform cubic C2 B-splines.
#include <gtest/gtest.h>

#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <random>

#include "fairsplines/baselines.hpp"
#include "fairsplines/bspline.hpp"
#include "fairsplines/errors.hpp"
#include "test_support.hpp"

using namespace fairsplines;

namespace {

struct RandomSpline {
  PointMatrix c;         // c_0..c_K
  Eigen::VectorXd t;     // t_{-2}..t_{K+2}: c_i has support [t_{i-2}, t_{i+2}]
  Eigen::VectorXd beta;  // beta_0..beta_K
};

RandomSpline randomSpline(int K, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  RandomSpline s;
  s.c.resize(K + 1, 3);
  for (int i = 0; i <= K; ++i) s.c.row(i) << unit(rng) * 10, unit(rng) * 10, unit(rng) * 10;
  s.t.resize(K + 5);
  s.t[0] = 0.0;
  for (int i = 1; i < K + 5; ++i) s.t[i] = s.t[i - 1] + 0.1 + 3.0 * unit(rng);  // strongly non-uniform
  s.beta.resize(K + 1);
  for (int i = 0; i <= K; ++i) {
    const int j = i + 2;                                        // index of t_i in s.t
    s.beta[i] = (s.t[j + 1] - s.t[j]) / (s.t[j] - s.t[j - 1]);  // eq. (1)
  }
  return s;
}

Handle(Geom_BSplineCurve) occtUnclamped(const RandomSpline& s) {
  const int n = static_cast<int>(s.c.rows());
  TColgp_Array1OfPnt poles(1, n);
  for (int i = 0; i < n; ++i) poles.SetValue(i + 1, gp_Pnt(s.c(i, 0), s.c(i, 1), s.c(i, 2)));
  TColStd_Array1OfReal knots(1, static_cast<int>(s.t.size()));
  TColStd_Array1OfInteger mults(1, static_cast<int>(s.t.size()));
  for (int i = 0; i < s.t.size(); ++i) {
    knots.SetValue(i + 1, s.t[i]);
    mults.SetValue(i + 1, 1);
  }
  return new Geom_BSplineCurve(poles, knots, mults, 3);
}

}  // namespace

TEST(G2Form, BezierPiecesMatchOcctEvaluation) {
  const RandomSpline s = randomSpline(9, 7);
  const G2Spline g2 = g2FromDeBoor(s.c, s.beta);
  const Handle(Geom_BSplineCurve) occt = occtUnclamped(s);
  ASSERT_EQ(g2.pieces(), 9 - 2);
  for (int k = 0; k < g2.pieces(); ++k) {
    const double a = s.t[k + 3], b = s.t[k + 4];  // piece k spans [t_{k+1}, t_{k+2}]
    for (double x : {0.0, 0.25, 0.5, 0.8, 1.0}) {
      Eigen::RowVector3d bez = Eigen::RowVector3d::Zero();
      const double B[4] = {std::pow(1 - x, 3), 3 * x * std::pow(1 - x, 2), 3 * x * x * (1 - x), x * x * x};
      for (int j = 0; j < 4; ++j) bez += B[j] * g2.bezier.row(4 * k + j);
      const gp_Pnt p = occt->Value(a + x * (b - a));
      EXPECT_NEAR((bez - Eigen::RowVector3d(p.X(), p.Y(), p.Z())).norm(), 0.0, 1e-12 * 10)
          << "piece " << k << " x " << x;
    }
  }
}

TEST(G2Form, Eq2ThenEq3RoundTrips) {
  const RandomSpline s = randomSpline(12, 11);
  const G2Spline g2 = g2FromDeBoor(s.c, s.beta);
  const PointMatrix back = deBoorFromG2(g2);
  ASSERT_EQ(back.rows(), 12 - 1);  // c_1..c_{K-1}
  for (int i = 0; i < back.rows(); ++i) {
    EXPECT_LT((back.row(i) - s.c.row(i + 1)).norm(), 1e-12 * 10) << "c_" << i + 1;
  }
}

TEST(G2Form, BothFormsOfEq3Agree) {
  const RandomSpline s = randomSpline(8, 3);
  const G2Spline g2 = g2FromDeBoor(s.c, s.beta);
  for (int k = 1; k < g2.pieces(); ++k) {
    const double beta = g2.beta[k];
    const Eigen::RowVectorXd left =
        -beta * g2.bezier.row(4 * (k - 1) + 1) + (1 + beta) * g2.bezier.row(4 * (k - 1) + 2);
    const Eigen::RowVectorXd right = (1 + 1 / beta) * g2.bezier.row(4 * k + 1) - (1 / beta) * g2.bezier.row(4 * k + 2);
    EXPECT_LT((left - right).norm(), 1e-11);
  }
}

TEST(G2Form, PiecesJoinWithEq1Continuity) {
  const RandomSpline s = randomSpline(8, 5);
  const G2Spline g2 = g2FromDeBoor(s.c, s.beta);
  for (int k = 1; k < g2.pieces(); ++k) {
    const auto f = [&](int j) { return Eigen::RowVectorXd(g2.bezier.row(4 * (k - 1) + j)); };
    const auto g = [&](int j) { return Eigen::RowVectorXd(g2.bezier.row(4 * k + j)); };
    const double beta = g2.beta[k];
    EXPECT_LT((g(0) - f(3)).norm(), 1e-12);
    EXPECT_LT((3 * (g(1) - g(0)) - beta * 3 * (f(3) - f(2))).norm(), 1e-10);  // g'(0) = beta f'(1)
    EXPECT_LT((6 * (g(2) - 2 * g(1) + g(0)) - beta * beta * 6 * (f(3) - 2 * f(2) + f(1))).norm(), 1e-9);
  }
}

TEST(G2Form, RejectsNonPositiveBeta) {
  const RandomSpline s = randomSpline(6, 1);
  Eigen::VectorXd beta = s.beta;
  beta[2] = 0.0;
  EXPECT_THROW(g2FromDeBoor(s.c, beta), InputError);
}

TEST(QuasiInterpolant, AllBetaOneGivesMinus1_8_Minus1_Over6) {
  // Uniform parameters: all beta = 1, and p_i = (-q_{i-1} + 8 q_i - q_{i+1}) / 6.
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  PointMatrix q(10, 3);
  for (int i = 0; i < 10; ++i) q.row(i) << unit(rng), unit(rng), unit(rng);
  const BSplineCurve curve = quasiInterpolant(q, Parametrization::Uniform, false);
  ASSERT_EQ(curve.poles.rows(), 12);
  for (int i = 1; i <= 8; ++i) {
    const Eigen::RowVectorXd expected = (-q.row(i - 1) + 8 * q.row(i) - q.row(i + 1)) / 6.0;
    EXPECT_LT((curve.poles.row(i + 1) - expected).norm(), 1e-14) << "p_" << i;
  }
}

TEST(Parameters, ChordalCentripetalUniform) {
  PointMatrix q(3, 2);
  q << 0, 0, 3, 4, 3, 13;
  EXPECT_DOUBLE_EQ(parameters(q, Parametrization::Chordal, false)[2], 14.0);
  EXPECT_DOUBLE_EQ(parameters(q, Parametrization::Centripetal, false)[2], std::sqrt(5.0) + 3.0);
  EXPECT_DOUBLE_EQ(parameters(q, Parametrization::Uniform, false)[2], 2.0);
  EXPECT_EQ(parameters(q, Parametrization::Chordal, true).size(), 4);
  EXPECT_DOUBLE_EQ(parameters(q, Parametrization::Chordal, true)[3], 14.0 + std::sqrt(9.0 + 169.0));
}
