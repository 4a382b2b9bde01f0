// Bindings for curves: the csr-spline, the baselines, the G2 form and curve analysis.
#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <TopoDS_Edge.hxx>
#include <cstdint>

#include "fairsplines/analysis.hpp"
#include "fairsplines/baselines.hpp"
#include "fairsplines/bspline.hpp"
#include "fairsplines/csr.hpp"
#include "fairsplines/occt.hpp"
#include "bindings.hpp"
#include "shape_capsule.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace fairsplines::python {

void bindCurves(py::module_& m) {
  py::class_<BSplineCurve>(m, "BSplineCurve",
                           "A B-spline curve in OpenCASCADE's layout (distinct knots + multiplicities).")
      .def(py::init([](PointMatrix poles, Eigen::VectorXd knots, Eigen::VectorXi mults, int degree, bool periodic,
                       Eigen::VectorXd weights) {
             return BSplineCurve{degree,           std::move(poles), std::move(weights),
                                 std::move(knots), std::move(mults), periodic};
           }),
           "poles"_a, "knots"_a, "mults"_a, "degree"_a, "periodic"_a = false, "weights"_a = Eigen::VectorXd())
      .def_readwrite("degree", &BSplineCurve::degree)
      .def_readwrite("poles", &BSplineCurve::poles)
      .def_readwrite("weights", &BSplineCurve::weights)
      .def_readwrite("knots", &BSplineCurve::knots)
      .def_readwrite("mults", &BSplineCurve::mults)
      .def_readwrite("periodic", &BSplineCurve::periodic)
      .def_property_readonly("rational", &BSplineCurve::isRational);

  py::enum_<EpsilonRule>(m, "EpsilonRule")
      .value("CaseDistinction", EpsilonRule::CaseDistinction)
      .value("Additive", EpsilonRule::Additive);

  m.def(
      "csr_spline",
      [](PointsRef q, bool closed, const std::string& parametrization, double epsilon, EpsilonRule rule,
         const Eigen::VectorXd& t) {
        return csrSpline(q, CsrOptions{parseParametrization(parametrization), closed, epsilon, rule, t});
      },
      "points"_a, "closed"_a = false, "parametrization"_a = "chordal", "epsilon"_a = 1e-9,
      "rule"_a = EpsilonRule::CaseDistinction, "parameters"_a = Eigen::VectorXd(), "csr-spline, Section 4, eq. (6).");
  m.def(
      "quadratic_design",
      [](PointsRef q, bool closed, const std::string& parametrization, double epsilon) {
        return quadraticDesign(q, parseParametrization(parametrization), closed, epsilon);
      },
      "points"_a, "closed"_a = false, "parametrization"_a = "chordal", "epsilon"_a = 1e-9,
      "Quadratic design, Section 7, eq. (12).");
  m.def(
      "quasi_interpolant",
      [](PointsRef q, bool closed, const std::string& parametrization) {
        return quasiInterpolant(q, parseParametrization(parametrization), closed);
      },
      "points"_a, "closed"_a = false, "parametrization"_a = "chordal",
      "The cubic quasi-interpolant baseline: c_i := p_i, the blossom of f_i at (t_{i-1}, t_i, t_{i+1}); same knots "
      "and ends as the csr-spline.");
  m.def("control_point_spline", &controlPointSpline, "points"_a, "closed"_a = false,
        "The 'data as control points' baseline: a cubic B-spline with uniform knots and the samples as its poles.");
  m.def(
      "classic_interpolation",
      [](PointsRef q, bool closed, const std::string& parametrization) {
        return fromOcct(classicInterpolation(q, parseParametrization(parametrization), closed));
      },
      "points"_a, "closed"_a = false, "parametrization"_a = "chordal",
      "Classic C2 cubic interpolation by OCCT's GeomAPI_Interpolate.");

  m.def(
      "parameters",
      [](PointsRef q, const std::string& kind, bool closed) {
        validateSamples(q, closed, 2, "parametrization");
        return parameters(q, parseParametrization(kind), closed);
      },
      "points"_a, "parametrization"_a = "chordal", "closed"_a = false,
      "The samples' parameters: t_0 = 0, t_{i+1} - t_i = |q_{i+1} - q_i|^a (a = 1 chordal, 1/2 centripetal, 0 uniform).");
  m.def("beta_from_knots", &betaFromKnots, "knots"_a,
        "Eq. (1): beta_i = h_i / h_{i-1} for every knot with both neighbours.");
  m.def(
      "g2_from_de_boor",
      [](const PointMatrix& c, const Eigen::VectorXd& beta) {
        G2Spline g2 = g2FromDeBoor(c, beta);
        return py::make_tuple(g2.bezier, g2.beta);
      },
      "control_points"_a, "beta"_a, "Eq. (2): Bezier pieces (4 rows each) and their betas.");
  m.def(
      "de_boor_from_g2",
      [](const PointMatrix& bezier, const Eigen::VectorXd& beta) {
        return deBoorFromG2(G2Spline{bezier, beta});
      },
      "bezier"_a, "beta"_a, "Eq. (3): de Boor points of a G2 spline.");

  m.def(
      "curvature_profile",
      [](const BSplineCurve& curve, int n, int minPerSpan) {
        const CurvatureProfile p = curvatureProfile(toOcct(curve), n, minPerSpan);
        return py::make_tuple(p.u, p.s, p.kappa, p.isSigned, Eigen::Vector3d(p.normal.X(), p.normal.Y(), p.normal.Z()));
      },
      "curve"_a, "n"_a = 512, "min_per_span"_a = 8, "(u, s, kappa, signed, plane normal)");
  m.def(
      "curvature_sign_changes",
      [](const BSplineCurve& curve, int minPerSpan, double zeroTol) {
        const Handle(Geom_BSplineCurve) c = toOcct(curve);
        return curvatureSignChanges(curvatureProfile(c, 0, minPerSpan), zeroTol);
      },
      "curve"_a, "min_per_span"_a = 32, "zero_tol"_a = 1e-6,
      "Sign changes of the signed curvature along the curve (0 for a non-planar curve).");
  m.def(
      "curvature_extrema",
      [](const BSplineCurve& curve, int n, int minPerSpan) {
        py::list out;
        for (const CurvatureExtremum& e : curvatureExtrema(curvatureProfile(toOcct(curve), n, minPerSpan))) {
          out.append(py::make_tuple(e.u, e.s, e.kappa, e.maximum));
        }
        return out;
      },
      "curve"_a, "n"_a = 2048, "min_per_span"_a = 16, "[(u, s, kappa, is_maximum)]");
  m.def(
      "max_distance", [](const BSplineCurve& curve, PointsRef q) { return maxDistanceToPoints(toOcct(curve), q); },
      "curve"_a, "points"_a, "The largest distance from the points to the curve (by projection).");
  m.def(
      "edge_capsule",
      [](const BSplineCurve& curve) {
        return py::reinterpret_steal<py::object>(
            newShapeCapsule(new TopoDS_Shape(BRepBuilderAPI_MakeEdge(toOcct(curve)).Edge())));
      },
      "curve"_a, "A capsule owning a new TopoDS_Edge of the curve, for occ_bridge.adopt_shape (kernel.adopt).");
  m.def(
      "csr_edge_capsule",
      [](PointsRef q, bool closed, const std::string& parametrization, double epsilon, EpsilonRule rule,
         const Eigen::VectorXd& t) {
        // csr_spline and edge_address in one call: the fit goes straight into OCCT
        // (csrSplineOcct) without a BSplineCurve for Python in between.
        const CsrOptions options{parseParametrization(parametrization), closed, epsilon, rule, t};
        return py::reinterpret_steal<py::object>(
            newShapeCapsule(new TopoDS_Shape(BRepBuilderAPI_MakeEdge(csrSplineOcct(q, options)).Edge())));
      },
      "points"_a, "closed"_a = false, "parametrization"_a = "chordal", "epsilon"_a = 1e-9,
      "rule"_a = EpsilonRule::CaseDistinction, "parameters"_a = Eigen::VectorXd(),
      "A capsule owning a new TopoDS_Edge of the csr-spline, for occ_bridge.adopt_shape (kernel.adopt).");
  m.def(
      "to_brep", [](const BSplineCurve& curve) { return py::bytes(toBrepString(toOcct(curve))); }, "curve"_a,
      "The curve as BRep edge text with 17 significant digits (exact).");
}

}  // namespace fairsplines::python
