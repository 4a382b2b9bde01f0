// Fair blends in space (issue 28): the space spiral of the ends (space_spiral.hpp) followed
// by a C2 cubic whose curvature is proved monotone by the space certificate
// (certifySpaceCurvature, monotone_space.cpp); coplanar ends go to the planar solver. See
// fair_blend.hpp and docs/FAIR_BLENDS.md sections 8-10.
#include <BSplCLib.hxx>
#include <Geom_BSplineCurve.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <math_Matrix.hxx>

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <tuple>
#include <vector>

#include "fairsplines/errors.hpp"
#include "fairsplines/fair_blend.hpp"
#include "fairsplines/occt.hpp"
#include "clothoid.hpp"
#include "finite.hpp"
#include "space_spiral.hpp"
#include "spiral.hpp"
#include "work_budget.hpp"

namespace fairsplines {
namespace {

using Vec3 = Eigen::Vector3d;
using detail::SpaceSpiral;

constexpr int kMaxRounds = 12;       // refinement rounds
constexpr int kMaxSpans = 400;       // spans at the most
constexpr double kWorkBudget = 4e6;  // detail::WorkBudget units of one fairBlendSpace
constexpr double kCoplanar = 1e-12;  // out-of-plane part, relative, that counts as coplanar

/// End data in chord units: p0 = 0, |p1| = 1; unit tangents; curvature vectors.
struct Ends3 {
  Vec3 p1, T0, T1, K0, K1;
};

/// The first knots: m spans of equal arc length plus one knot in the middle of each end span
/// (room for the end 2-jets), as fractions of the length.
std::vector<double> firstKnots(int m) {
  std::vector<double> sigma{0.0, 0.5 / m};
  for (int j = 1; j < m; ++j) sigma.push_back(static_cast<double>(j) / m);
  sigma.push_back(1.0 - 0.5 / m);
  sigma.push_back(1.0);
  return sigma;
}

/// The polynomial C2 cubic on the knots sigma (parameter = arc-length fraction) that
/// interpolates the spiral at every interior knot but the first and the last and has the
/// ends' 2-jets F(0) = 0, F'(0) = L T0, F''(0) = L^2 K0, F(1) = p1, F'(1) = L T1,
/// F''(1) = L^2 K1 (the planar followCurve of fair_blend.cpp with weights 1).
BSplineCurve followSpiral(const SpaceSpiral& c, const Ends3& e, const std::vector<double>& sigma) {
  const int K = static_cast<int>(sigma.size());
  const int n = K + 2;
  TColStd_Array1OfReal knots(1, n + 4);
  for (int i = 0; i < n + 4; ++i) knots(i + 1) = sigma[std::clamp(i - 3, 0, K - 1)];
  // Each row has the 4 basis functions of one span: a sparse (banded) system, so that a
  // refined cubic of 400 spans costs O(n), not the O(n^3) of a dense solve.
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::MatrixXd B(n, 3);
  int row = 0;
  math_Matrix basis(1, 3, 1, 4);
  auto addRow = [&](double u, int order, const Vec3& rhs) {
    Standard_Integer first = 0;
    BSplCLib::EvalBsplineBasis(order, 4, knots, u, first, basis);
    for (int j = 0; j < 4; ++j) {
      if (basis(order + 1, j + 1) != 0.0) entries.emplace_back(row, first - 1 + j, basis(order + 1, j + 1));
    }
    B.row(row++) = rhs.transpose();
  };
  const double L = c.length;
  addRow(0.0, 0, Vec3::Zero());
  addRow(0.0, 1, L * e.T0);
  addRow(0.0, 2, L * L * e.K0);
  const std::vector<double> inner(sigma.begin() + 2, sigma.end() - 2);
  const std::vector<SpaceSpiral::Frame> frames = c.frames(inner);
  for (size_t j = 0; j < inner.size(); ++j) addRow(inner[j], 0, frames[j].x);
  addRow(1.0, 0, e.p1);
  addRow(1.0, 1, L * e.T1);
  addRow(1.0, 2, L * L * e.K1);
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(entries.begin(), entries.end());
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu(A);
  Eigen::MatrixXd P =
      lu.info() == Eigen::Success ? Eigen::MatrixXd(lu.solve(B)) : Eigen::MatrixXd(A.toDense().partialPivLu().solve(B));
  BSplineCurve curve;
  curve.degree = 3;
  curve.poles = P;
  curve.knots = Eigen::Map<const Eigen::VectorXd>(sigma.data(), K);
  curve.mults.setOnes(K);
  curve.mults[0] = curve.mults[K - 1] = 4;
  return curve;
}

/// The spiral followed by a certified cubic: spans are halved where the certificate does not
/// prove the curvature to run the way `wanted` (with two neighbours on each side), until it
/// does or the limits are reached.
std::pair<BSplineCurve, bool> certifiedFollow(const SpaceSpiral& c, const Ends3& e, CurvatureTrend wanted,
                                              bool refine) {
  std::vector<double> sigma = firstKnots(refine ? 4 : 8);
  BSplineCurve curve;
  for (int round = 0; round < (refine ? kMaxRounds : 1) && static_cast<int>(sigma.size()) - 1 <= kMaxSpans; ++round) {
    detail::WorkBudget::spend(64.0 * static_cast<double>(sigma.size()));
    curve = followSpiral(c, e, sigma);
    if (!curve.poles.allFinite()) break;
    const SpaceCurvatureCertificate cert = certifySpaceCurvature(curve);
    if (cert.monotone) return {curve, true};
    const int spans = static_cast<int>(sigma.size()) - 1;
    std::vector<char> halve(spans, 0);
    for (int i = 0; i < spans; ++i) {
      const CurvatureTrend t = cert.spans[i].trend;
      if (t == wanted || t == CurvatureTrend::Constant) continue;
      for (int k = std::max(0, i - 2); k <= std::min(spans - 1, i + 2); ++k) halve[k] = 1;
    }
    // A curvature step at a knot against the trend: halve around it too.
    for (const auto& x : cert.extrema) {
      for (int i = 0; i < spans; ++i) {
        if (std::get<0>(x) >= sigma[i] - 1e-15 && std::get<0>(x) <= sigma[i + 1] + 1e-15) {
          for (int k = std::max(0, i - 2); k <= std::min(spans - 1, i + 2); ++k) halve[k] = 1;
        }
      }
    }
    std::vector<double> refined{sigma[0]};
    for (int i = 0; i < spans; ++i) {
      if (halve[i]) refined.push_back(0.5 * (sigma[i] + sigma[i + 1]));
      refined.push_back(sigma[i + 1]);
    }
    if (refined.size() == sigma.size()) break;
    sigma = std::move(refined);
  }
  return {curve, false};
}

/// The model curve: p0 + r x, with the end poles the given points, their neighbours on the
/// tangent lines, and (G2) the third poles placed so that the end curvature vectors are the
/// given ones. At a clamped cubic's start with flat knots f, Q0 = 3 (P1 - P0) / (f4 - f1)
/// and c''(0) = 2 (3 (P2 - P1) / (f5 - f2) - Q0) / (f4 - f2), so kappa N(0), the part of c''
/// across the tangent over |Q0|^2, is 6 (P2 - P1)_perp / ((f5 - f2) (f4 - f2) |Q0|^2)
/// (the end by symmetry).
BSplineCurve toModel(const BSplineCurve& local, double r, const SpaceBlendEnds& ends, bool g2) {
  BSplineCurve out = local;
  const Eigen::Index n = local.poles.rows();
  for (Eigen::Index i = 0; i < n; ++i)
    out.poles.row(i) = (ends.p0 + r * Vec3(local.poles.row(i).transpose())).transpose();
  const Vec3 t0 = ends.t0.normalized(), t1 = ends.t1.normalized();
  out.poles.row(0) = ends.p0.transpose();
  out.poles.row(n - 1) = ends.p1.transpose();
  const Vec3 second = out.poles.row(1).transpose(), last2 = out.poles.row(n - 2).transpose();
  out.poles.row(1) = (ends.p0 + (second - ends.p0).dot(t0) * t0).transpose();
  out.poles.row(n - 2) = (ends.p1 - (ends.p1 - last2).dot(t1) * t1).transpose();
  if (!g2 || n < 6) return out;
  const Eigen::VectorXd& u = out.knots;
  const Eigen::Index last = u.size() - 1;
  for (const bool atEnd : {false, true}) {
    const Eigen::Index i0 = atEnd ? n - 1 : 0, i1 = atEnd ? n - 2 : 1, i2 = atEnd ? n - 3 : 2;
    const double gap1 = atEnd ? u[last] - u[last - 1] : u[1] - u[0];  // f4 - f2
    const double gap2 = atEnd ? u[last] - u[last - 2] : u[2] - u[0];  // f5 - f2
    const Vec3 P0 = out.poles.row(i0).transpose(), P1 = out.poles.row(i1).transpose(),
               P2 = out.poles.row(i2).transpose();
    const Vec3 t = atEnd ? t1 : t0, kN = atEnd ? ends.K1 : ends.K0;
    const double q0 = 3.0 * (P1 - P0).norm() / gap1;
    const Vec3 d = P2 - P1, along = d.dot(t) * t;
    const Vec3 across = (kN - kN.dot(t) * t) * (q0 * q0 * gap1 * gap2 / 6.0);
    out.poles.row(i2) = (P1 + along + across).transpose();
  }
  return out;
}

/// Scale-free curvature variation L^3 int (dkappa/ds)^2 ds of a space curve by OCCT's D3,
/// 8 Gauss points per span: d(kappa^2)/du = 2 (d1 x d2).(d1 x d3) / |d1|^6
/// - 6 |d1 x d2|^2 (d1.d2) / |d1|^8 (the certificate's N over |d1|^8), dkappa/ds =
/// d(kappa^2)/du / (2 kappa |d1|).
double spaceVariation(const BSplineCurve& curve) {
  const Handle(Geom_BSplineCurve) c = toOcct(curve);
  double length = 0.0, energy = 0.0;
  for (Eigen::Index i = 0; i + 1 < curve.knots.size(); ++i) {
    const double u0 = curve.knots[i], du = curve.knots[i + 1] - u0;
    for (int k = 0; k < 8; ++k) {
      const double x = 0.5 + (k < 4 ? -0.5 : 0.5) * detail::kGaussX[k % 4], w = 0.5 * detail::kGaussW[k % 4] * du;
      gp_Pnt p;
      gp_Vec v1, v2, v3;
      c->D3(u0 + x * du, p, v1, v2, v3);
      const Vec3 d1(v1.X(), v1.Y(), v1.Z()), d2(v2.X(), v2.Y(), v2.Z()), d3(v3.X(), v3.Y(), v3.Z());
      const double speed = d1.norm();
      const Vec3 X = d1.cross(d2);
      const double kappa = X.norm() / std::pow(speed, 3);
      const double dk2 =
          2.0 * X.dot(d1.cross(d3)) / std::pow(speed, 6) - 6.0 * X.squaredNorm() * d1.dot(d2) / std::pow(speed, 8);
      const double dkds = kappa > 0.0 ? dk2 / (2.0 * kappa * speed) : 0.0;
      length += w * speed;
      energy += w * dkds * dkds * speed;
    }
  }
  return energy * length * length * length;
}

int torsionChanges(const SpaceCurvatureCertificate& c) { return static_cast<int>(c.torsionSignChanges.size()); }

}  // namespace

SpaceFairBlend fairBlendSpace(const SpaceBlendEnds& ends) {
  requireFiniteInput(ends.p0, "p0");
  requireFiniteInput(ends.p1, "p1");
  requireFiniteInput(ends.t0, "t0");
  requireFiniteInput(ends.t1, "t1");
  const bool g2 = !ends.K0.hasNaN() || !ends.K1.hasNaN();
  if (g2 && (ends.K0.hasNaN() || ends.K1.hasNaN())) {
    throw InputError("give both end curvature vectors K0 and K1 for a G2 blend, or neither for G1");
  }
  if (g2) {
    requireFiniteInput(ends.K0, "K0");
    requireFiniteInput(ends.K1, "K1");
  }
  const Vec3 d = ends.p1 - ends.p0;
  const double size = std::max(ends.p0.cwiseAbs().maxCoeff(), ends.p1.cwiseAbs().maxCoeff());
  if (!(d.norm() > 1e-14 * std::max(size, 1e-300)))
    throw InputError("the end points p0 and p1 coincide: a blend needs two points");
  if (!(ends.t0.norm() > 0.0)) throw InputError("the start tangent t0 is zero");
  if (!(ends.t1.norm() > 0.0)) throw InputError("the end tangent t1 is zero");
  const double r = d.norm();
  const Vec3 u = d / r, T0 = ends.t0.normalized(), T1 = ends.t1.normalized();
  Vec3 K0 = Vec3::Zero(), K1 = Vec3::Zero();
  if (g2) {
    K0 = ends.K0 - ends.K0.dot(T0) * T0;  // the part across the tangent: kappa N
    K1 = ends.K1 - ends.K1.dot(T1) * T1;
    if (!(std::abs(ends.K0.dot(T0)) <= 1e-6 * std::max(ends.K0.norm(), 1e-300)) ||
        !(std::abs(ends.K1.dot(T1)) <= 1e-6 * std::max(ends.K1.norm(), 1e-300))) {
      throw InputError("a curvature vector must be perpendicular to its tangent (kappa N)");
    }
    if (!(K0.norm() * r <= 1e6) || !(K1.norm() * r <= 1e6)) {
      throw InputError("an end curvature is too large for the chord: its radius would be below a millionth of it");
    }
  }

  // Coplanar ends: the planar solver, in their plane.
  Vec3 normal = Vec3::Zero();
  for (const Vec3& v : {T0, T1, Vec3(K0.normalized()), Vec3(K1.normalized())}) {
    const Vec3 n = u.cross(v);
    if (n.norm() > normal.norm()) normal = n;
  }
  bool coplanar = true;
  if (normal.norm() > 1e-9) {
    normal.normalize();
    for (const Vec3& v : {T0, T1, K0, K1}) coplanar = coplanar && std::abs(v.dot(normal)) <= kCoplanar * v.norm();
  } else {
    normal = Vec3::Zero();  // everything along the chord
  }
  SpaceFairBlend out;
  std::ostringstream why;
  if (coplanar) {
    BlendEnds planar{ends.p0, ends.t0, ends.p1, ends.t1};
    planar.normal = normal;
    if (g2) {
      if (normal.norm() == 0.0) {
        planar.normal = u.cross(std::abs(u.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY()).normalized();
      }
      planar.k0 = K0.dot(planar.normal.cross(T0));
      planar.k1 = K1.dot(planar.normal.cross(T1));
    }
    const FairBlend b = fairBlend(planar);
    out.curve = b.curve;
    out.monotone = b.monotone;
    out.planar = true;
    out.normal = b.normal;
    out.length = b.length;
    out.reason = "coplanar ends: the planar fair blend; " + b.reason;
  } else {
    detail::WorkBudget budget(kWorkBudget, "the fair blend of these ends in space");
    const Ends3 e0{u, T0, T1, K0 * r, K1 * r};
    const detail::SpaceSpiralSolution sol =
        g2 ? detail::solveSpaceG2(T0, e0.K0, u, T1, e0.K1) : detail::solveSpaceG1(T0, u, T1);
    if (!sol.best) throw InputError(sol.reason + " (no fair blend in space was found)");
    const SpaceSpiral& s = *sol.best;
    Ends3 e = e0;
    if (!g2) {  // the spiral's end curvature vectors
      const SpaceSpiral::Frame f = s.end();
      e.K0 = s.k0 * s.N0;
      e.K1 = s.k1 * (f.N - f.N.dot(T1) * T1);
    }
    const CurvatureTrend wanted = s.k1 > s.k0 ? CurvatureTrend::Increasing : CurvatureTrend::Decreasing;
    // A monotone spiral is refined until the cubic is proved monotone; a non-monotone one is
    // followed with 8 spans (refining would only resolve its extrema into more of them).
    auto [local, proved] = certifiedFollow(s, e, wanted, sol.monotone);
    if (local.poles.rows() == 0 || !local.poles.allFinite()) {
      throw InputError("the cubic following the space spiral is not finite");
    }
    out.curve = toModel(local, r, ends, g2);
    out.length = s.length * r;
    why << (g2 ? "G2" : "G1") << " space spiral (curvature " << s.k0 / r << " to " << s.k1 / r << ", torsion "
        << s.torsion(0.0) / r << " to " << s.torsion(1.0) / r << ", " << sol.solutions
        << " solutions found) followed by " << out.curve.knots.size() - 1 << " C2 spans";
    if (!sol.monotone)
      why << "; " << sol.reason;
    else if (!proved)
      why << ", not all proved monotone";
    if (g2 && !sol.monotone) {
      // The fairest found: of this cubic and the G1 spiral followed with the given curvature
      // vectors (both G2 to the ends), the fewest curvature extrema, then the fewest torsion
      // sign changes, then the least variation.
      const detail::SpaceSpiralSolution g1 = detail::solveSpaceG1(T0, u, T1);
      if (g1.best) {
        const SpaceSpiral& c = *g1.best;
        BSplineCurve other = toModel(certifiedFollow(c, e0, wanted, false).first, r, ends, true);
        if (other.poles.allFinite()) {
          const SpaceCurvatureCertificate a = certifySpaceCurvature(out.curve), b = certifySpaceCurvature(other);
          const auto key = [](const SpaceCurvatureCertificate& x, const BSplineCurve& curve) {
            return std::make_tuple(x.extrema.size(), x.torsionSignChanges.size(), spaceVariation(curve));
          };
          if (key(b, other) < key(a, out.curve)) {
            out.curve = std::move(other);
            out.length = c.length * r;
            why << "; the G1 space spiral followed with the given curvature vectors is fairer (" << b.extrema.size()
                << " curvature extrema against " << a.extrema.size() << ") and is shown instead";
          }
        }
      }
    }
    out.reason = why.str();
  }
  requireFinite(out.curve.poles, "the space blend", "poles");
  out.certificate = certifySpaceCurvature(out.curve);
  if (!out.planar) out.monotone = out.certificate.monotone;
  out.curvatureExtrema = static_cast<int>(out.certificate.extrema.size());
  out.torsionSignChanges = torsionChanges(out.certificate);
  out.spans = static_cast<int>(out.curve.knots.size()) - 1;
  out.variation = spaceVariation(out.curve);
  out.reason += "; " + out.certificate.reason;
  return out;
}

}  // namespace fairsplines
