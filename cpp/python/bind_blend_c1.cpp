// Bindings for Section 5 of the blending paper: basic shapes as G1 rational biquadratic
// splines joined to biquadratic C1 NURBS by a (4,2) double strip (blend_c1.hpp). The
// BlendComplex class itself is registered by bind_blend.cpp (call bindBlend first).
#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <optional>

#include "bindings.hpp"
#include "fairsplines/blend_c1.hpp"
#include "fairsplines/surfaces.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace fairsplines::python {

namespace {

ShapeFrame c1FrameOf(const Eigen::Vector3d& origin, const Eigen::Vector3d& x, const Eigen::Vector3d& y) {
  ShapeFrame f;
  f.origin = origin;
  f.x = x;
  f.y = y;
  f.z = x.cross(y);
  f.check();
  return f;
}

BlendComplex c1Blend(const G1RevolvedShape& shape, const std::optional<BSplineSurface>& ring,
                     const Eigen::VectorXd& betaT, bool quarticInV) {
  C1BlendOptions options;
  options.betaT = betaT;
  options.quarticInV = quarticInV;
  return blendC1(shape, ring ? toOcct(*ring) : Handle(Geom_BSplineSurface)(), options);
}

}  // namespace

void bindBlendC1(py::module_& m) {
  m.def(
      "blend_sphere_zone_c1",
      [](const Eigen::Vector3d& o, const Eigen::Vector3d& x, const Eigen::Vector3d& y, double radius,
         const Eigen::VectorXd& longitudes, const Eigen::VectorXd& latitudes, const std::optional<BSplineSurface>& ring,
         const Eigen::VectorXd& betaT, bool quarticInV) {
        return c1Blend(g1SphereZone(c1FrameOf(o, x, y), radius, longitudes, latitudes), ring, betaT, quarticInV);
      },
      "origin"_a, "x"_a, "y"_a, "radius"_a, "longitudes"_a, "latitudes"_a, "ring"_a = py::none(),
      "beta_t"_a = Eigen::VectorXd(), "quartic_in_v"_a = true,
      "Section 5: the G1 biquadratic sphere zone joined at its top latitude to a biquadratic C1 ring "
      "by a (4,2) double strip (a C1 complex; BlendComplex.smoothness is 1).");
  m.def(
      "blend_cone_c1",
      [](const Eigen::Vector3d& o, const Eigen::Vector3d& x, const Eigen::Vector3d& y, double radius0, double slope,
         const Eigen::VectorXd& angles, const Eigen::VectorXd& heights, const std::optional<BSplineSurface>& ring,
         const Eigen::VectorXd& betaT) {
        return c1Blend(g1Cone(c1FrameOf(o, x, y), radius0, slope, angles, heights), ring, betaT, false);
      },
      "origin"_a, "x"_a, "y"_a, "radius0"_a, "slope"_a, "angles"_a, "heights"_a, "ring"_a = py::none(),
      "beta_t"_a = Eigen::VectorXd(), "Section 5 for a cone (a cylinder with slope 0), joined at its top height.");
  m.def(
      "blend_torus_c1",
      [](const Eigen::Vector3d& o, const Eigen::Vector3d& x, const Eigen::Vector3d& y, double R, double r,
         const Eigen::VectorXd& anglesU, const Eigen::VectorXd& anglesV, const std::optional<BSplineSurface>& ring,
         const Eigen::VectorXd& betaT, bool quarticInV) {
        return c1Blend(g1Torus(c1FrameOf(o, x, y), R, r, anglesU, anglesV), ring, betaT, quarticInV);
      },
      "origin"_a, "x"_a, "y"_a, "major_radius"_a, "minor_radius"_a, "angles_u"_a, "angles_v"_a,
      "ring"_a = py::none(), "beta_t"_a = Eigen::VectorXd(), "quartic_in_v"_a = true,
      "Section 5 for a torus zone, joined at its last tube angle.");
  m.def("ring_knots_c1", &ringKnotsC1, "angles"_a, "beta_t"_a = Eigen::VectorXd(),
        "The u knots (one period) a biquadratic free-form ring must have to join a shape with continuity C1.");
}

}  // namespace fairsplines::python
