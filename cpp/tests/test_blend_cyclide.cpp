// Dupin ring cyclides (issue 32, the paper's "generalized tori"), judged by OCCT evaluation:
// the implicit quartic at dense samples, the single surface of the blend C2.
#include <gtest/gtest.h>

#include <Geom_BSplineSurface.hxx>
#include <algorithm>
#include <cmath>

#include "fairsplines/blend_shapes.hpp"
#include "fairsplines/blend_surface.hpp"
#include "fairsplines/errors.hpp"
#include "blend_test_support.hpp"

using namespace fairsplines;
using namespace fairsplines::test::blend;

namespace {

/// Relative defect of (x^2 + y^2 + z^2 - mu^2 + b^2)^2 = 4 (a x - c mu)^2 + 4 b^2 y^2.
double quartic(const ShapeFrame& f, const gp_Pnt& p, double a, double c, double mu) {
  const Eigen::Vector3d q = localOf(f, p);
  const double b2 = a * a - c * c, lhs = std::pow(q.squaredNorm() - mu * mu + b2, 2);
  const double rhs = 4 * std::pow(a * q.x() - c * mu, 2) + 4 * b2 * q.y() * q.y();
  return std::abs(lhs - rhs) / (lhs + rhs);
}

}  // namespace

TEST(Cyclide, PatchesLieOnTheQuarticAndTheBlendKeepsThem) {
  const ShapeFrame f = tilted();
  const double a = 3.0, c = 1.0, mu = 2.0;
  const Eigen::VectorXd v = vec({-1.2, -0.4, 0.5, 1.1});
  const G2Surface s = dupinCyclide(f, a, c, mu, nonUniformTurn(), v);
  double worst = 0.0;
  for (int I = 0; I < s.nu; ++I) {
    for (int J = 0; J < s.nv; ++J) {
      const Handle(Geom_BSplineSurface) patch = patchToOcct(s, I, J);
      for (int i = 0; i <= 12; ++i) {
        for (int j = 0; j <= 12; ++j) worst = std::max(worst, quartic(f, patch->Value(i / 12.0, j / 12.0), a, c, mu));
      }
    }
  }
  EXPECT_LT(worst, 1e-12);
  const BlendComplex complex = blendCyclide(f, a, c, mu, nonUniformTurn(), v);
  double basic = 0.0;
  for (const TaggedPatch& p : complex.patches) {
    if (p.role != TaggedPatch::Role::Basic) continue;
    const Handle(Geom_BSplineSurface) patch = patchToOcct(p);
    for (int i = 0; i <= 8; ++i) {
      for (int j = 0; j <= 8; ++j) basic = std::max(basic, quartic(f, patch->Value(i / 8.0, j / 8.0), a, c, mu));
    }
  }
  EXPECT_LT(basic, 1e-12);
  EXPECT_EQ(singleSurface(complex)->Continuity(), GeomAbs_C2);
}

TEST(Cyclide, ParametersWithoutARingCyclideAreNamed) {
  const ShapeFrame f;
  const Eigen::VectorXd v = vec({-1.0, 0.0, 1.0});
  EXPECT_THROW(dupinCyclide(f, 1.0, 2.0, 1.5, nonUniformTurn(), v), InputError);  // a < c: no real surface
  EXPECT_THROW(dupinCyclide(f, 3.0, 1.0, 0.5, nonUniformTurn(), v), InputError);  // mu < c: spindle
  EXPECT_THROW(dupinCyclide(f, 3.0, 1.0, 3.5, nonUniformTurn(), v), InputError);  // mu > a: horn
  EXPECT_THROW(dupinCyclide(f, NAN, 1.0, 2.0, nonUniformTurn(), v), InputError);
}
