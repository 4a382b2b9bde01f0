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
#include <cstring>

#include "vectorise.hpp"

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

/// The span of a sorted breakpoint list holding x: [0, spans - 1], the end spans beyond
/// (a binary search: Spans::build's table, and the buckets' few steps below).
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

/// A homogeneous point or vector (w x, w y, w z, w): one AVX register where the processor
/// has AVX (vectorise.hpp), two SSE2 registers elsewhere. Every operation acts on the four
/// coordinates alike, as Eigen's Vector4d did.
typedef double Homogeneous __attribute__((vector_size(32)));

/// The homogeneous point A(s, t) and its first and second derivatives in s and t.
struct HomogeneousD2 {
  Homogeneous A, As, At, Ass, Ast, Att;
};

/// HomogeneousD2 of one span's (p + 1) x (q + 1) power coefficients a_kl (4 doubles each) at
/// (s, t): Horner in s over the rows' values r_k(t), r_k'(t) and half r_k''(t), each by
/// Horner in t (d2 = d2 t + d1, d1 = d1 t + x, x = x t + c), its first steps, whose
/// accumulators are still 0, taken as the copies they amount to. P, Q > 0: the degrees, known
/// when compiling (the bicubic case: loops of fixed length, unrolled, the steps' choices
/// settled); 0: p and q as given.
template <int P, int Q>
__attribute__((always_inline)) inline HomogeneousD2 horner(const double* a, int p, int q, double s, double t) {
  if constexpr (P > 0) p = P;
  if constexpr (Q > 0) q = Q;
  const Homogeneous zero = {0.0, 0.0, 0.0, 0.0};
  HomogeneousD2 h{zero, zero, zero, zero, zero, zero};
  for (int k = p; k >= 0; --k) {
    const double* row = a + 4 * k * (q + 1);
    Homogeneous r, r1 = zero, r2 = zero, a_kl;
    std::memcpy(&r, row + 4 * q, sizeof r);
    for (int l = q - 1; l >= 0; --l) {
      std::memcpy(&a_kl, row + 4 * l, sizeof a_kl);
      if (l <= q - 3) r2 = r2 * t + r1;
      if (l == q - 2) r2 = r1;
      r1 = l <= q - 2 ? r1 * t + r : r;
      r = r * t + a_kl;
    }
    if (k == p) {
      h.A = r;
      h.At = r1;
      h.Att = r2;
      continue;
    }
    if (k <= p - 3) h.Ass = h.Ass * s + h.As;
    if (k == p - 2) h.Ass = h.As;
    h.As = k <= p - 2 ? h.As * s + h.A : h.A;
    h.A = h.A * s + r;
    h.Ast = k <= p - 2 ? h.Ast * s + h.At : h.At;
    h.At = h.At * s + r1;
    h.Att = h.Att * s + r2;
  }
  h.Ass *= 2.0;
  h.Att *= 2.0;  // the half r_k'' summed, then doubled: the same bits as summing 2 r_k''
  return h;
}

/// S and its derivatives in u and v at one point, the first three coordinates of each
/// (the fourth is left over from the homogeneous arithmetic).
struct Jet {
  Homogeneous S, Su, Sv, Suu, Svv, Suv;
};

/// The patches' arrays, for the loops below.
struct PatchView {
  int p, q;
  const PowerPatches::Spans &u, &v;
  const double* a;
};

/// The span holding x (spanOf's answer): its bucket's first candidate, then a step to the
/// next span without a branch, then (where knots crowd a bucket) a binary search among the
/// bucket's candidates.
__attribute__((always_inline)) inline int spanAt(const PowerPatches::Spans& d, double x) {
  const double f = (x - d.breaks[0]) * d.bucketsPerUnit;
  const int last = static_cast<int>(d.lower.size()) - 1;
  const int bucket = f > 0.0 ? (f < last ? static_cast<int>(f) : last) : 0;
  int span = d.lower[bucket];
  const int upper = d.upper[bucket];
  span += (span < upper) & (d.breaks[span + 1] <= x);
  if (span < upper && d.breaks[span + 1] <= x) {  // the last candidate with breaks[span] <= x
    const auto first = d.breaks.begin() + span + 2, last = d.breaks.begin() + upper + 1;
    span = static_cast<int>(std::upper_bound(first, last, x) - d.breaks.begin()) - 1;
  }
  return span;
}

/// The jet at (u, v): the span's power form by Horner's rule, then the quotient rule, and
/// d/du = (ds/du) d/ds. Inlined always, so that in jetsOf it is compiled for AVX too. P, Q:
/// as horner's.
template <int P = 0, int Q = 0>
__attribute__((always_inline)) inline Jet jetAt(const PatchView& w, double u, double v) {
  u = wrap(u, w.u.first, w.u.period);
  v = wrap(v, w.v.first, w.v.period);
  const int i = spanAt(w.u, u), j = spanAt(w.v, v);
  const double dsdu = w.u.scale[i], dtdv = w.v.scale[j];  // 1 / the span's widths: ds/du, dt/dv
  const double s = (u - w.u.breaks[i]) * dsdu, t = (v - w.v.breaks[j]) * dtdv;
  const int nv = static_cast<int>(w.v.breaks.size()) - 1;
  const double* a = w.a + 4 * (static_cast<std::size_t>(i) * nv + j) * (w.p + 1) * (w.q + 1);
  HomogeneousD2 h = horner<P, Q>(a, w.p, w.q, s, t);
  h.As *= dsdu;
  h.Ass *= dsdu * dsdu;
  h.At *= dtdv;
  h.Att *= dtdv * dtdv;
  h.Ast *= dsdu * dtdv;
  const double wInverse = 1.0 / h.A[3];  // one division; the quotient rule multiplies by 1 / w
  Jet x;
  x.S = h.A * wInverse;
  x.Su = (h.As - h.As[3] * x.S) * wInverse;
  x.Sv = (h.At - h.At[3] * x.S) * wInverse;
  x.Suu = (h.Ass - 2.0 * h.As[3] * x.Su - h.Ass[3] * x.S) * wInverse;
  x.Svv = (h.Att - 2.0 * h.At[3] * x.Sv - h.Att[3] * x.S) * wInverse;
  x.Suv = (h.Ast - h.As[3] * x.Sv - h.At[3] * x.Su - h.Ast[3] * x.S) * wInverse;
  return x;
}

gp_Vec vec(const Homogeneous& x) { return gp_Vec(x[0], x[1], x[2]); }

/// The jets of m points into the batch's arrays, compiled for AVX and for the baseline.
FAIRSPLINES_VECTORISE void jetsOf(const PatchView& w, const double* uv, std::ptrdiff_t stride, int m,
                                  CurvatureBatch& b) {
  const bool bicubic = w.p == 3 && w.q == 3;
  for (int i = 0; i < m; ++i) {
    const Jet x =
        bicubic ? jetAt<3, 3>(w, uv[i * stride], uv[i * stride + 1]) : jetAt(w, uv[i * stride], uv[i * stride + 1]);
    for (int c = 0; c < 3; ++c) {
      b.p[c][i] = x.S[c];
      b.su[c][i] = x.Su[c];
      b.sv[c][i] = x.Sv[c];
      b.suu[c][i] = x.Suu[c];
      b.svv[c][i] = x.Svv[c];
      b.suv[c][i] = x.Suv[c];
    }
  }
}

}  // namespace

void PowerPatches::Spans::build() {
  const int spans = static_cast<int>(breaks.size()) - 1;
  scale.clear();
  for (int i = 0; i < spans; ++i) scale.push_back(1.0 / (breaks[i + 1] - breaks[i]));
  // 8 buckets a span (at most 2^16): with even knots a bucket's candidates, taken half a
  // bucket wider each side (so that rounding of the bucket's index cannot leave the span
  // outside them), hold one knot at most.
  const int buckets = std::min(8 * spans, 1 << 16);
  const double width = (breaks.back() - breaks.front()) / buckets;
  bucketsPerUnit = 1.0 / width;
  lower.resize(buckets);
  upper.resize(buckets);
  for (int b = 0; b < buckets; ++b) {
    lower[b] = b == 0 ? 0 : spanOf(breaks, breaks.front() + (b - 0.5) * width);
    upper[b] = b == buckets - 1 ? spans - 1 : spanOf(breaks, breaks.front() + (b + 1.5) * width);
  }
}

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
  out->u_.first = u0;
  out->v_.first = v0;
  out->u_.period = bspline->IsUPeriodic() ? u1 - u0 : 0.0;
  out->v_.period = bspline->IsVPeriodic() ? v1 - v0 : 0.0;
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
  for (int i = 1; i <= nu + 1; ++i) out->u_.breaks.push_back(uKnots(i));
  for (int j = 1; j <= nv + 1; ++j) out->v_.breaks.push_back(vKnots(j));
  out->u_.build();
  out->v_.build();

  const int p = out->p_, q = out->q_;
  const Eigen::MatrixXd mu = bernsteinToPower(p), mv = bernsteinToPower(q);
  out->a_.resize(4 * static_cast<std::size_t>(nu) * nv * (p + 1) * (q + 1));
  Eigen::MatrixXd b(p + 1, q + 1);
  for (int i = 1; i <= nu; ++i) {
    for (int j = 1; j <= nv; ++j) {
      const Handle(Geom_BezierSurface)& patch = patches(i, j);
      double* a = &out->a_[4 * ((static_cast<std::size_t>(i) - 1) * nv + (j - 1)) * (p + 1) * (q + 1)];
      for (int c = 0; c < 4; ++c) {  // one homogeneous coordinate at a time: a = M^p b (M^q)^T
        for (int k = 0; k <= p; ++k) {
          for (int l = 0; l <= q; ++l) {
            const double w = patch->Weight(k + 1, l + 1);
            b(k, l) = c < 3 ? w * patch->Pole(k + 1, l + 1).Coord(c + 1) : w;
          }
        }
        const Eigen::MatrixXd power = mu * b * mv.transpose();
        for (int k = 0; k <= p; ++k) {
          for (int l = 0; l <= q; ++l) a[4 * (k * (q + 1) + l) + c] = power(k, l);
        }
      }
    }
  }
  return out;
}

void PowerPatches::d2(double u, double v, gp_Pnt& p, gp_Vec& su, gp_Vec& sv, gp_Vec& suu, gp_Vec& svv,
                      gp_Vec& suv) const {
  const PatchView w{p_, q_, u_, v_, a_.data()};
  const Jet x = p_ == 3 && q_ == 3 ? jetAt<3, 3>(w, u, v) : jetAt(w, u, v);
  p.SetCoord(x.S[0], x.S[1], x.S[2]);
  su = vec(x.Su);
  sv = vec(x.Sv);
  suu = vec(x.Suu);
  svv = vec(x.Svv);
  suv = vec(x.Suv);
}

void PowerPatches::jets(const double* uv, std::ptrdiff_t stride, int m, CurvatureBatch& batch) const {
  jetsOf(PatchView{p_, q_, u_, v_, a_.data()}, uv, stride, m, batch);
}

}  // namespace fairsplines::detail
