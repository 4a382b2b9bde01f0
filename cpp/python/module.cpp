// The private compiled module `freecad_workbench._kernel`: a thin pybind11 layer over
// the C++ kernel. Python names are snake_case; the facade in freecad_workbench re-exports.
#include <pybind11/pybind11.h>

#include <Standard_Failure.hxx>

#include "fairsplines/errors.hpp"
#include "bindings.hpp"

namespace py = pybind11;

PYBIND11_MODULE(_kernel, m) {
  m.doc() = "FairSplines geometry kernel (C++); use the freecad_workbench package instead.";
  // Bad input: a ValueError subclass whose message names the problem.
  static py::exception<fairsplines::InputError> inputError(m, "InputError", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const fairsplines::InputError& e) {
      inputError(e.what());
    } catch (const Standard_Failure& e) {
      // An OCCT failure the kernel's own checks did not foresee is still about this input
      // (a degenerate or out-of-range curve): InputError, saying which OCCT check failed.
      inputError((std::string("OpenCASCADE could not process this input (") + e.DynamicType()->Name() + ": " +
                  e.GetMessageString() + ")")
                     .c_str());
    }
  });
  fairsplines::python::bindCurves(m);
  fairsplines::python::bindDesign(m);
  fairsplines::python::bindBlend(m);
  fairsplines::python::bindBlendC1(m);
  fairsplines::python::bindMonotone(m);
  fairsplines::python::bindFairBlend(m);
  fairsplines::python::bindFairFit(m);
  fairsplines::python::bindSurfaceAnalysis(m);
  fairsplines::python::bindFaceBlend(m);
}
