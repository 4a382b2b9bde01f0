// Fitted boundary data of a face blend (issue 29; docs/FACE_BLENDS.md section 1b): for an edge
// that is not an isoparametric boundary of its face (a trimmed edge, a seam, an edge across the
// parameter rectangle, a face whose surface has no exact B-spline form).
//
// Method. The face is reparametrised near the edge as X(u, v) = C(u) + v T(u) + v^2/2 K(u), with
//   C(u) = S(c(u))                    the edge as the face sees it (S the surface, c the pcurve),
//   T(u) = unit(N x C') towards the face,   the cross-boundary direction in the tangent plane,
//   K(u) = k_n(T) N                     N the unit normal, k_n(T) = II(T, T) / I(T, T) the face's
//                                       normal curvature in the direction T (do Carmo section 3-2).
// X has the face's normal (C' x T is normal to the tangent plane) and its whole second
// fundamental form along v = 0: N . C'' = II(C', C') (C lies on S), N . T' = II(C', T) (T . N = 0
// along the edge, so T' . N = -T . N' = II(C', T) by Weingarten's equations), N . K = II(T, T). So a
// blend with second-order contact to X is G2 to the face (G1: C and T). C, T and K are sampled
// from OCCT's D2 of the surface and fitted together, by least squares, with one quintic B-spline
// on a knot vector in u (Piegl & Tiller, The NURBS Book, section 9.4.1: least-squares curve
// approximation); knots go where the data loses smoothness (the pcurve's knots, the surface's knot
// lines crossed), of the multiplicity that lets the fit follow it. The fit is judged against the
// face at points between the samples (position, normal, normal curvature along, across and at 45
// degrees: the quantities, aiming at a tenth of its tolerances), and the failing spans are
// halved (and their long neighbours: a graded knot vector) and the data fitted again, until the
// aim holds, or the spans reach kMinSpan and the tolerances themselves hold, or the budget
// (kMaxSpans spans, kMaxRounds rounds) is spent: then InputError names the edge. The side leaves
// as a B-spline surface of v-degree 2 whose three rows of poles are the poles of C, C + T/2 and
// C + T + K/2 (v-knots 0, 0, 0, 1, 1, 1): the exact route's boundaryRows then reads back r0 = C,
// d1 = T, d2 = K, and the rest of the blend is built as for exact sides.
#include <Eigen/Geometry>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <Geom2d_BSplineCurve.hxx>
#include <Geom2d_TrimmedCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "fairsplines/errors.hpp"
#include "face_blend_detail.hpp"
#include "monotone_common.hpp"

namespace fairsplines::face_blend_detail {

namespace {

using detail::num;

constexpr int kDegree = 5;        // the fit's degree in u
constexpr int kPerSpan = 6;       // samples per span (and check points between them)
constexpr int kInitialSpans = 8;  // before the breaks of the data
constexpr int kMaxSpans = 1024;   // the budget: spans of the fit
constexpr int kMaxRounds = 40;    // the budget: rounds of halving
constexpr double kMargin = 0.1;   // the fit aims at a tenth of each tolerance at its check points
// Spans are not halved below this (of u in [0, 1]): the fit's rounding error e in position becomes
// e / h^2 in its second derivatives, so shorter spans would add noise, not accuracy.
constexpr double kMinSpan = 1e-4;

// ---------------------------------------------------------------------------------------
// The face along the edge

/// The face's surface and its derivatives at the edge's point u, and the fit's targets C, T, K.
struct FaceJet {
  Vec3 P, Su, Sv, Suu, Suv, Svv;  // S and its derivatives in the surface's parameters
  Vec3 N;                         // unit normal, Su x Sv
  Vec3 tau;                       // dC/du, the edge's tangent in the blend's u
  Vec3 T;                         // unit cross-boundary direction into the face
  double kT = 0.0;                // k_n(T)
};

Vec3 vec(const gp_XYZ& p) { return Vec3(p.X(), p.Y(), p.Z()); }

}  // namespace

double normalCurvature(const Vec3& Xu, const Vec3& Xv, const Vec3& Xuu, const Vec3& Xuv, const Vec3& Xvv, const Vec3& N,
                       const Vec3& d) {
  // d = a Xu + b Xv by least squares (the first fundamental form), then II(d, d) / I(d, d).
  const double E = Xu.dot(Xu), F = Xu.dot(Xv), G = Xv.dot(Xv), det = E * G - F * F;
  const double a = (G * Xu.dot(d) - F * Xv.dot(d)) / det, b = (E * Xv.dot(d) - F * Xu.dot(d)) / det;
  const Vec3 t = a * Xu + b * Xv;
  return (a * a * N.dot(Xuu) + 2.0 * a * b * N.dot(Xuv) + b * b * N.dot(Xvv)) / t.squaredNorm();
}

namespace {

FaceJet faceAt(const FittedEdge& e, double u) {
  const double t = e.from + u * (e.to - e.from);
  gp_Pnt2d uv;
  gp_Vec2d duv;
  e.pcurve->D1(t, uv, duv);
  gp_Pnt P;
  gp_Vec Su, Sv, Suu, Svv, Suv;
  e.surface->D2(uv.X(), uv.Y(), P, Su, Sv, Suu, Svv, Suv);
  FaceJet j;
  j.P = vec(P.XYZ());
  j.Su = vec(Su.XYZ());
  j.Sv = vec(Sv.XYZ());
  j.Suu = vec(Suu.XYZ());
  j.Suv = vec(Suv.XYZ());
  j.Svv = vec(Svv.XYZ());
  const Vec3 normal = j.Su.cross(j.Sv);
  const double scale = j.Su.norm() * j.Sv.norm();
  if (!(normal.norm() > 1e-12 * scale) || !std::isfinite(normal.norm()))
    throw InputError(e.faceName + " has no normal at u = " + num(u) + " of " + e.edgeName +
                     " (its surface is singular there)");
  j.N = normal.normalized();
  j.tau = (e.to - e.from) * (duv.X() * j.Su + duv.Y() * j.Sv);
  if (!(j.tau.norm() > 0)) throw InputError(e.edgeName + " stands still at u = " + num(u) + " (a singular point)");
  // The face's side in the parameter plane, carried to space; T lies in the tangent plane,
  // normal to the edge, on that side.
  const Vec3 inward = e.inward * (-duv.Y() * j.Su + duv.X() * j.Sv);
  j.T = j.N.cross(j.tau).normalized();
  if (j.T.dot(inward) < 0) j.T = -j.T;
  j.kT = normalCurvature(j.Su, j.Sv, j.Suu, j.Suv, j.Svv, j.N, j.T);
  return j;
}

// ---------------------------------------------------------------------------------------
// The least-squares fit of C, T, K (9 coordinates) on one knot vector

struct Knots {
  std::map<double, int> interior;  // u -> multiplicity
  std::vector<double> flat() const {
    std::vector<double> t(kDegree + 1, 0.0);
    for (const auto& [u, m] : interior) t.insert(t.end(), m, u);
    t.insert(t.end(), kDegree + 1, 1.0);
    return t;
  }
  std::vector<double> breaks() const {
    std::vector<double> b{0.0};
    for (const auto& [u, m] : interior) b.push_back(u);
    b.push_back(1.0);
    return b;
  }
};

using Data = Eigen::Matrix<double, 1, 9>;

Data target(const FaceJet& j) {
  Data d;
  d << j.P.transpose(), j.T.transpose(), (j.kT * j.N).transpose();
  return d;
}

/// The degree-5 B-spline basis functions non-zero at u and their first `order` (<= 2) derivatives,
/// for the flat knots t: ders[k][j] is the k-th derivative of N_{first + j} (Piegl & Tiller, The
/// NURBS Book, algorithms A2.1 FindSpan and A2.3 DersBasisFuns, without tolerances: the span is
/// the one with t[i] <= u < t[i + 1], the last one at u = 1).
std::array<std::array<double, kDegree + 1>, 3> basisAt(const std::vector<double>& t, int order, double u, int& first) {
  constexpr int p = kDegree;
  const int n = static_cast<int>(t.size()) - p - 2;  // the last basis function's index
  int i = n;
  if (u < t[n + 1]) i = static_cast<int>(std::upper_bound(t.begin() + p, t.begin() + n + 1, u) - t.begin()) - 1;
  first = i - p;
  double ndu[p + 1][p + 1], left[p + 1], right[p + 1];
  ndu[0][0] = 1.0;
  for (int j = 1; j <= p; ++j) {
    left[j] = u - t[i + 1 - j];
    right[j] = t[i + j] - u;
    double saved = 0.0;
    for (int r = 0; r < j; ++r) {
      ndu[j][r] = right[r + 1] + left[j - r];
      const double temp = ndu[r][j - 1] / ndu[j][r];
      ndu[r][j] = saved + right[r + 1] * temp;
      saved = left[j - r] * temp;
    }
    ndu[j][j] = saved;
  }
  std::array<std::array<double, p + 1>, 3> ders{};
  for (int j = 0; j <= p; ++j) ders[0][j] = ndu[j][p];
  double a[2][p + 1];
  for (int r = 0; r <= p; ++r) {
    int s1 = 0, s2 = 1;
    a[0][0] = 1.0;
    for (int k = 1; k <= order; ++k) {
      double d = 0.0;
      const int rk = r - k, pk = p - k;
      if (r >= k) {
        a[s2][0] = a[s1][0] / ndu[pk + 1][rk];
        d = a[s2][0] * ndu[rk][pk];
      }
      const int j1 = rk >= -1 ? 1 : -rk, j2 = r - 1 <= pk ? k - 1 : p - r;
      for (int j = j1; j <= j2; ++j) {
        a[s2][j] = (a[s1][j] - a[s1][j - 1]) / ndu[pk + 1][rk + j];
        d += a[s2][j] * ndu[rk + j][pk];
      }
      if (r <= pk) {
        a[s2][k] = -a[s1][k - 1] / ndu[pk + 1][r];
        d += a[s2][k] * ndu[r][pk];
      }
      ders[k][r] = d;
      std::swap(s1, s2);
    }
  }
  for (int k = 1, f = p; k <= order; f *= p - k, ++k)
    for (int j = 0; j <= p; ++j) ders[k][j] *= f;
  return ders;
}

struct Fit {
  std::vector<double> flat;  // the flat knots
  Eigen::MatrixXd poles;     // (number of basis functions) x 9

  /// Values and first two derivatives of the 9 coordinates at u.
  std::array<Data, 3> jet(double u) const {
    int first = 0;
    const auto basis = basisAt(flat, 2, u, first);
    std::array<Data, 3> out{Data::Zero(), Data::Zero(), Data::Zero()};
    for (int d = 0; d < 3; ++d)
      for (int k = 0; k <= kDegree; ++k) out[d] += basis[d][k] * poles.row(first + k);
    return out;
  }
};

Fit fitData(const Knots& knots, const std::vector<double>& us, const std::vector<Data>& values,
            const std::string& what) {
  Fit fit;
  fit.flat = knots.flat();
  const int count = static_cast<int>(fit.flat.size()) - kDegree - 1;
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::MatrixXd Y(us.size(), 9);
  for (size_t s = 0; s < us.size(); ++s) {
    int first = 0;
    const auto basis = basisAt(fit.flat, 0, us[s], first);
    for (int k = 0; k <= kDegree; ++k) entries.emplace_back(static_cast<int>(s), first + k, basis[0][k]);
    Y.row(s) = values[s];
  }
  Eigen::SparseMatrix<double> A(static_cast<int>(us.size()), count);
  A.setFromTriplets(entries.begin(), entries.end());
  // The normal equations A^T A P = A^T Y: banded, positive definite with kPerSpan >= degree + 1
  // samples in every span (Schoenberg-Whitney).
  const Eigen::SparseMatrix<double> AtA = A.transpose() * A;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(AtA);
  if (solver.info() != Eigen::Success) throw InputError(what + ": its least-squares fit is singular");
  fit.poles = solver.solve(A.transpose() * Y);
  if (!fit.poles.allFinite()) throw InputError(what + ": its least-squares fit is not finite");
  return fit;
}

// ---------------------------------------------------------------------------------------
// Where the data loses smoothness: knots of the pcurve, knot lines of the surface crossed

/// Continuity of a B-spline with degree p at a knot of multiplicity m.
int knotContinuity(int p, int m) { return p - m; }

// The data's continuity where the surface is C^cs and the pcurve C^cp: C = S(c) is C^min(cs, cp),
// T (first derivatives of S, c') C^min(cs - 1, cp - 1), K (second derivatives of S, c') and so the
// face's normal curvature along a curve that crosses a knot line C^min(cs - 2, cp - 1). The fit's
// knot takes the least of those it fits (G1 uses C and T only).
int dataContinuity(int cs, int cp, bool g2) { return std::min(g2 ? cs - 2 : cs - 1, cp - 1); }

void addBreak(Knots& knots, double u, int continuity) {
  if (!(u > 1e-9 && u < 1 - 1e-9) || continuity >= kDegree - 1) return;
  const int m = kDegree - std::max(continuity, 0);
  for (auto& [v, mult] : knots.interior)
    if (std::abs(v - u) <= 1e-9) {
      mult = std::max(mult, m);
      return;
    }
  knots.interior[u] = m;
}

void pcurveBreaks(const FittedEdge& e, bool g2, Knots& knots) {
  Handle(Geom2d_Curve) c = e.pcurve;
  const Handle(Geom2d_TrimmedCurve) trimmed = Handle(Geom2d_TrimmedCurve)::DownCast(c);
  if (!trimmed.IsNull()) c = trimmed->BasisCurve();
  const Handle(Geom2d_BSplineCurve) b = Handle(Geom2d_BSplineCurve)::DownCast(c);
  if (b.IsNull()) return;
  for (int k = 2; k < b->NbKnots(); ++k)
    addBreak(knots, (b->Knot(k) - e.from) / (e.to - e.from),
             dataContinuity(kDegree, knotContinuity(b->Degree(), b->Multiplicity(k)), g2));
}

void surfaceBreaks(const FittedEdge& e, bool g2, Knots& knots) {
  Handle(Geom_Surface) s = e.surface;
  const Handle(Geom_RectangularTrimmedSurface) trimmed = Handle(Geom_RectangularTrimmedSurface)::DownCast(s);
  if (!trimmed.IsNull()) s = trimmed->BasisSurface();
  const Handle(Geom_BSplineSurface) b = Handle(Geom_BSplineSurface)::DownCast(s);
  if (b.IsNull()) return;
  // Each interior knot line w = k of the surface (w = u or v) crossed by the pcurve: sign changes
  // of w(c(t)) - k at 257 samples, then bisection.
  const int samples = 256;
  auto coordinate = [&](double u, int axis) {
    const gp_Pnt2d p = e.pcurve->Value(e.from + u * (e.to - e.from));
    return axis == 0 ? p.X() : p.Y();
  };
  for (int axis = 0; axis < 2; ++axis) {
    const int nk = axis == 0 ? b->NbUKnots() : b->NbVKnots();
    const int degree = axis == 0 ? b->UDegree() : b->VDegree();
    for (int k = 2; k < nk; ++k) {
      const double knot = axis == 0 ? b->UKnot(k) : b->VKnot(k);
      const int c =
          dataContinuity(knotContinuity(degree, axis == 0 ? b->UMultiplicity(k) : b->VMultiplicity(k)), kDegree, g2);
      double previous = coordinate(0.0, axis) - knot;
      for (int i = 1; i <= samples; ++i) {
        double lo = static_cast<double>(i - 1) / samples, hi = static_cast<double>(i) / samples;
        const double now = coordinate(hi, axis) - knot;
        if ((previous < 0) != (now < 0)) {
          double flo = previous;
          for (int it = 0; it < 60; ++it) {
            const double mid = 0.5 * (lo + hi), fm = coordinate(mid, axis) - knot;
            ((flo < 0) == (fm < 0) ? lo : hi) = mid;
            if ((flo < 0) == (fm < 0)) flo = fm;
          }
          addBreak(knots, 0.5 * (lo + hi), c);
        }
        previous = now;
      }
    }
  }
}

// ---------------------------------------------------------------------------------------
// The check between the samples

struct Misfit {
  double gap = 0.0, angle = 0.0, curvature = 0.0;
};

/// The fitted X against the face at u: position (over size), normal angle (degrees), normal
/// curvature along, across and at 45 degrees (over the curvature scale; G2 only).
Misfit misfit(const Fit& fit, const FaceJet& f, double u, double size, double scale, bool g2) {
  const auto x = fit.jet(u);
  const Vec3 C = x[0].segment<3>(0).transpose(), C1 = x[1].segment<3>(0).transpose();
  const Vec3 C2 = x[2].segment<3>(0).transpose(), T = x[0].segment<3>(3).transpose();
  const Vec3 T1 = x[1].segment<3>(3).transpose(), K = x[0].segment<3>(6).transpose();
  Misfit m;
  m.gap = (C - f.P).norm() / size;
  const Vec3 n = C1.cross(T);
  m.angle = std::atan2(n.cross(f.N).norm(), std::abs(n.dot(f.N))) * 180.0 / M_PI;
  if (!g2) return m;
  const Vec3 along = f.tau.normalized(), across = f.N.cross(along), diagonal = (along + across) / std::sqrt(2.0);
  for (const Vec3& d : {along, across, diagonal}) {
    const double kX = normalCurvature(C1, T, C2, T1, K, f.N, d);
    const double kF = normalCurvature(f.Su, f.Sv, f.Suu, f.Suv, f.Svv, f.N, d);
    m.curvature = std::max(m.curvature, std::abs(kX - kF) / scale);
  }
  if (!std::isfinite(m.gap + m.angle + m.curvature)) m.gap = std::numeric_limits<double>::infinity();
  return m;
}

/// The face's largest |normal curvature| along, across and at 45 degrees at a sample.
double curvatureScale(const FaceJet& f) {
  const Vec3 along = f.tau.normalized(), across = f.N.cross(along), diagonal = (along + across) / std::sqrt(2.0);
  double k = 0.0;
  for (const Vec3& d : {along, across, diagonal})
    k = std::max(k, std::abs(normalCurvature(f.Su, f.Sv, f.Suu, f.Suv, f.Svv, f.N, d)));
  return k;
}

/// The side as a B-spline surface of v-degree 2 (v-knots 0, 0, 0, 1, 1, 1) whose rows of poles are
/// C, C + T/2, C + T + K/2: eq. (2.1) reads back P = C, P_v = T, P_vv = K.
Handle(Geom_BSplineSurface) rowsSurface(const Fit& fit, const Knots& knots) {
  const int nu = static_cast<int>(fit.poles.rows());
  TColgp_Array2OfPnt poles(1, nu, 1, 3);
  for (int i = 0; i < nu; ++i) {
    const Vec3 C = fit.poles.block<1, 3>(i, 0).transpose(), T = fit.poles.block<1, 3>(i, 3).transpose();
    const Vec3 K = fit.poles.block<1, 3>(i, 6).transpose();
    const Vec3 rows[3] = {C, C + 0.5 * T, C + T + 0.5 * K};
    for (int r = 0; r < 3; ++r) poles(i + 1, r + 1) = gp_Pnt(rows[r][0], rows[r][1], rows[r][2]);
  }
  const int nk = static_cast<int>(knots.interior.size()) + 2;
  TColStd_Array1OfReal ku(1, nk), kv(1, 2);
  TColStd_Array1OfInteger mu(1, nk), mv(1, 2);
  ku(1) = 0.0;
  mu(1) = kDegree + 1;
  int k = 2;
  for (const auto& [u, m] : knots.interior) {
    ku(k) = u;
    mu(k++) = m;
  }
  ku(nk) = 1.0;
  mu(nk) = kDegree + 1;
  kv(1) = 0.0;
  kv(2) = 1.0;
  mv(1) = mv(2) = 3;
  return new Geom_BSplineSurface(poles, ku, kv, mu, mv, kDegree, 2);
}

/// Halves every span more than twice as long as a neighbour, until none is: a fit's error at a
/// knot is shared by the spans on both sides (they meet there), so a long span beside short ones
/// would carry its error into them, where their derivatives magnify it.
void grade(Knots& knots) {
  for (bool changed = true; changed;) {
    changed = false;
    const std::vector<double> b = knots.breaks();
    for (size_t i = 0; i + 1 < b.size(); ++i) {
      const double w = b[i + 1] - b[i];
      const bool longer =
          (i > 0 && w > 2.0 * (b[i] - b[i - 1])) || (i + 2 < b.size() && w > 2.0 * (b[i + 2] - b[i + 1]));
      if (longer) {
        knots.interior.emplace(0.5 * (b[i] + b[i + 1]), 1);
        changed = true;
      }
    }
  }
}

}  // namespace

FittedSide fitSide(const FittedEdge& e, int continuity, double size) {
  const bool g2 = continuity == 2;
  const std::string what = e.edgeName + "'s fitted boundary";
  Knots knots;
  for (int k = 1; k < kInitialSpans; ++k) knots.interior[static_cast<double>(k) / kInitialSpans] = 1;
  pcurveBreaks(e, g2, knots);
  surfaceBreaks(e, g2, knots);
  std::map<double, FaceJet> cache;  // the face at every u sampled or checked so far
  auto face = [&](double u) -> const FaceJet& {
    auto it = cache.find(u);
    if (it == cache.end()) it = cache.emplace(u, faceAt(e, u)).first;
    return it->second;
  };
  double scale = 1.0 / size;
  FittedSide out;
  for (int round = 0;; ++round) {
    const std::vector<double> b = knots.breaks();
    std::vector<double> us;
    std::vector<Data> values;
    for (size_t i = 0; i + 1 < b.size(); ++i)
      for (int k = 0; k < kPerSpan; ++k) us.push_back(b[i] + (b[i + 1] - b[i]) * k / kPerSpan);
    us.push_back(1.0);
    for (double u : us) {
      const FaceJet& f = face(u);
      values.push_back(target(f));
      if (g2) scale = std::max(scale, curvatureScale(f));
    }
    const Fit fit = fitData(knots, us, values, what);
    // Check between the samples; halve the spans that fail.
    Misfit worst;
    std::vector<double> halves;
    for (size_t i = 0; i + 1 < b.size(); ++i) {
      bool fails = false;
      for (int k = 0; k < kPerSpan; ++k) {
        const double u = b[i] + (b[i + 1] - b[i]) * (k + 0.5) / kPerSpan;
        const Misfit m = misfit(fit, face(u), u, size, scale, g2);
        worst.gap = std::max(worst.gap, m.gap);
        worst.angle = std::max(worst.angle, m.angle);
        worst.curvature = std::max(worst.curvature, m.curvature);
        fails = fails || !(m.gap <= kMargin * kGapTolerance && m.angle <= kMargin * kAngleTolerance &&
                           m.curvature <= kMargin * kCurvatureTolerance);
      }
      if (fails && b[i + 1] - b[i] >= 2.0 * kMinSpan) halves.push_back(0.5 * (b[i] + b[i + 1]));
    }
    out.gap = worst.gap;
    out.angle = worst.angle;
    out.curvature = worst.curvature;
    out.spans = static_cast<int>(b.size()) - 1;
    out.refinements = round;
    out.samples = static_cast<int>(us.size());
    // Done when every check meets its aim, or when no failing span may be halved and the
    // tolerances themselves hold.
    const bool within =
        worst.gap <= kGapTolerance && worst.angle <= kAngleTolerance && worst.curvature <= kCurvatureTolerance;
    if (halves.empty() && within) {
      out.surface = rowsSurface(fit, knots);
      return out;
    }
    if (halves.empty() || round + 1 >= kMaxRounds || out.spans + static_cast<int>(halves.size()) > kMaxSpans)
      throw InputError(e.edgeName + " could not be fitted within the tolerances (" + std::to_string(out.spans) +
                       " spans, " + std::to_string(round) + " refinements; worst gap " + num(worst.gap) +
                       " of the size, angle " + num(worst.angle) + " deg, curvature " + num(worst.curvature) +
                       " of the curvature scale): its face is not smooth enough along it");
    for (double u : halves) knots.interior.emplace(u, 1);
    grade(knots);
  }
}

}  // namespace fairsplines::face_blend_detail
