// Bindings for surface analysis (issue 27): shapes arrive as BRep text (Part's
// exportBrepToString, the same on every FreeCAD and OCCT version) and results leave as arrays.
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstdint>

#include "fairsplines/surface_analysis.hpp"
#include "fairsplines/types.hpp"
#include "bindings.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace fairsplines::python {

namespace {

py::dict continuityDict(const EdgeContinuity& r) {
  py::dict d;
  d["edge"] = r.edge;
  d["faces"] = r.faces;
  d["kind"] = r.kind;
  d["continuity"] = r.continuity;
  d["gap"] = r.gap;
  d["angle"] = r.angle;
  d["curvature_jump"] = r.curvatureJump;
  d["curvature_jump_abs"] = r.curvatureJumpAbs;
  d["curvature_scale"] = r.curvatureScale;
  d["gap_point"] = r.gapPoint;
  d["angle_point"] = r.anglePoint;
  d["curvature_point"] = r.curvaturePoint;
  d["gap_parameter"] = r.gapParameter;
  d["angle_parameter"] = r.angleParameter;
  d["curvature_parameter"] = r.curvatureParameter;
  d["samples"] = r.samples;
  return d;
}

}  // namespace

void bindSurfaceAnalysis(py::module_& m) {
  m.def(
      "surface_curvature",
      [](const std::string& brep, const PointsRef& uv, int threads) {
        const TopoDS_Face face = singleFace(readBrepShape(brep));
        // The results in one numpy block, (16, n) in C order (the kernel's column-major n x 16),
        // written by the kernel in place and handed out as views of it. numpy allocates it and
        // advises huge pages for it: on the shared virtual machine first touching 26 MB of fresh
        // memory costs 3-8 ms so, against 75-120 ms in 4 KB pages (docs/SURFACE_ANALYSIS.md).
        const py::ssize_t n = uv.rows(), width = curvature_column::count;
        py::array_t<double> block({width, n});
        py::array_t<std::int8_t> state(n);
        surfaceCurvature(face, uv, Eigen::Map<CurvatureBlock>(block.mutable_data(), n, width),
                         Eigen::Map<PointStates>(state.mutable_data(), n), threads);
        const auto view = [&](int column, py::ssize_t size) {
          const py::ssize_t step = sizeof(double);
          const double* data = block.data() + column * n;
          return size == 1 ? py::array(block.dtype(), {n}, {step}, data, block)
                           : py::array(block.dtype(), {n, size}, {step, n * step}, data, block);
        };
        namespace column = curvature_column;
        return py::make_tuple(view(column::k1, 1), view(column::k2, 1), view(column::gaussian, 1),
                              view(column::mean, 1), view(column::dir1, 3), view(column::dir2, 3),
                              view(column::normal, 3), view(column::point, 3), state);
      },
      "brep"_a, "uv"_a, "threads"_a = 0,
      "(k1, k2, gaussian, mean, dir1, dir2, normal, points, state) at the rows (u, v) of uv on the one face of the "
      "BRep text; convex positive as seen from the face normal; state 0 regular, 1 umbilic, 2 degenerate (a limit). "
      "The arrays are views of one (16, N) block. threads: at most this many threads (0: one a core).");
  m.def(
      "edge_continuity",
      [](const std::string& brep, int samplesPerSpan, double gapTolerance, double angleTolerance,
         double curvatureTolerance) {
        const std::vector<EdgeContinuity> records = edgeContinuity(
            readBrepShape(brep), ContinuityOptions{samplesPerSpan, gapTolerance, angleTolerance, curvatureTolerance});
        py::list out;
        for (const EdgeContinuity& r : records) out.append(continuityDict(r));
        return out;
      },
      "brep"_a, "samples_per_span"_a = 0, "gap_tolerance"_a = -1.0, "angle_tolerance"_a = 0.1,
      "curvature_tolerance"_a = 0.02,
      "One dict per edge of the BRep shape (TopExp::MapShapes order): gap, angle (degrees), relative curvature "
      "jump, verdict and worst points.");
  m.def(
      "curvature_map",
      [](const std::string& brep, const std::string& quantity, double deflection, double fraction, int levels) {
        const CurvatureMap c =
            curvatureMap(readBrepShape(brep), parseMapQuantity(quantity), deflection, fraction, levels);
        return py::make_tuple(c.points, c.triangles, c.values, c.face, c.faceRanges, c.normals);
      },
      "brep"_a, "quantity"_a = "gaussian", "deflection"_a = 0.0, "fraction"_a = 0.05, "levels"_a = 3,
      "(points, triangles, values, face of each triangle from 1, per-face (min, max), unit normals) of the BRep "
      "shape's faces.");
}

}  // namespace fairsplines::python
