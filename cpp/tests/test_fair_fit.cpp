// Fair fit (fair_fit.hpp), judged by OCCT's evaluation of the returned curve: distances by
// GeomAPI_ProjectPointOnCurve, curvature and tangents by Geom_BSplineCurve::D2.
#include <gtest/gtest.h>

#include <GeomAPI_PointsToBSpline.hxx>
#include <GeomAPI_ProjectPointOnCurve.hxx>
#include <Geom_BSplineCurve.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "fairsplines/csr.hpp"
#include "fairsplines/errors.hpp"
#include "fairsplines/fair_fit.hpp"
#include "fairsplines/occt.hpp"
#include "fair_fit_detail.hpp"

using namespace fairsplines;

namespace {

double sizeOf(const PointMatrix& q) { return (q.colwise().maxCoeff() - q.colwise().minCoeff()).norm(); }

void addNoise(PointMatrix& q, double relative, unsigned seed) {
  std::mt19937 rng(seed);
  const double a = relative * sizeOf(q);
  std::uniform_real_distribution<double> u(-a, a);
  for (Eigen::Index i = 0; i < q.rows(); ++i)
    for (Eigen::Index c = 0; c < q.cols(); ++c) q(i, c) += u(rng);
}

/// Half circle of radius 1 (counter-clockwise, lower half) joined C1 at (1, 0) to the flat
/// parabola x = 1 - 0.1 y^2, y in [0, 1.5]: convex.
PointMatrix arcParabola(Eigen::Index n) {
  PointMatrix q(n, 2);
  const Eigen::Index m1 = n / 2;
  for (Eigen::Index i = 0; i < m1; ++i) {
    const double th = M_PI + M_PI * static_cast<double>(i) / static_cast<double>(m1);
    q.row(i) << std::cos(th), std::sin(th);
  }
  for (Eigen::Index i = m1; i < n; ++i) {
    const double y = 1.5 * static_cast<double>(i - m1) / static_cast<double>(n - m1 - 1);
    q.row(i) << 1.0 - 0.1 * y * y, y;
  }
  return q;
}

/// Line, arc left 90 deg, line, arc right 90 deg, line (radius 20, lines 30), sampled
/// uniformly in arc length: one curvature sign change.
PointMatrix road(Eigen::Index n) {
  const double R = 20.0, L = 30.0, arc = R * M_PI / 2, total = 3 * L + 2 * arc;
  PointMatrix q(n, 2);
  for (Eigen::Index i = 0; i < n; ++i) {
    double s = total * static_cast<double>(i) / static_cast<double>(n - 1);
    double x, y;
    if (s <= L) {
      x = s, y = 0;
    } else if ((s -= L) <= arc) {
      const double a = s / R;
      x = L + R * std::sin(a), y = R - R * std::cos(a);
    } else if ((s -= arc) <= L) {
      x = L + R, y = R + s;
    } else if ((s -= L) <= arc) {
      const double a = s / R;  // turning right from heading +y
      x = L + 2 * R - R * std::cos(a), y = R + L + R * std::sin(a);
    } else {
      s -= arc;
      x = L + 2 * R + s, y = 2 * R + L;
    }
    q.row(i) << x, y;
  }
  return q;
}

/// The ellipse 3 x 1, n samples at equal parameter steps, the first not repeated (closed data).
PointMatrix closedEllipse(Eigen::Index n) {
  PointMatrix q(n, 2);
  for (Eigen::Index i = 0; i < n; ++i) {
    const double t = 2 * M_PI * static_cast<double>(i) / static_cast<double>(n);
    q.row(i) << 3 * std::cos(t), std::sin(t);
  }
  return q;
}

/// OCCT's signed curvature (about +z) at `perSpan` parameters per knot span.
std::vector<double> signedCurvature(const Handle(Geom_BSplineCurve)& c, int perSpan = 20) {
  std::vector<double> k;
  for (int j = 1; j < c->NbKnots(); ++j) {
    const double a = c->Knot(j), b = c->Knot(j + 1);
    for (int s = 0; s < perSpan; ++s) {
      gp_Pnt p;
      gp_Vec d1, d2;
      c->D2(a + (b - a) * s / perSpan, p, d1, d2);
      k.push_back(d1.Crossed(d2).Z() / std::pow(d1.Magnitude(), 3));
    }
  }
  return k;
}

int signChanges(const std::vector<double>& k) {
  double mx = 0;
  for (double v : k) mx = std::max(mx, std::abs(v));
  int last = 0, changes = 0;
  for (double v : k) {
    if (std::abs(v) <= 1e-6 * mx) continue;
    const int s = v > 0 ? 1 : -1;
    if (last != 0 && s != last) ++changes;
    last = s;
  }
  return changes;
}

/// The largest OCCT distance (GeomAPI_ProjectPointOnCurve) from every `stride`-th sample.
double maxDistance(const Handle(Geom_BSplineCurve)& c, const PointMatrix& q, Eigen::Index stride = 1) {
  double worst = 0;
  for (Eigen::Index i = 0; i < q.rows(); i += stride) {
    const gp_Pnt p(q(i, 0), q(i, 1), q.cols() > 2 ? q(i, 2) : 0.0);
    GeomAPI_ProjectPointOnCurve proj(p, c);
    double d = proj.NbPoints() > 0 ? proj.LowerDistance() : HUGE_VAL;
    d = std::min({d, p.Distance(c->StartPoint()), p.Distance(c->EndPoint())});
    worst = std::max(worst, d);
  }
  return worst;
}

/// Interior extrema of OCCT's curvature sampled by signedCurvature: turns of its slope, where
/// steps below 1e-9 of the largest curvature count as flat (a flat run keeps the slope it
/// interrupts).
int extrema(const std::vector<double>& k) {
  double mx = 0;
  for (double v : k) mx = std::max(mx, std::abs(v));
  int last = 0, turns = 0;
  for (std::size_t i = 1; i < k.size(); ++i) {
    const double d = k[i] - k[i - 1];
    if (std::abs(d) <= 1e-9 * mx) continue;
    const int s = d > 0 ? 1 : -1;
    if (last != 0 && s != last) ++turns;
    last = s;
  }
  return turns;
}

/// The largest jump of OCCT's second derivative across the interior knots, relative to its size there.
double c2Jump(const Handle(Geom_BSplineCurve)& c) {
  double worst = 0;
  for (int j = 2; j < c->NbKnots(); ++j) {
    const double u = c->Knot(j), h = 1e-9 * (c->Knot(j + 1) - c->Knot(j - 1));
    gp_Pnt p;
    gp_Vec d1, left, right;
    c->D2(u - h, p, d1, left);
    c->D2(u + h, p, d1, right);
    worst = std::max(worst, (left - right).Magnitude() / std::max(right.Magnitude(), 1.0));
  }
  return worst;
}

std::string refusal(const PointMatrix& q, const FairFitOptions& o) {
  try {
    fairFit(q, o);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(FairFit, ConvexNoisyDataHasNoSignChangeAndStaysWithinTolerance) {
  PointMatrix q = arcParabola(10000);
  addNoise(q, 1e-4, 1);
  FairFitOptions o;
  o.tolerance = 1e-3 * sizeOf(q);
  const FairFitResult r = fairFitReport(q, o);
  const Handle(Geom_BSplineCurve) c = toOcct(r.curve);
  EXPECT_EQ(c->Degree(), 3);
  EXPECT_EQ(signChanges(signedCurvature(c)), 0);
  const double d = maxDistance(c, q);
  EXPECT_LE(d, o.tolerance);
  // the reported deviation is an upper bound of the true one, and within the tolerance
  EXPECT_GE(r.maxDeviation, d * (1 - 1e-9));
  EXPECT_LE(r.maxDeviation, o.tolerance);
  EXPECT_LT(c->NbPoles(), 200);
  EXPECT_EQ(r.dataSignChanges, 0);
  EXPECT_EQ(r.signChanges, 0);
}

TEST(FairFit, RoadAlignmentKeepsItsOneSignChange) {
  PointMatrix q = road(20000);
  addNoise(q, 1e-4, 2);
  FairFitOptions o;
  o.tolerance = 1e-3 * sizeOf(q);
  const FairFitResult r = fairFitReport(q, o);
  const Handle(Geom_BSplineCurve) c = toOcct(r.curve);
  EXPECT_EQ(r.dataSignChanges, 1);
  EXPECT_EQ(signChanges(signedCurvature(c)), 1);
  EXPECT_LE(maxDistance(c, q, 3), o.tolerance);
  EXPECT_LT(c->NbPoles(), 0.02 * q.rows());
}

TEST(FairFit, NoiseFreeDataUseNoMorePolesThanTheCsrSplineAndInterpolateTheEnds) {
  PointMatrix q(300, 2);
  for (Eigen::Index i = 0; i < q.rows(); ++i) {
    const double t = M_PI * static_cast<double>(i) / 299.0;
    q.row(i) << 2 * std::cos(t), std::sin(t);
  }
  FairFitOptions o;
  o.tolerance = 1e-5;
  const Handle(Geom_BSplineCurve) c = toOcct(fairFit(q, o));
  EXPECT_LE(maxDistance(c, q), o.tolerance);
  EXPECT_LE(c->NbPoles(), csrSpline(q).poles.rows());
  EXPECT_LT(c->NbPoles(), 0.4 * q.rows());
  EXPECT_LE(c->StartPoint().Distance(gp_Pnt(2, 0, 0)), 1e-14);
  EXPECT_LE(c->EndPoint().Distance(gp_Pnt(q(299, 0), q(299, 1), 0)), 1e-14);
}

TEST(FairFit, ClosedDataGiveAPeriodicConvexCurve) {
  PointMatrix q = closedEllipse(4000);
  addNoise(q, 1e-4, 3);
  FairFitOptions o;
  o.tolerance = 1e-3 * sizeOf(q);
  o.closed = true;
  const Handle(Geom_BSplineCurve) c = toOcct(fairFit(q, o));
  EXPECT_TRUE(c->IsPeriodic());
  EXPECT_EQ(signChanges(signedCurvature(c)), 0);
  std::vector<double> k = signedCurvature(c);
  EXPECT_GT(*std::min_element(k.begin(), k.end()), 0.0);  // counter-clockwise: positive throughout
  EXPECT_LE(maxDistance(c, q, 2), o.tolerance);
}

TEST(FairFit, HelixIn3DStaysWithinTolerance) {
  PointMatrix q(5000, 3);
  for (Eigen::Index i = 0; i < q.rows(); ++i) {
    const double t = 3 * M_PI * static_cast<double>(i) / 4999.0;
    q.row(i) << std::cos(t), std::sin(t), 0.1 * t;
  }
  addNoise(q, 1e-4, 4);
  FairFitOptions o;
  o.tolerance = 1e-3 * sizeOf(q);
  const FairFitResult r = fairFitReport(q, o);
  EXPECT_LE(maxDistance(toOcct(r.curve), q, 2), o.tolerance);
  EXPECT_EQ(r.curve.dimension(), 3);
  EXPECT_LT(r.curve.poles.rows(), 150);
}

TEST(FairFit, EndTangentsAndCurvaturesAreMet) {
  PointMatrix q = arcParabola(2000);
  addNoise(q, 1e-4, 5);
  FairFitOptions o;
  o.tolerance = 1e-3 * sizeOf(q);
  Eigen::VectorXd t0(2), t1(2), k0(2), k1(2);
  t0 << 0.1, -1.0;
  t1 << -0.2, 1.0;
  k0 << 0.9, 0.05;  // its part along t0 is ignored
  k1 << -0.25, 0.0;
  o.startTangent = t0, o.endTangent = t1, o.startCurvature = k0, o.endCurvature = k1;
  const Handle(Geom_BSplineCurve) c = toOcct(fairFit(q, o));
  EXPECT_LE(maxDistance(c, q, 2), o.tolerance);
  auto check = [&](double u, Eigen::VectorXd t, const Eigen::VectorXd& k) {
    gp_Pnt p;
    gp_Vec d1, d2;
    c->D2(u, p, d1, d2);
    t.normalize();
    const gp_Vec T(t[0], t[1], 0);
    EXPECT_LE(d1.Normalized().Subtracted(T).Magnitude(), 1e-12);
    const gp_Vec kv = (d2 - T * d2.Dot(T)) / d1.SquareMagnitude();
    const gp_Vec want = gp_Vec(k[0], k[1], 0) - T * gp_Vec(k[0], k[1], 0).Dot(T);
    EXPECT_LE(kv.Subtracted(want).Magnitude(), 1e-9 * want.Magnitude());
  };
  check(c->FirstParameter(), t0, k0);
  check(c->LastParameter(), t1, k1);
}

TEST(FairFit, BadInputIsRefusedByName) {
  PointMatrix q = arcParabola(50);
  FairFitOptions o;
  o.tolerance = 1e-3;
  PointMatrix nan = q;
  nan(7, 1) = std::nan("");
  EXPECT_NE(refusal(nan, o).find("finite"), std::string::npos);
  EXPECT_NE(refusal(q.topRows(3), o).find("at least 4"), std::string::npos);
  PointMatrix twice = q;  // repeated points are merged (issue 25); all coincident ones are refused
  twice.row(8) = twice.row(7);
  EXPECT_EQ(fairFitReport(twice, o).mergedPoints, 1);
  PointMatrix same = q;
  same.rowwise() = q.row(3);
  EXPECT_NE(refusal(same, o).find("coincide"), std::string::npos);
  for (double tol : {0.0, -1.0, HUGE_VAL, std::nan("")}) {
    FairFitOptions bad = o;
    bad.tolerance = tol;
    EXPECT_NE(refusal(q, bad).find("tolerance must be positive and finite"), std::string::npos) << tol;
  }
  FairFitOptions noisy = o;
  noisy.noise = -1.0;
  EXPECT_NE(refusal(q, noisy).find("noise"), std::string::npos);
  FairFitOptions closed = o;
  closed.closed = true;
  closed.endTangent = Eigen::VectorXd::Ones(2);
  EXPECT_NE(refusal(q, closed).find("open data only"), std::string::npos);
  FairFitOptions zero = o;
  zero.startTangent = Eigen::VectorXd::Zero(2);
  EXPECT_NE(refusal(q, zero).find("zero vector"), std::string::npos);
  FairFitOptions wrongDim = o;
  wrongDim.startTangent = Eigen::VectorXd::Ones(3);
  EXPECT_NE(refusal(q, wrongDim).find("2 coordinates"), std::string::npos);
  FairFitOptions curvatureOnly = o;
  curvatureOnly.startCurvature = Eigen::VectorXd::Ones(2);
  EXPECT_NE(refusal(q, curvatureOnly).find("needs the start tangent"), std::string::npos);
}

TEST(FairFit, ToleranceBelowTheNoiseIsRefusedNamingTheNoise) {
  PointMatrix q = arcParabola(3000);
  addNoise(q, 1e-3, 6);
  FairFitOptions o;
  o.tolerance = 1e-5 * sizeOf(q);
  const std::string why = refusal(q, o);
  EXPECT_NE(why.find("below the noise"), std::string::npos) << why;
  EXPECT_NE(why.find("3 times the noise"), std::string::npos) << why;
}

TEST(FairFit, EstimatesTheNoiseOfGaussianScatter) {
  PointMatrix q = arcParabola(20000);
  std::mt19937 rng(8);
  std::normal_distribution<double> g(0.0, 1e-3);
  for (Eigen::Index i = 0; i < q.rows(); ++i) q(i, 0) += g(rng), q(i, 1) += g(rng);
  FairFitOptions o;
  o.tolerance = 0.01;
  const FairFitResult r = fairFitReport(q, o);
  EXPECT_NEAR(r.noise, 1e-3, 0.15e-3);
  FairFitOptions given = o;
  given.noise = 2e-3;
  EXPECT_EQ(fairFitReport(q, given).noise, 2e-3);
}

// Step 10 (docs/FAIR_FIT.md): thinning removes knots and fairing third-derivative jumps at the
// knots, within the tolerance. Judged by OCCT: fewer poles and fewer curvature extrema than
// the same fit without step 10, every sample still within the tolerance, the same sign
// changes, still C2, the end points kept.
TEST(FairFit, ThinningAndFairingRemovePolesAndCurvatureExtremaWithinTheTolerance) {
  struct Case {
    const char* name;
    PointMatrix q;
    int signChanges;
  };
  std::vector<Case> cases;
  cases.push_back({"convex, noisy", arcParabola(10000), 0});
  addNoise(cases.back().q, 1e-4, 11);
  cases.push_back({"road, noisy", road(20000), 1});
  addNoise(cases.back().q, 1e-4, 12);
  PointMatrix e(2000, 2);
  for (Eigen::Index i = 0; i < e.rows(); ++i) {
    const double t = M_PI * static_cast<double>(i) / 1999.0;
    e.row(i) << 2 * std::cos(t), std::sin(t);
  }
  cases.push_back({"half ellipse, noise-free", e, 0});
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    FairFitOptions o;
    o.tolerance = 1e-3 * sizeOf(c.q);
    if (std::string(c.name).find("noise-free") != std::string::npos) o.tolerance = 1e-4 * sizeOf(c.q);
    FairFitOptions plain = o;
    plain.fairing = false;
    const Handle(Geom_BSplineCurve) before = toOcct(fairFit(c.q, plain)), after = toOcct(fairFit(c.q, o));
    const int eBefore = extrema(signedCurvature(before)), eAfter = extrema(signedCurvature(after));
    EXPECT_LT(eAfter, eBefore);
    EXPECT_EQ(signChanges(signedCurvature(after)), c.signChanges);
    EXPECT_LE(maxDistance(after, c.q, 2), o.tolerance);
    EXPECT_LE(c2Jump(after), 1e-6);
    EXPECT_LT(after->NbPoles(), before->NbPoles());
    const Eigen::Index last = c.q.rows() - 1;
    EXPECT_LE(after->StartPoint().Distance(gp_Pnt(c.q(0, 0), c.q(0, 1), 0)), 1e-12 * sizeOf(c.q));
    EXPECT_LE(after->EndPoint().Distance(gp_Pnt(c.q(last, 0), c.q(last, 1), 0)), 1e-12 * sizeOf(c.q));
  }
}

TEST(FairFit, ThinningKeepsClosedDataPeriodicAndWithinTheTolerance) {
  PointMatrix q = closedEllipse(4000);
  addNoise(q, 1e-4, 13);
  FairFitOptions o;
  o.tolerance = 1e-3 * sizeOf(q);
  o.closed = true;
  FairFitOptions plain = o;
  plain.fairing = false;
  const Handle(Geom_BSplineCurve) before = toOcct(fairFit(q, plain)), after = toOcct(fairFit(q, o));
  EXPECT_TRUE(after->IsPeriodic());
  EXPECT_LT(after->NbPoles(), before->NbPoles());
  EXPECT_EQ(signChanges(signedCurvature(after)), 0);
  EXPECT_LE(maxDistance(after, q, 2), o.tolerance);
  EXPECT_LE(c2Jump(after), 1e-6);
}

// The competitor at the same tolerance: OCCT's GeomAPI_PointsToBSpline (FreeCAD's
// approximate; degree 3..8, C2). On 1000 noisy samples of the bench's convex data it needs 9
// poles; the fair fit without step 10 had 18, with it 11 (docs/FAIR_FIT.md).
TEST(FairFit, UsesAboutAsFewPolesAsOcctsApproximation) {
  PointMatrix q = arcParabola(1000);
  addNoise(q, 1e-4, 7);
  FairFitOptions o;
  o.tolerance = 1e-3 * sizeOf(q);
  const Handle(Geom_BSplineCurve) fit = toOcct(fairFit(q, o));
  TColgp_Array1OfPnt pts(1, static_cast<int>(q.rows()));
  for (Eigen::Index i = 0; i < q.rows(); ++i) pts.SetValue(static_cast<int>(i) + 1, gp_Pnt(q(i, 0), q(i, 1), 0));
  const Handle(Geom_BSplineCurve) occt = GeomAPI_PointsToBSpline(pts, 3, 8, GeomAbs_C2, o.tolerance).Curve();
  EXPECT_LE(maxDistance(fit, q), o.tolerance);
  EXPECT_LE(fit->NbPoles(), 1.3 * occt->NbPoles()) << fit->NbPoles() << " vs OCCT's " << occt->NbPoles();
  EXPECT_EQ(signChanges(signedCurvature(fit)), 0);
}

// The fit reads its spans from the poles and knots (O(1) a span; OCCT's evaluation costs
// O(knots) per point): OCCT's LocalD3 is the referee, on clamped and periodic cubics with
// uneven knots, before and after OCCT removed a knot.
TEST(FairFit, SpanPolynomialsFromPolesAgreeWithOcct) {
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> step(0.2, 3.0), coord(-5.0, 5.0);
  for (bool periodic : {false, true}) {
    for (int m : {1, 2, 5, 12}) {
      if (periodic && m < 4) continue;
      Eigen::VectorXd t(m + 1);
      t[0] = -1.5;
      for (int i = 1; i <= m; ++i) t[i] = t[i - 1] + step(rng);
      BSplineCurve c;
      c.degree = 3;
      c.periodic = periodic;
      c.poles.resize(periodic ? m : m + 3, 3);
      for (Eigen::Index i = 0; i < c.poles.rows(); ++i) c.poles.row(i) << coord(rng), coord(rng), coord(rng);
      c.knots = t;
      c.mults = Eigen::VectorXi::Ones(m + 1);
      if (!periodic) c.mults[0] = c.mults[m] = 4;
      Handle(Geom_BSplineCurve) occ = toOcct(c);
      for (int pass = 0; pass < 2; ++pass) {
        SCOPED_TRACE(std::string(periodic ? "periodic" : "clamped") + ", spans " + std::to_string(occ->NbKnots() - 1));
        std::vector<double> knots;
        for (int i = 1; i <= occ->NbKnots(); ++i) knots.push_back(occ->Knot(i));
        for (Eigen::Index j = 0; j + 1 < static_cast<Eigen::Index>(knots.size()); ++j) {
          const auto poly = detail::fairfit::spanPoly(occ, knots, j);
          for (double f : {0.0, 0.37, 1.0}) {
            const double x = f * (knots[j + 1] - knots[j]);
            gp_Pnt p;
            gp_Vec d1, d2, d3;
            occ->LocalD3(knots[j] + x, static_cast<int>(j) + 1, static_cast<int>(j) + 2, p, d1, d2, d3);
            const Eigen::Vector3d C = ((poly[3] * x + poly[2]) * x + poly[1]) * x + poly[0];
            const Eigen::Vector3d C1 = (3 * poly[3] * x + 2 * poly[2]) * x + poly[1];
            const Eigen::Vector3d C2 = 6 * poly[3] * x + 2 * poly[2];
            EXPECT_LE((C - Eigen::Vector3d(p.X(), p.Y(), p.Z())).norm(), 1e-12 * 50);
            EXPECT_LE((C1 - Eigen::Vector3d(d1.X(), d1.Y(), d1.Z())).norm(), 1e-11 * (1 + d1.Magnitude()));
            EXPECT_LE((C2 - Eigen::Vector3d(d2.X(), d2.Y(), d2.Z())).norm(), 1e-10 * (1 + d2.Magnitude()));
            EXPECT_LE((6 * poly[3] - Eigen::Vector3d(d3.X(), d3.Y(), d3.Z())).norm(), 1e-9 * (1 + d3.Magnitude()));
          }
        }
        if (occ->NbKnots() - 1 < (periodic ? 6 : 3)) break;
        occ = Handle(Geom_BSplineCurve)::DownCast(occ->Copy());
        occ->RemoveKnot(occ->NbKnots() / 2, 0, HUGE_VAL);
      }
    }
  }
}

// Scale-free (docs/FAIR_FIT.md, "Checks"): samples 1e300 or 1e-300 in size fit as at size 1
// (they were refused as "points coincide": an overflowing or underflowing square). OCCT is the
// referee on the curve scaled back to size 1.
TEST(FairFit, SamplesOfAnySizeFitAsAtSizeOne) {
  PointMatrix q = arcParabola(2000);
  addNoise(q, 1e-4, 7);
  FairFitOptions o;
  o.tolerance = 1e-3 * sizeOf(q);
  const FairFitResult one = fairFitReport(q, o);
  for (double s : {1e300, 1e-300, 1e-150, 1e120}) {
    SCOPED_TRACE(s);
    FairFitOptions so = o;
    so.tolerance = o.tolerance * s;
    const FairFitResult r = fairFitReport(q * s, so);
    EXPECT_EQ(r.curve.poles.rows(), one.curve.poles.rows());
    EXPECT_EQ(r.curvatureExtrema, one.curvatureExtrema);
    EXPECT_LE(r.maxDeviation, so.tolerance);
    BSplineCurve back = r.curve;
    back.poles /= s;
    const Handle(Geom_BSplineCurve) c = toOcct(back);
    EXPECT_LE(maxDistance(c, q, 2), o.tolerance * (1 + 1e-9));
    EXPECT_EQ(signChanges(signedCurvature(c)), 0);
  }
}

// ---- The tolerance as a constraint (fair_fit_constrained.cpp; issue 25)

namespace {

/// A random cubic with simple interior knots, clamped or periodic, and its spline space.
BSplineCurve randomCubic(std::mt19937& rng, int m, bool periodic) {
  std::uniform_real_distribution<double> step(0.2, 3.0), coord(-5.0, 5.0);
  BSplineCurve c;
  c.degree = 3;
  c.periodic = periodic;
  c.knots.resize(m + 1);
  c.knots[0] = -0.5;
  for (int i = 1; i <= m; ++i) c.knots[i] = c.knots[i - 1] + step(rng);
  c.poles.resize(periodic ? m : m + 3, 3);
  for (Eigen::Index i = 0; i < c.poles.rows(); ++i) c.poles.row(i) << coord(rng), coord(rng), coord(rng);
  c.mults = Eigen::VectorXi::Ones(m + 1);
  if (!periodic) c.mults[0] = c.mults[m] = 4;
  return c;
}

detail::fairfit::SplineSpace spaceOf(const BSplineCurve& c) {
  return {std::vector<double>(c.knots.data(), c.knots.data() + c.knots.size()), c.periodic};
}

Eigen::Vector3d at(const Handle(Geom_BSplineCurve)& occ, double u, int derivative = 0) {
  gp_Pnt p;
  gp_Vec d1, d2, d3;
  occ->D3(u, p, d1, d2, d3);
  const gp_XYZ v = derivative == 0 ? p.XYZ() : derivative == 2 ? d2.XYZ() : d3.XYZ();
  return {v.X(), v.Y(), v.Z()};
}

}  // namespace

TEST(FairFitConstrained, BasisAndDerivativeWeightsAgreeWithOcct) {
  // The weights the constrained fit builds its rows from (C, C'' at span ends, C''') against
  // OCCT's D3 of the same curve: clamped and periodic, several span counts.
  std::mt19937 rng(5);
  for (bool periodic : {false, true}) {
    for (int m : {1, 3, 7, 12}) {
      if (periodic && m < 4) continue;
      const BSplineCurve c = randomCubic(rng, m, periodic);
      const Handle(Geom_BSplineCurve) occ = toOcct(c);
      const auto S = spaceOf(c);
      ASSERT_EQ(S.poles(), c.poles.rows());
      for (Eigen::Index j = 0; j < m; ++j) {
        SCOPED_TRACE((periodic ? "periodic, span " : "clamped, span ") + std::to_string(j));
        const double h = c.knots[j + 1] - c.knots[j];
        auto combine = [&](const std::array<double, 4>& w) {
          Eigen::Vector3d v = Eigen::Vector3d::Zero();
          for (int r = 0; r < 4; ++r) v += w[r] * c.poles.row(S.pole(j, r)).transpose();
          return v;
        };
        for (double f : {0.0, 0.3, 0.81}) {
          EXPECT_LE((combine(S.basis(j, f * h)) - at(occ, c.knots[j] + f * h)).norm(), 1e-12 * 10);
        }
        const auto second = S.secondDerivative(j);
        const double inside = 1e-9 * h;  // OCCT's D3 at a knot is the right-hand span's
        EXPECT_LE((combine(second[0]) - at(occ, c.knots[j] + inside, 2)).norm(),
                  1e-6 * (1 + combine(second[0]).norm()));
        EXPECT_LE((combine(second[1]) - at(occ, c.knots[j + 1] - inside, 2)).norm(),
                  1e-6 * (1 + combine(second[1]).norm()));
        EXPECT_LE((combine(S.thirdDerivative(j)) - at(occ, c.knots[j] + 0.5 * h, 3)).norm(),
                  1e-9 * (1 + combine(S.thirdDerivative(j)).norm()));
      }
    }
  }
}

TEST(FairFitConstrained, PinsPutTheCurveThroughTheirPointsAndKeepFixedPoles) {
  std::mt19937 rng(8);
  for (bool periodic : {false, true}) {
    BSplineCurve c = randomCubic(rng, 9, periodic);
    const auto S = spaceOf(c);
    Eigen::MatrixX3d P = detail::fairfit::polesOf(c);
    const Eigen::MatrixX3d before = P;
    std::vector<std::pair<Eigen::Index, Eigen::Vector3d>> pins;
    for (Eigen::Index k : {2, 3, 4, 7}) pins.push_back({k, Eigen::Vector3d(k, -k, 0.5 * k)});
    std::vector<char> fixed(P.rows(), 0);
    fixed[0] = fixed[P.rows() - 1] = 1;
    ASSERT_TRUE(detail::fairfit::pinAtKnots(S, P, pins, fixed));
    detail::fairfit::setPoles(c, P);
    const Handle(Geom_BSplineCurve) occ = toOcct(c);
    for (const auto& [k, q] : pins) EXPECT_LE((at(occ, c.knots[k]) - q).norm(), 1e-10) << "knot " << k;
    EXPECT_EQ(P.row(0), before.row(0));
    EXPECT_EQ(P.row(P.rows() - 1), before.row(P.rows() - 1));
  }
}

TEST(FairFitConstrained, FairingKeepsEverySampleWithinTheToleranceAndLowersTheEnergy) {
  // A wiggly cubic fitted to samples of a circle arc within 0.02: the constrained fairing
  // must lower the energy and leave every sample within 0.02 of its curve point (judged by
  // OCCT's evaluation of the new curve at the samples' parameters).
  std::mt19937 rng(3);
  std::normal_distribution<double> wiggle(0.0, 0.004);
  const int n = 400, m = 12;
  BSplineCurve c;
  c.degree = 3;
  c.knots = Eigen::VectorXd::LinSpaced(m + 1, 0.0, 3.0);
  c.mults = Eigen::VectorXi::Ones(m + 1);
  c.mults[0] = c.mults[m] = 4;
  // Poles near the unit circle (the curve near an arc of angle 3), with wiggles.
  c.poles.resize(m + 3, 3);
  for (int i = 0; i < m + 3; ++i) {
    const double a = 3.0 * i / (m + 2);
    c.poles.row(i) << std::cos(a) + wiggle(rng), std::sin(a) + wiggle(rng), 0.0;
  }
  const auto S = spaceOf(c);
  Handle(Geom_BSplineCurve) occ = toOcct(c);
  detail::fairfit::ConstrainedFairing f;
  f.tolerance = 0.02;
  std::vector<Eigen::Vector3d> q(n);
  for (int i = 0; i < n; ++i) {
    const double u = 3.0 * i / (n - 1);
    const Eigen::Index span = std::min<Eigen::Index>(static_cast<Eigen::Index>(u / 0.25), m - 1);
    q[i] = at(occ, u) + Eigen::Vector3d(0.01 * std::sin(7.0 * i), 0.01 * std::cos(5.0 * i), 0.0);
    f.sample.push_back(i);
    f.feet.push_back({span, u - c.knots[span], (at(occ, u) - q[i]).norm()});
  }
  f.q = &q;
  f.fixed.assign(m + 3, 0);
  f.fixed[0] = f.fixed[m + 2] = 1;
  Eigen::MatrixX3d P = detail::fairfit::polesOf(c);
  detail::fairfit::fairUnderTolerance(S, P, f);
  EXPECT_LT(f.energyAfter, 0.5 * f.energyBefore);
  detail::fairfit::setPoles(c, P);
  occ = toOcct(c);
  for (int i = 0; i < n; ++i) {
    const double u = c.knots[f.feet[i].span] + f.feet[i].x;
    EXPECT_LE((at(occ, u) - q[i]).norm(), 0.02 * (1 + 1e-12)) << "sample " << i;
  }
}
