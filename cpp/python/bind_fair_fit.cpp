// Bindings for the fair fit (fair_fit.hpp): samples and a tolerance to a cubic C2 spline.
#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>

#include "fairsplines/fair_fit.hpp"
#include "bindings.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace fairsplines::python {

void bindFairFit(py::module_& m) {
  m.def(
      "fair_fit",
      [](PointsRef q, double tolerance, bool closed, std::optional<double> noise,
         std::optional<Eigen::VectorXd> startTangent, std::optional<Eigen::VectorXd> endTangent,
         std::optional<Eigen::VectorXd> startCurvature, std::optional<Eigen::VectorXd> endCurvature,
         const std::string& corners) {
        using Corners = FairFitOptions::Corners;
        FairFitOptions o{tolerance, closed, noise, startTangent, endTangent, startCurvature, endCurvature};
        o.corners = corners == "keep" ? Corners::Keep : corners == "smooth" ? Corners::Smooth : Corners::Refuse;
        const FairFitResult r = fairFitReport(q, o);
        return py::dict("curve"_a = r.curve, "max_deviation"_a = r.maxDeviation, "sign_changes"_a = r.signChanges,
                        "data_sign_changes"_a = r.dataSignChanges, "curvature_extrema"_a = r.curvatureExtrema,
                        "noise"_a = r.noise, "iterations"_a = r.iterations, "merged_points"_a = r.mergedPoints,
                        "closed"_a = r.closed, "recognised_closed"_a = r.recognisedClosed, "corners"_a = r.corners,
                        "pinned"_a = r.pinned, "pieces"_a = r.pieces);
      },
      "points"_a, "tolerance"_a, "closed"_a = false, "noise"_a = py::none(), "start_tangent"_a = py::none(),
      "end_tangent"_a = py::none(), "start_curvature"_a = py::none(), "end_curvature"_a = py::none(),
      "corners"_a = "refuse",
      "fairFitReport: the csr-spline (eq. (6)) of an adaptive subset of noise-smoothed samples, within tolerance of "
      "every sample; a dict with the curve and its report.");
}

}  // namespace fairsplines::python
