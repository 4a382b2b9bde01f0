// Bindings for design with basic curves: basic curves, the Section 5/6 polygons, the
// Fig. 9 merge, eq. (11) and the exact revolve.
#include <pybind11/eigen.h>
#include <pybind11/functional.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <Precision.hxx>
#include <TopoDS_Face.hxx>
#include <cstdint>

#include "fairsplines/basic_curves.hpp"
#include "fairsplines/design.hpp"
#include "fairsplines/design_samples.hpp"
#include "fairsplines/errors.hpp"
#include "fairsplines/surfaces.hpp"
#include "bindings.hpp"
#include "shape_capsule.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace fairsplines::python {

namespace {
Frame frameOf(const Eigen::Vector3d& origin, const Eigen::Vector3d& x, const Eigen::Vector3d& y) {
  Frame frame{origin, x, y};
  frame.check();
  return frame;
}
}  // namespace

void bindDesign(py::module_& m) {
  py::class_<BasicCurve>(m, "BasicCurve", "A basic curve over u in [0, 1].")
      .def("value", &BasicCurve::value, "u"_a)
      .def("d1", &BasicCurve::d1, "u"_a)
      .def("d2", &BasicCurve::d2, "u"_a)
      .def("parameter_of", &BasicCurve::parameterOf, "point"_a, "tolerance"_a = 1e-9,
           "Eq. (4) for circle arcs, eq. (5) otherwise; InputError if the point is off the curve.")
      .def("homogeneous_cubic", &BasicCurve::homogeneousCubic)
      .def("size", &BasicCurve::size);
  py::class_<RationalBezierCurve, BasicCurve>(m, "RationalBezierCurve")
      .def(py::init<HomogeneousBezier>(), "homogeneous"_a)
      .def_property_readonly("homogeneous", &RationalBezierCurve::homogeneous);
  py::class_<CircleArc, RationalBezierCurve>(m, "CircleArc")
      .def(py::init([](const Eigen::Vector3d& o, const Eigen::Vector3d& x, const Eigen::Vector3d& y, double radius,
                       double start, double sweep) { return CircleArc(frameOf(o, x, y), radius, start, sweep); }),
           "origin"_a, "x"_a, "y"_a, "radius"_a, "start"_a, "sweep"_a);
  py::class_<ParametricCurve, BasicCurve>(m, "ParametricCurve")
      .def(py::init([](const py::function& jet, double s0, double s1) {
             // jet(s) -> (f, f', f''), each three numbers; errors surface as Python exceptions.
             auto call = [jet](double s, Eigen::Vector3d& f, Eigen::Vector3d& df, Eigen::Vector3d& d2f) {
               py::gil_scoped_acquire gil;
               const py::tuple t = jet(s);
               if (t.size() != 3) throw InputError("a parametric curve's function must return (f, df, d2f)");
               f = t[0].cast<Eigen::Vector3d>();
               df = t[1].cast<Eigen::Vector3d>();
               d2f = t[2].cast<Eigen::Vector3d>();
             };
             return ParametricCurve(call, s0, s1);
           }),
           "jet"_a, "s0"_a, "s1"_a);

  m.def("line_segment", &lineSegment, "p0"_a, "p1"_a, "The line segment from p0 to p1 (degree 1, weights 1).");
  m.def(
      "ellipse_arc",
      [](const Eigen::Vector3d& o, const Eigen::Vector3d& x, const Eigen::Vector3d& y, double a, double b, double start,
         double sweep) { return ellipseArc(frameOf(o, x, y), a, b, start, sweep); },
      "origin"_a, "x"_a, "y"_a, "a"_a, "b"_a, "start"_a, "sweep"_a,
      "An ellipse arc x = a cos t, y = b sin t in the frame, t from start over sweep (rational quadratic).");
  m.def(
      "parabola_arc",
      [](const Eigen::Vector3d& o, const Eigen::Vector3d& x, const Eigen::Vector3d& y, double focal, double t0,
         double t1) { return parabolaArc(frameOf(o, x, y), focal, t0, t1); },
      "origin"_a, "x"_a, "y"_a, "focal"_a, "t0"_a, "t1"_a,
      "A parabola arc x = t^2 / (4 focal), y = t in the frame (OCCT's convention), t from t0 to t1.");
  m.def(
      "hyperbola_arc",
      [](const Eigen::Vector3d& o, const Eigen::Vector3d& x, const Eigen::Vector3d& y, double a, double b, double t0,
         double t1) { return hyperbolaArc(frameOf(o, x, y), a, b, t0, t1); },
      "origin"_a, "x"_a, "y"_a, "a"_a, "b"_a, "t0"_a, "t1"_a,
      "A hyperbola arc x = a cosh t, y = b sinh t in the frame, t from t0 to t1 (rational quadratic).");
  m.def(
      "archimedean_spiral",
      [](const Eigen::Vector3d& o, const Eigen::Vector3d& x, const Eigen::Vector3d& y, double a, double b,
         double theta0, double theta1) { return archimedeanSpiral(frameOf(o, x, y), a, b, theta0, theta1); },
      "origin"_a, "x"_a, "y"_a, "a"_a, "b"_a, "theta0"_a, "theta1"_a,
      "The Archimedean spiral r = a + b theta in the frame, theta from theta0 to theta1 (a parametric curve: "
      "Section 5).");
  m.def(
      "circle_involute",
      [](const Eigen::Vector3d& o, const Eigen::Vector3d& x, const Eigen::Vector3d& y, double r, double t0, double t1) {
        return circleInvolute(frameOf(o, x, y), r, t0, t1);
      },
      "origin"_a, "x"_a, "y"_a, "r"_a, "t0"_a, "t1"_a,
      "The involute r (cos t + t sin t, sin t - t cos t) of the circle of radius r in the frame, t from t0 to t1.");

  py::class_<PiecePolygon>(m, "PiecePolygon", "A basic piece's control polygon (Sections 5, 6).")
      .def_readonly("marks", &PiecePolygon::marks)
      .def_readonly("start", &PiecePolygon::start)
      .def_readonly("inner", &PiecePolygon::inner)
      .def_readonly("end", &PiecePolygon::end)
      .def_readonly("exact", &PiecePolygon::exact)
      .def_readonly("marks_added", &PiecePolygon::marksAdded);
  m.def("complete_marks", &completeMarks, "marks"_a,
        "The marks with 0 and 1 added: increasing values in [0, 1] that become knots of the design.");
  m.def("piece_polygon", &piecePolygon, "curve"_a, "marks"_a,
        "Sections 5, 6: the control polygon of a basic curve between its marks (exact for rational curves of degree "
        "<= 3).");
  m.def("polygon_from_jets", &polygonFromJets, "f"_a, "df"_a, "d2f"_a, "marks"_a,
        "Section 5: the control polygon from the 2-jets (points, first and second derivatives) at the marks.");
  m.def("quintic_pieces", &quinticPieces, "curve"_a, "marks"_a,
        "The curve's quintic Bézier pieces between its marks (6 rows each).");
  m.def(
      "samples_polygon",
      [](PointsRef q, const std::string& parametrization, double epsilon, EpsilonRule rule) {
        return samplesPolygon(q, CsrOptions{parseParametrization(parametrization), false, epsilon, rule, {}});
      },
      "points"_a, "parametrization"_a = "chordal", "epsilon"_a = 1e-9, "rule"_a = EpsilonRule::CaseDistinction,
      "The unifying spline's sampled piece: the csr-spline (Section 4, eq. (6)) as a piece polygon.");
  m.def(
      "merge_pieces",
      [](const std::vector<PiecePolygon>& pieces, double joinTolerance) {
        const Design d = mergePieces(pieces, joinTolerance);
        py::list joins, ranges;
        for (JoinKind j : d.joins)
          joins.append(j == JoinKind::Agree ? "agree" : j == JoinKind::Averaged ? "averaged" : "edge");
        for (const PieceRange& r : d.ranges) ranges.append(py::make_tuple(r.t0, r.scale));
        return py::make_tuple(d.curve, joins, ranges);
      },
      "pieces"_a, "join_tolerance"_a, "Fig. 9: (curve, joins, [(t0, scale) per piece]).");

  py::class_<BSplineSurface>(m, "BSplineSurface")
      .def_readonly("degree_u", &BSplineSurface::degreeU)
      .def_readonly("degree_v", &BSplineSurface::degreeV)
      .def_readonly("nu", &BSplineSurface::nu)
      .def_readonly("nv", &BSplineSurface::nv)
      .def_readonly("poles", &BSplineSurface::poles)
      .def_readonly("weights", &BSplineSurface::weights)
      .def_readonly("knots_u", &BSplineSurface::knotsU)
      .def_readonly("knots_v", &BSplineSurface::knotsV)
      .def_readonly("mults_u", &BSplineSurface::multsU)
      .def_readonly("mults_v", &BSplineSurface::multsV);
  m.def("tensor_control_net", &tensorControlNet, "bezier"_a, "n_i"_a, "n_j"_a, "beta_u"_a, "beta_v"_a,
        "Eq. (11): the bicubic control points c_ij from the patches' interior Bézier points and the scalars beta_u, "
        "beta_v.");
  m.def("revolve", &revolve, "profile"_a, "axis_point"_a, "axis_direction"_a,
        "The exact surface of revolution of a profile curve about an axis (the rational quadratic circle in v).");
  m.def(
      "face_capsule",
      [](const BSplineSurface& surface) {
        return py::reinterpret_steal<py::object>(
            newShapeCapsule(new TopoDS_Shape(validFace(toOcct(surface), "the B-spline surface's face"))));
      },
      "surface"_a, "A capsule owning a new TopoDS_Face of the surface, for occ_bridge.adopt_shape (kernel.adopt).");
}

}  // namespace fairsplines::python
