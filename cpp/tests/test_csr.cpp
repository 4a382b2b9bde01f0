// csr-spline, Section 4, eq. (6), judged by OCCT evaluation of the produced curve.
#include <gtest/gtest.h>

#include <Geom_BSplineCurve.hxx>
#include <cmath>
#include <random>
#include <string>

#include "fairsplines/baselines.hpp"
#include "fairsplines/csr.hpp"
#include "fairsplines/errors.hpp"
#include "fairsplines/occt.hpp"
#include "fairsplines/parameters.hpp"
#include "csr_detail.hpp"
#include "test_support.hpp"

using namespace fairsplines;
using fairsplines::test::circleSamples;
using fairsplines::test::fig2Samples;
using fairsplines::test::signChanges;

namespace {

/// Largest jump of the second derivative across the interior knots, relative to its size.
double c2Jump(const Handle(Geom_BSplineCurve)& c) {
  double worst = 0.0, scale = 0.0;
  for (int k = 2; k < c->NbKnots(); ++k) {
    gp_Vec left = c->LocalDN(c->Knot(k), k - 1, k, 2);
    gp_Vec right = c->LocalDN(c->Knot(k), k, k + 1, 2);
    worst = std::max(worst, (left - right).Magnitude());
    scale = std::max(scale, std::max(left.Magnitude(), right.Magnitude()));
  }
  return worst / scale;
}

/// The message of the InputError csrSpline(q) throws, or "no error".
std::string message(const PointMatrix& q) {
  try {
    csrSpline(q);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST(Csr, StraightLine_IsReproduced) {
  PointMatrix q(9, 3);
  double s = 0.0;
  for (int i = 0; i < 9; ++i) {
    q.row(i) = Eigen::RowVector3d(1, 2, 3) + s * Eigen::RowVector3d(0.3, -0.5, 0.8);
    s += 0.2 + 0.7 * ((i * 7) % 5);  // uneven spacing
  }
  const Handle(Geom_BSplineCurve) c = toOcct(csrSpline(q));
  const gp_Dir dir(0.3, -0.5, 0.8);
  for (int j = 0; j <= 200; ++j) {
    const double u = c->FirstParameter() + (c->LastParameter() - c->FirstParameter()) * j / 200.0;
    const gp_Vec off(gp_Pnt(1, 2, 3), c->Value(u));
    EXPECT_LT(off.Crossed(gp_Vec(dir)).Magnitude(), 1e-12 * 20);  // on the line
    gp_Pnt p;
    gp_Vec d1, d2;
    c->D2(u, p, d1, d2);
    EXPECT_LT(d1.Crossed(d2).Magnitude() / std::pow(d1.Magnitude(), 3), 1e-9);
  }
}

TEST(Csr, DenseCircle_CurvatureWithin1e3OfInverseRadius) {
  const double r = 2.5;
  for (bool closed : {false, true}) {
    const PointMatrix q = closed ? circleSamples(120, r, 0, 2 * M_PI, false) : circleSamples(80, r, 0.3, 4.0);
    CsrOptions options;
    options.closed = closed;
    const Handle(Geom_BSplineCurve) c = toOcct(csrSpline(q, options));
    EXPECT_EQ(c->IsPeriodic(), closed);
    for (int j = 0; j <= 1000; ++j) {
      const double u = c->FirstParameter() + (c->LastParameter() - c->FirstParameter()) * j / 1000.0;
      gp_Pnt p;
      gp_Vec d1, d2;
      c->D2(u, p, d1, d2);
      const double kappa = d1.Crossed(d2).Magnitude() / std::pow(d1.Magnitude(), 3);
      EXPECT_NEAR(kappa, 1.0 / r, 1e-3) << (closed ? "closed" : "open") << " u " << u;
    }
  }
}

TEST(Csr, QuadraticData_IsReproducedExactly) {
  // Samples of a quadratic f at non-uniform parameters: every blossom in eq. (6) is f's.
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const int n = 15;
  Eigen::VectorXd t(n);
  t[0] = -1.0;
  for (int i = 1; i < n; ++i) t[i] = t[i - 1] + 0.05 + unit(rng);
  auto f = [](double x) { return Eigen::RowVector3d(1 + 2 * x - x * x, 0.5 * x * x, 3 - x); };
  PointMatrix q(n, 3);
  for (int i = 0; i < n; ++i) q.row(i) = f(t[i]);
  CsrOptions options;
  options.parameters = t;
  const Handle(Geom_BSplineCurve) c = toOcct(csrSpline(q, options));
  for (int j = 0; j <= 300; ++j) {
    const double u = t[0] + (t[n - 1] - t[0]) * j / 300.0;
    const gp_Pnt p = c->Value(u);
    EXPECT_LT((Eigen::RowVector3d(p.X(), p.Y(), p.Z()) - f(u)).norm(), 1e-12 * f(u).norm() + 1e-13);
  }
}

TEST(Csr, EndsInterpolatedAndC2Throughout) {
  const PointMatrix q = fig2Samples();
  const Handle(Geom_BSplineCurve) c = toOcct(csrSpline(q));
  const gp_Pnt a = c->Value(c->FirstParameter()), b = c->Value(c->LastParameter());
  EXPECT_EQ(a.X(), q(0, 0));
  EXPECT_EQ(a.Y(), q(0, 1));
  EXPECT_EQ(b.X(), q(q.rows() - 1, 0));
  EXPECT_EQ(b.Y(), q(q.rows() - 1, 1));
  EXPECT_GE(c->Continuity(), GeomAbs_C2);
  EXPECT_LT(c2Jump(c), 1e-12);
}

TEST(Csr, Fig2_ClassicOscillatesCsrDoesNot) {
  const PointMatrix q = fig2Samples();
  EXPECT_GE(signChanges(classicInterpolation(q, Parametrization::Chordal, false)), 2);
  EXPECT_EQ(signChanges(toOcct(csrSpline(q))), 0);
  EXPECT_GE(signChanges(toOcct(quasiInterpolant(q, Parametrization::Chordal, false))), 2);
}

TEST(Csr, ClosedCurveIsPeriodicC2) {
  PointMatrix q(40, 3);
  for (int i = 0; i < 40; ++i) {
    const double a = 2 * M_PI * i / 40;
    q.row(i) << 3 * std::cos(a), std::sin(a), 0.2 * std::sin(3 * a);
  }
  CsrOptions options;
  options.closed = true;
  const Handle(Geom_BSplineCurve) c = toOcct(csrSpline(q, options));
  EXPECT_TRUE(c->IsPeriodic());
  EXPECT_LT(c2Jump(c), 1e-12);
  EXPECT_LT(c->Value(c->FirstParameter()).Distance(c->Value(c->LastParameter())), 1e-12);
}

TEST(Csr, EpsilonRulesBothKeepALineStraight) {
  PointMatrix q(6, 2);
  q << 0, 0, 1, 1, 2, 2, 4, 4, 5, 5, 9, 9;
  for (EpsilonRule rule : {EpsilonRule::CaseDistinction, EpsilonRule::Additive}) {
    CsrOptions options;
    options.rule = rule;
    const BSplineCurve curve = csrSpline(q, options);
    for (int i = 0; i < curve.poles.rows(); ++i) EXPECT_NEAR(curve.poles(i, 0), curve.poles(i, 1), 1e-14);
  }
}

TEST(Csr, BadInputThrowsNamedInputError) {
  PointMatrix two(2, 2);
  two << 0, 0, 1, 1;
  EXPECT_NE(message(two).find("at least 3"), std::string::npos);
  PointMatrix dup(4, 2);
  dup << 0, 0, 1, 1, 1, 1, 2, 0;
  EXPECT_NE(message(dup).find("points 1 and 2 coincide"), std::string::npos);
  PointMatrix same = PointMatrix::Constant(4, 3, 1.5);
  EXPECT_NE(message(same).find("all points coincide"), std::string::npos);
  PointMatrix nan(4, 2);
  nan << 0, 0, 1, std::nan(""), 2, 0, 3, 1;
  EXPECT_NE(message(nan).find("point 1 is not finite"), std::string::npos);
  PointMatrix wide(4, 4);
  wide.setRandom();
  EXPECT_NE(message(wide).find("2 or 3 coordinates"), std::string::npos);
}

TEST(Csr, NeighboursTooCloseAlongLongDataAreRefusedUpFrontNamingTheSamples) {
  // Issue 26: data that go round and round (2000 samples a radian apart on a unit circle,
  // 1900 long in a box 2.8 wide) with one sample 1e-10 from the one before: far from
  // coinciding in the box (1e-12 of 2.8), but their knots would be closer than 1e-12 of the
  // parameter range. Refused before the fit (chordal parameters), naming the samples and the
  // fair fit, on every route: the windowed pass (open, 128 points or more), the reference
  // (closed), given parameters, and the fit straight into OCCT.
  const int n = 2000, k = 1000;
  PointMatrix q(n, 2);
  for (int i = 0; i < n; ++i) q.row(i) << std::cos(i), std::sin(i);
  q.row(k + 1) = q.row(k) + Eigen::RowVector2d(1e-10, 0.0);
  const std::string samples = "samples " + std::to_string(k) + " and " + std::to_string(k + 1);
  for (bool closed : {false, true}) {
    CsrOptions options;
    options.closed = closed;
    std::string what = "no error";
    try {
      csrSpline(q, options);
    } catch (const InputError& e) {
      what = e.what();
    }
    EXPECT_NE(what.find(samples), std::string::npos) << closed << ": " << what;
    EXPECT_NE(what.find("fw.fair_fit"), std::string::npos) << what;
    EXPECT_THROW(csrSplineOcct(q, options), InputError);
  }
  // Parameters given that close: named as parameters.
  CsrOptions given;
  given.parameters = Eigen::VectorXd::LinSpaced(n, 0.0, 1.0);
  given.parameters[k + 1] = given.parameters[k] + 1e-15;
  std::string what = "no error";
  try {
    csrSpline(q, given);
  } catch (const InputError& e) {
    what = e.what();
  }
  EXPECT_NE(what.find("parameters " + std::to_string(k) + " and " + std::to_string(k + 1)), std::string::npos) << what;
  // The centripetal and uniform parametrizations put them 1e-5 and 1 apart: those curves are fitted.
  for (Parametrization kind : {Parametrization::Centripetal, Parametrization::Uniform}) {
    CsrOptions other;
    other.parametrization = kind;
    EXPECT_EQ(csrSplineOcct(q, other)->NbPoles(), n + 2);
  }
}

TEST(Csr, FusedOcctRouteIsBitExact) {
  // csrSplineOcct builds the same Geom_BSplineCurve as toOcct(csrSpline(...)), bit for bit,
  // also when its reused memory shrinks and grows between calls.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (bool closed : {false, true}) {
    for (int n : {3, 4, 9, 200, 5000, 7}) {
      PointMatrix q(n, 3);
      for (int i = 0; i < n; ++i) {
        const double a = 2 * M_PI * i / n;
        q.row(i) << std::cos(a) + 0.2 * unit(rng), std::sin(a) + 0.2 * unit(rng), 0.3 * unit(rng);
      }
      for (EpsilonRule rule : {EpsilonRule::CaseDistinction, EpsilonRule::Additive}) {
        CsrOptions options;
        options.closed = closed;
        options.rule = rule;
        options.parametrization = n == 9 ? Parametrization::Centripetal : Parametrization::Chordal;
        const Handle(Geom_BSplineCurve) a = toOcct(csrSpline(q, options)), b = csrSplineOcct(q, options);
        ASSERT_EQ(a->NbPoles(), b->NbPoles());
        ASSERT_EQ(a->NbKnots(), b->NbKnots());
        EXPECT_EQ(a->IsPeriodic(), b->IsPeriodic());
        for (int i = 1; i <= a->NbPoles(); ++i) {
          EXPECT_EQ(a->Pole(i).X(), b->Pole(i).X());
          EXPECT_EQ(a->Pole(i).Y(), b->Pole(i).Y());
          EXPECT_EQ(a->Pole(i).Z(), b->Pole(i).Z());
        }
        for (int i = 1; i <= a->NbKnots(); ++i) {
          EXPECT_EQ(a->Knot(i), b->Knot(i));
          EXPECT_EQ(a->Multiplicity(i), b->Multiplicity(i));
        }
      }
    }
  }
  PointMatrix dup(4, 3);
  dup << 0, 0, 0, 1, 1, 0, 1, 1, 0, 2, 0, 0;
  EXPECT_THROW(csrSplineOcct(dup), InputError);
}

TEST(Csr, StreamingPassMatchesTheReference) {
  // Open data from kVectorisedFrom points on takes one streaming pass (bounding box, then
  // window by window: differences, chords, parameters, poles). It must give the knots of
  // validateSamples + parameters to the bit and the poles of the reference strategy,
  // also where the last window is shifted back and for every parametrization.
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int dim : {2, 3}) {
    for (int n : {128, 131, 2049, 2050, 5003}) {
      PointMatrix q(n, dim);
      for (int i = 0; i < n; ++i) {
        const double a = 6 * M_PI * i / n;
        q(i, 0) = (1 + a) * std::cos(a) + 0.05 * unit(rng);
        q(i, 1) = (1 + a) * std::sin(a) + 0.05 * unit(rng);
        if (dim == 3) q(i, 2) = 0.1 * a + 0.05 * unit(rng);
      }
      for (Parametrization kind : {Parametrization::Chordal, Parametrization::Centripetal, Parametrization::Uniform}) {
        CsrOptions options;
        options.parametrization = kind;
        const BSplineCurve fused = csrSpline(q, options);
        const SampleInfo info = validateSamples(q, false, 3, "test");
        const Eigen::VectorXd t = parameters(info.chords, kind);
        const BSplineCurve reference = detail::fitCubic(q, t, false, info.size, options.epsilon, options.rule, false,
                                                        detail::CsrStrategy::Streaming);
        ASSERT_EQ(fused.knots.size(), t.size());
        EXPECT_EQ((fused.knots - t).cwiseAbs().maxCoeff(), 0.0) << dim << " " << n;
        ASSERT_EQ(fused.poles.rows(), reference.poles.rows());
        EXPECT_LT((fused.poles - reference.poles).cwiseAbs().maxCoeff(), 1e-13 * (1 + 6 * M_PI)) << dim << " " << n;
      }
    }
  }
}

TEST(Csr, StreamingPassChecksEveryPoint) {
  // The streaming pass reads the points four at a time and the rest one by one: a bad
  // value anywhere is named, and the bounding box (which scales epsilon and the
  // coincidence tolerance) is that of every point.
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int n : {203, 204, 205, 206}) {
    for (int dim : {2, 3}) {
      PointMatrix q(n, dim);
      for (int i = 0; i < n; ++i) {
        for (int c = 0; c < dim; ++c) q(i, c) = i + unit(rng);
      }
      for (int bad : {0, 1, 101, n - 3, n - 2, n - 1}) {
        for (int c = 0; c < dim; ++c) {
          for (double value : {std::nan(""), HUGE_VAL, -HUGE_VAL}) {
            PointMatrix p = q;
            p(bad, c) = value;
            EXPECT_NE(message(p).find("point " + std::to_string(bad) + " is not finite"), std::string::npos)
                << n << " " << dim << " " << bad << " " << c;
          }
        }
        // An extreme value at this point and coordinate sets the box: the size agrees
        // with validateSamples, which reads the points in another order.
        for (int c = 0; c < dim; ++c) {
          for (double value : {-1e3, 1e3}) {
            PointMatrix p = q;
            p(bad, c) = value;
            EXPECT_EQ(detail::openSampleSize(p, 3, "test"), validateSamples(p, false, 3, "test").size);
          }
        }
      }
      EXPECT_EQ(detail::openSampleSize(q, 3, "test"), validateSamples(q, false, 3, "test").size);
      PointMatrix same = PointMatrix::Constant(n, dim, -2.5);
      EXPECT_NE(message(same).find("all points coincide"), std::string::npos);
      PointMatrix dup = q;
      dup.row(n - 2) = dup.row(n - 3);
      EXPECT_NE(message(dup).find("points " + std::to_string(n - 3) + " and " + std::to_string(n - 2) + " coincide"),
                std::string::npos);
    }
  }
}

TEST(Csr, DataFoldingBackIsTheLimitOfDataNearlyFoldingBack) {
  // q_{k+1} = q_{k-1}: the quadratic interpolant turns back at q_k, its curvature there is
  // 0/0. The fit must be finite and the limit of data that nearly fold back, with both
  // epsilon rules and both strategies (short data streams, long data is vectorised).
  for (int n : {9, 300}) {
    for (EpsilonRule rule : {EpsilonRule::CaseDistinction, EpsilonRule::Additive}) {
      PointMatrix q(n, 2);
      for (int i = 0; i < n; ++i) q.row(i) << i, 0.3 * std::sin(0.5 * i);
      const int k = n / 2;
      q.row(k + 1) = q.row(k - 1);  // a hairpin at q_k
      CsrOptions options;
      options.rule = rule;
      const BSplineCurve exact = csrSpline(q, options);
      ASSERT_TRUE(exact.poles.allFinite()) << n << " " << static_cast<int>(rule);
      for (double delta : {1e-7, -1e-7}) {
        PointMatrix near = q;
        near(k + 1, 1) += delta;
        const BSplineCurve nearly = csrSpline(near, options);
        EXPECT_LT((exact.poles - nearly.poles).cwiseAbs().maxCoeff(), 1e-5) << n << " " << delta;
      }
    }
  }
}

TEST(Csr, StreamingAndVectorisedStrategiesAgree) {
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int dim : {2, 3}) {
    for (bool closed : {false, true}) {
      for (int n : {3, 4, 5, 9, 50, 203}) {
        PointMatrix q(n, dim);
        for (int i = 0; i < n; ++i) {
          const double a = 2 * M_PI * i / n;
          q(i, 0) = std::cos(a) + 0.2 * unit(rng);
          q(i, 1) = std::sin(a) + 0.2 * unit(rng);
          if (dim == 3) q(i, 2) = 0.3 * unit(rng);
        }
        const SampleInfo info = validateSamples(q, closed, 3, "test");
        const Eigen::VectorXd t = parameters(info.chords, Parametrization::Chordal);
        for (EpsilonRule rule : {EpsilonRule::CaseDistinction, EpsilonRule::Additive}) {
          for (bool quasi : {false, true}) {
            const BSplineCurve a =
                detail::fitCubic(q, t, closed, info.size, 1e-9, rule, quasi, detail::CsrStrategy::Streaming);
            for (Eigen::Index window : {8, 13, 4096}) {  // windowed and whole
              const BSplineCurve b =
                  detail::fitCubic(q, t, closed, info.size, 1e-9, rule, quasi, detail::CsrStrategy::Vectorised, window);
              ASSERT_EQ(a.poles.rows(), b.poles.rows());
              EXPECT_LT((a.poles - b.poles).cwiseAbs().maxCoeff(), 1e-14) << dim << closed << n << quasi << window;
            }
          }
        }
      }
    }
  }
  EXPECT_EQ(detail::defaultStrategy(100), detail::CsrStrategy::Streaming);
  EXPECT_EQ(detail::defaultStrategy(10000), detail::CsrStrategy::Vectorised);
}
