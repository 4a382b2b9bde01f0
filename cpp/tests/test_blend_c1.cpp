// Section 5: G1 biquadratic basic shapes joined to biquadratic C1 NURBS by a (4,2) double
// strip; judged by OCCT evaluation of the returned patches (D1 on both sides of every seam).
#include <gtest/gtest.h>

#include <BRepCheck_Analyzer.hxx>
#include <GeomAbs_Shape.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <cmath>
#include <map>
#include <string>

#include "fairsplines/blend_c1.hpp"
#include "fairsplines/errors.hpp"
#include "blend_test_support.hpp"

using namespace fairsplines;
using namespace fairsplines::test::blend;

namespace {

struct C1Seams {
  double alongU = 0.0;            ///< between neighbouring patches in u (closing seam included)
  double basicTransition = 0.0;   ///< basic | lower strip row
  double centre = 0.0;            ///< lower | upper strip row (the centre line)
  double transitionFree = 0.0;    ///< upper strip row | ring
  double insideV = 0.0;           ///< inside the ring, and inside the basic rows where they are C1 across
  std::vector<double> alongURow;  ///< per row of the complex
  double worst() const { return std::max({alongU, basicTransition, centre, transitionFree, insideV}); }
};

/// Position and first derivatives across every seam, OCCT D1 on both sides; derivatives
/// scaled to the shared parameterization (across a seam: the ratio of the neighbouring knot
/// intervals; along it: equal). Relative to the largest first derivative there. knotsU:
/// the intervals the u-seams are judged with (default: the complex's).
C1Seams c1Seams(const BlendComplex& c, const Eigen::VectorXd* knotsU = nullptr) {
  const Eigen::VectorXd& ku = knotsU ? *knotsU : c.knotsU;
  std::map<std::pair<int, int>, Handle(Geom_BSplineSurface)> at;
  for (const TaggedPatch& p : c.patches) at[{p.uPiece, p.vPiece}] = patchToOcct(p);
  const int rows = c.rowsBasic + c.rowsTransition + c.rowsFreeForm;
  EXPECT_EQ(static_cast<int>(at.size()), rows * c.piecesU);
  C1Seams report;
  report.alongURow.assign(rows, 0.0);
  auto compare = [](const Handle(Geom_BSplineSurface)& left, const Handle(Geom_BSplineSurface)& right, bool inU,
                    double beta, double& bucket) {
    for (int k = 0; k <= 16; ++k) {
      const double t = k / 16.0;
      gp_Pnt pl, pr;
      gp_Vec lu, lv, ru, rv;  // lu, ru across the seam; lv, rv along it
      if (inU) {
        left->D1(1.0, t, pl, lu, lv);
        right->D1(0.0, t, pr, ru, rv);
      } else {
        left->D1(t, 1.0, pl, lv, lu);
        right->D1(t, 0.0, pr, rv, ru);
      }
      const double scale = std::max(lu.Magnitude(), lv.Magnitude());
      const double jumps[3] = {pl.Distance(pr), (ru - beta * lu).Magnitude(), (rv - lv).Magnitude()};
      for (double j : jumps) bucket = std::max(bucket, j / scale);
    }
  };
  for (int k = 0; k < c.piecesU; ++k) {
    const int kPrev = (k + c.piecesU - 1) % c.piecesU;
    const double hPrev = ku[kPrev + 1] - ku[kPrev], h = ku[k + 1] - ku[k];
    for (int v = 0; v < rows; ++v) {
      if (k > 0 || c.closedU) {  // a partial turn has no closing seam
        compare(at.at({kPrev, v}), at.at({k, v}), true, h / hPrev, report.alongURow[v]);
        report.alongU = std::max(report.alongU, report.alongURow[v]);
      }
      if (v == 0 || (v < c.rowsBasic && !c.basicC2InV)) continue;
      const double beta = (c.knotsV[v + 1] - c.knotsV[v]) / (c.knotsV[v] - c.knotsV[v - 1]);
      double& bucket = v == c.rowsBasic       ? report.basicTransition
                       : v == c.rowsBasic + 1 ? report.centre
                       : v == c.rowsBasic + 2 ? report.transitionFree
                                              : report.insideV;
      compare(at.at({k, v - 1}), at.at({k, v}), false, beta, bucket);
    }
  }
  return report;
}

/// Largest |distance| over dense samples (17 x 17) of the given patches.
template <class F>
double offShape(const std::vector<Handle(Geom_BSplineSurface)>& patches, F distance) {
  double worst = 0.0;
  for (const auto& s : patches) {
    for (int a = 0; a <= 16; ++a) {
      for (int b = 0; b <= 16; ++b) worst = std::max(worst, std::abs(distance(s->Value(a / 16.0, b / 16.0))));
    }
  }
  return worst;
}

std::vector<Handle(Geom_BSplineSurface)> basicOf(const BlendComplex& c) {
  std::vector<Handle(Geom_BSplineSurface)> out;
  for (const TaggedPatch& p : c.patches) {
    if (p.role == TaggedPatch::Role::Basic) out.push_back(patchToOcct(p));
  }
  return out;
}

std::vector<Handle(Geom_BSplineSurface)> patchesOf(const G1RevolvedShape& s) {
  std::vector<Handle(Geom_BSplineSurface)> out;
  for (int i = 0; i < s.piecesU(); ++i) {
    for (int j = 0; j < s.piecesV(); ++j) out.push_back(patchToOcct(s.patch(i, j)));
  }
  return out;
}

const Eigen::VectorXd kLatitudes = vec({-0.6, 0.1, 0.5, 0.8});
const Eigen::VectorXd kTube = vec({-1.0, -0.2, 0.4, 0.9});
const Eigen::VectorXd kHeights = vec({-1.0, 0.5, 0.7, 2.0});

auto sphereDistance(const ShapeFrame& f, double R) {
  return [&f, R](const gp_Pnt& q) { return localOf(f, q).norm() - R; };
}
auto coneDistance(const ShapeFrame& f, double r0, double slope) {
  return [&f, r0, slope](const gp_Pnt& q) {
    const auto l = localOf(f, q);
    return (std::hypot(l.x(), l.y()) - (r0 + slope * l.z())) / std::sqrt(1 + slope * slope);
  };
}
auto torusDistance(const ShapeFrame& f, double R, double r) {
  return [&f, R, r](const gp_Pnt& q) {
    const auto l = localOf(f, q);
    return std::hypot(std::hypot(l.x(), l.y()) - R, l.z()) - r;
  };
}

template <class Call>
std::string inputErrorOf(Call call) {
  try {
    call();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no InputError)";
}

}  // namespace

TEST(G1Revolved, BiquadraticPatchesLieExactlyOnSphereCylinderConeAndTorus) {
  const ShapeFrame f = tilted();
  const G1RevolvedShape sphere = g1SphereZone(f, 2.0, nonUniformTurn(), vec({-kPi / 2, -0.6, 0.1, 0.5, kPi / 2}));
  EXPECT_EQ(sphere.piecesU(), 7);
  EXPECT_EQ(sphere.piecesV(), 4);
  EXPECT_EQ(sphere.patch(0, 0).degreeU, 2);
  EXPECT_EQ(sphere.patch(0, 0).degreeV, 2);
  EXPECT_LT(offShape(patchesOf(sphere), sphereDistance(f, 2.0)), 1e-10 * 2.0);
  for (double slope : {0.0, -0.3, 0.4}) {
    const G1RevolvedShape cone = g1Cone(f, 2.0, slope, nonUniformTurn(), kHeights);
    EXPECT_LT(offShape(patchesOf(cone), coneDistance(f, 2.0, slope)), 1e-10 * 4) << slope;
  }
  const G1RevolvedShape torus = g1Torus(f, 3.0, 1.0, nonUniformTurn(), kTube);
  EXPECT_LT(offShape(patchesOf(torus), torusDistance(f, 3.0, 1.0)), 1e-10 * 4);
}

TEST(C1Blend, SphereZoneComplexIsC1AcrossEverySeamAndStaysExact) {
  const ShapeFrame f = tilted();
  const double R = 2.0;
  const G1RevolvedShape zone = g1SphereZone(f, R, nonUniformTurn(), kLatitudes);
  const BlendComplex c = blendC1(zone);
  EXPECT_EQ(c.smoothness, 1);
  EXPECT_EQ(c.piecesU, 14);  // two quartics per arc, eq. (12)
  EXPECT_EQ(c.rowsBasic, 3);
  EXPECT_EQ(c.rowsTransition, 2);
  EXPECT_EQ(c.rowsFreeForm, 1);
  EXPECT_EQ(static_cast<int>(c.patches.size()), 14 * (3 + 2 + 1));
  for (const TaggedPatch& p : c.patches) {
    if (p.role == TaggedPatch::Role::Basic) {
      EXPECT_EQ(p.degreeU, 4);
      EXPECT_EQ(p.degreeV, 2);
    } else if (p.role == TaggedPatch::Role::Transition) {
      EXPECT_EQ(p.degreeU, 4);
      EXPECT_EQ(p.degreeV, 2);
    }
  }
  EXPECT_LT(offShape(basicOf(c), sphereDistance(f, R)), 1e-10 * R);
  const C1Seams s = c1Seams(c);
  EXPECT_LT(s.alongU, 1e-8);
  EXPECT_LT(s.basicTransition, 1e-8);
  EXPECT_LT(s.centre, 1e-8);
  EXPECT_LT(s.transitionFree, 1e-8);
}

TEST(C1Blend, CylinderConeAndTorusComplexesAreC1AndStayExact) {
  const ShapeFrame f = tilted();
  for (double slope : {0.0, -0.3, 0.4}) {
    const BlendComplex c = blendC1(g1Cone(f, 2.0, slope, nonUniformTurn(), kHeights));
    EXPECT_TRUE(c.basicC2InV);  // lines are C1 over the heights
    EXPECT_LT(offShape(basicOf(c), coneDistance(f, 2.0, slope)), 1e-10 * 4) << slope;
    EXPECT_LT(c1Seams(c).worst(), 1e-8) << slope;
    EXPECT_GE(singleSurface(c, 1e-9, 1)->Continuity(), GeomAbs_C1) << slope;
  }
  for (bool both : {false, true}) {
    C1BlendOptions o;
    o.quarticInV = both;
    const BlendComplex c = blendC1(g1Torus(f, 3.0, 1.0, nonUniformTurn(), kTube), nullptr, o);
    EXPECT_LT(offShape(basicOf(c), torusDistance(f, 3.0, 1.0)), 1e-10 * 4) << both;
    EXPECT_LT(c1Seams(c).worst(), 1e-8) << both;
  }
}

TEST(C1Blend, BothDirectionsGiveOneC1SurfaceThatKeepsTheShape) {
  const ShapeFrame f = tilted();
  const double R = 1.5;
  C1BlendOptions o;
  o.quarticInV = true;
  const BlendComplex c = blendC1(g1SphereZone(f, R, nonUniformTurn(), kLatitudes), nullptr, o);
  ASSERT_TRUE(c.basicC2InV);
  EXPECT_EQ(c.rowsBasic, 6);
  EXPECT_LT(offShape(basicOf(c), sphereDistance(f, R)), 1e-10 * R);
  const C1Seams s = c1Seams(c);
  EXPECT_LT(s.worst(), 1e-8);
  EXPECT_LT(s.insideV, 1e-8);
  const Handle(Geom_BSplineSurface) single = singleSurface(c, 1e-9, 1);
  EXPECT_GE(single->Continuity(), GeomAbs_C1);
  EXPECT_EQ(single->UDegree(), 4);
  EXPECT_EQ(single->VDegree(), 4);
  double worst = 0.0;
  for (int a = 0; a <= 60; ++a) {
    for (int b = 0; b <= 30; ++b) {
      const double u = c.knotsU[0] + (c.knotsU[c.piecesU] - c.knotsU[0]) * a / 60.0;
      const double v = c.knotsV[0] + (c.knotsV[c.rowsBasic] - c.knotsV[0]) * b / 30.0;
      worst = std::max(worst, std::abs(localOf(f, single->Value(u, v)).norm() - R));
    }
  }
  EXPECT_LT(worst, 1e-9 * R);
  o.quarticInV = true;
  const BlendComplex torus = blendC1(g1Torus(f, 3.0, 1.0, nonUniformTurn(), kTube), nullptr, o);
  EXPECT_GE(singleSurface(torus, 1e-9, 1)->Continuity(), GeomAbs_C1);
  // Without the profile conversion the latitude arcs join only G1: no single C1 surface.
  EXPECT_THROW(singleSurface(blendC1(g1SphereZone(f, R, nonUniformTurn(), kLatitudes)), 1e-9, 1), InputError);
}

TEST(C1Blend, EightByFourZoneWithItsRing) {
  // The benchmark's configuration: 8 x 4 patches plus the default ring.
  C1BlendOptions o;
  o.quarticInV = true;
  const BlendComplex c = blendC1(
      g1SphereZone(tilted(), 1.0, Eigen::VectorXd::LinSpaced(9, 0.0, 2 * kPi), vec({-0.8, -0.3, 0.1, 0.5, 0.9})),
      nullptr, o);
  EXPECT_LT(c1Seams(c).worst(), 1e-8);
  EXPECT_GE(singleSurface(c, 1e-9, 1)->Continuity(), GeomAbs_C1);
}

TEST(C1Blend, AnyNewScalarsBetaTThatCloseTheTurnGiveAC1Complex) {
  // Appendix 7.3 with the derived numerators: betaT = 1 everywhere (uniform arc knots on a
  // non-uniform partition) keeps the sphere exact and the complex C1.
  const ShapeFrame f = tilted();
  C1BlendOptions o;
  o.betaT = Eigen::VectorXd::Ones(7);
  const BlendComplex c = blendC1(g1SphereZone(f, 1.0, nonUniformTurn(), kLatitudes), nullptr, o);
  EXPECT_NEAR(c.knotsU[2] - c.knotsU[0], c.knotsU[4] - c.knotsU[2], 1e-12);
  EXPECT_LT(offShape(basicOf(c), sphereDistance(f, 1.0)), 1e-10);
  EXPECT_LT(c1Seams(c).worst(), 1e-8);
}

TEST(C1Blend, TheSeamCheckFailsWithoutEtaOrWithTheWrongBetaT) {
  const ShapeFrame f = tilted();
  const G1RevolvedShape zone = g1SphereZone(f, 1.0, nonUniformTurn(), kLatitudes);
  // Without the reparameterization eta: quadratic arcs split and degree-raised, same knots.
  C1BlendOptions noEta;
  noEta.withoutEta = true;
  const BlendComplex naive = blendC1(zone, nullptr, noEta);
  EXPECT_LT(offShape(basicOf(naive), sphereDistance(f, 1.0)), 1e-10);  // still on the sphere, and
  const C1Seams bad = c1Seams(naive);
  // its basic rows still join C1 after projection (the knots have the ratios beta); but in
  // homogeneous space they join only G1 (the weight has a corner at every joint), so the
  // strip, built from homogeneous layers, is not C1 along u,
  EXPECT_LT(bad.alongURow[0], 1e-8);
  EXPECT_GT(bad.alongURow[naive.rowsBasic], 1e-3);
  EXPECT_GT(bad.alongURow[naive.rowsBasic + 1], 1e-3);
  EXPECT_LT(bad.alongURow[naive.rowsBasic + 2], 1e-8);  // (the ring is)
  // and no single C1 surface exists.
  noEta.quarticInV = true;
  EXPECT_THROW(singleSurface(blendC1(zone, nullptr, noEta), 1e-9, 1), InputError);
  // The correct complex judged with the wrong betaT (uniform knots in place of betaT = beta).
  const BlendComplex c = blendC1(zone);
  const Eigen::VectorXd uniform = Eigen::VectorXd::LinSpaced(c.piecesU + 1, 0.0, c.piecesU);
  EXPECT_GT(c1Seams(c, &uniform).alongU, 1e-3);
  EXPECT_LT(c1Seams(c).alongU, 1e-8);
}

TEST(C1Blend, UserRingOnTheInterfaceKnotsIsKeptExactly) {
  const ShapeFrame f = tilted();
  const G1RevolvedShape zone = g1SphereZone(f, 1.0, nonUniformTurn(), kLatitudes);
  const Eigen::VectorXd T = ringKnotsC1(nonUniformTurn());
  Handle(Geom_BSplineSurface) ring = defaultRingC1(zone, T);
  // Make it free-form: move poles, add a second span in v.
  ring->SetPole(3, 2, ring->Pole(3, 2).Translated(gp_Vec(0.1, -0.2, 0.15)));
  ring->InsertVKnot(0.4, 1, 1e-12);
  ring->SetPole(5, 3, ring->Pole(5, 3).Translated(gp_Vec(-0.1, 0.05, 0.1)));
  const BlendComplex c = blendC1(zone, ring);
  EXPECT_EQ(c.rowsFreeForm, 2);
  EXPECT_LT(c1Seams(c).worst(), 1e-8);
  // Every free-form patch is the user's ring over its span.
  double worst = 0.0;
  for (const TaggedPatch& p : c.patches) {
    if (p.role != TaggedPatch::Role::FreeForm) continue;
    const Handle(Geom_BSplineSurface) s = patchToOcct(p);
    const int span = p.vPiece - c.rowsBasic - 2;
    for (int a = 0; a <= 6; ++a) {
      for (int b = 0; b <= 6; ++b) {
        const double u = c.knotsU[p.uPiece] + (c.knotsU[p.uPiece + 1] - c.knotsU[p.uPiece]) * a / 6.0;
        const double v = ring->VKnot(span + 1) + (ring->VKnot(span + 2) - ring->VKnot(span + 1)) * b / 6.0;
        worst = std::max(worst, s->Value(a / 6.0, b / 6.0).Distance(ring->Value(u, v)));
      }
    }
  }
  EXPECT_LT(worst, 1e-12);
}

TEST(C1Blend, PatchesMakeOneValidShell) {
  const BlendComplex c = blendC1(g1SphereZone(tilted(), 1.0, nonUniformTurn(), kLatitudes));
  const TopoDS_Shape shell = blendShell(c).shell;
  EXPECT_EQ(shell.ShapeType(), TopAbs_SHELL);
  EXPECT_TRUE(BRepCheck_Analyzer(shell).IsValid());
  int faces = 0;
  for (TopExp_Explorer e(shell, TopAbs_FACE); e.More(); e.Next()) ++faces;
  EXPECT_EQ(faces, static_cast<int>(c.patches.size()));
}

TEST(C1Blend, BadInputRaisesInputErrorNamingTheProblem) {
  const ShapeFrame f = tilted();
  auto has = [](const std::string& message, const std::string& part) {
    return message.find(part) != std::string::npos;
  };
  // An arc of pi or more (arc 1 opens 3.5).
  EXPECT_TRUE(has(inputErrorOf([&] {
                    g1SphereZone(f, 1.0, vec({0.0, 1.0, 4.5, 2 * kPi}), kLatitudes);
                  }),
                  "longitude arc 1"));
  EXPECT_TRUE(has(inputErrorOf([&] {
                    g1SphereZone(f, 1.0, nonUniformTurn(), vec({-kPi / 2, kPi / 2}));
                  }),
                  "latitude arc 0"));
  // The interface at a pole.
  EXPECT_TRUE(has(inputErrorOf([&] { blendC1(g1SphereZone(f, 1.0, nonUniformTurn(), vec({0.0, kPi / 2}))); }), "pole"));
  // Non-positive radii.
  EXPECT_TRUE(has(inputErrorOf([&] { g1SphereZone(f, -1.0, nonUniformTurn(), kLatitudes); }), "positive radius"));
  EXPECT_TRUE(has(inputErrorOf([&] { g1Torus(f, 3.0, 0.0, nonUniformTurn(), kTube); }), "0 < r < R"));
  EXPECT_TRUE(has(inputErrorOf([&] { g1Cone(f, 1.0, -1.0, nonUniformTurn(), kHeights); }), "is not positive"));
  // A closed tube has no boundary.
  EXPECT_TRUE(has(inputErrorOf([&] {
                    g1Torus(f, 3.0, 1.0, nonUniformTurn(), vec({0.0, 2.0, 4.0, 2 * kPi}));
                  }),
                  "closed profile"));
  // Rings that do not match the interface: turning the other way around the axis; a
  // bicubic net; a ring open in u.
  const G1RevolvedShape zone = g1SphereZone(f, 1.0, nonUniformTurn(), kLatitudes);
  Handle(Geom_BSplineSurface) reversed = defaultRingC1(zone, ringKnotsC1(nonUniformTurn()));
  reversed->UReverse();
  EXPECT_TRUE(has(inputErrorOf([&] { blendC1(zone, reversed); }),
                  "the free-form net does not match the interface: its first row turns the other way"));
  Handle(Geom_BSplineSurface) cubic = defaultRingC1(zone, ringKnotsC1(nonUniformTurn()));
  cubic->IncreaseDegree(3, 3);
  EXPECT_TRUE(has(inputErrorOf([&] { blendC1(zone, cubic); }), "biquadratic"));
  Handle(Geom_BSplineSurface) open = defaultRingC1(zone, ringKnotsC1(nonUniformTurn()));
  open->SetUNotPeriodic();
  EXPECT_TRUE(has(inputErrorOf([&] { blendC1(zone, open); }), "periodic in u"));
  // Scalars that do not close the turn.
  C1BlendOptions o;
  o.betaT = Eigen::VectorXd::Constant(7, 1.1);
  EXPECT_TRUE(has(inputErrorOf([&] { blendC1(zone, nullptr, o); }), "multiply to 1"));
}

TEST(C1Join, TwoDifferentlyPartitionedToriJoinC1AndStayExact) {
  // The C1 counterpart of Figs. 11-12: the same torus on both sides, partitioned differently
  // around the axis (beta^a != beta^b) and across the tube.
  const ShapeFrame f = tilted();
  const G1RevolvedShape a = g1Torus(f, 3.0, 1.0, nonUniformTurn(), vec({-1.4, -1.0, -0.3}));
  const G1RevolvedShape b =
      g1Torus(f, 3.0, 1.0, vec({0.3, 1.1, 1.6, 2.9, 3.4, 4.8, 5.9, 0.3 + 2 * kPi}), vec({0.2, 0.5, 1.3, 1.6}));
  const BlendComplex c = joinShapesC1(a, b);
  EXPECT_EQ(c.smoothness, 1);
  EXPECT_EQ(c.piecesU, 14);
  const C1Seams seams = c1Seams(c);
  EXPECT_LT(seams.worst(), 1e-8);
  auto torus = [&](const gp_Pnt& q) {
    const auto l = localOf(f, q);
    return std::hypot(std::hypot(l.x(), l.y()) - 3.0, l.z()) - 1.0;
  };
  EXPECT_LT(offShape(basicOf(c), torus), 1e-10 * 4);
  EXPECT_GE(singleSurface(c, 1e-9, 1)->Continuity(), GeomAbs_C1);
  EXPECT_TRUE(BRepCheck_Analyzer(blendShell(c).shell).IsValid());
  // Judged on uniform knots instead, the same complex fails: the check can fail.
  const Eigen::VectorXd uniform = Eigen::VectorXd::LinSpaced(c.piecesU + 1, 0.0, c.piecesU);
  EXPECT_GT(c1Seams(c, &uniform).alongU, 1e-3);
}

TEST(C1Join, CylinderIntoADomeAndBadInput) {
  const ShapeFrame f = tilted();
  ShapeFrame top = f;
  top.origin = f.origin + 2.5 * f.z;
  const G1RevolvedShape post = g1Cone(f, 1.0, 0.0, nonUniformTurn(), vec({0.0, 1.0, 1.8}));
  const G1RevolvedShape dome = g1SphereZone(top, 1.0, nonUniformTurn(), vec({0.2, 0.9, kPi / 2}));
  const BlendComplex c = joinShapesC1(post, dome);
  EXPECT_LT(c1Seams(c).worst(), 1e-8);
  double worst = 0.0;
  for (const TaggedPatch& p : c.patches) {
    if (p.role != TaggedPatch::Role::Basic) continue;
    const Handle(Geom_BSplineSurface) s = patchToOcct(p);
    for (int u = 0; u <= 8; ++u) {
      for (int v = 0; v <= 8; ++v) {
        const gp_Pnt q = s->Value(u / 8.0, v / 8.0);
        const double d = p.vPiece < c.rowsBasic ? std::hypot(localOf(f, q).x(), localOf(f, q).y()) - 1.0
                                                : localOf(top, q).norm() - 1.0;
        worst = std::max(worst, std::abs(d));
      }
    }
  }
  EXPECT_LT(worst, 1e-10);
  EXPECT_THROW(joinShapesC1(dome, post), InputError);  // the dome's end is its pole
  // One full turn and one partial one cannot share a strip.
  EXPECT_THROW(joinShapesC1(post, g1Cone(f, 1.0, 0.0, vec({0.0, 2.0, 4.0}), vec({2.0, 3.0}))), InputError);
}

TEST(C1Blend, PartialTurnsAreC1AndStayExact) {
  // Issue 15: Section 5 over part of a turn, the default ring clamped at the open ends.
  const ShapeFrame f = tilted();
  const Eigen::VectorXd around = vec({0.3, 1.0, 2.4, 3.1, 4.0});  // 3.7 radians, non-uniform
  const G1RevolvedShape cone = g1Cone(f, 1.5, 0.2, around, kHeights);
  const G1RevolvedShape zone = g1SphereZone(f, 1.0, around, kLatitudes);
  C1BlendOptions both;
  both.quarticInV = true;  // C1 along the sphere's profile too: one C1 surface
  for (const G1RevolvedShape* shape : {&cone, &zone}) {
    const BlendComplex c = blendC1(*shape, nullptr, both);
    EXPECT_FALSE(c.closedU);
    EXPECT_EQ(c.piecesU, 2 * 4);
    EXPECT_LT(c1Seams(c).worst(), 1e-8);
    EXPECT_TRUE(BRepCheck_Analyzer(blendShell(c).shell).IsValid());
    EXPECT_GE(singleSurface(c, 1e-9, 1)->Continuity(), GeomAbs_C1);
    // Without eta the same check fails: it can fail on an open turn too.
    C1BlendOptions naive;
    naive.withoutEta = true;
    EXPECT_GT(c1Seams(blendC1(*shape, nullptr, naive)).alongU, 1e-3);
  }
  EXPECT_LT(offShape(basicOf(blendC1(cone)), coneDistance(f, 1.5, 0.2)), 1e-10 * 4);
  EXPECT_LT(offShape(basicOf(blendC1(zone)), sphereDistance(f, 1.0)), 1e-10);
  // The ring's knots span the partial turn.
  const Eigen::VectorXd T = ringKnotsC1(around);
  EXPECT_EQ(T.size(), 5);
}

TEST(C1Join, DifferentPartitionsMeetInTJoints) {
  // Figs. 14, 15e: a post of 7 arcs into a dome of 4; each side keeps its own scalars, the
  // transversal 1-jets are split to the finest partition, and the complex is C1 throughout.
  const ShapeFrame f = tilted();
  ShapeFrame top = f;
  top.origin = f.origin + 2.5 * f.z;
  const G1RevolvedShape post = g1Cone(f, 1.0, 0.0, nonUniformTurn(), vec({0.0, 1.0, 1.8}));
  const G1RevolvedShape dome = g1SphereZone(top, 1.0, vec({0.0, 1.4, 3.3, 4.5, 2 * kPi}), vec({0.2, 0.9, 1.4}));
  const BlendComplex c = joinShapesC1(post, dome);
  EXPECT_GT(c.piecesU, 2 * 7);  // the post's 14 pieces and the dome's 8, merged
  EXPECT_LT(c1Seams(c).worst(), 1e-8);
  EXPECT_LT(offShape(basicOf(c),
                     [&](const gp_Pnt& q) {
                       const double onPost = std::hypot(localOf(f, q).x(), localOf(f, q).y()) - 1.0;
                       const double onDome = localOf(top, q).norm() - 1.0;
                       return std::min(std::abs(onPost), std::abs(onDome));
                     }),
            1e-10);
  EXPECT_TRUE(BRepCheck_Analyzer(blendShell(c).shell).IsValid());
  EXPECT_GE(singleSurface(c, 1e-9, 1)->Continuity(), GeomAbs_C1);
  // Judged on uniform knots instead of the merged ones, the complex fails the check.
  Eigen::VectorXd coarse = Eigen::VectorXd::LinSpaced(c.piecesU + 1, 0.0, c.piecesU);
  EXPECT_GT(c1Seams(c, &coarse).alongU, 1e-3);
}

TEST(C1Blend, RingOnOtherKnotsSharesTheParameterizationAndStaysExact) {
  // A biquadratic ring on its own uniform knots: its period mapped onto the circle's, the
  // quartic pieces split at its knots, the ring given theirs; the ring itself unchanged.
  const ShapeFrame f = tilted();
  const G1RevolvedShape zone = g1SphereZone(f, 1.0, nonUniformTurn(), kLatitudes);
  const Handle(Geom_BSplineSurface) ring = defaultRingC1(zone, Eigen::VectorXd::LinSpaced(8, 0.0, 7.0));
  C1BlendOptions options;
  options.quarticInV = true;
  const BlendComplex c = blendC1(zone, ring, options);
  EXPECT_GT(c.piecesU, 14);
  EXPECT_LT(c1Seams(c).worst(), 1e-8);
  EXPECT_LT(offShape(basicOf(c), sphereDistance(f, 1.0)), 1e-10);
  EXPECT_GE(singleSurface(c, 1e-9, 1)->Continuity(), GeomAbs_C1);
  const double u0 = ring->UKnot(1), P = ring->UKnot(ring->NbUKnots()) - u0, T = c.knotsU[c.piecesU];
  double worst = 0.0;
  for (const TaggedPatch& p : c.patches) {
    if (p.role != TaggedPatch::Role::FreeForm) continue;
    const Handle(Geom_BSplineSurface) s = patchToOcct(p);
    for (int a = 0; a <= 4; ++a) {
      const double x = a / 4.0, u = c.knotsU[p.uPiece] + x * (c.knotsU[p.uPiece + 1] - c.knotsU[p.uPiece]);
      worst = std::max(worst, s->Value(x, 0.5).Distance(ring->Value(u0 + u * P / T, 0.5)));
    }
  }
  EXPECT_LT(worst, 1e-12);
}

TEST(C1Blend, ReversedProfileJoinsADomeAtItsStart) {
  const ShapeFrame f = tilted();
  const G1RevolvedShape dome = g1SphereZone(f, 1.0, nonUniformTurn(), vec({0.3, 0.8, 1.2, kPi / 2}));
  EXPECT_THROW(blendC1(dome), InputError);  // its end is the pole
  C1BlendOptions options;
  options.quarticInV = true;
  const BlendComplex c = blendC1(reversedProfile(dome), nullptr, options);
  EXPECT_LT(c1Seams(c).worst(), 1e-8);
  EXPECT_LT(offShape(basicOf(c), sphereDistance(f, 1.0)), 1e-10);
  EXPECT_GE(singleSurface(c, 1e-9, 1)->Continuity(), GeomAbs_C1);
  // Reversing twice gives the shape back.
  const G1RevolvedShape twice = reversedProfile(reversedProfile(dome));
  for (int j = 0; j < dome.piecesV(); ++j) EXPECT_LT((twice.profile[j] - dome.profile[j]).norm(), 1e-15);
  EXPECT_LT((twice.profileBeta - dome.profileBeta).norm(), 1e-14);
}
