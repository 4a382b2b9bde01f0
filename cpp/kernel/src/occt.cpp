#include "fairsplines/occt.hpp"

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepTools.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TopoDS_Edge.hxx>
#include <sstream>

#include "fairsplines/errors.hpp"

namespace fairsplines {

Handle(Geom_BSplineCurve) toOcct(const BSplineCurve& curve) {
  const int n = static_cast<int>(curve.poles.rows());
  const int dim = curve.dimension();
  TColgp_Array1OfPnt poles(1, n);
  for (int i = 0; i < n; ++i) {
    poles.SetValue(i + 1, gp_Pnt(curve.poles(i, 0), curve.poles(i, 1), dim > 2 ? curve.poles(i, 2) : 0.0));
  }
  const int k = static_cast<int>(curve.knots.size());
  TColStd_Array1OfReal knots(1, k);
  TColStd_Array1OfInteger mults(1, k);
  for (int i = 0; i < k; ++i) {
    knots.SetValue(i + 1, curve.knots[i]);
    mults.SetValue(i + 1, curve.mults[i]);
  }
  try {
    if (curve.isRational()) {
      TColStd_Array1OfReal weights(1, n);
      for (int i = 0; i < n; ++i) weights.SetValue(i + 1, curve.weights[i]);
      return new Geom_BSplineCurve(poles, weights, knots, mults, curve.degree, curve.periodic);
    }
    return new Geom_BSplineCurve(poles, knots, mults, curve.degree, curve.periodic);
  } catch (const Standard_Failure& failure) {
    throw InputError(std::string("OpenCASCADE rejected the B-spline: ") + failure.GetMessageString());
  }
}

BSplineCurve fromOcct(const Handle(Geom_BSplineCurve)& curve) {
  BSplineCurve out;
  out.degree = curve->Degree();
  out.periodic = curve->IsPeriodic();
  const int n = curve->NbPoles();
  out.poles.resize(n, 3);
  for (int i = 0; i < n; ++i) {
    const gp_Pnt& p = curve->Pole(i + 1);
    out.poles.row(i) << p.X(), p.Y(), p.Z();
  }
  if (curve->IsRational()) {
    out.weights.resize(n);
    for (int i = 0; i < n; ++i) out.weights[i] = curve->Weight(i + 1);
  }
  const int k = curve->NbKnots();
  out.knots.resize(k);
  out.mults.resize(k);
  for (int i = 0; i < k; ++i) {
    out.knots[i] = curve->Knot(i + 1);
    out.mults[i] = curve->Multiplicity(i + 1);
  }
  return out;
}

std::string toBrepString(const Handle(Geom_BSplineCurve)& curve) {
  const TopoDS_Edge edge = BRepBuilderAPI_MakeEdge(curve);
  std::ostringstream out;
  out.precision(17);
  BRepTools::Write(edge, out);
  return out.str();
}

}  // namespace fairsplines
