// Issue 13, "handled by meaning, not by accident": the analyses are scale-invariant. A
// curve 1e300 or 1e-300 in size has the curvature of its unit-size copy divided by the
// scale, the same certificate and the same curvature variation; before, the squares and
// cubes of its lengths overflowed or underflowed into NaN (the Python fuzz's findings
// "huge" and "tiny", tests/fuzz/strategies.py). A curve that does not move is refused by
// that name. The unit-size results are checked against OpenCASCADE in test_analysis.cpp
// and test_monotone.cpp; here each scaled result is compared with them.
#include <gtest/gtest.h>

#include <GeomLProp_CLProps.hxx>
#include <cmath>
#include <functional>
#include <optional>
#include <string>

#include "fairsplines/analysis.hpp"
#include "fairsplines/baselines.hpp"
#include "fairsplines/basic_curves.hpp"
#include "fairsplines/csr.hpp"
#include "fairsplines/errors.hpp"
#include "fairsplines/fair_blend.hpp"
#include "fairsplines/monotone.hpp"
#include "fairsplines/occt.hpp"

#include "test_support.hpp"

using namespace fairsplines;
using Eigen::Vector2d;
using Eigen::Vector3d;

namespace {

/// A planar cubic with one curvature extremum and an inflection-free S-less turn, in a tilted
/// plane (3 columns), moved by `offset` and scaled by `s` about it.
BSplineCurve tilted(double s, const Vector3d& offset = Vector3d::Zero()) {
  const Vector3d e1 = Vector3d(1, 2, 2) / 3.0, e2 = Vector3d(2, 1, -2) / 3.0;  // orthonormal
  const double uv[6][2] = {{0, 0}, {1, 0.2}, {2, 0.9}, {2.6, 2}, {2.7, 3.1}, {2.4, 4}};
  BSplineCurve c;
  c.degree = 3;
  c.poles.resize(6, 3);
  for (int i = 0; i < 6; ++i) c.poles.row(i) = (offset + s * (uv[i][0] * e1 + uv[i][1] * e2)).transpose();
  c.knots = (Eigen::VectorXd(4) << 0, 1, 2, 3).finished();
  c.mults = (Eigen::VectorXi(4) << 4, 1, 1, 4).finished();
  return c;
}

Vector3d toEigen(const gp_Vec& v) { return Vector3d(v.X(), v.Y(), v.Z()); }

double relative(double a, double b) { return std::abs(a - b) / std::max(std::abs(a), std::abs(b)); }

using test::refusal;

}  // namespace

TEST(ScaleInvariance, TheUnitCurveMatchesOcctsCurvature) {  // the reference the scaled ones are held to
  const Handle(Geom_BSplineCurve) unit = toOcct(tilted(1.0));
  const CurvatureProfile p = curvatureProfile(unit, 64);
  for (Eigen::Index j = 0; j < p.u.size(); ++j) {
    GeomLProp_CLProps props(unit, p.u[j], 2, 1e-12);
    EXPECT_NEAR(std::abs(p.kappa[j]), props.Curvature(), 1e-12 * props.Curvature());
  }
}

TEST(ScaleInvariance, CurvatureProfileOfHugeAndTinyCurvesIsTheUnitOnesScaled) {
  const CurvatureProfile unit = curvatureProfile(toOcct(tilted(1.0)), 64);
  for (double s : {1e300, 1e-300, 1e-3, 7.0}) {
    const CurvatureProfile p = curvatureProfile(toOcct(tilted(s, Vector3d(0.5 * s, -s, 2 * s))), 64);
    ASSERT_EQ(p.kappa.size(), unit.kappa.size()) << s;
    EXPECT_TRUE(p.isSigned) << "a curve of size " << s << " lies in its plane";
    EXPECT_NEAR((toEigen(p.normal) - toEigen(unit.normal)).norm(), 0.0, 1e-12) << s;
    for (Eigen::Index j = 0; j < p.kappa.size(); ++j) {
      ASSERT_TRUE(std::isfinite(p.kappa[j]) && std::isfinite(p.s[j])) << s;
      EXPECT_LT(relative(p.kappa[j] * s, unit.kappa[j]), 1e-12) << "size " << s << ", sample " << j;
      if (j > 0) EXPECT_LT(relative(p.s[j] / s, unit.s[j]), 1e-12) << "size " << s << ", sample " << j;
    }
  }
  // A curve of size 3e-310 has curvatures of about 1e310: beyond double precision, refused.
  EXPECT_NE(refusal([] { curvatureProfile(toOcct(tilted(3e-310)), 64); }).find("curvatures are not finite"),
            std::string::npos);
}

TEST(ScaleInvariance, CertificateAndVariationOfHugeAndTinyCurvesAreTheUnitOnes) {
  const MonotonicityCertificate unit = certifyMonotoneCurvature(tilted(1.0));
  const double variation = curvatureVariation(tilted(1.0));
  for (double s : {1e300, 1e-300, 1e-3, 7.0}) {
    const BSplineCurve c = tilted(s, Vector3d(s, s, -s));
    const MonotonicityCertificate cert = certifyMonotoneCurvature(c);
    EXPECT_EQ(cert.monotone, unit.monotone) << s;
    EXPECT_EQ(cert.increasing, unit.increasing) << s;
    EXPECT_NEAR((cert.normal - unit.normal).norm(), 0.0, 1e-12) << s;
    ASSERT_EQ(cert.spans.size(), unit.spans.size()) << s;
    for (size_t k = 0; k < cert.spans.size(); ++k) {
      EXPECT_EQ(cert.spans[k].trend, unit.spans[k].trend) << s;
      EXPECT_LT(relative(cert.spans[k].kappa0 * s, unit.spans[k].kappa0), 1e-12) << s;
      EXPECT_LT(relative(cert.spans[k].kappa1 * s, unit.spans[k].kappa1), 1e-12) << s;
    }
    EXPECT_LT(relative(curvatureVariation(c), variation), 1e-12) << s;
  }
}

TEST(ScaleInvariance, ACurveThatDoesNotMoveIsRefusedByThatName) {
  BSplineCurve point = tilted(1.0);
  point.poles.rowwise() = Eigen::RowVector3d(1, 1, 0);
  const std::string words = "the curve does not move";
  EXPECT_NE(refusal([&] { curvatureProfile(toOcct(point), 16); }).find(words), std::string::npos);
  EXPECT_NE(refusal([&] { certifyMonotoneCurvature(point); }).find(words), std::string::npos);
  EXPECT_NE(refusal([&] { curvatureVariation(point); }).find(words), std::string::npos);
  // Moving by less than the rounding of its coordinates is not moving either.
  point.poles(2, 0) += 1e-15;
  EXPECT_NE(refusal([&] { curvatureVariation(point); }).find(words), std::string::npos);
}

TEST(ScaleInvariance, AStationaryPointNamesWhereTheCurvatureIsUndefined) {
  BSplineCurve cusp = tilted(1.0);
  cusp.poles.row(1) = cusp.poles.row(0);  // the derivative vanishes at u = 0
  EXPECT_NE(refusal([&] { curvatureProfile(toOcct(cusp), 16); }).find("the curvature is undefined at u = 0"),
            std::string::npos);
}

TEST(ScaleInvariance, Algorithm1OfScaledDataIsTheScaledDesign) {
  // The Python fuzz's finding: differences 1e307 apart gave NaN differences.
  const PointMatrix dV = (PointMatrix(4, 2) << 1, 1, 1, -1, 1, 1, 1, -1).finished();
  const MonotoneDesign unit = designMonotone(Vector2d(1, 0), dV);
  for (double s : {0x1p1018, 1e307 / 1.5, 1e-300, 0.1}) {
    const MonotoneDesign d = designMonotone(Vector2d(s, 0), s * dV);
    ASSERT_TRUE(d.differences.allFinite() && d.moved.allFinite() && d.curve.poles.allFinite()) << s;
    for (Eigen::Index i = 0; i < dV.rows(); ++i) {
      EXPECT_NEAR((d.differences.row(i) / s - unit.differences.row(i)).norm(), 0.0, 1e-12) << s;
      EXPECT_NEAR(d.moved[i] / s, unit.moved[i], 1e-12) << s;
    }
  }
  EXPECT_GT(unit.moved.maxCoeff(), 0.1) << "the data must be clamped for the test to mean anything";
}

TEST(ScaleInvariance, AFairBlendOfEndsVeryCloseTogetherIsFinite) {
  // The Python fuzz's finding: ends 2.4e-63 apart gave an infinite curvature variation.
  BlendEnds e;
  e.p0 = Vector3d(2.4308653429145085e-63, 0, 0);
  e.t0 = Vector3d(0, 1, 0);
  e.p1 = Vector3d(0, 0, 0);
  e.t1 = Vector3d(1, 0, 0);
  const FairBlend b = fairBlend(e);
  EXPECT_TRUE(b.curve.poles.allFinite());
  EXPECT_TRUE(std::isfinite(b.variation));
  EXPECT_TRUE(b.monotone);
  BlendEnds unit = e;
  unit.p0 = Vector3d(1, 0, 0);
  EXPECT_LT(relative(fairBlend(unit).variation, b.variation), 1e-9) << "the variation is scale-invariant";
}

TEST(ScaleInvariance, LongBasicCurvesHaveAFiniteSize) {
  // Their extent was |hi - lo| by squares: 1e300 long overflowed into "the extent overflows".
  const auto segment = lineSegment(Vector3d(1e300, 0, 0), Vector3d(1e300, 1e300, 0));
  EXPECT_LT(relative(segment->size(), 1e300), 1e-12);
  const auto parabola = parabolaArc(Frame{}, 0.0098, -6.0, 3.3e150);  // fuzz: parabola_t1_3e150_size_inf
  const double x1 = 3.3e150 * 3.3e150 / (4 * 0.0098);
  EXPECT_LT(relative(parabola->size(), std::hypot(x1, 3.3e150)), 1e-9);
  // Near the largest doubles its cubic form (degree elevation) stays finite: fuzz finding
  // line_segment_1.7e308_raise_inf, an overflow of (i b_{i-1} + (n + 1 - i) b_i).
  const auto far = lineSegment(Vector3d(1.7e308, 0, 0), Vector3d(0, 0, -0.00439453125));
  const std::optional<HomogeneousBezier> cubic = far->homogeneousCubic();
  ASSERT_TRUE(cubic.has_value());
  EXPECT_TRUE(cubic->allFinite());
  EXPECT_LT(relative((*cubic)(1, 0), 1.7e308 / 3 * 2), 1e-15);
  // Beyond doubles it is refused, and by the curve's own name.
  const std::string message = refusal([] { parabolaArc(Frame{}, 0.0098, -6.0, 1e160); });
  EXPECT_NE(message.find("the parabola arc"), std::string::npos) << message;
  EXPECT_NE(message.find("too large for double precision"), std::string::npos) << message;
}

// Points whose squared distances leave double precision (1e160, 1e300, 1e-300) were refused
// as "points coincide" by the csr-spline and the quadratic design: now they are fitted
// divided by a power of two and the poles multiplied back, so the curve is the unit one
// scaled (open and closed, the streaming and the vectorised paths, csrSplineOcct too).
// Fits that do not rescale name the size instead of a coincidence.
TEST(ScaleInvariance, CsrAndQuadraticDesignOfHugeAndTinyPointsAreTheUnitOnesScaled) {
  for (Eigen::Index n : {40, 300}) {  // below and above kVectorisedFrom
    for (bool closed : {false, true}) {
      PointMatrix q(n, 3);
      for (Eigen::Index i = 0; i < n; ++i) {
        const double t = (closed ? 2 * M_PI : 3.0) * static_cast<double>(i) / static_cast<double>(n);
        q.row(i) << 2 * std::cos(t), std::sin(t), 0.1 * std::sin(3 * t);
      }
      CsrOptions o;
      o.closed = closed;
      const BSplineCurve unit = csrSpline(q, o);
      const BSplineCurve unitDesign = quadraticDesign(q, Parametrization::Chordal, closed);
      for (double s : {1e160, 1e300, 1e-300, -1e200}) {
        SCOPED_TRACE("n " + std::to_string(n) + (closed ? " closed" : " open") + ", scale " + std::to_string(s));
        const BSplineCurve c = csrSpline(q * s, o);
        ASSERT_EQ(c.poles.rows(), unit.poles.rows());
        EXPECT_LE((c.poles / s - unit.poles).cwiseAbs().maxCoeff(), 1e-12 * unit.poles.cwiseAbs().maxCoeff());
        const Handle(Geom_BSplineCurve) occ = csrSplineOcct(q * s, o);
        ASSERT_EQ(occ->NbPoles(), c.poles.rows());
        for (int i = 1; i <= occ->NbPoles(); ++i) EXPECT_EQ(occ->Pole(i).X(), c.poles(i - 1, 0));
        const BSplineCurve d = quadraticDesign(q * s, Parametrization::Chordal, closed);
        ASSERT_EQ(d.poles.rows(), unitDesign.poles.rows());
        EXPECT_LE((d.poles / s - unitDesign.poles).cwiseAbs().maxCoeff(),
                  1e-12 * unitDesign.poles.cwiseAbs().maxCoeff());
      }
    }
  }
  PointMatrix line(5, 2);
  line << 0, 0, 1, 0.5, 2, 0.25, 3, 1, 4, 0;
  try {
    classicInterpolation(line * 1e300, Parametrization::Chordal, false);
    ADD_FAILURE() << "classic interpolation took points it cannot measure";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("double precision"), std::string::npos) << e.what();
  }
}
