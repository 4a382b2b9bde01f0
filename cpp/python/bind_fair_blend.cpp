// Bindings for fair blends (fair_blend.hpp): two end conditions to a certified
// monotone-curvature cubic.
#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <limits>

#include "fairsplines/fair_blend.hpp"
#include "bindings.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace fairsplines::python {

void bindFairBlend(py::module_& m) {
  m.def(
      "fair_blend",
      [](const Eigen::Vector3d& p0, const Eigen::Vector3d& t0, const Eigen::Vector3d& p1, const Eigen::Vector3d& t1,
         double k0, double k1, const Eigen::Vector3d& normal) {
        const FairBlend b = fairBlend(BlendEnds{p0, t0, p1, t1, k0, k1, normal});
        return py::dict("curve"_a = b.curve, "certificate"_a = certificateDict(b.certificate),
                        "monotone"_a = b.monotone, "normal"_a = b.normal, "kappa0"_a = b.kappa0, "kappa1"_a = b.kappa1,
                        "turning"_a = b.turning, "length"_a = b.length, "variation"_a = b.variation,
                        "spans"_a = b.spans, "reason"_a = b.reason);
      },
      "p0"_a, "t0"_a, "p1"_a, "t1"_a, "k0"_a = std::numeric_limits<double>::quiet_NaN(),
      "k1"_a = std::numeric_limits<double>::quiet_NaN(), "normal"_a = Eigen::Vector3d::Zero(),
      "fairBlend: the certified monotone-curvature cubic between two ends (NaN curvature: G1 there; zero normal: "
      "derived).");

  m.def(
      "fair_blend_space",
      [](const Eigen::Vector3d& p0, const Eigen::Vector3d& t0, const Eigen::Vector3d& p1, const Eigen::Vector3d& t1,
         const Eigen::Vector3d& K0, const Eigen::Vector3d& K1) {
        const SpaceFairBlend b = fairBlendSpace(SpaceBlendEnds{p0, t0, p1, t1, K0, K1});
        return py::dict("curve"_a = b.curve, "certificate"_a = spaceCertificateDict(b.certificate),
                        "monotone"_a = b.monotone, "planar"_a = b.planar, "normal"_a = b.normal,
                        "curvature_extrema"_a = b.curvatureExtrema, "torsion_sign_changes"_a = b.torsionSignChanges,
                        "length"_a = b.length, "variation"_a = b.variation, "spans"_a = b.spans, "reason"_a = b.reason);
      },
      "p0"_a, "t0"_a, "p1"_a, "t1"_a, "K0"_a = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN()),
      "K1"_a = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN()),
      "fairBlendSpace: the fair blend of two ends in space (K0, K1: end curvature vectors kappa N for G2; NaN: "
      "G1); coplanar ends get fairBlend's planar result.");
}

}  // namespace fairsplines::python
