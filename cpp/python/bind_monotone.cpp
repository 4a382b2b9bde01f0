// Bindings for monotonic-curvature cubics: eqs. (3), (5), the paper's per-segment conditions,
// Algorithms 1 and 2 and the exact certificate. Registers NoMonotoneSolution (an InputError).
#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "fairsplines/monotone.hpp"
#include "bindings.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace fairsplines::python {

namespace {

MonotoneMethod parseMethod(const std::string& name) {
  if (name == "fairest") return MonotoneMethod::Fairest;
  if (name == "grid") return MonotoneMethod::PaperGrid;
  throw InputError("unknown method '" + name + "': use 'fairest' or 'grid'");
}

const char* trendName(CurvatureTrend trend) {
  switch (trend) {
    case CurvatureTrend::Increasing:
      return "increasing";
    case CurvatureTrend::Decreasing:
      return "decreasing";
    case CurvatureTrend::Constant:
      return "constant";
    case CurvatureTrend::Extremum:
      return "extremum";
    case CurvatureTrend::Singular:
      return "singular";
    case CurvatureTrend::Undecided:
      break;
  }
  return "undecided";
}

}  // namespace

py::dict certificateDict(const MonotonicityCertificate& c) {
  py::list spans;
  for (const SpanCertificate& s : c.spans) {
    spans.append(py::dict("u0"_a = s.u0, "u1"_a = s.u1, "kappa0"_a = s.kappa0, "kappa1"_a = s.kappa1,
                          "trend"_a = trendName(s.trend), "degree"_a = s.degree, "pieces"_a = s.pieces, "at"_a = s.at,
                          "kappa_at"_a = s.kappaAt, "maximum"_a = s.maximum, "reason"_a = s.reason));
  }
  return py::dict("monotone"_a = c.monotone, "increasing"_a = c.increasing, "decreasing"_a = c.decreasing,
                  "normal"_a = c.normal, "kappa_start"_a = c.kappaStart, "kappa_end"_a = c.kappaEnd,
                  "reason"_a = c.reason, "spans"_a = spans);
}

py::dict spaceCertificateDict(const SpaceCurvatureCertificate& c) {
  py::list spans, extrema;
  for (const SpaceSpanCertificate& s : c.spans) {
    spans.append(py::dict("u0"_a = s.u0, "u1"_a = s.u1, "kappa0"_a = s.kappa0, "kappa1"_a = s.kappa1,
                          "trend"_a = trendName(s.trend), "degree"_a = s.degree, "torsion_sign"_a = s.torsionSign,
                          "torsion_changes"_a = s.torsionChanges, "reason"_a = s.reason));
  }
  for (const auto& [u, kappa, maximum] : c.extrema) extrema.append(py::make_tuple(u, kappa, maximum));
  return py::dict("monotone"_a = c.monotone, "increasing"_a = c.increasing, "decreasing"_a = c.decreasing,
                  "planar"_a = c.planar, "kappa_start"_a = c.kappaStart, "kappa_end"_a = c.kappaEnd,
                  "extrema"_a = extrema, "torsion_sign_changes"_a = c.torsionSignChanges, "reason"_a = c.reason,
                  "spans"_a = spans);
}

void bindMonotone(py::module_& m) {
  // No curve of the family meets the end conditions: a subclass of InputError (a ValueError).
  static py::exception<NoMonotoneSolution> noSolution(m, "NoMonotoneSolution", m.attr("InputError"));
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const NoMonotoneSolution& e) {
      noSolution(e.what());
    }
  });

  m.def(
      "derivative_polygons",
      [](const BSplineCurve& cubic) {
        DerivativePolygons d = derivativePolygons(cubic);
        return py::make_tuple(d.first, d.second);
      },
      "cubic"_a, "Eqs. (3) and (5): (C^1, C^2) of a non-periodic, non-rational cubic.");

  m.def(
      "check_segments",
      [](const BSplineCurve& cubic) {
        py::list out;
        for (const SegmentReport& r : checkSegments(cubic)) {
          const SegmentCheck& c = r.check;
          out.append(py::dict("u0"_a = r.u0, "u1"_a = r.u1, "turn"_a = c.turn, "lemma1"_a = c.lemma1,
                              "lemma2"_a = c.lemma2, "lemma3"_a = c.lemma3, "theorem1"_a = c.theorem1(),
                              "fair_location"_a = c.fairLocation, "theorem2"_a = c.theorem2, "angle"_a = c.angle,
                              "reason"_a = describe(c)));
        }
        return out;
      },
      "cubic"_a, "Lemmas 1-3 and Theorems 1-2 per segment, in each segment's local frame.");

  m.def(
      "design_monotone",
      [](const Eigen::Vector2d& first, PointsRef differences, const Eigen::VectorXd& knots,
         const Eigen::Vector2d& start) {
        MonotoneDesign d = designMonotone(first, differences, knots, start);
        return py::make_tuple(d.curve, d.differences, d.moved, d.turn);
      },
      "first_vector"_a, "differences"_a, "knots"_a = Eigen::VectorXd(), "start"_a = Eigen::Vector2d::Zero(),
      "Algorithm 1: (curve, differences used, how far each moved, turn +1/-1).");

  m.def(
      "analyze_end_conditions",
      [](const Eigen::Vector3d& p0, const Eigen::Vector3d& t0, const Eigen::Vector3d& p1, const Eigen::Vector3d& t1) {
        const EndConditions e = analyzeEndConditions(p0, t0, p1, t1);
        return py::dict("admissible"_a = e.admissible, "straight"_a = e.straight, "reversed"_a = e.reversed,
                        "a"_a = e.a, "b"_a = e.b, "turn"_a = e.turn, "reason"_a = e.reason);
      },
      "p0"_a, "t0"_a, "p1"_a, "t1"_a,
      "Classifies the G2 Hermite data (p0, t0, p1, t1) for Algorithm 2: admissible, straight, reversed, a, b, turn "
      "and the reason.");

  m.def(
      "monotone_spline",
      [](const Eigen::Vector3d& p0, const Eigen::Vector3d& t0, const Eigen::Vector3d& p1, const Eigen::Vector3d& t1,
         const std::string& method, double gridStep) {
        MonotoneSpline s = monotoneCurvatureSpline(p0, t0, p1, t1, parseMethod(method), gridStep);
        return py::make_tuple(s.curve, s.reversed, s.boundary, s.margin, s.iterations);
      },
      "p0"_a, "t0"_a, "p1"_a, "t1"_a, "method"_a = "fairest", "grid_step"_a = 0.02,
      "Algorithm 2: (curve, reversed, boundary, margin, iterations); raises NoMonotoneSolution.");

  m.def(
      "certify_monotone",
      [](const BSplineCurve& curve, double relTol) { return certificateDict(certifyMonotoneCurvature(curve, relTol)); },
      "curve"_a, "rel_tol"_a = 1e-12, "The exact monotonicity certificate of a planar B-spline.");

  m.def(
      "certify_space_curvature",
      [](const BSplineCurve& curve, double relTol) {
        return spaceCertificateDict(certifySpaceCurvature(curve, relTol));
      },
      "curve"_a, "rel_tol"_a = 1e-12,
      "The exact certificate of monotone curvature of a space B-spline (sign of d(kappa^2)/dt in Bernstein form), "
      "with its curvature extrema and torsion sign changes.");

  m.def("curvature_variation", &curvatureVariation, "curve"_a,
        "L^3 * integral (dkappa/ds)^2 ds of a planar B-spline (0 for lines and circles).");
}

}  // namespace fairsplines::python
