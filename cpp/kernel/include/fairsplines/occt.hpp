// Exact conversion between the kernel's BSplineCurve and OpenCASCADE's Geom_BSplineCurve.
#pragma once
#include <Geom_BSplineCurve.hxx>
#include <string>
#include "fairsplines/csr.hpp"
#include "fairsplines/types.hpp"

namespace fairsplines {

/// Exact conversion; 2D poles get z = 0. Throws InputError when OCCT rejects the data.
Handle(Geom_BSplineCurve) toOcct(const BSplineCurve& curve);

/// toOcct(csrSpline(q, options)), the same curve bit for bit, without the intermediate
/// BSplineCurve: its parameters, poles and multiplicities are computed in memory kept
/// per thread and reused (it grows to the largest fit, about 36 bytes per point), and
/// the Geom_BSplineCurve constructor copies them from there. Repeated fits thus touch
/// no fresh pages but OCCT's own.
Handle(Geom_BSplineCurve) csrSplineOcct(PointsRef q, const CsrOptions& options = {});

/// Exact conversion back; always 3 columns.
/// Throws nothing; the handle must not be null (not checked).
BSplineCurve fromOcct(const Handle(Geom_BSplineCurve)& curve);

/// The curve as the text of a BRep edge (BRepTools format), every real with 17
/// significant digits so that reading it back is exact.
/// Throws nothing; the handle must not be null (not checked).
std::string toBrepString(const Handle(Geom_BSplineCurve)& curve);

}  // namespace fairsplines
