// Profiles of the shapes of revolution in the (distance from the axis, height) plane, and
// the tensor rows of a revolved shape: Karčiauskas & Peters, Section 4.1 (the C2 sextic
// pieces of a circle), eq. (2) (its G2 cubic pieces); see blend_surface_detail.hpp.
#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "fairsplines/errors.hpp"
#include "blend_detail.hpp"
#include "blend_surface_detail.hpp"

namespace fairsplines {
namespace detail {

// ---------------------------------------------------------------------------------------
// A surface of revolution in tensor form (docs/READINGS.md, blending paper)

Homogeneous4 revolveRows(const ShapeFrame& f, const Eigen::Ref<const PointMatrix>& circle,
                         const Homogeneous3& profile) {
  const Eigen::Index ku = circle.rows(), kv = profile.rows();
  Homogeneous4 out(ku * kv, 4);
  for (Eigen::Index a = 0; a < ku; ++a) {
    for (Eigen::Index b = 0; b < kv; ++b) {
      const double weight = profile(b, 2) * circle(a, 2);
      const Eigen::Vector3d p = profile(b, 0) * circle(a, 0) * f.x + profile(b, 0) * circle(a, 1) * f.y +
                                profile(b, 1) * circle(a, 2) * f.z + weight * f.origin;
      out.row(a * kv + b) << p.transpose(), weight;
    }
  }
  return out;
}

// ---------------------------------------------------------------------------------------
// Profiles: circles (sphere zone, torus) and lines (cone, cylinder)

namespace {

const double kPi = std::acos(-1.0);

/// Section 4.2 for a shape of revolution with its interface at the profile's end.
/// Throws InputError where the profile's end (the interface) lies on the axis.
void checkInterfaceOffAxis(const RevolvedProfile& profile, const char* which) {
  if (!(profile.end.x() > 1e-9 * (std::abs(profile.end.y()) + profile.size))) {
    throw InputError(
        std::string("the interface at the ") + which +
        " of the profile lies on the axis (a pole): there is nothing to join there; join at the other end");
  }
}

}  // namespace

RevolvedProfile reversedProfile(const RevolvedProfile& p) {
  RevolvedProfile r;
  for (auto it = p.cubic.rbegin(); it != p.cubic.rend(); ++it) r.cubic.push_back(it->colwise().reverse());
  for (auto it = p.sextic.rbegin(); it != p.sextic.rend(); ++it) r.sextic.push_back(it->colwise().reverse());
  const Eigen::Index m = p.sexticKnots.size() - 1;
  r.sexticKnots.resize(m + 1);
  for (Eigen::Index j = 0; j <= m; ++j) r.sexticKnots[j] = p.sexticKnots[m] - p.sexticKnots[m - j];
  r.end = p.start;
  r.tangent = p.startTangent;
  r.size = p.startSize;
  r.start = p.end;
  r.startTangent = p.tangent;
  r.startSize = p.size;
  return r;
}

RevolvedProfile circleProfile(double rhoOffset, double r, const Eigen::VectorXd& angles, CircleReparam method) {
  const G2CircleSpline c = g2Circle(angles);
  if (c.closed) throw InputError("a closed profile circle has no boundary to blend at; give an open range of angles");
  RevolvedProfile p;
  auto map = [&](const Eigen::RowVectorXd& h) {
    Eigen::RowVector3d out;
    out << rhoOffset * h[2] + r * h[0], r * h[1], h[2];
    return out;
  };
  for (int j = 0; j < c.pieces(); ++j) {
    Homogeneous3 q(4, 3);
    for (int k = 0; k < 4; ++k) q.row(k) = map(c.cubic.row(4 * j + k));
    p.cubic.push_back(q);
  }
  const C2SexticSpline c2 = circleToC2(c, method);
  for (int j = 0; j < c2.pieces(); ++j) {
    Homogeneous3 q(7, 3);
    for (int k = 0; k < 7; ++k) q.row(k) = map(c2.bezier.row(7 * j + k));
    p.sextic.push_back(q);
  }
  p.sexticKnots = c2.knots();
  const double phi = c.theta[c.pieces()];
  p.end << rhoOffset + r * std::cos(phi), r * std::sin(phi);
  p.tangent << -std::sin(phi), std::cos(phi);
  p.size = r * c.alpha[c.pieces() - 1];
  const double phi0 = c.theta[0];
  p.start << rhoOffset + r * std::cos(phi0), r * std::sin(phi0);
  p.startTangent << std::sin(phi0), -std::cos(phi0);
  p.startSize = r * c.alpha[0];
  return p;
}

RevolvedProfile lineProfile(double radius0, double slope, const Eigen::VectorXd& heights) {
  detail::checkHeights(heights, radius0, slope);
  const int m = static_cast<int>(heights.size()) - 1;
  RevolvedProfile p;
  for (int j = 0; j < m; ++j) {
    Homogeneous3 q(4, 3);
    for (int k = 0; k < 4; ++k) {
      const double z = heights[j] + (heights[j + 1] - heights[j]) * k / 3.0;
      q.row(k) << radius0 + slope * z, z, 1.0;
    }
    p.cubic.push_back(q);
    const PointMatrix raised = raiseCubicToSextic(PointMatrix(q));
    p.sextic.push_back(Homogeneous3(raised));
  }
  p.sexticKnots = heights.array() - heights[0];
  setLineEnds(p, radius0, slope, heights);
  return p;
}

RevolvedProfile sphereProfile(double radius, const Eigen::VectorXd& latitudes, CircleReparam method) {
  if (!(radius > 0) || !std::isfinite(radius)) throw InputError("a sphere needs a positive radius");
  for (Eigen::Index j = 0; j < latitudes.size(); ++j) {
    if (!(std::abs(latitudes[j]) <= kPi / 2 + 1e-15)) throw InputError("latitudes must lie in [-pi/2, pi/2]");
  }
  return circleProfile(0.0, radius, latitudes, method);
}

RevolvedProfile torusProfile(double R, double r, const Eigen::VectorXd& anglesV, CircleReparam method) {
  if (!(r > 0) || !(R > r) || !std::isfinite(R)) throw InputError("a torus needs radii 0 < r < R");
  return circleProfile(R, r, anglesV, method);
}

bool joinsHomogeneousC(int order, const Homogeneous3& a, const Homogeneous3& b, double h0, double h1) {
  const double scale = std::max(a.cwiseAbs().maxCoeff(), b.cwiseAbs().maxCoeff());
  const bool c1 = ((b.row(1) - b.row(0)) / h1 - (a.row(3) - a.row(2)) / h0).norm() <= 1e-9 * scale / std::min(h0, h1);
  if (order < 2 || !c1) return c1;
  return ((b.row(2) - 2 * b.row(1) + b.row(0)) / (h1 * h1) - (a.row(3) - 2 * a.row(2) + a.row(1)) / (h0 * h0)).norm() <=
         1e-9 * scale / std::min(h0 * h0, h1 * h1);
}

namespace {

/// The identity reparameterization in the normal form of Appendix 7.1: h_k = (k/3, 1).
Reparam identityMap() {
  Reparam h;
  h << 0.0, 1.0, 1.0 / 3, 1.0, 2.0 / 3, 1.0, 1.0, 1.0;
  return h;
}

/// Whether the map r = rbar / rlow is a monotone reparameterization of its part of [0, 1]
/// (positive denominator, increasing), on 33 samples.
bool monotoneMap(const Reparam& r) {
  double last = -1.0;
  for (int k = 0; k <= 32; ++k) {
    const double u = k / 32.0, v = 1 - u, b[4] = {v * v * v, 3 * u * v * v, 3 * u * u * v, u * u * u};
    double num = 0.0, den = 0.0;
    for (int i = 0; i < 4; ++i) {
      num += b[i] * r(i, 0);
      den += b[i] * r(i, 1);
    }
    if (!(den > 0) || !(num / den > last)) return false;
    last = num / den;
  }
  return true;
}

/// Section 4.1 at a profile join that is G2 but not C2 in homogeneous space: Appendix 7.2
/// generalised from circle arcs to any rational pieces. The left piece keeps the identity
/// map; the right piece gets the map h (normal form, h_0 = (0,1), h_3 = (1,1)) whose 2-jet
/// at 0, composed with the right piece's Hermite quadratic Q at 0 (eq. (9): with s = rlow -
/// rbar, t = rbar, F = Q_0 s^2 + 2 Q_1 s t + Q_2 t^2), continues the left piece C2 with
/// scalar beta: F(0) = L(1), F'(0) = beta L'(1), F''(0) = beta^2 L''(1). At s = 1, t = 0:
///   F' = 2 (Q_0 s' + Q_1 t'),  F'' = 2 (Q_0 s'^2 + 2 Q_1 s' t' + Q_2 t'^2) + 2 (Q_0 s'' + Q_1 t''),
/// two 3 x 2 systems for (s', t') and (s'', t''), consistent exactly when the projected
/// pieces join G2. The map's first third is all the rho split uses of it at this end.
/// Returns false where the systems are inconsistent (less than G2) or the split maps are
/// not monotone: the caller falls back to eq. (11).
bool g2StartMap(const Homogeneous3& left, const Homogeneous3& right, double beta, std::array<Reparam, 3>& split) {
  const PointMatrix Q = hermiteQuadratic(PointMatrix(right), 0.0);
  const Eigen::Vector3d L0 = left.row(3).transpose(), L1 = 3 * (left.row(3) - left.row(2)).transpose(),
                        L2 = 6 * (left.row(3) - 2 * left.row(2) + left.row(1)).transpose();
  const Eigen::Vector3d Q0 = Q.row(0).transpose(), Q1 = Q.row(1).transpose(), Q2 = Q.row(2).transpose();
  const double scale = std::max(L0.norm(), Q0.norm());
  if (!((L0 - Q0).norm() <= 1e-9 * scale)) return false;  // not C0 in homogeneous space
  Eigen::Matrix<double, 3, 2> A;
  A << Q0, Q1;
  const auto qr = A.colPivHouseholderQr();
  const Eigen::Vector3d g1 = beta * L1 / 2;
  const Eigen::Vector2d d1 = qr.solve(g1);
  if (!((A * d1 - g1).norm() <= 1e-9 * (g1.norm() + scale))) return false;
  const double s1 = d1[0], t1 = d1[1];
  const Eigen::Vector3d g2 = (beta * beta * L2 - 2 * (Q0 * s1 * s1 + 2 * Q1 * s1 * t1 + Q2 * t1 * t1)) / 2;
  const Eigen::Vector2d d2 = qr.solve(g2);
  if (!((A * d2 - g2).norm() <= 1e-9 * (g2.norm() + beta * beta * L2.norm() + scale))) return false;
  // (rbar, rlow) = (t, s + t): its Bézier points from the 2-jet at 0.
  const Eigen::RowVector2d h0(0.0, 1.0), dh(t1, s1 + t1), ddh(d2[1], d2[0] + d2[1]);
  Reparam h;
  h.row(0) = h0;
  h.row(1) = h0 + dh / 3;
  h.row(2) = 2 * h.row(1) - h0 + ddh / 6;
  h.row(3) << 1.0, 1.0;
  split = rhoSplitFromMaps(h, identityMap());
  return monotoneMap(split[0]) && monotoneMap(split[1]) && monotoneMap(split[2]);
}

}  // namespace

RevolvedProfile curveProfile(const Homogeneous3& cubic, const Eigen::VectorXd& knots, std::vector<int>* adjusted) {
  const int m = static_cast<int>(cubic.rows() / 4);
  if (m < 1 || cubic.rows() != 4 * m || knots.size() != m + 1) {
    throw InputError("a profile needs 4 homogeneous Bézier points per piece and one knot more than pieces");
  }
  for (int j = 0; j < m; ++j) {
    if (!(knots[j + 1] > knots[j])) throw InputError("the profile's knots must increase");
  }
  RevolvedProfile p;
  for (int j = 0; j < m; ++j) p.cubic.push_back(cubic.middleRows(4 * j, 4));
  // Per join: C2 in homogeneous space as it is (eqs. (3)-(4) with beta = h_j / h_{j-1},
  // gamma = 0: the identity map, a degree raise), G2 (the right piece reparameterized by
  // g2StartMap and split in three, conic pieces staying exact), or less (eq. (11)).
  std::vector<int> kind(m, 0);  // 0: C2 at the piece's start, 1: g2StartMap, 2: eq. (11)
  std::vector<std::array<Reparam, 3>> maps(m);
  for (int j = 1; j < m; ++j) {
    const double h0 = knots[j] - knots[j - 1], h1 = knots[j + 1] - knots[j];
    if (joinsHomogeneousC(2, p.cubic[j - 1], p.cubic[j], h0, h1)) continue;
    kind[j] = g2StartMap(p.cubic[j - 1], p.cubic[j], h1 / h0, maps[j]) ? 1 : 2;
  }
  std::vector<double> t{0.0};
  std::vector<int> first(m);
  for (int j = 0; j < m; ++j) {
    first[j] = static_cast<int>(p.sextic.size());
    const double L = knots[j + 1] - knots[j];
    if (kind[j] == 1) {
      // Section 4.1 for this piece: its Hermite quadratics composed with the three maps
      // (eq. (9)) and merged (eq. (10)); the thirds join C2 with scalar 1.
      const C2SexticSpline c2 = g2ToC2(PointMatrix(p.cubic[j]), {std::vector<Reparam>(maps[j].begin(), maps[j].end())},
                                       Eigen::VectorXd::Ones(1), false);
      for (int k = 0; k < 3; ++k) {
        p.sextic.push_back(Homogeneous3(c2.bezier.middleRows(7 * k, 7)));
        t.push_back(t.back() + L / 3);
      }
    } else {
      p.sextic.push_back(Homogeneous3(raiseCubicToSextic(PointMatrix(p.cubic[j]))));
      t.push_back(t.back() + L);
    }
  }
  p.sexticKnots = Eigen::Map<const Eigen::VectorXd>(t.data(), static_cast<Eigen::Index>(t.size()));
  for (int j = 1; j < m; ++j) {
    if (kind[j] != 2) continue;
    // Less than G2: the identity map on both sides, then eq. (11) at their C0 interface.
    const int k = first[j];
    const double h0 = p.sexticKnots[k] - p.sexticKnots[k - 1], h1 = p.sexticKnots[k + 1] - p.sexticKnots[k];
    PointMatrix left = p.sextic[k - 1], right = p.sextic[k];
    adjustC2(left, right, h1 / h0);
    p.sextic[k - 1] = Homogeneous3(left);
    p.sextic[k] = Homogeneous3(right);
    if (adjusted) adjusted->push_back(j);
  }
  setCurveEnds(p, p.cubic.front(), p.cubic.back());
  return p;
}

// ---------------------------------------------------------------------------------------
// The interface and the circle around the axis

RevolvedProfile atInterface(const RevolvedProfile& p, Interface at, bool defaultRing) {
  if (at == Interface::Auto) {
    const RevolvedProfile back = reversedProfile(p);
    auto onAxis = [](const RevolvedProfile& q) { return !(q.end.x() > 1e-9 * (std::abs(q.end.y()) + q.size)); };
    if (onAxis(p)) {
      at = Interface::Start;
    } else if (onAxis(back) || !defaultRing) {
      at = Interface::End;
    } else {
      const double endRoom = detail::defaultRingRoom(p.end, p.tangent, p.size, 4);
      const double startRoom = detail::defaultRingRoom(back.end, back.tangent, back.size, 4);
      at = endRoom >= std::min(1.0, startRoom) ? Interface::End : Interface::Start;
    }
  }
  RevolvedProfile out = at == Interface::End ? p : reversedProfile(p);
  checkInterfaceOffAxis(out, at == Interface::End ? "end" : "start");
  return out;
}

G2CircleSpline checkedLongitudes(const ShapeFrame& frame, const Eigen::VectorXd& longitudes) {
  frame.check();
  return g2Circle(longitudes);  // a full turn (closed in u) or a partial one (open)
}

}  // namespace detail
}  // namespace fairsplines
