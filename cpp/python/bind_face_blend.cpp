// Bindings for G1/G2 face blends (issue 29): faces arrive as BRep text, the blend leaves as a
// BSplineSurface and its report as a dict.
#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "fairsplines/face_blend.hpp"
#include "fairsplines/surface_analysis.hpp"
#include "fairsplines/surfaces.hpp"
#include "bindings.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace fairsplines::python {

namespace {

py::dict sideDict(const FaceBlendSide& s) {
  py::dict d;
  d["method"] = s.method;
  d["surface_type"] = s.surfaceType;
  d["isoparametric"] = s.isoparametric;
  d["alpha"] = s.alpha;
  d["beta"] = s.beta;
  d["scale"] = s.scale;
  d["bend"] = s.bend;
  d["rational"] = s.rational;
  d["closed"] = s.closed;
  d["continuity"] = s.continuity;
  d["reason"] = s.reason;
  if (s.method == "fitted") {
    d["spans"] = s.spans;
    d["refinements"] = s.refinements;
    d["samples"] = s.samples;
    d["fit_gap"] = s.fitGap;
    d["fit_angle"] = s.fitAngle;
    d["fit_curvature"] = s.fitCurvature;
  }
  return d;
}

py::dict sectionDict(const FaceBlendSection& s) {
  py::dict d;
  d["u"] = s.u;
  d["monotone"] = s.monotone;
  d["curvature_extrema"] = s.curvatureExtrema;
  d["sampled_extrema"] = s.sampledExtrema;
  d["kappa_min"] = s.kappaMin;
  d["kappa_max"] = s.kappaMax;
  d["variation"] = s.variation;
  d["reason"] = s.reason;
  return d;
}

}  // namespace

void bindFaceBlend(py::module_& m) {
  m.def(
      "blend_faces",
      [](const std::string& brepA, int edgeA, const std::string& brepB, int edgeB, int continuity, bool flip,
         double start, double end, int sections, double scaleA, double scaleB, int continuityB) {
        FaceBlendOptions o;
        o.continuity = continuity;
        o.continuityB = continuityB;
        o.flip = flip;
        o.start = start;
        o.end = end;
        o.sections = sections;
        o.scaleA = scaleA;
        o.scaleB = scaleB;
        const FaceBlend blend =
            blendFaces(singleFace(readBrepShape(brepA)), edgeA, singleFace(readBrepShape(brepB)), edgeB, o);
        py::dict report;
        report["sides"] = py::make_tuple(sideDict(blend.sides[0]), sideDict(blend.sides[1]));
        py::list sectionList;
        for (const FaceBlendSection& s : blend.sections) sectionList.append(sectionDict(s));
        report["sections"] = sectionList;
        report["evaluations"] = blend.evaluations;
        report["size"] = blend.size;
        return py::make_tuple(fromOcct(blend.surface), report);
      },
      "brep_a"_a, "edge_a"_a, "brep_b"_a, "edge_b"_a, "continuity"_a = 2, "flip"_a = false, "start"_a = 0.0,
      "end"_a = 1.0, "sections"_a = 13, "scale_a"_a = 0.0, "scale_b"_a = 0.0, "continuity_b"_a = 0,
      "(BSplineSurface, report) of the G1 (continuity 1) or G2 (2) blend between the one face of brep_a along its "
      "edge number edge_a (from 1, as Face.Edges) and that of brep_b along edge_b; u along the edges in [0, 1], v "
      "from edge a to edge b. continuity_b: edge b's when it differs (0: continuity). scale_a, scale_b > 0 fix the "
      "derivative magnitudes (0: chosen for fairness).");
}

}  // namespace fairsplines::python
