// Exact conversion between the kernel's BSplineCurve and OpenCASCADE's Geom_BSplineCurve.
#pragma once
#include <string>
#include <Geom_BSplineCurve.hxx>
#include "fairsplines/types.hpp"

namespace fairsplines {

/// Exact conversion; 2D poles get z = 0. Throws InputError when OCCT rejects the data.
Handle(Geom_BSplineCurve) toOcct(const BSplineCurve& curve);

/// Exact conversion back; always 3 columns.
BSplineCurve fromOcct(const Handle(Geom_BSplineCurve)& curve);

/// The curve as the text of a BRep edge (BRepTools format), every real with 17
/// significant digits so that reading it back is exact.
std::string toBrepString(const Handle(Geom_BSplineCurve)& curve);

}  // namespace fairsplines
