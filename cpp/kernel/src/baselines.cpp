#include "fairsplines/baselines.hpp"

#include <GeomAPI_Interpolate.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_HArray1OfReal.hxx>
#include <TColgp_HArray1OfPnt.hxx>

#include "fairsplines/bspline.hpp"
#include "fairsplines/errors.hpp"
#include "fairsplines/occt.hpp"
#include "csr_detail.hpp"
#include "finite.hpp"

namespace fairsplines {

Handle(Geom_BSplineCurve) classicInterpolation(PointsRef q, Parametrization parametrization, bool closed) {
  const Eigen::VectorXd t =
      parameters(validateSamples(q, closed, closed ? 3 : 2, "classic interpolation").chords, parametrization);
  const int n = static_cast<int>(q.rows());
  Handle(TColgp_HArray1OfPnt) points = new TColgp_HArray1OfPnt(1, n);
  Handle(TColStd_HArray1OfReal) params = new TColStd_HArray1OfReal(1, closed ? n + 1 : n);
  for (int i = 0; i < n; ++i) {
    points->SetValue(i + 1, gp_Pnt(q(i, 0), q(i, 1), q.cols() > 2 ? q(i, 2) : 0.0));
  }
  for (int i = 0; i < params->Length(); ++i) params->SetValue(i + 1, t[i]);
  try {
    GeomAPI_Interpolate interpolate(points, params, closed, 0.0);
    interpolate.Perform();
    if (!interpolate.IsDone()) throw InputError("classic interpolation failed (GeomAPI_Interpolate)");
    const Handle(Geom_BSplineCurve) curve = interpolate.Curve();
    requireValidCurve(fromOcct(curve), "the classic interpolation of these points");
    return curve;
  } catch (const Standard_Failure& failure) {
    throw InputError(std::string("classic interpolation failed: ") + failure.GetMessageString());
  }
}

BSplineCurve quasiInterpolant(PointsRef q, Parametrization parametrization, bool closed) {
  const SampleInfo info = validateSamples(q, closed, 3, "the quasi-interpolant");
  Eigen::VectorXd t = parameters(info.chords, parametrization);
  return detail::fitCubic(q, std::move(t), closed, info.size, 1e-9, EpsilonRule::CaseDistinction, true);
}

BSplineCurve controlPointSpline(PointsRef q, bool closed) {
  validateSamples(q, closed, closed ? 3 : 4, "the control-point spline");
  const Eigen::Index n = q.rows();
  if (closed) {
    Eigen::VectorXd t = Eigen::VectorXd::LinSpaced(n + 1, 0.0, static_cast<double>(n));
    return periodicCubic(q, t);
  }
  // Clamped, uniform: n poles, n - 2 distinct knots.
  Eigen::VectorXd t = Eigen::VectorXd::LinSpaced(n - 2, 0.0, static_cast<double>(n - 3));
  BSplineCurve curve;
  curve.degree = 3;
  curve.poles = q;
  curve.knots = t;
  curve.mults = Eigen::VectorXi::Ones(n - 2);
  curve.mults[0] = curve.mults[n - 3] = 4;
  return curve;
}

}  // namespace fairsplines
