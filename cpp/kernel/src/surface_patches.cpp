// Knot spans of a B-spline face in power form (surface_patches.hpp). Each span is first a
// Bezier patch (GeomConvert_BSplineSurfaceToBezierSurface: knot insertion to full
// multiplicity), whose homogeneous Bernstein coefficients b_ij = (w x, w y, w z, w) turn into
// power coefficients about the span's corner, in its local parameters s, t in [0, 1]:
//   a_kl = sum_i sum_j M^p_ki M^q_lj b_ij,  M^n_ki = C(n, i) C(n - i, k - i) (-1)^(k - i)  (i <= k),
// the expansion of the Bernstein polynomials B_i^n(s) = C(n, i) s^i (1 - s)^(n - i) in powers of s
// (Farin, Curves and Surfaces for CAGD, 5th ed., §5.7, the monomial form). The point and its
// derivatives are then the homogeneous ones by Horner's rule and the quotient rule:
//   S = A / w,  S_s = (A_s - w_s S) / w,  S_ss = (A_ss - 2 w_s S_s - w_ss S) / w,
//   S_st = (A_st - w_s S_t - w_t S_s - w_st S) / w   (A the first three coordinates),
// divided by the span's widths for u and v (s = (u - u_i) / (u_{i+1} - u_i)).
#include "surface_patches.hpp"

#include <BRep_Tool.hxx>
#include <GeomConvert.hxx>
#include <GeomConvert_BSplineSurfaceToBezierSurface.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_BezierSurface.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <TColGeom_Array2OfBezierSurface.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <algorithm>
#include <cmath>

namespace fairsplines::detail {

namespace {

/// M^n: row k holds the power coefficients of s^k in terms of the Bernstein coefficients.
Eigen::MatrixXd bernsteinToPower(int n) {
  Eigen::MatrixXd binomial = Eigen::MatrixXd::Zero(n + 1, n + 1);
  for (int i = 0; i <= n; ++i) {
    binomial(i, 0) = 1.0;
    for (int j = 1; j <= i; ++j) binomial(i, j) = binomial(i - 1, j - 1) + (j < i ? binomial(i - 1, j) : 0.0);
  }
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(n + 1, n + 1);
  for (int k = 0; k <= n; ++k) {
    for (int i = 0; i <= k; ++i) m(k, i) = binomial(n, i) * binomial(n - i, k - i) * ((k - i) % 2 ? -1.0 : 1.0);
  }
  return m;
}

/// The span of a sorted breakpoint list holding x: [0, spans - 1], the end spans beyond.
int spanOf(const std::vector<double>& breaks, double x) {
  const auto inner = std::upper_bound(breaks.begin() + 1, breaks.end() - 1, x);
  return static_cast<int>(inner - (breaks.begin() + 1));
}

/// x moved by whole periods into [first, first + period), for a periodic direction.
double wrap(double x, double first, double period) {
  if (period <= 0.0) return x;
  const double r = std::fmod(x - first, period);
  return first + (r < 0.0 ? r + period : r);
}

gp_Vec vec(const Eigen::Vector3d& x) { return gp_Vec(x.x(), x.y(), x.z()); }

}  // namespace

std::unique_ptr<PowerPatches> PowerPatches::of(const TopoDS_Face& face) {
  Handle(Geom_Surface) surface = BRep_Tool::Surface(face);  // the face's location applied
  if (surface.IsNull()) return nullptr;
  if (const auto trimmed = Handle(Geom_RectangularTrimmedSurface)::DownCast(surface)) {
    surface = trimmed->BasisSurface();
  }
  Handle(Geom_BSplineSurface) bspline;
  if (const auto bezier = Handle(Geom_BezierSurface)::DownCast(surface)) {
    bspline = GeomConvert::SurfaceToBSplineSurface(bezier);
  } else if (const auto b = Handle(Geom_BSplineSurface)::DownCast(surface)) {
    bspline = b;
  }
  if (bspline.IsNull() || bspline->UDegree() > kMaxDegree || bspline->VDegree() > kMaxDegree) return nullptr;

  auto out = std::unique_ptr<PowerPatches>(new PowerPatches);
  out->p_ = bspline->UDegree();
  out->q_ = bspline->VDegree();
  double u0, u1, v0, v1;
  bspline->Bounds(u0, u1, v0, v1);
  out->uFirst_ = u0;
  out->vFirst_ = v0;
  out->uPeriod_ = bspline->IsUPeriodic() ? u1 - u0 : 0.0;
  out->vPeriod_ = bspline->IsVPeriodic() ? v1 - v0 : 0.0;
  if (bspline->IsUPeriodic() || bspline->IsVPeriodic()) {  // the same surface over one period, clamped
    bspline = Handle(Geom_BSplineSurface)::DownCast(bspline->Copy());
    if (bspline->IsUPeriodic()) bspline->SetUNotPeriodic();
    if (bspline->IsVPeriodic()) bspline->SetVNotPeriodic();
  }
  GeomConvert_BSplineSurfaceToBezierSurface convert(bspline);
  const int nu = convert.NbUPatches(), nv = convert.NbVPatches();
  TColGeom_Array2OfBezierSurface patches(1, nu, 1, nv);
  convert.Patches(patches);
  TColStd_Array1OfReal uKnots(1, nu + 1), vKnots(1, nv + 1);
  convert.UKnots(uKnots);
  convert.VKnots(vKnots);
  for (int i = 1; i <= nu + 1; ++i) out->uBreaks_.push_back(uKnots(i));
  for (int j = 1; j <= nv + 1; ++j) out->vBreaks_.push_back(vKnots(j));

  const int p = out->p_, q = out->q_;
  const Eigen::MatrixXd mu = bernsteinToPower(p), mv = bernsteinToPower(q);
  out->a_.resize(static_cast<std::size_t>(nu) * nv * (p + 1) * (q + 1));
  Eigen::MatrixXd b(p + 1, q + 1);
  for (int i = 1; i <= nu; ++i) {
    for (int j = 1; j <= nv; ++j) {
      const Handle(Geom_BezierSurface)& patch = patches(i, j);
      Eigen::Vector4d* a = &out->a_[((static_cast<std::size_t>(i) - 1) * nv + (j - 1)) * (p + 1) * (q + 1)];
      for (int c = 0; c < 4; ++c) {  // one homogeneous coordinate at a time: a = M^p b (M^q)^T
        for (int k = 0; k <= p; ++k) {
          for (int l = 0; l <= q; ++l) {
            const double w = patch->Weight(k + 1, l + 1);
            b(k, l) = c < 3 ? w * patch->Pole(k + 1, l + 1).Coord(c + 1) : w;
          }
        }
        const Eigen::MatrixXd power = mu * b * mv.transpose();
        for (int k = 0; k <= p; ++k) {
          for (int l = 0; l <= q; ++l) a[k * (q + 1) + l][c] = power(k, l);
        }
      }
    }
  }
  return out;
}

void PowerPatches::d2(double u, double v, gp_Pnt& p, gp_Vec& su, gp_Vec& sv, gp_Vec& suu, gp_Vec& svv,
                      gp_Vec& suv) const {
  u = wrap(u, uFirst_, uPeriod_);
  v = wrap(v, vFirst_, vPeriod_);
  const int i = spanOf(uBreaks_, u), j = spanOf(vBreaks_, v);
  const double hu = uBreaks_[i + 1] - uBreaks_[i], hv = vBreaks_[j + 1] - vBreaks_[j];
  const double s = (u - uBreaks_[i]) / hu, t = (v - vBreaks_[j]) / hv;
  const int nv = static_cast<int>(vBreaks_.size()) - 1;
  const Eigen::Vector4d* a = &a_[(static_cast<std::size_t>(i) * nv + j) * (p_ + 1) * (q_ + 1)];

  // Horner in s over the rows' values r_k(t), r_k'(t), r_k''(t), each by Horner in t
  // (value, first and half the second derivative: d2 = d2 t + d1, d1 = d1 t + x, x = x t + c).
  Eigen::Vector4d A = Eigen::Vector4d::Zero(), As = A, Ass = A, At = A, Ast = A, Att = A;
  for (int k = p_; k >= 0; --k) {
    const Eigen::Vector4d* row = a + k * (q_ + 1);
    Eigen::Vector4d r = row[q_], r1 = Eigen::Vector4d::Zero(), r2 = Eigen::Vector4d::Zero();
    for (int l = q_ - 1; l >= 0; --l) {
      r2 = r2 * t + r1;
      r1 = r1 * t + r;
      r = r * t + row[l];
    }
    Ass = Ass * s + As;
    As = As * s + A;
    A = A * s + r;
    Ast = Ast * s + At;
    At = At * s + r1;
    Att = Att * s + 2.0 * r2;
  }
  Ass *= 2.0;
  // To (u, v): d/du = (1 / hu) d/ds.
  As /= hu;
  Ass /= hu * hu;
  At /= hv;
  Att /= hv * hv;
  Ast /= hu * hv;
  const double w = A[3];
  const Eigen::Vector3d S = A.head<3>() / w;
  const Eigen::Vector3d Su = (As.head<3>() - As[3] * S) / w;
  const Eigen::Vector3d Sv = (At.head<3>() - At[3] * S) / w;
  const Eigen::Vector3d Suu = (Ass.head<3>() - 2.0 * As[3] * Su - Ass[3] * S) / w;
  const Eigen::Vector3d Svv = (Att.head<3>() - 2.0 * At[3] * Sv - Att[3] * S) / w;
  const Eigen::Vector3d Suv = (Ast.head<3>() - As[3] * Sv - At[3] * Su - Ast[3] * S) / w;
  p.SetCoord(S.x(), S.y(), S.z());
  su = vec(Su);
  sv = vec(Sv);
  suu = vec(Suu);
  svv = vec(Svv);
  suv = vec(Suv);
}

}  // namespace fairsplines::detail
