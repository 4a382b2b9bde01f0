#pragma once
#include <pybind11/pybind11.h>

namespace fairsplines::python {
void bindCurves(pybind11::module_& m);
void bindDesign(pybind11::module_& m);
void bindBlend(pybind11::module_& m);
void bindMonotone(pybind11::module_& m);  // after the InputError translator: registers NoMonotoneSolution
}
