// G2 to C2 for curves (blending paper, Sections 3 and 4.1, Appendix 7.1-7.2), judged by
// OCCT evaluation: the homogeneous sextics as one polynomial B-spline in (X, Y, W) space
// (C2 across every joint, knot removal down to multiplicity 4), and the projected rational
// B-spline on the unit circle.
#include <gtest/gtest.h>

#include <Geom_BSplineCurve.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <cmath>
#include <random>

#include "fairsplines/blend_shapes.hpp"
#include "fairsplines/errors.hpp"
#include "fairsplines/g2_to_c2.hpp"

using namespace fairsplines;

namespace {

const double kPi = std::acos(-1.0);

Eigen::VectorXd vec(std::initializer_list<double> v) {
  Eigen::VectorXd out(static_cast<Eigen::Index>(v.size()));
  Eigen::Index i = 0;
  for (double x : v) out[i++] = x;
  return out;
}

Eigen::VectorXd nonUniformTurn() { return vec({0.0, 0.4, 1.5, 2.1, 3.9, 4.3, 5.2, 2 * kPi}); }
/// A uniform run (0.5 x 4) inside a non-uniform closed partition.
Eigen::VectorXd mixedTurn() { return vec({0.0, 0.5, 1.0, 1.5, 2.0, 2.9, 3.3, 4.6, 5.5, 2 * kPi}); }

/// The sextics as one degree-6 B-spline over the spline's knots, interior multiplicity 6
/// (C0 as assembled); rational = false: polynomial in homogeneous (X, Y, W) space; true:
/// the projected rational curve.
Handle(Geom_BSplineCurve) toOcct(const C2SexticSpline& s, bool rational) {
  const int n = s.pieces();
  const Eigen::VectorXd t = s.knots();
  TColgp_Array1OfPnt poles(1, 6 * n + 1);
  TColStd_Array1OfReal weights(1, 6 * n + 1), knots(1, n + 1);
  TColStd_Array1OfInteger mults(1, n + 1);
  for (int k = 0; k < n; ++k) {
    for (int j = 0; j <= 6; ++j) {
      if (k > 0 && j == 0) continue;
      const auto h = s.bezier.row(7 * k + j);
      poles.SetValue(6 * k + j + 1, rational ? gp_Pnt(h[0] / h[2], h[1] / h[2], 0) : gp_Pnt(h[0], h[1], h[2]));
      weights.SetValue(6 * k + j + 1, rational ? h[2] : 1.0);
    }
  }
  for (int k = 0; k <= n; ++k) {
    knots.SetValue(k + 1, t[k]);
    mults.SetValue(k + 1, k == 0 || k == n ? 7 : 6);
  }
  return new Geom_BSplineCurve(poles, weights, knots, mults, 6);
}

/// Largest relative jump of OCCT's position, first and second derivatives across every
/// interior knot (LocalDN on both spans), plus the closing join of a closed spline, plus
/// the gap between b_6 and the next piece's b_0.
double c2Jump(const C2SexticSpline& s) {
  const Handle(Geom_BSplineCurve) c = toOcct(s, false);
  double worst = 0.0;
  const int n = s.pieces();
  auto jump = [&](const gp_Vec& l, const gp_Vec& r, double scale) {
    worst = std::max(worst, (l - r).Magnitude() / scale);
  };
  for (int k = 2; k <= n; ++k) {
    const double u = c->Knot(k);
    const gp_Vec l0 = c->LocalDN(u, k - 1, k, 1), r0 = c->LocalDN(u, k, k + 1, 1);
    const double scale = std::max(l0.Magnitude(), c->LocalDN(u, k - 1, k, 2).Magnitude());
    gp_Pnt pl = c->LocalValue(u, k - 1, k), pr = c->LocalValue(u, k, k + 1);
    worst = std::max(worst, pl.Distance(pr) / scale);
    for (int order = 1; order <= 2; ++order)
      jump(c->LocalDN(u, k - 1, k, order), c->LocalDN(u, k, k + 1, order), scale);
    worst = std::max(worst, (s.bezier.row(7 * (k - 1) - 1) - s.bezier.row(7 * (k - 1))).norm() / scale);
  }
  if (s.closed) {
    const double u0 = c->FirstParameter(), u1 = c->LastParameter();
    const double scale = c->DN(u0, 1).Magnitude();
    worst = std::max(worst, c->Value(u0).Distance(c->Value(u1)) / scale);
    // The closing scalar beta[0] relates the last span to the first: derivatives in the
    // global parameter agree when h_0 / h_{n-1} = beta[0].
    const double h0 = c->Knot(2) - c->Knot(1), hLast = c->Knot(n + 1) - c->Knot(n);
    const double ratio = h0 / hLast / s.beta[0];
    for (int order = 1; order <= 2; ++order) {
      jump(c->LocalDN(u1, n, n + 1, order) * std::pow(ratio, order), c->LocalDN(u0, 1, 2, order), scale);
    }
  }
  return worst;
}

/// Largest | |p| - 1 | of the projected OCCT curve at 50 samples per span.
double offCircle(const C2SexticSpline& s) {
  const Handle(Geom_BSplineCurve) c = toOcct(s, true);
  double worst = 0.0;
  for (int k = 1; k < c->NbKnots(); ++k) {
    for (int j = 0; j <= 50; ++j) {
      const double u = c->Knot(k) + (c->Knot(k + 1) - c->Knot(k)) * j / 50.0;
      worst = std::max(worst, std::abs(gp_Vec(c->Value(u).XYZ()).Magnitude() - 1.0));
    }
  }
  return worst;
}

/// Every homogeneous weight coefficient positive (the projected curve is well defined).
bool weightsPositive(const C2SexticSpline& s) { return (s.bezier.col(2).array() > 0).all(); }

/// OCCT accepts removing every interior knot down to multiplicity 4: a C2 degree-6 B-spline.
bool reducesToC2(const C2SexticSpline& s) {
  Handle(Geom_BSplineCurve) c = toOcct(s, false);
  const double size = s.bezier.cwiseAbs().maxCoeff();
  for (int k = 2; k < c->NbKnots(); ++k) {
    if (!c->RemoveKnot(k, 4, 1e-10 * size)) return false;
  }
  return c->Continuity() >= GeomAbs_C2;
}

}  // namespace

TEST(Rho, Appendix71TernarySplitJoinsC2AndKeepsTheCircleExact) {
  const G2CircleSpline circle = g2Circle(nonUniformTurn());
  const C2SexticSpline s = circleToC2(circle, CircleReparam::Rho);
  EXPECT_EQ(s.pieces(), 3 * circle.pieces());
  EXPECT_TRUE(weightsPositive(s));
  EXPECT_LT(c2Jump(s), 1e-12);
  EXPECT_LT(offCircle(s), 1e-12);
  EXPECT_TRUE(reducesToC2(s));
}

TEST(Rho, OpenArcAndFreeScalarsBetaTilde) {
  const G2CircleSpline circle = g2Circle(vec({-0.3, 0.1, 1.2, 1.6, 3.0}));
  for (double scale : {1.0, 0.8, 1.25}) {
    Eigen::VectorXd betaT = circle.beta * scale;
    const C2SexticSpline s = circleToC2(circle, CircleReparam::Rho, betaT);
    EXPECT_LT(c2Jump(s), 1e-12) << scale;
    EXPECT_LT(offCircle(s), 1e-12) << scale;
    for (int i = 1; i < circle.pieces(); ++i) {
      // arc to arc betaT; piece to piece scaled by parts_{i-1} / parts_i
      const double partsPrev = s.firstPiece[i] - s.firstPiece[i - 1], parts = s.firstPiece[i + 1] - s.firstPiece[i];
      EXPECT_DOUBLE_EQ(s.beta[s.firstPiece[i]], betaT[i] * partsPrev / parts);
    }
  }
}

TEST(Rho, UniformClosedCircleKeepsOnePiecePerArc) {
  const G2CircleSpline circle = g2Circle(Eigen::VectorXd::LinSpaced(8, 0.0, 2 * kPi));
  const C2SexticSpline s = circleToC2(circle, CircleReparam::Rho);
  EXPECT_EQ(s.pieces(), 7);
  EXPECT_LT(c2Jump(s), 1e-12);
  EXPECT_LT(offCircle(s), 1e-12);
  EXPECT_TRUE(reducesToC2(s));
}

TEST(Rho, UniformPartitionNeedsNoSplitYetIsNotTheIdentity) {
  // Appendix 7.1: for a uniform partition and betaT = 1, d and nu do not depend on i
  // (d = 1/3), but nu != 1: the G2 circle (gamma != 0) is not C2 as it stands.
  const double tau = std::tan(0.5 / 4);
  const Reparam h = rhoEndMap(tau, tau, 1.0);
  EXPECT_NEAR(h(1, 0) / h(1, 1), 1.0 / 3, 1e-15);
  EXPECT_GT(std::abs(h(1, 1) - 1.0), 1e-4);
}

TEST(Sigma, Eq7HalvesTheAngleAndEq8ReturnsToTheCircle) {
  for (double theta : {-1.2, 0.0, 0.7, 2.0, 3.1, 4.5}) {
    const Eigen::Vector2d p(std::cos(theta), std::sin(theta));
    const Eigen::Vector2d q = projectToHalfAngle(p);
    // On the circle about C = (0, -1), at angle theta / 2 + pi / 4 (Section 3, [BP97]).
    EXPECT_NEAR(std::atan2(q.y() + 1, q.x()), std::remainder(theta / 2 + kPi / 4, 2 * kPi), 1e-14);
    const Eigen::Vector3d h = projectBack(q);
    EXPECT_NEAR(h.x() / h.z(), p.x(), 1e-14);
    EXPECT_NEAR(h.y() / h.z(), p.y(), 1e-14);
  }
}

TEST(Sigma, TridiagonalSplineGivesC2SexticsOnTheCircle) {
  // Closed (cyclic system) and open (tridiagonal), non-uniform.
  for (const Eigen::VectorXd& theta : {nonUniformTurn(), vec({0.2, 0.5, 1.5, 1.8, 2.9, 3.6})}) {
    const G2CircleSpline circle = g2Circle(theta);
    const C2SexticSpline s = circleToC2(circle, CircleReparam::Sigma);
    EXPECT_EQ(s.pieces(), circle.pieces());
    EXPECT_TRUE(weightsPositive(s));
    EXPECT_LT(c2Jump(s), 1e-12);
    EXPECT_LT(offCircle(s), 1e-12);
    EXPECT_TRUE(reducesToC2(s));
  }
}

TEST(Sigma, UniformClosedCircleGivesTheSameMapsAsRhoWouldPreserve) {
  // On a uniform closed partition every sigma map is the same (the system is circulant).
  const G2CircleSpline circle = g2Circle(vec({0.0, kPi / 3, 2 * kPi / 3, kPi, 4 * kPi / 3, 5 * kPi / 3, 2 * kPi}));
  const std::vector<Reparam> maps = sigmaMaps(circle, circle.beta);
  for (const Reparam& m : maps) EXPECT_LT((m - maps[0]).norm(), 1e-12);
}

TEST(Transition72, JoinsAnyNormalFormMapC2) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> nu(0.8, 1.3), d(0.2, 0.45), alpha(0.3, 1.8), beta(0.6, 1.6);
  for (int trial = 0; trial < 20; ++trial) {
    const double a = alpha(rng), aBar = alpha(rng), b = beta(rng);
    const G2CircleSpline c = g2Circle(vec({0.3, 0.3 + a, 0.3 + a + aBar}));
    Reparam h;
    const double nu1 = nu(rng), nu2 = nu(rng), d1 = d(rng), d2 = 1 - d(rng);
    h << 0, 1, nu1 * d1, nu1, nu2 * d2, nu2, 1, 1;
    const Reparam hBar = transitionMap(std::tan(a / 4), std::tan(aBar / 4), h, b);
    C2SexticSpline s;
    s.bezier.resize(14, 3);
    s.bezier.topRows(7) = composeQuadratic(PointMatrix(c.quadratic(0)), h);
    s.bezier.bottomRows(7) = composeQuadratic(PointMatrix(c.quadratic(1)), hBar);
    s.beta = vec({1.0, b});
    EXPECT_LT(c2Jump(s), 1e-11) << trial;
    // and its mirror image, as used at the left end of a sigma run
    const Reparam left = reverseMap(transitionMap(std::tan(aBar / 4), std::tan(a / 4), reverseMap(hBar), 1 / b));
    EXPECT_LT((left - h).norm(), 1e-10) << trial;
  }
}

TEST(Mixed, RhoOnUniformRunsSigmaElsewhereJoinC2) {
  for (const Eigen::VectorXd& theta : {mixedTurn(), vec({0.0, 0.5, 1.0, 1.5, 2.4, 2.7, 3.5, 4.0, 4.5})}) {
    const G2CircleSpline circle = g2Circle(theta);
    const std::vector<CircleReparam> choice = mixedChoice(circle);
    EXPECT_EQ(choice[0], CircleReparam::Rho);
    EXPECT_EQ(choice[4], CircleReparam::Sigma);
    C2SexticSpline s;
    try {
      s = circleToC2(circle, CircleReparam::Mixed);
    } catch (const std::exception& e) {
      FAIL() << e.what();
    }
    EXPECT_TRUE(weightsPositive(s));
    EXPECT_LT(c2Jump(s), 1e-11);
    EXPECT_LT(offCircle(s), 1e-12);
    EXPECT_TRUE(reducesToC2(s));
  }
  // Uniformity is kept inside the run: arcs 1 and 2 of mixedTurn (both neighbours rho,
  // betaT = 1) are one piece each, and the same piece up to rotation.
  const C2SexticSpline s = circleToC2(g2Circle(mixedTurn()), CircleReparam::Mixed);
  EXPECT_EQ(s.firstPiece[1], 3);
  EXPECT_EQ(s.firstPiece[2], 4);
  EXPECT_EQ(s.firstPiece[3], 5);
  const PointMatrix a = s.bezier.middleRows(7 * 3, 7), b = s.bezier.middleRows(7 * 4, 7);
  EXPECT_LT((a.col(2) - b.col(2)).norm(), 1e-13);  // same weights (rotated points)
}

TEST(Mixed, SymmetricRunsGetRhoAndStayMirrorSymmetric) {
  // Openings 0.9, | 0.5, 1.2, 0.5 |, 1.4, 0.7, ...: arcs 1-3 read the same both ways.
  const Eigen::VectorXd theta = vec({0.0, 0.9, 1.4, 2.6, 3.1, 4.5, 5.2, 2 * kPi});
  const G2CircleSpline circle = g2Circle(theta);
  const std::vector<CircleReparam> choice = mixedChoice(circle);
  const std::vector<CircleReparam> expected = {CircleReparam::Sigma, CircleReparam::Rho,   CircleReparam::Rho,
                                               CircleReparam::Rho,   CircleReparam::Sigma, CircleReparam::Sigma,
                                               CircleReparam::Sigma};
  EXPECT_EQ(choice, expected);
  // The centre arc (2, from 1.4 to 2.6) is parameterised mirror-symmetrically about its
  // bisector with rho (Mixed), not with sigma alone: point at s vs mirror of point at 1 - s.
  auto asymmetry = [&](CircleReparam method) {
    const C2SexticSpline s = circleToC2(circle, method);
    const Eigen::VectorXd t = s.knots();
    const double t0 = t[s.firstPiece[2]], t1 = t[s.firstPiece[3]];
    auto at = [&](double x) {
      int k = s.firstPiece[2];
      while (k + 1 < s.firstPiece[3] && x > t[k + 1]) ++k;
      const double u = (x - t[k]) / (t[k + 1] - t[k]);
      const double binom[7] = {1, 6, 15, 20, 15, 6, 1};
      Eigen::RowVector3d p = Eigen::RowVector3d::Zero();
      for (int i = 0; i <= 6; ++i) p += binom[i] * std::pow(u, i) * std::pow(1 - u, 6 - i) * s.bezier.row(7 * k + i);
      return std::atan2(p[1] / p[2], p[0] / p[2]);
    };
    const double bisector = 2.0;
    double worst = 0.0;
    for (int k = 0; k <= 20; ++k) {
      const double x = t0 + (t1 - t0) * k / 20.0, y = t1 - (t1 - t0) * k / 20.0;
      worst = std::max(worst, std::abs((at(x) - bisector) + (at(y) - bisector)));
    }
    return worst;
  };
  EXPECT_LT(asymmetry(CircleReparam::Mixed), 1e-12);
  EXPECT_GT(asymmetry(CircleReparam::Sigma), 1e-4);
  const C2SexticSpline mixed = circleToC2(circle, CircleReparam::Mixed);
  EXPECT_LT(c2Jump(mixed), 1e-11);
  EXPECT_LT(offCircle(mixed), 1e-12);
}

TEST(Eq10, HermiteQuadraticsOfThePerturbedCubicStayC2InsideEachArc) {
  // A modified control structure (Fig. 4a): one inner point of an arc moved. Inside each
  // arc the rho pieces share Hermite quadratics at 1/3 and 2/3, so they join C2; the sextic
  // stays close to the cubic (Fig. 6: a small parametric difference).
  const G2CircleSpline circle = g2Circle(nonUniformTurn());
  PointMatrix cubic(circle.cubic.rows(), 3);
  for (Eigen::Index k = 0; k < cubic.rows(); ++k) cubic.row(k) = circle.cubic.row(k);
  cubic.row(4 * 2 + 1) *= 1.05;
  cubic(4 * 2 + 1, 2) /= 1.05;  // same weight, point pushed out by 5%
  std::vector<std::vector<Reparam>> maps;
  for (int i = 0; i < circle.pieces(); ++i) {
    const int n = circle.pieces();
    const auto rho = rhoSplit(std::tan(circle.alpha[(i + n - 1) % n] / 4), std::tan(circle.alpha[i] / 4),
                              std::tan(circle.alpha[(i + 1) % n] / 4), circle.beta[i], circle.beta[(i + 1) % n]);
    maps.push_back({rho[0], rho[1], rho[2]});
  }
  const C2SexticSpline s = g2ToC2(cubic, maps, circle.beta, true);
  const Handle(Geom_BSplineCurve) c = toOcct(s, false);
  for (int piece = 6; piece <= 7; ++piece) {  // the joints inside arc 2 (pieces 6, 7, 8)
    const double u = c->Knot(piece + 2);
    EXPECT_LT(c->LocalValue(u, piece + 1, piece + 2).Distance(c->LocalValue(u, piece + 2, piece + 3)), 1e-14);
    for (int order = 1; order <= 2; ++order) {
      const gp_Vec l = c->LocalDN(u, piece + 1, piece + 2, order), r = c->LocalDN(u, piece + 2, piece + 3, order);
      EXPECT_LT((l - r).Magnitude() / l.Magnitude(), 1e-12) << piece << " " << order;
    }
  }
  // Projected distance between the sextic and the cubic at matching parameters is small.
  const Handle(Geom_BSplineCurve) projected = toOcct(s, true);
  const Reparam& r = maps[2][1];
  for (int j = 0; j <= 10; ++j) {
    const double u = j / 10.0, b0 = std::pow(1 - u, 3), b1 = 3 * u * (1 - u) * (1 - u), b2 = 3 * u * u * (1 - u),
                 b3 = u * u * u;
    const double t = (b0 * r(0, 0) + b1 * r(1, 0) + b2 * r(2, 0) + b3 * r(3, 0)) /
                     (b0 * r(0, 1) + b1 * r(1, 1) + b2 * r(2, 1) + b3 * r(3, 1));
    const double c0 = std::pow(1 - t, 3), c1 = 3 * t * (1 - t) * (1 - t), c2 = 3 * t * t * (1 - t), c3 = t * t * t;
    const Eigen::RowVector3d h = c0 * cubic.row(8) + c1 * cubic.row(9) + c2 * cubic.row(10) + c3 * cubic.row(11);
    const gp_Pnt p = projected->Value(projected->Knot(8) + u * (projected->Knot(9) - projected->Knot(8)));
    EXPECT_LT(std::hypot(p.X() - h[0] / h[2], p.Y() - h[1] / h[2]), 5e-3);
  }
}

TEST(Eq11, AdjustmentMakesTheInterfaceWithADegreeRaisedPieceC2) {
  // A C2 sextic circle arc followed by a degree-raised cubic (identity map): C0 as
  // assembled, C2 after eq. (11).
  const G2CircleSpline circle = g2Circle(vec({0.0, 0.6, 1.5, 2.0}));
  C2SexticSpline s = circleToC2(circle, CircleReparam::Rho);
  const int n = s.pieces();
  const Eigen::RowVector3d end = s.bezier.row(7 * n - 1);
  PointMatrix cubic(4, 3);
  cubic.row(0) = end;
  cubic.row(1) = end + Eigen::RowVector3d(-0.3, 0.1, 0.05);
  cubic.row(2) = end + Eigen::RowVector3d(-0.7, -0.1, 0.0);
  cubic.row(3) = end + Eigen::RowVector3d(-1.0, -0.4, 0.0);
  PointMatrix tail = raiseCubicToSextic(cubic);
  PointMatrix last = s.bezier.bottomRows(7);
  const double beta = 1.4;
  C2SexticSpline joined;
  joined.bezier.resize(7 * (n + 1), 3);
  joined.bezier.topRows(7 * n) = s.bezier;
  joined.bezier.bottomRows(7) = tail;
  joined.beta.resize(n + 1);
  joined.beta << s.beta, beta;
  EXPECT_GT(c2Jump(joined), 1e-3);  // the referee sees the C0 join
  adjustC2(last, tail, beta);
  joined.bezier.middleRows(7 * (n - 1), 7) = last;
  joined.bezier.bottomRows(7) = tail;
  EXPECT_LT(c2Jump(joined), 1e-12);
  EXPECT_TRUE(reducesToC2(joined));
}

TEST(G2ToC2, BadScalarsAndNonMonotoneMapsRaiseInputError) {
  const G2CircleSpline circle = g2Circle(nonUniformTurn());
  EXPECT_THROW(circleToC2(circle, CircleReparam::Rho, vec({1.0, 2.0})), InputError);
  Eigen::VectorXd bad = circle.beta;
  bad[3] = -1.0;
  EXPECT_THROW(circleToC2(circle, CircleReparam::Rho, bad), InputError);
  // Scalars far from the shape's beta make sigma non-monotone (Section 3's warning).
  const G2CircleSpline open = g2Circle(vec({0.0, 0.2, 1.8, 2.0}));
  Eigen::VectorXd wild = open.beta;
  wild[1] = 40.0;
  wild[2] = 0.02;
  EXPECT_THROW(circleToC2(open, CircleReparam::Sigma, wild), InputError);
}
