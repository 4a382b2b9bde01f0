#include "fairsplines/occt.hpp"

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepTools.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TopoDS_Edge.hxx>
#include <algorithm>
#include <sstream>
#include <vector>

#include "fairsplines/errors.hpp"
#include "csr_detail.hpp"
#include "finite.hpp"

namespace fairsplines {

Handle(Geom_BSplineCurve) toOcct(const BSplineCurve& curve) {
  const int n = static_cast<int>(curve.poles.rows());
  const int k = static_cast<int>(curve.knots.size());
  // The arrays below borrow the kernel's memory: check the layout first (no null data,
  // rows of 2 or 3 coordinates), then that every number is finite and the knots separate.
  requireValidCurve(curve, "the B-spline curve");
  // Row-major (n x 3) doubles have gp_Pnt's layout: OCCT's arrays can borrow the
  // kernel's memory (NCollection_Array1's non-owning constructor); the curve copies it.
  static_assert(sizeof(gp_Pnt) == 3 * sizeof(double), "gp_Pnt is three doubles");
  PointMatrix padded;
  const PointMatrix* source = &curve.poles;
  if (curve.dimension() == 2) {
    padded = PointMatrix::Zero(n, 3);
    padded.leftCols(2) = curve.poles;
    source = &padded;
  }
  try {
    const TColgp_Array1OfPnt poles(*reinterpret_cast<const gp_Pnt*>(source->data()), 1, n);
    const TColStd_Array1OfReal knots(*curve.knots.data(), 1, k);
    const TColStd_Array1OfInteger mults(*curve.mults.data(), 1, k);
    if (curve.isRational()) {
      const TColStd_Array1OfReal weights(*curve.weights.data(), 1, n);
      return new Geom_BSplineCurve(poles, weights, knots, mults, curve.degree, curve.periodic);
    }
    return new Geom_BSplineCurve(poles, knots, mults, curve.degree, curve.periodic);
  } catch (const Standard_Failure& failure) {
    throw InputError(std::string("OpenCASCADE rejected the B-spline: ") + failure.GetMessageString());
  }
}

Handle(Geom_BSplineCurve) csrSplineOcct(PointsRef q, const CsrOptions& options) {
  // 2D poles need a z column: the plain route.
  if (q.cols() != 3) return toOcct(csrSpline(q, options));
  struct Scratch {
    std::vector<double> t, poles;
    std::vector<int> mults;
  };
  thread_local Scratch scratch;
  const bool closed = options.closed;
  const Eigen::Index n = q.rows(), segments = closed ? n : n - 1, knots = segments + 1;
  const Eigen::Index poles = closed ? n : n + 2;
  if (n < 3) return toOcct(csrSpline(q, options));  // the error message
  // Grow only: resize value-initialises the new part once, later fits reuse it.
  if (scratch.t.size() < static_cast<size_t>(knots)) scratch.t.resize(knots);
  if (scratch.poles.size() < static_cast<size_t>(3 * poles)) scratch.poles.resize(3 * poles);
  if (scratch.mults.size() < static_cast<size_t>(knots)) scratch.mults.resize(knots);
  double* t = scratch.t.data();
  detail::csrSplineInto(q, options, t, scratch.poles.data());
  requireFinite(scratch.poles.data(), poles, 3, "the csr-spline of these points and parameters", "poles");
  requireFinite(t, knots, 1, "the csr-spline of these points and parameters", "knots");
  requireSeparateKnots(Eigen::Map<const Eigen::VectorXd>(t, knots), "the csr-spline of these points and parameters");
  int* m = scratch.mults.data();
  std::fill(m, m + knots, 1);
  if (!closed) m[0] = m[knots - 1] = 4;
  static_assert(sizeof(gp_Pnt) == 3 * sizeof(double), "gp_Pnt is three doubles");
  try {
    const TColgp_Array1OfPnt P(*reinterpret_cast<const gp_Pnt*>(scratch.poles.data()), 1, static_cast<int>(poles));
    const TColStd_Array1OfReal K(*t, 1, static_cast<int>(knots));
    const TColStd_Array1OfInteger M(*m, 1, static_cast<int>(knots));
    return new Geom_BSplineCurve(P, K, M, 3, closed);
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
