// Space spirals and the G1/G2 problems they solve; see space_spiral.hpp and
// docs/FAIR_BLENDS.md section 9.
#include "space_spiral.hpp"

#include <Eigen/Dense>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <functional>

#include "clothoid.hpp"
#include "spiral.hpp"
#include "work_budget.hpp"

namespace fairsplines::detail {
namespace {

using Vec3 = Eigen::Vector3d;
using VecX = Eigen::VectorXd;

constexpr double kStepRotation = 0.01;  // radians of the Darboux rotation per RK4 step, at most
constexpr int kMaxGrid = 1 << 14;
constexpr double kSolveTol = 1e-12;  // residual, chord units
constexpr int kMaxIterations = 60;

/// Two unit vectors completing t (unit) to an orthonormal basis.
void basisAround(const Vec3& t, Vec3& e1, Vec3& e2) {
  const Vec3 any = std::abs(t.x()) < 0.6 ? Vec3::UnitX() : (std::abs(t.y()) < 0.6 ? Vec3::UnitY() : Vec3::UnitZ());
  e1 = t.cross(any).normalized();
  e2 = t.cross(e1);
}

/// Damped Gauss-Newton with minimum-norm steps, dz = -J^T (J J^T + lambda I)^{-1} r
/// (Levenberg-Marquardt in its underdetermined form), J by forward differences. true when
/// |r| <= kSolveTol.
bool solve(const std::function<VecX(const VecX&)>& residual, VecX& z) {
  VecX r = residual(z);
  if (!r.allFinite()) return false;
  double lambda = 1e-6;
  for (int it = 0; it < kMaxIterations; ++it) {
    const double norm = r.norm();
    if (norm <= kSolveTol) return true;
    Eigen::MatrixXd J(r.size(), z.size());
    for (Eigen::Index i = 0; i < z.size(); ++i) {
      VecX zi = z;
      const double h = 1e-7 * std::max(1.0, std::abs(z[i]));
      zi[i] += h;
      const VecX ri = residual(zi);
      if (!ri.allFinite()) return false;
      J.col(i) = (ri - r) / h;
    }
    const Eigen::MatrixXd JJt = J * J.transpose();
    bool accepted = false;
    for (int tries = 0; tries < 12 && !accepted; ++tries) {
      Eigen::MatrixXd A = JJt;
      A.diagonal().array() += lambda * std::max(JJt.diagonal().maxCoeff(), 1e-300);
      const VecX dz = -J.transpose() * A.ldlt().solve(r);
      const VecX zn = z + dz;
      const VecX rn = residual(zn);
      if (rn.allFinite() && rn.norm() < norm) {
        z = zn;
        r = rn;
        lambda = std::max(lambda * 0.1, 1e-15);
        accepted = true;
      } else {
        lambda *= 10.0;
      }
    }
    if (!accepted) return r.norm() <= kSolveTol;
  }
  return r.norm() <= kSolveTol;
}

/// The fairer of two solutions: monotone first, then fewer torsion sign changes, then the
/// least variation.
bool fairer(const SpaceSpiral& x, const SpaceSpiral& y) {
  const bool mx = x.minSlope() >= kMinSlope, my = y.minSlope() >= kMinSlope;
  if (mx != my) return mx;
  const int tx = x.torsionSignChanges(), ty = y.torsionSignChanges();
  if (tx != ty) return tx < ty;
  return x.variation() < y.variation();
}

void consider(SpaceSpiralSolution& out, const SpaceSpiral& s) {
  ++out.solutions;
  if (!out.best || fairer(s, *out.best)) out.best = s;
  out.monotone = out.best->minSlope() >= kMinSlope;
}

bool settled(const SpaceSpiralSolution& out) { return out.best && out.monotone && out.best->torsionSignChanges() == 0; }

/// Positive curvature where the profile is negative throughout: kappa -> -kappa, N -> -N
/// (B -> -B, so the torsion keeps its sign).
void makePositive(SpaceSpiral& s) {
  if (s.k0 + s.k1 < 0.0) {
    s.k0 = -s.k0;
    s.k1 = -s.k1;
    s.a = -s.a;
    s.b = -s.b;
    s.N0 = -s.N0;
  }
}

}  // namespace

// ---------------------------------------------------------------------------------------
// The curve

double SpaceSpiral::kappa(double sigma) const {
  const double v = 1.0 - 2.0 * sigma;
  return k0 + (k1 - k0) * sigma + 0.25 * (1.0 - v * v) * (a + b * v);
}

double SpaceSpiral::dkappa(double sigma) const {
  const double v = 1.0 - 2.0 * sigma;  // spiral.hpp's profile: (k1 - k0 - b/2) + a v + (3b/2) v^2
  return (k1 - k0 - 0.5 * b) + a * v + 1.5 * b * v * v;
}

double SpaceSpiral::torsion(double sigma) const { return t0 + t1 * sigma + t2 * sigma * (1.0 - sigma); }

int SpaceSpiral::gridFor(double safety) const {
  double omega = 0.0;  // the largest Darboux rotation rate per unit sigma
  for (int i = 0; i <= 8; ++i) omega = std::max(omega, std::hypot(kappa(i / 8.0), torsion(i / 8.0)) * length);
  int n = 64;
  while (n < kMaxGrid && n * kStepRotation < safety * omega) n *= 2;
  return n;
}

std::vector<SpaceSpiral::Frame> SpaceSpiral::frames(const std::vector<double>& sigma) const {
  const int N = grid > 0 ? grid : gridFor(1.0);
  const double hGrid = 1.0 / N;
  // y = (x, T, N); dy/dsigma = L (T, kappa N, -kappa T + tau T x N): Frenet-Serret.
  auto f = [&](double s, const Vec3& T, const Vec3& Nv, Vec3& dx, Vec3& dT, Vec3& dN) {
    const double k = kappa(s) * length, t = torsion(s) * length;
    dx = length * T;
    dT = k * Nv;
    dN = -k * T + t * T.cross(Nv);
  };
  // One classical RK4 step of size h from s.
  auto step = [&](double s, double h, Vec3& x, Vec3& T, Vec3& Nv) {
    Vec3 a1, b1, c1, a2, b2, c2, a3, b3, c3, a4, b4, c4;
    f(s, T, Nv, a1, b1, c1);
    f(s + 0.5 * h, T + 0.5 * h * b1, Nv + 0.5 * h * c1, a2, b2, c2);
    f(s + 0.5 * h, T + 0.5 * h * b2, Nv + 0.5 * h * c2, a3, b3, c3);
    f(s + h, T + h * b3, Nv + h * c3, a4, b4, c4);
    x += h / 6.0 * (a1 + 2.0 * a2 + 2.0 * a3 + a4);
    T += h / 6.0 * (b1 + 2.0 * b2 + 2.0 * b3 + b4);
    Nv += h / 6.0 * (c1 + 2.0 * c2 + 2.0 * c3 + c4);
  };
  // The grid of N equal steps is walked whatever the targets, and a target between grid
  // points is one short step from the grid point before it: the points then carry the
  // grid's smooth global error, not one that changes with the set of targets (that noise,
  // 1e-9 at knots 1/128 apart, made the cubic's curvature wiggle).
  std::vector<Frame> out;
  out.reserve(sigma.size());
  Vec3 x = Vec3::Zero(), T = T0, Nv = N0;
  int i = 0, steps = 0;
  for (const double target : sigma) {
    const int j = std::clamp(static_cast<int>(std::floor(target * N + 1e-9)), 0, N);
    for (; i < j; ++i, ++steps) step(i * hGrid, hGrid, x, T, Nv);
    const double rest = target - i * hGrid;
    if (rest > 1e-15) {
      Vec3 xp = x, Tp = T, Np = Nv;
      step(i * hGrid, rest, xp, Tp, Np);
      out.push_back({xp, Tp, Np});
      ++steps;
    } else {
      out.push_back({x, T, Nv});
    }
  }
  WorkBudget::spend(0.25 * steps);
  return out;
}

double SpaceSpiral::minSlope() const {
  if (k0 * k1 < 0.0) return -1.0;  // the curvature passes through 0: |kappa| has a minimum
  const double d = k1 - k0;
  if (d == 0.0) return a == 0.0 && b == 0.0 ? 0.0 : -1.0;
  // sign(d) d kappa / d sigma = sign(d) ((d - b/2) + a v + (3b/2) v^2) over v in [-1, 1]:
  // the ends and the vertex v = -a / (3b).
  const double sg = d > 0.0 ? 1.0 : -1.0;
  auto slope = [&](double v) { return sg * ((d - 0.5 * b) + a * v + 1.5 * b * v * v); };
  double m = std::min(slope(-1.0), slope(1.0));
  if (b != 0.0 && std::abs(a / (3.0 * b)) <= 1.0) m = std::min(m, slope(-a / (3.0 * b)));
  return m / std::abs(d);
}

int SpaceSpiral::torsionSignChanges() const {
  int changes = 0, last = 0;
  for (int i = 0; i <= 32; ++i) {
    const double t = torsion(i / 32.0), scale = std::abs(t0) + std::abs(t1) + std::abs(t2);
    const int sg = t > 1e-9 * scale ? 1 : (t < -1e-9 * scale ? -1 : 0);
    if (sg != 0 && last != 0 && sg != last) ++changes;
    if (sg != 0) last = sg;
  }
  return changes;
}

double SpaceSpiral::variation() const {
  double v = 0.0;
  for (int k = 0; k < 8; ++k) {  // Gauss-Legendre, 8 points on [0, 1]: exact for these degrees
    const double x = 0.5 + (k < 4 ? -0.5 : 0.5) * kGaussX[k % 4], w = 0.5 * kGaussW[k % 4];
    const double dtau = t1 + t2 * (1.0 - 2.0 * x);
    v += w * (dkappa(x) * dkappa(x) + dtau * dtau);
  }
  return length * length * v;
}

// ---------------------------------------------------------------------------------------
// G1

SpaceSpiralSolution solveSpaceG1(const Vec3& T0, const Vec3& p1, const Vec3& T1) {
  SpaceSpiralSolution out;
  Vec3 E1, E2, F1, F2;
  basisAround(T0, E1, E2);
  basisAround(T1, F1, F2);
  const Vec3 u = p1.normalized();
  int grid = 0;  // the RK4 grid of the current solve
  auto spiralOf = [&](const VecX& z) {
    SpaceSpiral s;
    s.T0 = T0;
    s.N0 = std::cos(z[0]) * E1 + std::sin(z[0]) * E2;
    s.k0 = z[1];
    s.k1 = z[2];
    s.t0 = z[3];
    s.t1 = z[4];
    s.length = z[5];
    s.grid = grid;
    return s;
  };
  auto residual = [&](const VecX& z) {
    VecX r(5);
    if (!(z[5] > 0.0) || !(z[5] < 1e3)) return VecX(VecX::Constant(5, std::numeric_limits<double>::quiet_NaN()));
    const SpaceSpiral::Frame e = spiralOf(z).end();
    r << e.x - p1, e.T.dot(F1), e.T.dot(F2);
    return r;
  };
  // Starts: the planar G1 clothoid in planes through the chord, lifted to space with zero
  // torsion: the plane nearest both tangents (least squares), then those of each tangent.
  std::vector<Vec3> normals;
  {
    Vec3 c1, c2;
    basisAround(u, c1, c2);
    Eigen::Matrix2d M = Eigen::Matrix2d::Zero();
    for (const Vec3& t : {T0, T1}) {
      const Eigen::Vector2d q(t.dot(c1), t.dot(c2));
      M += q * q.transpose();
    }
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(M);
    const Eigen::Vector2d m = eig.eigenvectors().col(0);
    normals.push_back((m[0] * c1 + m[1] * c2).normalized());
    for (const Vec3& t : {T0, T1}) {
      const Vec3 n = u.cross(t);
      if (n.norm() > 1e-8) normals.push_back(n.normalized());
    }
  }
  for (const Vec3& n : normals) {
    const Vec3 e2 = n.cross(u);
    const double theta0 = std::atan2(T0.dot(e2), T0.dot(u)), theta1 = std::atan2(T1.dot(e2), T1.dot(u));
    const Clothoid c = clothoidG1(Eigen::Vector2d::Zero(), theta0, Eigen::Vector2d::UnitX(), theta1);
    if (!std::isfinite(c.length) || !(c.length > 0.0)) continue;
    const Vec3 N0 = n.cross(T0).normalized();  // signed curvature about n: T' = kappa n x T
    VecX z(6);
    z << std::atan2(N0.dot(E2), N0.dot(E1)), c.kappa0, c.kappa(c.length), 0.0, 0.0, c.length;
    grid = 0;
    grid = spiralOf(z).gridFor(1.0);  // fixed for the solve: the residual stays smooth
    if (!solve(residual, z)) continue;
    SpaceSpiral s = spiralOf(z);
    if (!(s.end().T.dot(T1) > 0.0)) continue;
    makePositive(s);
    consider(out, s);
    if (settled(out)) break;
  }
  if (!out.best)
    out.reason = "no space spiral of linear curvature and torsion meets these G1 ends";
  else if (!out.monotone)
    out.reason = "the space spirals found have curvature through zero";
  return out;
}

// ---------------------------------------------------------------------------------------
// G2

SpaceSpiralSolution solveSpaceG2(const Vec3& T0, const Vec3& K0, const Vec3& p1, const Vec3& T1, const Vec3& K1) {
  SpaceSpiralSolution out;
  Vec3 E1, E2, F1, F2;
  basisAround(T0, E1, E2);
  basisAround(T1, F1, F2);
  const double k0 = K0.norm(), k1 = K1.norm();
  const bool freeNormal = !(k0 > 0.0);  // a straight start: its normal is an unknown
  const Vec3 n1 = k1 > 0.0 ? Vec3(K1 / k1) : Vec3::Zero(), side = T1.cross(n1);
  const int unknowns = freeNormal ? 7 : 6, conditions = k1 > 0.0 ? 6 : 5;
  int grid = 0;  // the RK4 grid of the current solve
  auto spiralOf = [&](const VecX& z) {
    SpaceSpiral s;
    s.T0 = T0;
    s.N0 = freeNormal ? Vec3(std::cos(z[6]) * E1 + std::sin(z[6]) * E2) : Vec3(K0 / k0);
    s.k0 = k0;
    s.k1 = k1;
    s.length = z[0];
    s.a = z[1];
    s.b = z[2];
    s.t0 = z[3];
    s.t1 = z[4];
    s.t2 = z[5];
    s.grid = grid;
    return s;
  };
  auto residual = [&](const VecX& z) {
    VecX r(conditions);
    if (!(z[0] > 0.0) || !(z[0] < 1e3))
      return VecX(VecX::Constant(conditions, std::numeric_limits<double>::quiet_NaN()));
    const SpaceSpiral::Frame e = spiralOf(z).end();
    r.head<5>() << e.x - p1, e.T.dot(F1), e.T.dot(F2);
    if (k1 > 0.0) r[5] = e.N.dot(side);
    return r;
  };
  // Starts: the G1 solutions' length and torsion with curvature linear from k0 to k1, then
  // other lengths and curvature bumps.
  std::vector<VecX> starts;
  const SpaceSpiralSolution g1 = solveSpaceG1(T0, p1, T1);
  std::vector<SpaceSpiral> bases;
  if (g1.best) bases.push_back(*g1.best);
  SpaceSpiral chordStart;
  chordStart.length = 1.2;
  bases.push_back(chordStart);
  for (const SpaceSpiral& g : bases) {
    double phi = 0.0;
    if (freeNormal) phi = std::atan2(g.N0.dot(E2), g.N0.dot(E1));
    for (const double scale : {1.0, 1.25, 0.85}) {
      for (const double bump : {0.0, 0.5, -0.5}) {
        VecX z(unknowns);
        z.head<6>() << g.length * scale, bump * (k1 - k0), 0.0, g.t0 + 0.5 * g.t1, 0.0, 0.0;
        if (freeNormal) z[6] = phi;
        starts.push_back(z);
        z[3] = g.t0;
        z[4] = g.t1;
        if (g.t1 != 0.0) starts.push_back(z);
      }
    }
  }
  int afterMonotone = 0;  // starts tried since a monotone solution was found
  for (VecX z : starts) {
    // A monotone solution whose torsion changes sign: a few more starts may find one of one
    // sign (27 starts cost 20 ms where the ends' torsion must change sign).
    if (out.monotone && ++afterMonotone > 4) break;
    grid = 0;
    grid = spiralOf(z).gridFor(1.0);  // fixed for the solve: the residual stays smooth
    if (!solve(residual, z)) continue;
    const SpaceSpiral s = spiralOf(z);
    const SpaceSpiral::Frame e = s.end();
    if (!(e.T.dot(T1) > 0.0) || (k1 > 0.0 && !(e.N.dot(n1) > 0.0))) continue;
    consider(out, s);
    if (settled(out)) break;
  }
  if (!out.best)
    out.reason = "no space spiral meets these G2 ends";
  else if (!out.monotone)
    out.reason = "no space spiral of monotone curvature was found for these G2 ends";
  return out;
}

}  // namespace fairsplines::detail
