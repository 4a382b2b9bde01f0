#pragma once
#include <pybind11/pybind11.h>

namespace fairsplines::python {
void bindCurves(pybind11::module_& m);
void bindDesign(pybind11::module_& m);
void bindBlend(pybind11::module_& m);
void bindBlendC1(pybind11::module_& m);  // after bindBlend: returns its BlendComplex
void bindMonotone(pybind11::module_& m);  // after the InputError translator: registers NoMonotoneSolution
}
