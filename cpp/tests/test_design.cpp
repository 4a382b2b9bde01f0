// Design with basic curves, Sections 3.2, 5, 6 and Fig. 9, judged by OCCT evaluation.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <random>

#include "fairsplines/bspline.hpp"
#include "fairsplines/design.hpp"
#include "fairsplines/errors.hpp"
#include "fairsplines/occt.hpp"
#include "fairsplines/surfaces.hpp"
#include "test_support.hpp"

using namespace fairsplines;

namespace {

Eigen::VectorXd randomMarks(std::mt19937& rng, int count) {
  std::uniform_real_distribution<double> unit(0.02, 0.98);
  std::vector<double> v(count);
  for (double& x : v) x = unit(rng);
  std::sort(v.begin(), v.end());
  return Eigen::Map<Eigen::VectorXd>(v.data(), count);
}

Eigen::Vector3d at(const Handle(Geom_BSplineCurve)& c, double t) {
  const gp_Pnt p = c->Value(t);
  return {p.X(), p.Y(), p.Z()};
}

/// Largest |F(p)| / |grad F(p)| (first-order distance to the implicit curve) over samples
/// of the OCCT curve on [t0, t1].
template <class F, class G>
double implicitDeviation(const Handle(Geom_BSplineCurve)& c, double t0, double t1, F value, G gradient) {
  double worst = 0.0;
  for (int j = 0; j <= 2000; ++j) {
    const Eigen::Vector3d p = at(c, t0 + (t1 - t0) * j / 2000.0);
    worst = std::max(worst, std::abs(value(p)) / gradient(p).norm());
  }
  return worst;
}

Design single(const BasicCurve& curve, const Eigen::VectorXd& marks) {
  return mergePieces({piecePolygon(curve, marks)}, 0.0);
}

/// Relative jump of the second derivative across interior knots (OCCT's LocalDN per span).
double c2Jump(const Handle(Geom_BSplineCurve)& c) {
  double worst = 0.0, scale = 0.0;
  for (int k = 2; k < c->NbKnots(); ++k) {
    for (int order = 1; order <= 2; ++order) {
      const gp_Vec left = c->LocalDN(c->Knot(k), k - 1, k, order), right = c->LocalDN(c->Knot(k), k, k + 1, order);
      worst = std::max(worst, (left - right).Magnitude());
      scale = std::max(scale, left.Magnitude());
    }
  }
  return worst / scale;
}

const Frame kTilted{{1.0, -2.0, 0.5}, Eigen::Vector3d(1, 1, 0).normalized(), Eigen::Vector3d(-1, 1, 1).normalized()};

}  // namespace

TEST(BasicCurves, CircleArcParameterOfPointByEq4RoundTrips) {
  for (double sweep : {0.4, 2.0, 3.0, 4.5, -2.5, 6.0}) {
    const CircleArc arc(kTilted, 2.0, 0.3, sweep);
    for (double u : {0.0, 0.1, 0.37, 0.5, 0.81, 1.0}) {
      EXPECT_NEAR(arc.parameterOf(arc.value(u)), u, 1e-12) << "sweep " << sweep;
      EXPECT_NEAR((arc.value(u) - kTilted.origin).norm(), 2.0, 1e-13);
    }
  }
  const CircleArc arc(kTilted, 2.0, 0.3, 1.0);
  EXPECT_THROW(arc.parameterOf(kTilted.at(3.0, 0.0)), InputError);                                  // off the circle
  EXPECT_THROW(arc.parameterOf(kTilted.at(2.0 * std::cos(2.0), 2.0 * std::sin(2.0))), InputError);  // outside the arc
}

TEST(BasicCurves, Eq5FindsParametersOnEveryCurve) {
  std::vector<std::unique_ptr<BasicCurve>> curves;
  curves.push_back(ellipseArc(kTilted, 3.0, 1.0, 0.2, 4.0));
  curves.push_back(parabolaArc(kTilted, 0.7, -1.0, 2.0));
  curves.push_back(hyperbolaArc(kTilted, 1.0, 0.5, -1.0, 1.5));
  curves.push_back(archimedeanSpiral(kTilted, 0.2, 0.3, 0.5, 7.0));
  curves.push_back(circleInvolute(kTilted, 0.5, 0.2, 3.0));
  curves.push_back(lineSegment({0, 0, 0}, {1, 2, 3}));
  for (const auto& c : curves) {
    for (double u : {0.0, 0.05, 0.33, 0.71, 1.0}) EXPECT_NEAR(c->parameterOf(c->value(u)), u, 1e-10);
    EXPECT_THROW(c->parameterOf(c->value(0.5) + Eigen::Vector3d(0.3, -0.2, 0.1) * c->size()), InputError);
  }
}

TEST(BasicCurves, DerivativesMatchDifferenceQuotients) {
  auto check = [](const BasicCurve& c) {
    for (double u : {0.2, 0.5, 0.9}) {
      const double e = 1e-6;
      EXPECT_LT((c.d1(u) - (c.value(u + e) - c.value(u - e)) / (2 * e)).norm(), 1e-6 * (1 + c.d1(u).norm()));
      EXPECT_LT((c.d2(u) - (c.d1(u + e) - c.d1(u - e)) / (2 * e)).norm(), 1e-5 * (1 + c.d2(u).norm()));
    }
  };
  check(*ellipseArc(kTilted, 3.0, 1.0, 0.2, 4.0));
  check(*hyperbolaArc(kTilted, 1.0, 0.5, -1.0, 1.5));
  check(*archimedeanSpiral(kTilted, 0.2, 0.3, 0.5, 7.0));
  check(*circleInvolute(kTilted, 0.5, 0.2, 3.0));
}

TEST(BasicCurves, DegenerateInputThrows) {
  EXPECT_THROW(CircleArc(kTilted, 0.0, 0.0, 1.0), InputError);
  EXPECT_THROW(CircleArc(kTilted, 1.0, 0.0, 0.0), InputError);
  EXPECT_THROW(CircleArc(kTilted, 1.0, 0.0, 7.0), InputError);
  EXPECT_THROW(ellipseArc(kTilted, 1.0, -1.0, 0.0, 1.0), InputError);
  EXPECT_THROW(parabolaArc(kTilted, 1.0, 2.0, 1.0), InputError);
  EXPECT_THROW(lineSegment({1, 1, 1}, {1, 1, 1}), InputError);
  EXPECT_THROW(archimedeanSpiral(kTilted, -1.0, 1.0, 0.0, 2.0), InputError);  // passes its centre
}

TEST(Section6, ConicArcsWithRandomMarksAreExact) {
  std::mt19937 rng(17);
  const double a = 3.0, b = 1.2;
  for (int trial = 0; trial < 10; ++trial) {
    const Eigen::VectorXd marks = randomMarks(rng, 2 + trial);
    // circle (in the plane z = 0 of a shifted frame)
    const Frame frame{{0.5, -1, 0}, Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY()};
    Handle(Geom_BSplineCurve) c = toOcct(single(CircleArc(frame, a, 0.4, 2.2), marks).curve);
    const double size = 2 * a;
    EXPECT_LT(implicitDeviation(
                  c, c->FirstParameter(), c->LastParameter(),
                  [&](const Eigen::Vector3d& p) { return (p - frame.origin).squaredNorm() - a * a; },
                  [&](const Eigen::Vector3d& p) { return Eigen::Vector3d(2 * (p - frame.origin)); }),
              1e-12 * size);
    auto local = [&](const Eigen::Vector3d& p) { return Eigen::Vector2d(p.x() - 0.5, p.y() + 1); };
    c = toOcct(single(*ellipseArc(frame, a, b, -0.5, 2.5), marks).curve);
    EXPECT_LT(implicitDeviation(
                  c, c->FirstParameter(), c->LastParameter(),
                  [&](const Eigen::Vector3d& p) {
                    const auto q = local(p);
                    return q.x() * q.x() / (a * a) + q.y() * q.y() / (b * b) - 1;
                  },
                  [&](const Eigen::Vector3d& p) {
                    const auto q = local(p);
                    return Eigen::Vector3d(2 * q.x() / (a * a), 2 * q.y() / (b * b), 0);
                  }),
              1e-12 * size);
    c = toOcct(single(*parabolaArc(frame, 0.8, -1.5, 2.0), marks).curve);
    EXPECT_LT(implicitDeviation(
                  c, c->FirstParameter(), c->LastParameter(),
                  [&](const Eigen::Vector3d& p) {
                    const auto q = local(p);
                    return q.y() * q.y() - 4 * 0.8 * q.x();
                  },
                  [&](const Eigen::Vector3d& p) {
                    const auto q = local(p);
                    return Eigen::Vector3d(-4 * 0.8, 2 * q.y(), 0);
                  }),
              1e-12 * size);
    c = toOcct(single(*hyperbolaArc(frame, a, b, -1.0, 1.2), marks).curve);
    EXPECT_LT(implicitDeviation(
                  c, c->FirstParameter(), c->LastParameter(),
                  [&](const Eigen::Vector3d& p) {
                    const auto q = local(p);
                    return q.x() * q.x() / (a * a) - q.y() * q.y() / (b * b) - 1;
                  },
                  [&](const Eigen::Vector3d& p) {
                    const auto q = local(p);
                    return Eigen::Vector3d(2 * q.x() / (a * a), -2 * q.y() / (b * b), 0);
                  }),
              1e-12 * size);
  }
}

TEST(Section6, EndExtensionReproducesTheWholeCurveAtItsOwnParameters) {
  // With eq. (10) at both ends the spline is the basic curve itself: same points at the
  // same parameters, end to end.
  std::mt19937 rng(3);
  const auto e = ellipseArc(kTilted, 2.0, 0.7, 1.0, 3.5);
  const Handle(Geom_BSplineCurve) c = toOcct(single(*e, randomMarks(rng, 5)).curve);
  EXPECT_EQ(c->FirstParameter(), 0.0);
  EXPECT_EQ(c->LastParameter(), 1.0);
  for (int j = 0; j <= 500; ++j) EXPECT_LT((at(c, j / 500.0) - e->value(j / 500.0)).norm(), 1e-13 * 4);
}

TEST(Section6, LargeSweepGetsJustEnoughMarksForPositiveWeights) {
  const CircleArc arc(kTilted, 1.0, 0.0, 5.5);  // middle weight cos(2.75) < 0
  const PiecePolygon few = piecePolygon(arc, Eigen::VectorXd::Constant(1, 0.5));
  EXPECT_GT(few.marksAdded, 0);
  for (const HomogeneousPoints* rows : {&few.start, &few.inner, &few.end}) {
    for (Eigen::Index r = 0; r < rows->rows(); ++r) EXPECT_GT((*rows)(r, 3), 0.0);
  }
  // Enough marks already: nothing added.
  Eigen::VectorXd dense = Eigen::VectorXd::LinSpaced(15, 1.0 / 16, 15.0 / 16);
  EXPECT_EQ(piecePolygon(arc, dense).marksAdded, 0);
  const Handle(Geom_BSplineCurve) c = toOcct(mergePieces({few}, 0.0).curve);
  for (int j = 0; j <= 1000; ++j) {
    EXPECT_NEAR((at(c, j / 1000.0) - kTilted.origin).norm(), 1.0, 1e-13);
  }
}

TEST(Section5, CubicsAreReproducedExactly) {
  // The 2-jet blossom c_i of eqs. (7), (8), (3) is exact for cubics (paper, Section 5).
  const ParametricCurve cubic(
      [](double s, Eigen::Vector3d& f, Eigen::Vector3d& df, Eigen::Vector3d& d2f) {
        f << s * s * s - s, 2 * s * s, 1 - s * s * s;
        df << 3 * s * s - 1, 4 * s, -3 * s * s;
        d2f << 6 * s, 4, -6 * s;
      },
      -1.0, 1.5);
  std::mt19937 rng(8);
  const Handle(Geom_BSplineCurve) c = toOcct(single(cubic, randomMarks(rng, 6)).curve);
  for (int j = 0; j <= 400; ++j) EXPECT_LT((at(c, j / 400.0) - cubic.value(j / 400.0)).norm(), 1e-13);
}

TEST(Section5, HomogeneousJetsOfARationalCubicGiveTheSection6Result) {
  std::mt19937 rng(5);
  const auto arc = ellipseArc(kTilted, 2.0, 1.0, 0.3, 2.0);
  const auto* rational = dynamic_cast<RationalBezierCurve*>(arc.get());
  const Eigen::VectorXd u = completeMarks(randomMarks(rng, 4));
  PointMatrix f(u.size(), 4), df(u.size(), 4), d2f(u.size(), 4);
  for (Eigen::Index i = 0; i < u.size(); ++i) {
    Eigen::Vector4d a, b, c;
    rational->jets(u[i], a, b, c);
    f.row(i) = a.transpose();
    df.row(i) = b.transpose();
    d2f.row(i) = c.transpose();
  }
  const PiecePolygon jets = polygonFromJets(f, df, d2f, u);
  const PiecePolygon exact = exactPolygon(*arc->homogeneousCubic(), u);
  EXPECT_LT((jets.inner - exact.inner).cwiseAbs().maxCoeff(), 1e-13);
  EXPECT_LT((jets.start - exact.start).cwiseAbs().maxCoeff(), 1e-13);
  EXPECT_LT((jets.end - exact.end).cwiseAbs().maxCoeff(), 1e-13);
}

TEST(Section5, SpiralQuinticBelow1e8AndCubicFourthOrder) {
  // A unit-size Archimedean spiral (r = theta / 2 pi, a quarter turn to one turn), 24
  // equal marks. Measured (README): the quintics of eq. (7) stay below 1e-8; the cubic
  // spline converges with order 4 (not "about twice the quintic's error": see README).
  const auto spiral = archimedeanSpiral(Frame{}, 0.0, 1.0 / (2 * M_PI), 0.5 * M_PI, 2 * M_PI);
  auto errors = [&](int m) {
    const Eigen::VectorXd marks = Eigen::VectorXd::LinSpaced(m - 1, 1.0 / m, (m - 1.0) / m);
    const PointMatrix q = quinticPieces(*spiral, marks);
    double quintic = 0.0, cubic = 0.0;
    for (int i = 0; i < m; ++i) {
      for (int j = 0; j <= 40; ++j) {
        const double x = j / 40.0, u = (i + x) / m;
        const double bin[6] = {1, 5, 10, 10, 5, 1};
        Eigen::RowVector3d p = Eigen::RowVector3d::Zero();
        for (int k = 0; k < 6; ++k) p += bin[k] * std::pow(1 - x, 5 - k) * std::pow(x, k) * q.row(6 * i + k);
        quintic = std::max(quintic, (p.transpose() - spiral->value(u)).norm());
      }
    }
    const Handle(Geom_BSplineCurve) c = toOcct(single(*spiral, marks).curve);
    for (int j = 0; j <= 4000; ++j) cubic = std::max(cubic, (at(c, j / 4000.0) - spiral->value(j / 4000.0)).norm());
    return std::make_pair(quintic, cubic);
  };
  const auto [q24, c24] = errors(24);
  const auto [q48, c48] = errors(48);
  EXPECT_LT(q24, 1e-8);
  EXPECT_GT(c24 / c48, 12.0);  // order 4: 16 when the marks double
  EXPECT_LT(c24 / c48, 20.0);
  EXPECT_GT(q24 / q48, 40.0);  // order 6: 64
}

TEST(Merge, ThreeJoinCasesAreC2WithExactInteriors) {
  // A circle arc followed by an ellipse arc whose start (a) coincides with, (b) is close
  // to, (c) is apart from the arc's end.
  const Frame frame{};
  const CircleArc arc(frame, 1.0, 0.0, 2.0);
  const Eigen::Vector3d end = arc.value(1.0);
  std::mt19937 rng(21);
  const Eigen::VectorXd marksA = randomMarks(rng, 6), marksB = randomMarks(rng, 7);
  for (double offset : {0.0, 1e-4, 0.3}) {
    // An ellipse arc starting at end + offset (x direction), heading on.
    const Frame fe{end + Eigen::Vector3d(offset, 0, 0) - Eigen::Vector3d(2.0 * std::cos(2.5), 0.8 * std::sin(2.5), 0),
                   Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY()};
    const auto ellipse = ellipseArc(fe, 2.0, 0.8, 2.5, 1.5);
    const Design d = mergePieces({piecePolygon(arc, marksA), piecePolygon(*ellipse, marksB)}, 1e-3);
    const JoinKind expected = offset == 0.0 ? JoinKind::Agree : (offset < 1e-3 ? JoinKind::Averaged : JoinKind::Edge);
    ASSERT_EQ(d.joins.size(), 1u);
    EXPECT_EQ(d.joins[0], expected);
    const Handle(Geom_BSplineCurve) c = toOcct(d.curve);
    EXPECT_GE(c->Continuity(), GeomAbs_C2);
    EXPECT_LT(c2Jump(c), 1e-10);
    // Exact interiors: the circle up to its u_{m-2}, the ellipse from its u_2 on.
    const Eigen::VectorXd uA = completeMarks(marksA), uB = completeMarks(marksB);
    const PieceRange ra = d.ranges[0], rb = d.ranges[1];
    for (int j = 0; j <= 300; ++j) {
      const double u = uA[uA.size() - 3] * j / 300.0;
      EXPECT_LT((at(c, ra.t0 + ra.scale * u) - arc.value(u)).norm(), 1e-13);
      const double v = uB[2] + (1.0 - uB[2]) * j / 300.0;
      EXPECT_LT((at(c, rb.t0 + rb.scale * v) - ellipse->value(v)).norm(), 1e-13);
    }
    // And the transition is not the basic curves: the join really blends.
    EXPECT_GT((at(c, ra.t0 + ra.scale * (1.0 - 1e-3)) - arc.value(1.0 - 1e-3)).norm(), 1e-9);
  }
}

TEST(Merge, Proposition1ConvexPolygonsGiveNoCurvatureSignChange) {
  // A quarter circle touching a line segment (Fig. 14), and an ellipse arc continuing a
  // circle arc, both with control polygons that join convexly.
  const Frame frame{};
  const CircleArc quarter(frame, 1.0, 0.0, 0.5 * M_PI);  // (1,0) .. (0,1), ccw
  const auto line = lineSegment({0, 1, 0}, {-2, 1, 0});  // tangent continuation
  const auto ellipse = ellipseArc(Frame{{-2, 0, 0}, Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY()}, 1.0, 1.0,
                                  0.5 * M_PI, 0.5 * M_PI);  // (-2,1) .. (-3,0), ccw
  const Eigen::VectorXd m5 = Eigen::VectorXd::LinSpaced(5, 1.0 / 6, 5.0 / 6);
  const Design d = mergePieces({piecePolygon(quarter, m5), piecePolygon(*line, m5), piecePolygon(*ellipse, m5)}, 1e-9);
  EXPECT_EQ(test::signChanges(toOcct(d.curve), 64), 0);
  const Handle(Geom_BSplineCurve) c = toOcct(d.curve);
  for (int j = 0; j <= 400; ++j) {
    const double t = c->FirstParameter() + (c->LastParameter() - c->FirstParameter()) * j / 400.0;
    EXPECT_GT(test::signedKappa(c, t), -1e-9);  // locally convex: curvature never negative
  }
}

TEST(Merge, BadInputThrows) {
  EXPECT_THROW(mergePieces({}, 0.0), InputError);
  EXPECT_THROW(completeMarks(Eigen::Vector2d(0.6, 0.4)), InputError);
  EXPECT_THROW(completeMarks(Eigen::Vector2d(0.2, 1.4)), InputError);
  EXPECT_THROW(completeMarks(Eigen::Vector2d(0.2, std::nan(""))), InputError);
  EXPECT_EQ(completeMarks(Eigen::Vector3d(0.0, 0.5, 1.0)).size(), 3);  // the ends are dropped, then added
}

TEST(Surfaces, Eq11RecoversTheBicubicNet) {
  // A tensor product of two random G2 (beta) splines: its patches' Bézier points by eq. (2)
  // in each variable, then eq. (11) gives back the control net.
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> unit(0.2, 2.0);
  const int KU = 7, KV = 6;  // control points c_0..c_K in each variable
  Eigen::VectorXd betaU(KU + 1), betaV(KV + 1);
  for (auto* beta : {&betaU, &betaV}) {
    for (Eigen::Index i = 0; i < beta->size(); ++i) (*beta)[i] = unit(rng);
  }
  std::vector<PointMatrix> net(KU + 1, PointMatrix(KV + 1, 3));
  for (auto& row : net) row.setRandom();
  // Rows: for every u-control row, the v-direction Bézier points of eq. (2).
  const int pv = KV - 2, pu = KU - 2;
  std::vector<PointMatrix> vBezier;  // (KU + 1) rows, each 4 pv x 3
  for (const auto& row : net) vBezier.push_back(g2FromDeBoor(row, betaV).bezier);
  PointMatrix patches(16 * pu * pv, 3);
  for (int col = 0; col < 4 * pv; ++col) {
    PointMatrix column(KU + 1, 3);
    for (int i = 0; i <= KU; ++i) column.row(i) = vBezier[i].row(col);
    const PointMatrix uBezier = g2FromDeBoor(column, betaU).bezier;  // 4 pu x 3
    for (int I = 0; I < pu; ++I) {
      for (int r = 0; r < 4; ++r) patches.row(((I * pv) + col / 4) * 16 + 4 * r + col % 4) = uBezier.row(4 * I + r);
    }
  }
  // eq. (11) on patches I, J >= 0 gives c_{I+2, J+2} (patch k of g2FromDeBoor starts at t_{k+1}).
  const PointMatrix c = tensorControlNet(patches, pu, pv, betaU.segment(1, pu + 1), betaV.segment(1, pv + 1));
  for (int i = 1; i <= pu; ++i) {
    for (int j = 1; j <= pv; ++j) {
      EXPECT_LT((c.row((i - 1) * pv + (j - 1)) - net[i + 1].row(j + 1)).norm(), 1e-12) << i << " " << j;
    }
  }
}

TEST(Surfaces, RevolvedDesignedProfileIsExact) {
  const Frame xz{{2, 0, 0}, Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitZ()};
  const CircleArc arc(xz, 1.0, -0.5 * M_PI, M_PI);  // a half circle of radius 1 around (2, 0, 0) in the xz plane
  const Design d = mergePieces({piecePolygon(arc, Eigen::Vector3d(0.2, 0.5, 0.7))}, 0.0);
  const Handle(Geom_BSplineSurface) s = toOcct(revolve(d.curve, {0, 0, 0}, {0, 0, 1}));  // a torus
  double u0, u1, v0, v1;
  s->Bounds(u0, u1, v0, v1);
  for (int i = 0; i <= 40; ++i) {
    for (int j = 0; j <= 40; ++j) {
      const gp_Pnt p = s->Value(u0 + (u1 - u0) * i / 40, v0 + (v1 - v0) * j / 40);
      const double ring = std::hypot(p.X(), p.Y()) - 2.0;
      EXPECT_NEAR(std::hypot(ring, p.Z()), 1.0, 1e-12 * 3);  // on the torus R = 2, r = 1
    }
  }
  EXPECT_THROW(revolve(d.curve, {0, 0, 0}, {0, 0, 0}), InputError);  // no axis
  // A space curve revolves exactly too: every pole keeps its distance to the axis.
  const auto spiral = archimedeanSpiral(kTilted, 0.5, 0.2, 0.0, 4.0);
  const BSplineSurface twisted =
      revolve(mergePieces({piecePolygon(*spiral, Eigen::Vector3d(0.3, 0.5, 0.7))}, 0.0).curve, {0, 0, 0}, {0, 0, 1});
  const Handle(Geom_BSplineCurve) profile =
      toOcct(mergePieces({piecePolygon(*spiral, Eigen::Vector3d(0.3, 0.5, 0.7))}, 0.0).curve);
  const Handle(Geom_BSplineSurface) ts = toOcct(twisted);
  ts->Bounds(u0, u1, v0, v1);
  for (int i = 0; i <= 20; ++i) {
    const double u = u0 + (u1 - u0) * i / 20;
    const gp_Pnt p = profile->Value(u);
    for (int j = 0; j <= 20; ++j) {
      const gp_Pnt q = ts->Value(u, v0 + (v1 - v0) * j / 20);
      EXPECT_NEAR(std::hypot(q.X(), q.Y()), std::hypot(p.X(), p.Y()), 1e-12 * 5);
      EXPECT_NEAR(q.Z(), p.Z(), 1e-12 * 5);
    }
  }
}
