// Bindings for Section 5 of the blending paper: basic shapes as G1 rational biquadratic
// splines joined to biquadratic C1 NURBS by a (4,2) double strip (blend_c1.hpp). The
// BlendComplex class itself is registered by bind_blend.cpp (call bindBlend first).
#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>

#include <Geom_BSplineSurface.hxx>

#include "fairsplines/blend_c1.hpp"
#include "fairsplines/errors.hpp"
#include "fairsplines/surfaces.hpp"
#include "bindings.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace fairsplines::python {

void bindBlendC1(py::module_& m) {
  m.def(
      "join_shapes_c1",
      [](const ShapeOfRevolution& a, const ShapeOfRevolution& b, bool quarticInV) {
        return joinShapesC1(g1Shape(a), g1Shape(b), quarticInV);
      },
      "a"_a, "b"_a, "quartic_in_v"_a = true,
      "Section 5 shape to shape: the end of a's profile joined C1 to the start of b's by a (4,2) double strip.");
  m.def(
      "blend_c1",
      [](const ShapeOfRevolution& shape, const std::optional<BSplineSurface>& ring, const Eigen::VectorXd& betaT,
         bool quarticInV, bool naive, const std::string& at) {
        C1BlendOptions options;
        options.betaT = betaT;
        options.quarticInV = quarticInV;
        options.withoutEta = naive;
        if (at != "end" && at != "start") throw InputError("the interface must be at the profile's 'end' or 'start'");
        const G1RevolvedShape g1 = at == "end" ? g1Shape(shape) : reversedProfile(g1Shape(shape));
        return blendC1(g1, ring ? toOcct(*ring) : Handle(Geom_BSplineSurface)(), options);
      },
      "shape"_a, "ring"_a = py::none(), "beta_t"_a = Eigen::VectorXd(), "quartic_in_v"_a = true, "naive"_a = false,
      "at"_a = "end",
      "Section 5: the shape as a G1 biquadratic spline joined at the end of its profile to a biquadratic C1 ring by "
      "a (4,2) double strip (a C1 complex; smoothness 1). naive: without eta (the arcs only split and raised).");
  m.def("ring_knots_c1", &ringKnotsC1, "angles"_a, "beta_t"_a = Eigen::VectorXd(),
        "The u knots (one period) a biquadratic free-form ring must have to join a shape with continuity C1.");
}

}  // namespace fairsplines::python
