#pragma once
#include <pybind11/pybind11.h>

#include "fairsplines/monotone.hpp"

namespace fairsplines::python {
void bindCurves(pybind11::module_& m);
void bindDesign(pybind11::module_& m);
void bindBlend(pybind11::module_& m);
void bindBlendC1(pybind11::module_& m);   // after bindBlend: returns its BlendComplex
void bindMonotone(pybind11::module_& m);  // after the InputError translator: registers NoMonotoneSolution
void bindFairBlend(pybind11::module_& m);
void bindFairFit(pybind11::module_& m);
void bindSurfaceAnalysis(pybind11::module_& m);
void bindFaceBlend(pybind11::module_& m);

/// A MonotonicityCertificate as the dict the Python layer reads (bind_monotone.cpp).
pybind11::dict certificateDict(const MonotonicityCertificate& certificate);
pybind11::dict spaceCertificateDict(const SpaceCurvatureCertificate& certificate);
}  // namespace fairsplines::python
