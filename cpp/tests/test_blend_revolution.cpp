// Surfaces of revolution of any rational cubic profile and affine images (issue 32), judged
// by OCCT evaluation: implicit equations at dense samples, the single surface's derivatives
// across its knots.
#include <gtest/gtest.h>

#include <Geom_BSplineSurface.hxx>
#include <algorithm>
#include <cmath>
#include <functional>

#include "fairsplines/blend_shapes.hpp"
#include "fairsplines/blend_surface.hpp"
#include "fairsplines/errors.hpp"
#include "blend_test_support.hpp"

using namespace fairsplines;
using namespace fairsplines::test::blend;

namespace {

/// The parabola z = r^2 / (4 f) from r0 to r1 in the plane of the frame's x and z, as one
/// quadratic Bézier (a B-spline of degree 2, weights 1) in space.
BSplineCurve parabola(const ShapeFrame& f, double focal, double r0, double r1) {
  BSplineCurve c;
  c.degree = 2;
  c.poles.resize(3, 3);
  const double rho[3] = {r0, (r0 + r1) / 2, r1},
               z[3] = {r0 * r0 / (4 * focal), r0 * r1 / (4 * focal), r1 * r1 / (4 * focal)};
  for (int k = 0; k < 3; ++k) c.poles.row(k) = (f.origin + rho[k] * f.x + z[k] * f.z).transpose();
  c.knots = vec({0.0, 1.0});
  c.mults = Eigen::VectorXi::Constant(2, 3);
  return c;
}

/// Largest relative jump of the first and second derivatives across the interior knots of
/// a B-spline surface, both directions: OCCT's local derivatives from the left (the span
/// before the knot) and from the right.
/// The index k of the knot span [knot(k), knot(k + 1)] holding t (OCCT numbering from 1).
int spanOf(double t, int count, const std::function<double(int)>& knot) {
  int k = 1;
  while (k + 1 < count && knot(k + 1) <= t) ++k;
  return std::min(k, count - 1);
}

double knotJump(const Handle(Geom_BSplineSurface)& s) {
  auto uKnot = [&](int k) { return s->UKnot(k); };
  auto vKnot = [&](int k) { return s->VKnot(k); };
  double u0, u1, v0, v1, scale = 0.0;
  s->Bounds(u0, u1, v0, v1);
  for (int a = 0; a <= 6; ++a) {
    for (int b = 0; b <= 6; ++b) {
      const double u = u0 + (u1 - u0) * a / 6, v = v0 + (v1 - v0) * b / 6;
      for (int du = 0; du <= 2; ++du) {
        for (int dv = 0; dv + du <= 2; ++dv) {
          if (du + dv > 0) scale = std::max(scale, s->DN(u, v, du, dv).Magnitude());
        }
      }
    }
  }
  double worst = 0.0;
  for (int k = 2; k < s->NbUKnots(); ++k) {
    for (int b = 0; b <= 4; ++b) {
      const double v = v0 + (v1 - v0) * b / 4;
      const int j = spanOf(v, s->NbVKnots(), vKnot);
      for (int d = 1; d <= 2; ++d) {
        const gp_Vec l = s->LocalDN(s->UKnot(k), v, k - 1, k, j, j + 1, d, 0);
        const gp_Vec r = s->LocalDN(s->UKnot(k), v, k, k + 1, j, j + 1, d, 0);
        worst = std::max(worst, (l - r).Magnitude() / scale);
      }
    }
  }
  for (int k = 2; k < s->NbVKnots(); ++k) {
    for (int a = 0; a <= 4; ++a) {
      const double u = u0 + (u1 - u0) * a / 4;
      const int i = spanOf(u, s->NbUKnots(), uKnot);
      for (int d = 1; d <= 2; ++d) {
        const gp_Vec l = s->LocalDN(u, s->VKnot(k), i, i + 1, k - 1, k, 0, d);
        const gp_Vec r = s->LocalDN(u, s->VKnot(k), i, i + 1, k, k + 1, 0, d);
        worst = std::max(worst, (l - r).Magnitude() / scale);
      }
    }
  }
  return worst;
}

}  // namespace

TEST(Revolution, ParabolaProfileGivesAParaboloidExactlyAndBlendsC2) {
  const ShapeFrame f = tilted();
  const double focal = 0.7;
  const RevolutionProfile p = revolutionProfile(parabola(f, focal, 0.5, 2.2), f.origin, f.z, vec({0.3, 0.55}));
  ASSERT_EQ(p.pieces(), 3);
  const G2Surface s = revolution(p, nonUniformTurn());
  double worst = 0.0;
  for (int I = 0; I < s.nu; ++I) {
    for (int J = 0; J < s.nv; ++J) {
      const Handle(Geom_BSplineSurface) patch = patchToOcct(s, I, J);
      for (int a = 0; a <= 12; ++a) {
        for (int b = 0; b <= 12; ++b) {
          const Eigen::Vector3d q = localOf(f, patch->Value(a / 12.0, b / 12.0));
          const double r2 = q.x() * q.x() + q.y() * q.y();
          worst = std::max(worst, std::abs(q.z() - r2 / (4 * focal)) / (std::abs(q.z()) + r2 / (4 * focal)));
        }
      }
    }
  }
  EXPECT_LT(worst, 1e-12);
  const BlendComplex c = blendShape(ShapeOfRevolution::of(p, nonUniformTurn()));
  const Handle(Geom_BSplineSurface) single = singleSurface(c);
  EXPECT_EQ(single->Continuity(), GeomAbs_C2);
  EXPECT_LT(knotJump(single), 1e-9);
}

TEST(Revolution, AG2JoinOfTheProfileIsMadeC2AndStaysExact) {
  // Two circle pieces of eq. (2) with different openings joined at a triple knot: G2, not
  // C2 in homogeneous space. Section 4.1 with a transition map for the right piece (Appendix
  // 7.2 generalised): the complex is C2 and the sphere exact.
  const ShapeFrame f;
  const G2CircleSpline circle = g2Circle(vec({-0.5, 0.1, 0.9}));
  BSplineCurve c;
  c.degree = 3;
  c.poles.resize(7, 3);
  c.weights.resize(7);
  for (int k = 0; k < 7; ++k) {
    const auto h = circle.cubic.row(k < 4 ? k : k + 1);
    c.poles.row(k) << 2 * h[0] / h[2], 0.0, 2 * h[1] / h[2];
    c.weights[k] = h[2];
  }
  c.knots = vec({0.0, 1.0, 2.5});  // unequal intervals: eq. (11) needs beta = 1.5
  c.mults = Eigen::Vector3i(4, 3, 4);
  const RevolutionProfile p = revolutionProfile(c, f.origin, f.z);
  const BlendComplex complex = blendShape(ShapeOfRevolution::of(p, nonUniformTurn()));
  EXPECT_LT(knotJump(singleSurface(complex)), 1e-9);
  // The generalised transition map of Section 4.1 keeps both circle pieces exact.
  double worst = 0.0;
  for (const TaggedPatch& patch : complex.patches) {
    if (patch.role != TaggedPatch::Role::Basic) continue;
    const Handle(Geom_BSplineSurface) s = patchToOcct(patch);
    for (int a = 0; a <= 8; ++a) {
      for (int b = 0; b <= 8; ++b) {
        const gp_Pnt q = s->Value(a / 8.0, b / 8.0);
        worst = std::max(worst, std::abs(std::sqrt(q.X() * q.X() + q.Y() * q.Y() + q.Z() * q.Z()) - 2) / 2);
      }
    }
  }
  EXPECT_LT(worst, 1e-12);
}

TEST(Revolution, AffineImageOfASphereZoneIsAnEllipsoidZone) {
  const ShapeFrame f;
  const G2Surface sphere = sphereZone(f, 1.0, nonUniformTurn(), vec({-0.6, 0.1, 0.8}));
  const Eigen::Vector3d radii(3.0, 2.0, 1.25), t(1.0, -2.0, 0.5);
  G2Surface e = sphere;
  e.bezier = affineImage(sphere.bezier, radii.asDiagonal(), t);
  double worst = 0.0;
  for (int I = 0; I < e.nu; ++I) {
    for (int J = 0; J < e.nv; ++J) {
      const Handle(Geom_BSplineSurface) patch = patchToOcct(e, I, J);
      for (int a = 0; a <= 12; ++a) {
        for (int b = 0; b <= 12; ++b) {
          const gp_Pnt q = patch->Value(a / 12.0, b / 12.0);
          const Eigen::Vector3d d = (Eigen::Vector3d(q.X(), q.Y(), q.Z()) - t).cwiseQuotient(radii);
          worst = std::max(worst, std::abs(d.squaredNorm() - 1));
        }
      }
    }
  }
  EXPECT_LT(worst, 1e-12);
  EXPECT_THROW(affineImage(sphere.bezier, Eigen::Vector3d(1, 0, 1).asDiagonal(), t), InputError);
}

TEST(Revolution, BadProfilesAreNamed) {
  const ShapeFrame f;
  BSplineCurve across = parabola(f, 1.0, 0.5, 2.0);
  across.poles(1, 0) = -3.0;  // the middle pole far across the axis: the curve crosses it
  EXPECT_THROW(revolutionProfile(across, f.origin, f.z), InputError);
  BSplineCurve twisted = parabola(f, 1.0, 0.5, 2.0);
  twisted.poles(1, 1) = 0.3;  // off the plane through the axis
  try {
    revolutionProfile(twisted, f.origin, f.z);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("not in a plane through the axis"), std::string::npos) << e.what();
  }
  EXPECT_THROW(revolutionProfile(parabola(f, 1.0, 0.5, 2.0), f.origin, Eigen::Vector3d::Zero()), InputError);
  EXPECT_THROW(revolutionProfile(parabola(f, 1.0, 0.5, 2.0), f.origin, f.z, vec({1.5})), InputError);
}
