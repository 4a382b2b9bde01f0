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
#include <cstddef>

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
/// It counts the inner breakpoints <= x by a binary search whose steps are selects, not
/// branches: on scattered points a branch would be mispredicted at every other step.
int spanOf(const std::vector<double>& breaks, double x) {
  const double* const inner = breaks.data() + 1;
  const double* b = inner;
  std::size_t count = breaks.size() - 2;  // the answer lies in [b - inner, b - inner + count]
  while (count > 1) {
    const std::size_t half = count / 2;
    b = b[half - 1] <= x ? b + half : b;
    count -= half;
  }
  return static_cast<int>(b - inner) + (count == 1 && b[0] <= x ? 1 : 0);
}

/// x moved by whole periods into [first, first + period), for a periodic direction.
double wrap(double x, double first, double period) {
  if (period <= 0.0) return x;
  const double r = std::fmod(x - first, period);
  return first + (r < 0.0 ? r + period : r);
}

gp_Vec vec(const Eigen::Vector3d& x) { return gp_Vec(x.x(), x.y(), x.z()); }

/// The homogeneous point A(s, t) and its first and second derivatives in s and t.
struct HomogeneousD2 {
  Eigen::Vector4d A, As, At, Ass, Ast, Att;
};

/// HomogeneousD2 of one span's (p + 1) x (q + 1) power coefficients a_kl at (s, t): Horner in s
/// over the rows' values r_k(t), r_k'(t) and half r_k''(t), each by Horner in t
/// (d2 = d2 t + d1, d1 = d1 t + x, x = x t + c). P, Q > 0: the degrees, known when compiling
/// (the bicubic case: loops of fixed length, unrolled); 0: p and q as given.
template <int P, int Q>
HomogeneousD2 horner(const Eigen::Vector4d* a, int p, int q, double s, double t) {
  if constexpr (P > 0) p = P;
  if constexpr (Q > 0) q = Q;
  HomogeneousD2 h;
  h.A = h.As = h.Ass = h.At = h.Ast = h.Att = Eigen::Vector4d::Zero();
  for (int k = p; k >= 0; --k) {
    const Eigen::Vector4d* row = a + k * (q + 1);
    Eigen::Vector4d r = row[q], r1 = Eigen::Vector4d::Zero(), r2 = Eigen::Vector4d::Zero();
    for (int l = q - 1; l >= 0; --l) {
      r2 = r2 * t + r1;
      r1 = r1 * t + r;
      r = r * t + row[l];
    }
    h.Ass = h.Ass * s + h.As;
    h.As = h.As * s + h.A;
    h.A = h.A * s + r;
    h.Ast = h.Ast * s + h.At;
    h.At = h.At * s + r1;
    h.Att = h.Att * s + 2.0 * r2;
  }
  h.Ass *= 2.0;
  return h;
}

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
  for (int i = 0; i < nu; ++i) out->uScale_.push_back(1.0 / (out->uBreaks_[i + 1] - out->uBreaks_[i]));
  for (int j = 0; j < nv; ++j) out->vScale_.push_back(1.0 / (out->vBreaks_[j + 1] - out->vBreaks_[j]));

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
  const double dsdu = uScale_[i], dtdv = vScale_[j];  // 1 / the span's widths: ds/du, dt/dv
  const double s = (u - uBreaks_[i]) * dsdu, t = (v - vBreaks_[j]) * dtdv;
  const int nv = static_cast<int>(vBreaks_.size()) - 1;
  const Eigen::Vector4d* a = &a_[(static_cast<std::size_t>(i) * nv + j) * (p_ + 1) * (q_ + 1)];

  HomogeneousD2 h = p_ == 3 && q_ == 3 ? horner<3, 3>(a, p_, q_, s, t) : horner<0, 0>(a, p_, q_, s, t);
  Eigen::Vector4d &A = h.A, &As = h.As, &At = h.At, &Ass = h.Ass, &Ast = h.Ast, &Att = h.Att;
  // To (u, v): d/du = (ds/du) d/ds.
  As *= dsdu;
  Ass *= dsdu * dsdu;
  At *= dtdv;
  Att *= dtdv * dtdv;
  Ast *= dsdu * dtdv;
  const double wInverse = 1.0 / A[3];  // one division; the quotient rule multiplies by 1 / w
  const Eigen::Vector3d S = A.head<3>() * wInverse;
  const Eigen::Vector3d Su = (As.head<3>() - As[3] * S) * wInverse;
  const Eigen::Vector3d Sv = (At.head<3>() - At[3] * S) * wInverse;
  const Eigen::Vector3d Suu = (Ass.head<3>() - 2.0 * As[3] * Su - Ass[3] * S) * wInverse;
  const Eigen::Vector3d Svv = (Att.head<3>() - 2.0 * At[3] * Sv - Att[3] * S) * wInverse;
  const Eigen::Vector3d Suv = (Ast.head<3>() - As[3] * Sv - At[3] * Su - Ast[3] * S) * wInverse;
  p.SetCoord(S.x(), S.y(), S.z());
  su = vec(Su);
  sv = vec(Sv);
  suu = vec(Suu);
  svv = vec(Svv);
  suv = vec(Suv);
}

}  // namespace fairsplines::detail
