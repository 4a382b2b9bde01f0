// Basic shapes as G2 rational bi-cubic splines (blending paper, Section 2, eqs. (1)-(4)),
// judged by OCCT evaluation of the patches.
#include <gtest/gtest.h>

#include <Geom_BSplineSurface.hxx>
#include <cmath>
#include <functional>

#include "fairsplines/blend_shapes.hpp"
#include "fairsplines/errors.hpp"
#include "blend_test_support.hpp"

using namespace fairsplines;
using namespace fairsplines::test::blend;

namespace {

/// Point in the frame's coordinates.
Eigen::Vector3d local(const ShapeFrame& f, const gp_Pnt& p) {
  const Eigen::Vector3d d = Eigen::Vector3d(p.X(), p.Y(), p.Z()) - f.origin;
  return {d.dot(f.x), d.dot(f.y), d.dot(f.z)};
}

/// Largest |distance(p)| over 21 x 21 OCCT samples of every patch.
double worstDistance(const G2Surface& s, const std::function<double(const gp_Pnt&)>& distance) {
  double worst = 0.0;
  for (int I = 0; I < s.nu; ++I) {
    for (int J = 0; J < s.nv; ++J) {
      const Handle(Geom_BSplineSurface) patch = patchToOcct(s, I, J);
      for (int a = 0; a <= 20; ++a) {
        for (int b = 0; b <= 20; ++b) worst = std::max(worst, std::abs(distance(patch->Value(a / 20.0, b / 20.0))));
      }
    }
  }
  return worst;
}

double rel(const gp_Vec& a, const gp_Vec& b, double scale) { return (a - b).Magnitude() / scale; }

/// Largest relative defect of eqs. (3)-(4) across every seam, by OCCT D2 on both sides:
/// across the seam f'_R = beta f'_L, f''_R = beta^2 f''_L + gamma f'_L; along it the
/// position, first and second derivatives agree, and the mixed derivative scales by beta.
double worstSeamDefect(const G2Surface& s) {
  double worst = 0.0;
  auto check = [&](const Handle(Geom_BSplineSurface)& left, const Handle(Geom_BSplineSurface)& right, bool inU,
                   double beta, double gamma) {
    for (int k = 0; k <= 10; ++k) {
      const double t = k / 10.0;
      gp_Pnt pl, pr;
      gp_Vec lu, lv, luu, lvv, luv, ru, rv, ruu, rvv, ruv;
      if (inU) {
        left->D2(1.0, t, pl, lu, lv, luu, lvv, luv);
        right->D2(0.0, t, pr, ru, rv, ruu, rvv, ruv);
      } else {  // swap the roles of u and v
        left->D2(t, 1.0, pl, lv, lu, lvv, luu, luv);
        right->D2(t, 0.0, pr, rv, ru, rvv, ruu, ruv);
      }
      // One scale for the sample: at a pole the derivatives across vanish, those along do not.
      const double scale = std::max({lu.Magnitude(), luu.Magnitude(), lv.Magnitude(), lvv.Magnitude(), 1e-300});
      worst = std::max(worst, pl.Distance(pr) / scale);
      worst = std::max(worst, rel(ru, beta * lu, scale));
      worst = std::max(worst, rel(ruu, beta * beta * luu + gamma * lu, scale));
      worst = std::max(worst, rel(rv, lv, scale));
      worst = std::max(worst, rel(rvv, lvv, scale));
      worst = std::max(worst, rel(ruv, beta * luv, scale));
    }
  };
  for (int I = 0; I < s.nu; ++I) {
    for (int J = 0; J < s.nv; ++J) {
      if (I > 0 || s.closedU)
        check(patchToOcct(s, (I + s.nu - 1) % s.nu, J), patchToOcct(s, I, J), true, s.betaU[I], s.gammaU[I]);
      if (J > 0 || s.closedV)
        check(patchToOcct(s, I, (J + s.nv - 1) % s.nv), patchToOcct(s, I, J), false, s.betaV[J], s.gammaV[J]);
    }
  }
  return worst;
}

}  // namespace

TEST(G2Circle, Eq2PiecesLieOnTheCircleAndJoinG2WithTheScalarsOfEqs3And4) {
  const G2CircleSpline c = g2Circle(nonUniformTurn());
  ASSERT_TRUE(c.closed);
  ASSERT_EQ(c.pieces(), 7);
  for (int i = 0; i < c.pieces(); ++i) {
    EXPECT_NEAR(c.cubic(4 * i + 1, 2), 1.0 / 3 + 2.0 / 3 * std::cos(c.alpha[i] / 2), 1e-15);  // eq. (2)
  }
  // The circle as a cylinder of height 1: its bottom edge is the curve; the seam check
  // covers the closing join too.
  const G2Surface s = cylinder(ShapeFrame{}, 1.0, nonUniformTurn(), vec({0.0, 1.0}));
  EXPECT_LT(worstDistance(s, [](const gp_Pnt& p) { return std::hypot(p.X(), p.Y()) - 1.0; }), 1e-14);
  EXPECT_LT(worstSeamDefect(s), 1e-12);
}

TEST(BasicShapes, SphereZonePatchesLieOnTheSphereAndJoinG2) {
  const ShapeFrame f = tilted();
  const double R = 2.5;
  const G2Surface s = sphereZone(f, R, nonUniformTurn(), vec({-1.2, -0.5, 0.1, 0.35, 1.0}));
  EXPECT_EQ(s.nu, 7);
  EXPECT_EQ(s.nv, 4);
  EXPECT_LT(worstDistance(s, [&](const gp_Pnt& p) { return local(f, p).norm() - R; }), 1e-10 * R);
  EXPECT_LT(worstSeamDefect(s), 1e-10);
}

TEST(BasicShapes, SphereDomeWithPoleLiesOnTheSphereAndJoinsG2) {
  const ShapeFrame f = tilted();
  const G2Surface s = sphereZone(f, 1.0, vec({0.0, 0.9, 2.0, 3.0, 4.6, 2 * kPi}), vec({0.3, 0.9, kPi / 2}));
  EXPECT_LT(worstDistance(s, [&](const gp_Pnt& p) { return local(f, p).norm() - 1.0; }), 1e-10);
  EXPECT_LT(worstSeamDefect(s), 1e-10);
}

TEST(BasicShapes, CylinderAndConeLieOnTheirSurfacesAndJoinG2) {
  const ShapeFrame f = tilted();
  const G2Surface cyl = cylinder(f, 3.0, vec({0.2, 1.0, 1.3, 2.9}), vec({-1.0, 0.5, 0.7, 4.0}));
  EXPECT_LT(worstDistance(cyl,
                          [&](const gp_Pnt& p) {
                            const auto q = local(f, p);
                            return std::hypot(q.x(), q.y()) - 3.0;
                          }),
            1e-10 * 3.0);
  EXPECT_LT(worstSeamDefect(cyl), 1e-10);
  const G2Surface con = cone(f, 2.0, -0.3, nonUniformTurn(), vec({-1.0, 0.5, 0.7, 4.0}));
  EXPECT_LT(worstDistance(con,
                          [&](const gp_Pnt& p) {
                            const auto q = local(f, p);
                            return (std::hypot(q.x(), q.y()) - (2.0 - 0.3 * q.z())) / std::sqrt(1 + 0.09);
                          }),
            1e-10 * 4.0);
  EXPECT_LT(worstSeamDefect(con), 1e-10);
}

TEST(BasicShapes, TorusPatchesLieOnTheTorusAndJoinG2BothWaysRound) {
  const ShapeFrame f = tilted();
  const G2Surface s = torus(f, 3.0, 1.0, nonUniformTurn(), vec({0.0, 0.7, 2.0, 2.5, 4.0, 2 * kPi}));
  EXPECT_TRUE(s.closedU);
  EXPECT_TRUE(s.closedV);
  EXPECT_LT(worstDistance(s,
                          [&](const gp_Pnt& p) {
                            const auto q = local(f, p);
                            return std::hypot(std::hypot(q.x(), q.y()) - 3.0, q.z()) - 1.0;
                          }),
            1e-10 * 4.0);
  EXPECT_LT(worstSeamDefect(s), 1e-10);
}

TEST(BasicShapes, EditedControlStructureShowsInTheOcctPatch) {
  G2Surface s = cylinder(ShapeFrame{}, 1.0, vec({0.0, 1.0, 2.0}), vec({0.0, 1.0}));
  s.setControl(1, 0, 1, 1, Eigen::Vector3d(2.0, 2.0, 0.5), 0.7);
  const Handle(Geom_BSplineSurface) patch = patchToOcct(s, 1, 0);
  EXPECT_NEAR(patch->Weight(2, 2), 0.7, 1e-15);
  EXPECT_NEAR(patch->Pole(2, 2).X(), 2.0, 1e-15);
  EXPECT_THROW(s.setControl(1, 0, 1, 1, Eigen::Vector3d(2.0, 2.0, 0.5), 0.0), InputError);
  EXPECT_THROW(s.setControl(2, 0, 1, 1, Eigen::Vector3d::Zero(), 1.0), InputError);
}

TEST(BasicShapes, BadPartitionsRaiseInputErrorWithTheReason) {
  auto message = [](const std::function<void()>& f) {
    try {
      f();
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message([] {
              g2Circle(vec({0.0, 1.0, 1.0, 2.0}));
            }).find("angles must increase: angle 2"),
            std::string::npos);
  EXPECT_NE(message([] { g2Circle(vec({0.0, 2.0, 1.5})); }).find("angles must increase"), std::string::npos);
  // An arc of 4 pi / 3 leaves w = 1/3 + 2/3 cos(alpha/2) = 0.
  EXPECT_NE(message([] { g2Circle(vec({0.0, 4 * kPi / 3, 2 * kPi})); }).find("positive weight"), std::string::npos);
  EXPECT_NE(message([] { g2Circle(vec({0.0, 4.3, 6.0})); }).find("positive weight"), std::string::npos);
  EXPECT_NE(message([] { g2Circle(vec({0.0, 3.0, 6.0, 7.0})); }).find("full turn"), std::string::npos);
  EXPECT_NE(message([] {
              sphereZone(ShapeFrame{}, 1.0, nonUniformTurn(), vec({0.0, 2.0}));
            }).find("latitudes"),
            std::string::npos);
  EXPECT_NE(message([] {
              cone(ShapeFrame{}, 1.0, -1.0, nonUniformTurn(), vec({0.0, 2.0}));
            }).find("not positive"),
            std::string::npos);
  EXPECT_NE(message([] { torus(ShapeFrame{}, 1.0, 2.0, nonUniformTurn(), nonUniformTurn()); }).find("0 < r < R"),
            std::string::npos);
  EXPECT_NE(message([] {
              cylinder(ShapeFrame{}, 1.0, nonUniformTurn(), vec({0.0, 0.0}));
            }).find("heights must increase"),
            std::string::npos);
}

TEST(BasicShapes, SeamCheckFailsWithoutTheGammaOfEq4) {
  // The referee can fail: with C2 scalars (beta as given, gamma = 0) a non-uniform sphere
  // zone does not pass.
  G2Surface s = sphereZone(tilted(), 1.0, nonUniformTurn(), vec({-0.5, 0.2, 0.9}));
  s.gammaU.setZero();
  EXPECT_GT(worstSeamDefect(s), 1e-3);
}

TEST(G2Circle, HomogeneousPiecesAreNotEvenG1OnlyTheirProjectionIsG2) {
  // Reading (docs/BLENDING.md): beta, gamma of eqs. (3)-(4) hold for the projected pieces.
  // In homogeneous space the weight function of eq. (2) has a corner at every joint:
  // derivative 3 (1 - w) > 0 arriving, 3 (w - 1) < 0 leaving, so no beta > 0 relates them.
  const G2CircleSpline c = g2Circle(Eigen::VectorXd::LinSpaced(7, 0.0, 2 * kPi));  // uniform
  for (int i = 1; i < c.pieces(); ++i) {
    const double arriving = 3 * (c.cubic(4 * i - 1, 2) - c.cubic(4 * i - 2, 2));
    const double leaving = 3 * (c.cubic(4 * i + 1, 2) - c.cubic(4 * i, 2));
    EXPECT_GT(arriving, 0.1);
    EXPECT_LT(leaving, -0.1);
    EXPECT_GT(c.gamma[i], 0.1);  // and gamma != 0 even for a uniform partition
  }
}
