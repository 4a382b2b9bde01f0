#include "fairsplines/blend_surface.hpp"

#include <Standard_Failure.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "fairsplines/bspline.hpp"
#include "fairsplines/errors.hpp"
#include "bernstein.hpp"
#include "blend_detail.hpp"
#include "finite.hpp"

namespace fairsplines {

namespace detail {

Homogeneous4 revolveRows(const ShapeFrame& f, const Eigen::Ref<const PointMatrix>& circle, const Homogeneous3& profile) {
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

Homogeneous4 bezierOf(const Handle(Geom_BSplineSurface)& s, double u0, double u1, double v0, double v1, int& du,
                      int& dv) {
  Handle(Geom_BSplineSurface) c = Handle(Geom_BSplineSurface)::DownCast(s->Copy());
  c->Segment(u0, u1, v0, v1);
  du = c->UDegree();
  dv = c->VDegree();
  if (c->NbUPoles() != du + 1 || c->NbVPoles() != dv + 1) throw InputError("the free-form net could not be split into Bézier patches");
  Homogeneous4 out((du + 1) * (dv + 1), 4);
  for (int a = 0; a <= du; ++a) {
    for (int b = 0; b <= dv; ++b) {
      const gp_Pnt p = c->Pole(a + 1, b + 1);
      const double w = c->Weight(a + 1, b + 1);
      out.row(a * (dv + 1) + b) << w * p.X(), w * p.Y(), w * p.Z(), w;
    }
  }
  return out;
}

Handle(Geom_BSplineSurface) matchRingStrict(const Handle(Geom_BSplineSurface)& ring, const Eigen::VectorXd& T,
                                            const Eigen::VectorXd& cuts, int degree, bool closed) {
  const int n = static_cast<int>(T.size()) - 1;
  auto mismatch = [](const std::string& why) { return InputError("the free-form net does not match the interface: " + why); };
  if (ring.IsNull()) throw mismatch("no surface");
  if (closed != ring->IsUPeriodic()) {
    throw mismatch(closed ? "it must be periodic in u (closed around the axis)" : "it must be open in u, like the shape");
  }
  if (ring->UDegree() != degree || ring->VDegree() != degree) {
    throw mismatch(degree == 3 ? "it must be bicubic" : "it must be biquadratic (degree 2 in u and v)");
  }
  if (ring->NbUKnots() != n + 1) {
    std::ostringstream os;
    os << "it needs " << n << " knot intervals in u (one per arc around the axis), not " << ring->NbUKnots() - 1;
    throw mismatch(os.str());
  }
  const double period = T[n] - T[0];
  for (int i = 0; i <= n; ++i) {
    if (i > 0 && i < n && ring->UMultiplicity(i + 1) != 1) throw mismatch("its u knots must be simple");
    if (std::abs(ring->UKnot(i + 1) - T[i]) > 1e-9 * period) {
      std::ostringstream os;
      os << "u knot " << i << " is " << ring->UKnot(i + 1) << ", the interface needs " << T[i]
         << " (knot intervals in the ratios beta of the arcs)";
      throw mismatch(os.str());
    }
  }
  if (ring->VMultiplicity(1) != degree + 1) throw mismatch("it must be clamped in v (its first row is at the interface)");
  Handle(Geom_BSplineSurface) r = Handle(Geom_BSplineSurface)::DownCast(ring->Copy());
  for (Eigen::Index k = 0; k < cuts.size(); ++k) {
    bool existing = false;
    for (int i = 0; i <= n; ++i) existing = existing || std::abs(cuts[k] - T[i]) <= 1e-12 * period;
    if (!existing) r->InsertUKnot(cuts[k], 1, 1e-12 * period);
  }
  return r;
}

Handle(Geom_BSplineSurface) normalisedRing(const Handle(Geom_BSplineSurface)& ring, const ShapeFrame& frame,
                                           double period, int degree, double turn) {
  auto mismatch = [](const std::string& why) { return InputError("the free-form net does not match the interface: " + why); };
  const bool closed = std::abs(turn - 2 * M_PI) <= 1e-9;
  if (ring.IsNull()) throw mismatch("no surface");
  if (closed && !ring->IsUPeriodic()) throw mismatch("it must be periodic in u (closed around the axis)");
  if (!closed && (ring->IsUPeriodic() || ring->UMultiplicity(1) != degree + 1 ||
                  ring->UMultiplicity(ring->NbUKnots()) != degree + 1)) {
    throw mismatch("it must be clamped in u (open, like the shape's partial turn)");
  }
  if (ring->UDegree() != degree || ring->VDegree() != degree) {
    throw mismatch(degree == 3 ? "it must be bicubic" : "it must be biquadratic (degree 2 in u and v)");
  }
  if (ring->VMultiplicity(1) != degree + 1) throw mismatch("it must be clamped in v (its first row is the interface)");
  const double u0 = ring->UKnot(1), P = ring->UKnot(ring->NbUKnots()) - u0, v0 = ring->VKnot(1);
  // How far the first row turns about the axis (a winding number for a full turn), from 64
  // samples per knot span, against the shape's turn.
  const int samples = 64 * (ring->NbUKnots() - 1);
  double turned = 0.0, previous = 0.0;
  for (int k = 0; k <= samples; ++k) {
    const gp_Pnt q = ring->Value(u0 + P * k / samples, v0);
    const Eigen::Vector3d d = Eigen::Vector3d(q.X(), q.Y(), q.Z()) - frame.origin;
    const double angle = std::atan2(d.dot(frame.y), d.dot(frame.x));
    if (k > 0) turned += std::remainder(angle - previous, 2 * M_PI);
    previous = angle;
  }
  const double winding = turned / turn;
  if (std::abs(winding + 1) < 0.5) throw mismatch("its first row turns the other way around the axis (reverse its u direction)");
  if (std::abs(winding - 1) >= 0.5) {
    throw mismatch(closed ? "its first row does not go once around the shape's axis"
                          : "its first row does not run along the shape's angles around the axis");
  }
  Handle(Geom_BSplineSurface) r = Handle(Geom_BSplineSurface)::DownCast(ring->Copy());
  TColStd_Array1OfReal knots(1, r->NbUKnots());
  for (int i = 1; i <= r->NbUKnots(); ++i) knots.SetValue(i, (r->UKnot(i) - u0) * period / P);
  r->SetUKnots(knots);
  return r;
}

Handle(Geom_BSplineSurface) withKnots(const Handle(Geom_BSplineSurface)& ring, const Eigen::VectorXd& knotsU) {
  Handle(Geom_BSplineSurface) r = Handle(Geom_BSplineSurface)::DownCast(ring->Copy());
  const double period = knotsU[knotsU.size() - 1] - knotsU[0];
  for (Eigen::Index k = 0; k < knotsU.size(); ++k) {
    bool existing = false;
    for (int i = 1; i <= ring->NbUKnots(); ++i) existing = existing || std::abs(knotsU[k] - ring->UKnot(i)) <= 1e-12 * period;
    if (!existing) r->InsertUKnot(knotsU[k], 1, 1e-12 * period);
  }
  return r;
}

std::vector<std::vector<double>> ringCuts(const Handle(Geom_BSplineSurface)& ring, const Eigen::VectorXd& knotsU) {
  const int P = static_cast<int>(knotsU.size()) - 1;
  const double period = knotsU[P] - knotsU[0];
  std::vector<std::vector<double>> cuts(P);
  for (int i = 1; i <= ring->NbUKnots(); ++i) {
    const double u = ring->UKnot(i);
    for (int k = 0; k < P; ++k) {
      if (u > knotsU[k] + 1e-9 * period && u < knotsU[k + 1] - 1e-9 * period) {
        cuts[k].push_back((u - knotsU[k]) / (knotsU[k + 1] - knotsU[k]));
      }
    }
  }
  return cuts;
}
}  // namespace detail

using detail::bezierOf;
using detail::normalisedRing;
using detail::ringCuts;
using detail::withKnots;
using detail::matchRingStrict;
using detail::revolveRows;

namespace {

const double kPi = std::acos(-1.0);

/// The profile of a shape of revolution in the (distance from the axis, height) plane, as
/// G2 cubic pieces (eq. (2) for circles, degree-raised lines) and as C2 sextic pieces
/// (Section 4.1), with the interface at its end.
struct RevolvedProfile {
  std::vector<Homogeneous3> cubic;   ///< 4 homogeneous rows (rho w, zeta w, w) per piece
  std::vector<Homogeneous3> sextic;  ///< 7 rows per piece, C2 in homogeneous space
  Eigen::VectorXd sexticKnots;       ///< pieces + 1 knots of the sextic pieces
  Eigen::Vector2d end, tangent;      ///< (rho, zeta) at the interface and the unit direction leaving it
  double size = 1.0;                 ///< length scale of the last piece (for the default ring)
  Eigen::Vector2d start, startTangent;  ///< the same at the profile's start (direction leaving it backwards)
  double startSize = 1.0;
};

/// The profile run backwards, so that its start becomes the interface at its end. Pieces and
/// their Bézier rows in reverse order; the knots mirrored.
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

/// A circle profile: centre (rhoOffset, 0), radius r, partition `angles` (the circle's
/// pieces (x, y, w) map to (rhoOffset w + r x, r y, w)).
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

/// A straight profile rho = radius0 + slope z over increasing heights: degree-raised
/// lines (beta_j = h_j / h_{j-1}, gamma_j = 0), which are already C2 over the heights.
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
  p.end << radius0 + slope * heights[m], heights[m];
  p.tangent = Eigen::Vector2d(slope, 1.0).normalized();
  p.size = heights[m] - heights[m - 1];
  p.start << radius0 + slope * heights[0], heights[0];
  p.startTangent = -p.tangent;
  p.startSize = heights[1] - heights[0];
  return p;
}

/// Degree raise in u of a homogeneous patch of degree (du, dv) to degree 6 in u (du = 3).
Homogeneous4 raiseU(const Homogeneous4& patch, int du, int dv) {
  TaggedPatch p;
  p.degreeU = du;
  p.degreeV = dv;
  p.bezier = patch;
  return raisePatch(p, 6, dv).bezier;
}

/// Second-order Hermite data (three layers) of both sides, degree-raised to 5 in v: rows
/// 0..2 from the lower patch's top (v = 1, layers dv-2..dv), rows 3..5 from the upper
/// patch's bottom (v = 0, layers 0..2), scalar 1 across both seams. Both have `ku` columns.
Homogeneous4 hermiteStrip(const Homogeneous4& lower, int dvLower, const Homogeneous4& upper, int dvUpper, int ku) {
  Homogeneous4 out(ku * 6, 4);
  const int nl = dvLower + 1, nu = dvUpper + 1, n = dvLower;
  for (int a = 0; a < ku; ++a) {
    const Eigen::RowVector4d b1 = lower.row(a * nl + n - 2), b2 = lower.row(a * nl + n - 1), b3 = lower.row(a * nl + n);
    // Degree n to 5 with the same 2-jet at the seam: 5 (c1 - c0) = n (b3 - b2),
    // 20 (c2 - 2 c1 + c0) = n (n - 1) (b3 - 2 b2 + b1).
    const Eigen::RowVector4d c0 = b3, c1 = b3 + n / 5.0 * (b3 - b2);
    const Eigen::RowVector4d c2 = 2 * c1 - c0 + n * (n - 1) / 20.0 * (b3 - 2 * b2 + b1);
    const Eigen::RowVector4d r0 = upper.row(a * nu), r1 = upper.row(a * nu + 1), r2 = upper.row(a * nu + 2);
    const int m = dvUpper;
    const Eigen::RowVector4d c5 = r0, c4 = r0 - m / 5.0 * (r1 - r0);
    const Eigen::RowVector4d c3 = 2 * c4 - c5 + m * (m - 1) / 20.0 * (r2 - 2 * r1 + r0);
    const Eigen::RowVector4d rows[6] = {c0, c1, c2, c3, c4, c5};
    for (int b = 0; b < 6; ++b) out.row(a * 6 + b) = rows[b];
  }
  return out;
}

/// The transition patch of u-piece k (row vPiece, degree (degreeU, 5)) from the Hermite data
/// of the patch below (`lower`, degree dvLower in v) and the one above (`upper`).
TaggedPatch stripPatch(int k, int vPiece, int degreeU, const Homogeneous4& lower, int dvLower,
                       const Homogeneous4& upper, int dvUpper) {
  TaggedPatch strip;
  strip.role = TaggedPatch::Role::Transition;
  strip.degreeU = degreeU;
  strip.degreeV = 5;
  strip.uPiece = k;
  strip.vPiece = vPiece;
  strip.bezier = hermiteStrip(lower, dvLower, upper, dvUpper, degreeU + 1);
  return strip;
}

}  // namespace

namespace detail {

SplitPieces splitBezierPieces(const PointMatrix& bezier, int order, const Eigen::VectorXd& knots,
                              const std::vector<std::vector<double>>& cuts) {
  const int P = static_cast<int>(bezier.rows()) / order;
  if (static_cast<int>(cuts.size()) != P || knots.size() != P + 1) {
    throw InputError("splitting needs one list of cuts per piece and one knot more than pieces");
  }
  std::vector<PointMatrix> pieces;
  std::vector<double> t{knots[0]};
  SplitPieces out;
  out.first.assign(P + 1, 0);
  for (int k = 0; k < P; ++k) {
    out.first[k] = static_cast<int>(pieces.size());
    PointMatrix rest = bezier.middleRows(order * k, order);
    double done = 0.0;  // the part of piece k already cut off
    for (double x : cuts[k]) {
      if (!(x > done && x < 1.0)) throw InputError("cuts must increase strictly inside (0, 1)");
      PointMatrix left, right;
      bernstein::split(rest, (x - done) / (1.0 - done), left, right);
      pieces.push_back(left);
      t.push_back(knots[k] + x * (knots[k + 1] - knots[k]));
      rest = right;
      done = x;
    }
    pieces.push_back(rest);
    t.push_back(knots[k + 1]);
  }
  out.first[P] = static_cast<int>(pieces.size());
  out.bezier.resize(order * static_cast<Eigen::Index>(pieces.size()), bezier.cols());
  for (size_t k = 0; k < pieces.size(); ++k) out.bezier.middleRows(order * static_cast<Eigen::Index>(k), order) = pieces[k];
  out.knots = Eigen::Map<const Eigen::VectorXd>(t.data(), static_cast<Eigen::Index>(t.size()));
  return out;
}

}  // namespace detail

C2SexticSpline splitPieces(const C2SexticSpline& c2, const std::vector<std::vector<double>>& cuts) {
  if (static_cast<int>(cuts.size()) != c2.pieces()) throw InputError("splitPieces needs one list of cuts per piece");
  const Eigen::VectorXd t = c2.knots();
  const detail::SplitPieces split = detail::splitBezierPieces(c2.bezier, 7, t, cuts);
  C2SexticSpline out;
  out.closed = c2.closed;
  out.bezier = split.bezier;
  for (int first : c2.firstPiece) out.firstPiece.push_back(split.first[first]);
  const int P = out.pieces();
  out.beta.resize(P);
  for (int k = 0; k < P; ++k) {
    out.beta[k] = k > 0 ? (split.knots[k + 1] - split.knots[k]) / (split.knots[k] - split.knots[k - 1]) : 1.0;
  }
  // The closing join keeps its scalar, rescaled by the new lengths of the first and last pieces.
  const int last = c2.pieces() - 1;
  out.beta[0] = c2.closed ? c2.beta[0] * ((split.knots[1] - split.knots[0]) / (t[1] - t[0])) /
                                ((split.knots[P] - split.knots[P - 1]) / (t[last + 1] - t[last]))
                          : c2.beta[0];
  return out;
}

Handle(Geom_BSplineSurface) patchToOcct(const TaggedPatch& patch) {
  const int nu = patch.degreeU + 1, nv = patch.degreeV + 1;
  if (patch.bezier.rows() != nu * nv) throw InputError("a patch needs (degreeU + 1) (degreeV + 1) points");
  TColgp_Array2OfPnt poles(1, nu, 1, nv);
  TColStd_Array2OfReal weights(1, nu, 1, nv);
  for (int a = 0; a < nu; ++a) {
    for (int b = 0; b < nv; ++b) {
      const auto h = patch.bezier.row(a * nv + b);
      requireFinite(h, "a patch of the blend", "homogeneous control points");
      if (!(h[3] > 0)) throw InputError("a patch has a non-positive weight");
      poles.SetValue(a + 1, b + 1, gp_Pnt(h[0] / h[3], h[1] / h[3], h[2] / h[3]));
      weights.SetValue(a + 1, b + 1, h[3]);
    }
  }
  TColStd_Array1OfReal knots(1, 2);
  knots.SetValue(1, 0.0);
  knots.SetValue(2, 1.0);
  TColStd_Array1OfInteger multsU(1, 2), multsV(1, 2);
  multsU.Init(nu);
  multsV.Init(nv);
  try {
    return new Geom_BSplineSurface(poles, weights, knots, knots, multsU, multsV, patch.degreeU, patch.degreeV);
  } catch (const Standard_Failure& failure) {
    throw InputError(std::string("OpenCASCADE rejected the patch: ") + failure.GetMessageString());
  }
}

Eigen::VectorXd arcKnots(const C2SexticSpline& c2) {
  const Eigen::VectorXd t = c2.knots();
  const int n = static_cast<int>(c2.firstPiece.size()) - 1;
  const double firstArc = t[c2.firstPiece[1]] - t[0];  // normalise: the first arc has length 1
  Eigen::VectorXd T(n + 1);
  for (int i = 0; i <= n; ++i) T[i] = t[c2.firstPiece[i]] / firstArc;
  return T;
}

namespace {

G2CircleSpline checkedLongitudes(const ShapeFrame& frame, const Eigen::VectorXd& longitudes) {
  frame.check();
  return g2Circle(longitudes);  // a full turn (closed in u) or a partial one (open)
}

/// The default free-form ring after a profile's end: 4 rows along the end tangent, the
/// first half the last piece's length beyond the interface, a quarter apart; in u one
/// pole per longitude (Boehm's form: pole i centred on knot u_i), periodic cubic.
Handle(Geom_BSplineSurface) defaultRing(const ShapeFrame& frame, const G2CircleSpline& lon, const RevolvedProfile& p,
                                        const Eigen::VectorXd& knotsU) {
  const int n = lon.pieces();
  if (knotsU.size() != n + 1) throw InputError("the ring needs one knot per longitude");
  const Eigen::Vector2d base = p.end + p.size / 2 * p.tangent;
  const double step = p.size / 4;
  const double scale = std::max(std::abs(p.end.x()), std::abs(p.end.y())) + p.size;
  if (!(base.x() > 0.05 * scale) || !(base.x() + 3 * step * p.tangent.x() > 0.05 * scale)) {
    throw InputError("the default ring would reach the axis: give a free-form net");
  }
  // Full turn: one pole per longitude, periodic. Partial turn: clamped, the end poles on the
  // circle, the next ones along its tangent (a third of the end arc), one per inner longitude.
  const int poleCount = lon.closed ? n : n + 3;
  TColgp_Array2OfPnt poles(1, poleCount, 1, 4);
  BSplineCurve layout;
  for (int j = 0; j < 4; ++j) {
    const Eigen::Vector2d rz = base + j * step * p.tangent;
    auto at = [&](double theta, double radius) {
      const Eigen::Vector3d q = frame.origin + radius * (std::cos(theta) * frame.x + std::sin(theta) * frame.y) +
                                rz.y() * frame.z;
      return Eigen::RowVector3d(q.transpose());
    };
    auto inner = [&](int i) {
      // Pushed out so that the spline passes near the circle of radius rz.x(): a uniform
      // cubic at a knot is (c_{i-1} + 4 c_i + c_{i+1}) / 6.
      const double a = (lon.alpha[(i + n - 1) % n] + lon.alpha[i % n]) / 2, f = 3.0 / (2.0 + std::cos(a));
      return at(lon.theta[i], f * rz.x());
    };
    PointMatrix row(poleCount, 3);
    if (lon.closed) {
      for (int i = 0; i < n; ++i) row.row(i) = inner(i);
      layout = periodicCubic(row, knotsU);
    } else {
      const auto tangentAt = [&](double theta) {
        const Eigen::Vector3d d = -std::sin(theta) * frame.x + std::cos(theta) * frame.y;
        return Eigen::RowVector3d(d.transpose());
      };
      row.row(0) = at(lon.theta[0], rz.x());
      row.row(1) = row.row(0) + rz.x() * lon.alpha[0] / 3 * tangentAt(lon.theta[0]);
      for (int i = 1; i < n; ++i) row.row(i + 1) = inner(i);
      row.row(n + 2) = at(lon.theta[n], rz.x());
      row.row(n + 1) = row.row(n + 2) - rz.x() * lon.alpha[n - 1] / 3 * tangentAt(lon.theta[n]);
      layout = clampedCubic(row, knotsU);
    }
    for (int i = 0; i < poleCount; ++i) {
      poles.SetValue(i + 1, j + 1, gp_Pnt(layout.poles(i, 0), layout.poles(i, 1), layout.poles(i, 2)));
    }
  }
  TColStd_Array1OfReal uKnots(1, static_cast<int>(layout.knots.size())), vKnots(1, 2);
  TColStd_Array1OfInteger uMults(1, static_cast<int>(layout.mults.size())), vMults(1, 2);
  for (int k = 0; k < layout.knots.size(); ++k) {
    uKnots.SetValue(k + 1, layout.knots[k]);
    uMults.SetValue(k + 1, layout.mults[k]);
  }
  vKnots.SetValue(1, 0.0);
  vKnots.SetValue(2, 1.0);
  vMults.Init(4);
  return new Geom_BSplineSurface(poles, uKnots, vKnots, uMults, vMults, 3, 3, lon.closed, false);
}

/// Section 4.2 for a shape of revolution with its interface at the profile's end.
/// Throws InputError where the profile's end (the interface) lies on the axis.
void checkInterfaceOffAxis(const RevolvedProfile& profile, const char* which) {
  if (!(profile.end.x() > 1e-9 * (std::abs(profile.end.y()) + profile.size))) {
    throw InputError(std::string("the interface at the ") + which +
                     " of the profile lies on the axis (a pole): there is nothing to join there; join at the other end");
  }
}

/// The profile with the interface at its end: as it is (Interface::End) or reversed.
RevolvedProfile atInterface(const RevolvedProfile& p, Interface at) {
  RevolvedProfile out = at == Interface::End ? p : reversedProfile(p);
  checkInterfaceOffAxis(out, at == Interface::End ? "end" : "start");
  return out;
}

/// The basic side of a blend along u: one C2 sextic spline per control layer of the basic
/// rows (layer J (dv + 1) + s holds Bézier index s in v of row J), all on the same pieces.
struct BasicLayers {
  std::vector<C2SexticSpline> layers;
  int rows = 0, dv = 3;
  Eigen::VectorXd knotsV;  ///< rows + 1 values
  bool c2InV = false;
};

/// The layers of a shape of revolution: the C2 sextic circle times each profile point.
BasicLayers revolvedLayers(const ShapeFrame& frame, const C2SexticSpline& c2, const RevolvedProfile& profile,
                           bool sexticInV) {
  BasicLayers basic;
  const std::vector<Homogeneous3>& rows = sexticInV ? profile.sextic : profile.cubic;
  basic.rows = static_cast<int>(rows.size());
  basic.dv = sexticInV ? 6 : 3;
  basic.knotsV = sexticInV ? profile.sexticKnots : Eigen::VectorXd::LinSpaced(basic.rows + 1, 0.0, basic.rows);
  basic.c2InV = sexticInV;
  for (int J = 0; J < basic.rows; ++J) {
    for (int sv = 0; sv <= basic.dv; ++sv) {
      C2SexticSpline layer = c2;
      layer.bezier = revolveRows(frame, c2.bezier, Homogeneous3(rows[J].row(sv)));
      basic.layers.push_back(std::move(layer));
    }
  }
  return basic;
}

/// Section 4.2 from the basic side's layers (C2 along u): the ring (default, or a user's
/// with its period mapped onto the circle's and the pieces split at its knots), then the
/// patches and the (6,5) strip from three layers on each side.
BlendComplex assembleBlend(const ShapeFrame& frame, const G2CircleSpline& lon, const RevolvedProfile& profile,
                           BasicLayers basic, Handle(Geom_BSplineSurface) ring) {
  const C2SexticSpline& first = basic.layers.front();
  const Eigen::VectorXd T = arcKnots(first);
  BlendComplex out;
  out.knotsU = first.knots() * (T[1] / first.knots()[first.firstPiece[1]]);
  // A user ring: its u period mapped onto the circle's; where it has knots inside the
  // sextic's pieces, those pieces are split there (exactly, de Casteljau), and the ring gets
  // the sextic's knots: both sides then share one C2 parameterization without changing either.
  Handle(Geom_BSplineSurface) r;
  if (ring.IsNull()) {
    r = defaultRing(frame, lon, profile, T);
  } else {
    r = normalisedRing(ring, frame, out.knotsU[out.knotsU.size() - 1], 3, lon.theta[lon.pieces()] - lon.theta[0]);
    const std::vector<std::vector<double>> cuts = ringCuts(r, out.knotsU);
    const bool any = std::any_of(cuts.begin(), cuts.end(), [](const std::vector<double>& c) { return !c.empty(); });
    if (any) {
      const double period = out.knotsU[out.knotsU.size() - 1];
      for (C2SexticSpline& layer : basic.layers) layer = splitPieces(layer, cuts);
      const Eigen::VectorXd t = basic.layers.front().knots();
      out.knotsU = t * (period / t[t.size() - 1]);
    }
  }
  r = withKnots(r, out.knotsU);
  out.piecesU = basic.layers.front().pieces();
  out.closedU = lon.closed;
  out.basicC2InV = basic.c2InV;
  out.rowsBasic = basic.rows;
  const int dvBasic = basic.dv, spansV = r->NbVKnots() - 1;
  out.rowsFreeForm = spansV;
  // Shared v parameterization: scalar 1 across both seams of the strip.
  out.knotsV.resize(out.rowsBasic + spansV + 2);
  out.knotsV.head(out.rowsBasic + 1) = basic.knotsV;
  const double stripLength = basic.knotsV[out.rowsBasic] - basic.knotsV[out.rowsBasic - 1];
  out.knotsV[out.rowsBasic + 1] = basic.knotsV[out.rowsBasic] + stripLength;
  for (int sp = 0; sp < spansV; ++sp) {
    out.knotsV[out.rowsBasic + 2 + sp] = out.knotsV[out.rowsBasic + 1 + sp] +
                                         stripLength * (r->VKnot(sp + 2) - r->VKnot(sp + 1)) / (r->VKnot(2) - r->VKnot(1));
  }
  for (int k = 0; k < out.piecesU; ++k) {
    Homogeneous4 top;
    for (int j = 0; j < out.rowsBasic; ++j) {
      TaggedPatch p;
      p.role = TaggedPatch::Role::Basic;
      p.degreeU = 6;
      p.degreeV = dvBasic;
      p.uPiece = k;
      p.vPiece = j;
      p.bezier.resize(7 * (dvBasic + 1), 4);
      for (int a = 0; a <= 6; ++a) {
        for (int sv = 0; sv <= dvBasic; ++sv) {
          p.bezier.row(a * (dvBasic + 1) + sv) = basic.layers[j * (dvBasic + 1) + sv].bezier.row(7 * k + a);
        }
      }
      if (j + 1 == out.rowsBasic) top = p.bezier;
      out.patches.push_back(std::move(p));
    }
    Homogeneous4 ringBottom;
    for (int sp = 0; sp < spansV; ++sp) {
      int du = 0, dv = 0;
      TaggedPatch p;
      p.role = TaggedPatch::Role::FreeForm;
      p.uPiece = k;
      p.vPiece = out.rowsBasic + 1 + sp;
      p.bezier = bezierOf(r, out.knotsU[k], out.knotsU[k + 1], r->VKnot(sp + 1), r->VKnot(sp + 2), du, dv);
      p.degreeU = du;
      p.degreeV = dv;
      if (sp == 0) ringBottom = raiseU(p.bezier, du, dv);
      out.patches.push_back(std::move(p));
    }
    // Steps 2-3: three layers of Bézier coefficients on both sides, degree-raised to (6,5).
    out.patches.push_back(stripPatch(k, out.rowsBasic, 6, top, dvBasic, ringBottom, 3));
  }
  return out;
}

BlendComplex blendRevolved(const ShapeFrame& frame, const G2CircleSpline& lon, const RevolvedProfile& profile,
                           CircleReparam method, Handle(Geom_BSplineSurface) ring, bool sexticInV) {
  // Step 1: along the interface the G2 circle becomes the C2 sextic of 4.1 (betaT = beta,
  // the heuristic of Section 3); the basic shape stays exact.
  const C2SexticSpline c2 = circleToC2(lon, method);
  return assembleBlend(frame, lon, profile, revolvedLayers(frame, c2, profile, sexticInV), ring);
}

/// The naive baseline of Fig. 2a for a shape of revolution.
BlendComplex blendRevolvedNaive(const ShapeFrame& frame, const G2CircleSpline& lon, const RevolvedProfile& profile,
                                Handle(Geom_BSplineSurface) ring) {
  // The same arc knots as the blend (sigma: one piece per arc).
  const Eigen::VectorXd T = arcKnots(circleToC2(lon, CircleReparam::Sigma));
  if (ring.IsNull()) ring = defaultRing(frame, lon, profile, T);
  const Handle(Geom_BSplineSurface) r = matchRingStrict(ring, T, T, 3, lon.closed);
  BlendComplex out;
  out.knotsU = T;
  out.piecesU = lon.pieces();
  out.closedU = lon.closed;
  out.rowsBasic = static_cast<int>(profile.cubic.size());
  out.rowsFreeForm = r->NbVKnots() - 1;
  out.knotsV = Eigen::VectorXd::LinSpaced(out.rowsBasic + out.rowsFreeForm + 2, 0.0, out.rowsBasic + out.rowsFreeForm + 1);
  for (int k = 0; k < out.piecesU; ++k) {
    const PointMatrix circle = lon.cubic.middleRows(4 * k, 4);
    Homogeneous4 top, ringBottom;
    for (int j = 0; j < out.rowsBasic; ++j) {
      TaggedPatch p;
      p.uPiece = k;
      p.vPiece = j;
      p.bezier = revolveRows(frame, circle, profile.cubic[j]);
      if (j + 1 == out.rowsBasic) top = p.bezier;
      out.patches.push_back(std::move(p));
    }
    for (int s = 0; s < out.rowsFreeForm; ++s) {
      int du = 0, dv = 0;
      TaggedPatch p;
      p.role = TaggedPatch::Role::FreeForm;
      p.uPiece = k;
      p.vPiece = out.rowsBasic + 1 + s;
      p.bezier = bezierOf(r, T[k], T[k + 1], r->VKnot(s + 1), r->VKnot(s + 2), du, dv);
      if (s == 0) ringBottom = p.bezier;
      out.patches.push_back(std::move(p));
    }
    // Fig. 2a: direct second-order Hermite interpolation, degree (3,5), no reparameterization.
    out.patches.push_back(stripPatch(k, out.rowsBasic, 3, top, 3, ringBottom, 3));
  }
  return out;
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

}  // namespace

Handle(Geom_BSplineSurface) defaultSphereRing(const ShapeFrame& frame, double radius, const Eigen::VectorXd& longitudes,
                                              const Eigen::VectorXd& latitudes, const Eigen::VectorXd& knotsU) {
  return defaultRing(frame, checkedLongitudes(frame, longitudes),
                     atInterface(sphereProfile(radius, latitudes, CircleReparam::Rho), Interface::End), knotsU);
}

BlendComplex blendSphereZone(const ShapeFrame& frame, double radius, const Eigen::VectorXd& longitudes,
                             const Eigen::VectorXd& latitudes, CircleReparam method, Handle(Geom_BSplineSurface) ring,
                             bool sexticInV, Interface at) {
  const G2CircleSpline lon = checkedLongitudes(frame, longitudes);
  return blendRevolved(frame, lon, atInterface(sphereProfile(radius, latitudes, method), at), method, ring, sexticInV);
}

BlendComplex blendSphereZoneNaive(const ShapeFrame& frame, double radius, const Eigen::VectorXd& longitudes,
                                  const Eigen::VectorXd& latitudes, Handle(Geom_BSplineSurface) ring, Interface at) {
  const G2CircleSpline lon = checkedLongitudes(frame, longitudes);
  return blendRevolvedNaive(frame, lon, atInterface(sphereProfile(radius, latitudes, CircleReparam::Rho), at), ring);
}

BlendComplex blendCone(const ShapeFrame& frame, double radius0, double slope, const Eigen::VectorXd& angles,
                       const Eigen::VectorXd& heights, CircleReparam method, Handle(Geom_BSplineSurface) ring,
                       bool sexticInV, bool naive, Interface at) {
  if (!std::isfinite(radius0) || !std::isfinite(slope)) throw InputError("a cone needs a finite radius and slope");
  const G2CircleSpline lon = checkedLongitudes(frame, angles);
  const RevolvedProfile p = atInterface(lineProfile(radius0, slope, heights), at);
  return naive ? blendRevolvedNaive(frame, lon, p, ring) : blendRevolved(frame, lon, p, method, ring, sexticInV);
}

BlendComplex blendTorus(const ShapeFrame& frame, double R, double r, const Eigen::VectorXd& anglesU,
                        const Eigen::VectorXd& anglesV, CircleReparam method, Handle(Geom_BSplineSurface) ring,
                        bool sexticInV, bool naive, Interface at) {
  const G2CircleSpline lon = checkedLongitudes(frame, anglesU);
  const RevolvedProfile p = atInterface(torusProfile(R, r, anglesV, method), at);
  return naive ? blendRevolvedNaive(frame, lon, p, ring) : blendRevolved(frame, lon, p, method, ring, sexticInV);
}

namespace {

/// One side of a shape-to-shape join: the circle around the axis and the profile.
struct JoinSide {
  ShapeFrame frame;
  G2CircleSpline lon;
  RevolvedProfile profile;  ///< in its own direction (v increasing)
};

JoinSide joinSide(const ShapeOfRevolution& shape, CircleReparam method, Interface at, const char* name) {
  JoinSide side;
  side.frame = shape.frame;
  side.lon = checkedLongitudes(shape.frame, shape.around);
  switch (shape.kind) {
    case ShapeOfRevolution::Kind::SphereZone:
      side.profile = sphereProfile(shape.size0, shape.profile, method);
      break;
    case ShapeOfRevolution::Kind::Cone:
      if (!std::isfinite(shape.size0) || !std::isfinite(shape.size1)) throw InputError("a cone needs a finite radius and slope");
      side.profile = lineProfile(shape.size0, shape.size1, shape.profile);
      break;
    case ShapeOfRevolution::Kind::Torus:
      side.profile = torusProfile(shape.size0, shape.size1, shape.profile, method);
      break;
  }
  const RevolvedProfile interface = at == Interface::End ? side.profile : reversedProfile(side.profile);
  if (!(interface.end.x() > 1e-9 * (std::abs(interface.end.y()) + interface.size))) {
    throw InputError(std::string("the ") + name + " shape's profile meets the axis (a pole) at the join");
  }
  return side;
}

/// The Fig. 2a baseline between two G2 complexes: cubic circle pieces as they are, a (3,5)
/// Hermite strip without reparameterization.
BlendComplex joinNaive(const JoinSide& a, const JoinSide& b) {
  BlendComplex out;
  out.knotsU = arcKnots(circleToC2(a.lon, CircleReparam::Sigma));
  out.piecesU = a.lon.pieces();
  out.closedU = a.lon.closed;
  out.rowsBasic = static_cast<int>(a.profile.cubic.size());
  out.rowsFreeForm = static_cast<int>(b.profile.cubic.size());
  out.knotsV = Eigen::VectorXd::LinSpaced(out.rowsBasic + out.rowsFreeForm + 2, 0.0, out.rowsBasic + out.rowsFreeForm + 1);
  for (int k = 0; k < out.piecesU; ++k) {
    Homogeneous4 top, bottom;
    for (int j = 0; j < out.rowsBasic; ++j) {
      TaggedPatch p;
      p.uPiece = k;
      p.vPiece = j;
      p.bezier = revolveRows(a.frame, a.lon.cubic.middleRows(4 * k, 4), a.profile.cubic[j]);
      if (j + 1 == out.rowsBasic) top = p.bezier;
      out.patches.push_back(std::move(p));
    }
    for (int j = 0; j < out.rowsFreeForm; ++j) {
      TaggedPatch p;
      p.uPiece = k;
      p.vPiece = out.rowsBasic + 1 + j;
      p.bezier = revolveRows(b.frame, b.lon.cubic.middleRows(4 * k, 4), b.profile.cubic[j]);
      if (j == 0) bottom = p.bezier;
      out.patches.push_back(std::move(p));
    }
    out.patches.push_back(stripPatch(k, out.rowsBasic, 3, top, 3, bottom, 3));
  }
  return out;
}

}  // namespace

BlendComplex blendEdited(const ShapeOfRevolution& shape, const G2Surface& edited, CircleReparam method,
                         Handle(Geom_BSplineSurface) ring) {
  const JoinSide side = joinSide(shape, method, Interface::End, "edited");
  const int n = side.lon.pieces(), rows = static_cast<int>(side.profile.cubic.size());
  if (edited.nu != n || edited.nv != rows || edited.bezier.rows() != 16 * n * rows) {
    std::ostringstream os;
    os << "the edited control structure has " << edited.nu << " x " << edited.nv << " patches; the shape has " << n
       << " x " << rows;
    throw InputError(os.str());
  }
  for (Eigen::Index k = 0; k < edited.bezier.rows(); ++k) {
    if (!edited.bezier.row(k).allFinite() || !(edited.bezier(k, 3) > 0)) {
      throw InputError("the edited control structure has a non-finite point or a non-positive weight");
    }
  }
  // Section 4.1 on every control layer of the structure: the circle partition's maps (rho,
  // sigma or mixed) compose the Hermite quadratics of each layer's cubic pieces (eqs. (9),
  // (10)); eq. (11) then makes every arc-to-arc join C2 (it changes nothing where the join
  // is already C2, i.e. away from the edits).
  const CircleMaps maps = circleMaps(side.lon, method);
  BasicLayers basic;
  basic.rows = rows;
  basic.dv = 3;
  basic.knotsV = Eigen::VectorXd::LinSpaced(rows + 1, 0.0, rows);
  for (int J = 0; J < rows; ++J) {
    for (int sv = 0; sv <= 3; ++sv) {
      PointMatrix cubic(4 * n, 4);
      for (int I = 0; I < n; ++I) {
        for (int r = 0; r < 4; ++r) cubic.row(4 * I + r) = edited.point(I, J, r, sv);
      }
      C2SexticSpline layer = g2ToC2(cubic, maps.maps, maps.betaPieces, side.lon.closed);
      const int P = layer.pieces();
      for (int i = side.lon.closed ? 0 : 1; i < n; ++i) {
        const int k = layer.firstPiece[i], left = (k + P - 1) % P;
        PointMatrix a = layer.bezier.middleRows(7 * left, 7), b = layer.bezier.middleRows(7 * k, 7);
        adjustC2(a, b, layer.beta[k]);
        layer.bezier.middleRows(7 * left, 7) = a;
        layer.bezier.middleRows(7 * k, 7) = b;
      }
      basic.layers.push_back(std::move(layer));
    }
  }
  return assembleBlend(side.frame, side.lon, side.profile, std::move(basic), ring);
}

C2SexticSpline refineArcs(const C2SexticSpline& c2, const std::vector<int>& parts) {
  const int n = static_cast<int>(c2.firstPiece.size()) - 1;
  if (static_cast<int>(parts.size()) != n) throw InputError("refineArcs needs one piece count per arc");
  std::vector<std::vector<double>> cuts(c2.pieces());
  for (int i = 0; i < n; ++i) {
    const int have = c2.firstPiece[i + 1] - c2.firstPiece[i];
    if (parts[i] < have || parts[i] % have != 0) {
      std::ostringstream os;
      os << "arc " << i << " has " << have << " pieces; it cannot be split into " << parts[i];
      throw InputError(os.str());
    }
    const int m = parts[i] / have;  // every piece of the arc into m equal parts
    for (int k = c2.firstPiece[i]; k < c2.firstPiece[i + 1]; ++k) {
      for (int j = 1; j < m; ++j) cuts[k].push_back(static_cast<double>(j) / m);
    }
  }
  return splitPieces(c2, cuts);
}

BlendComplex joinShapes(const ShapeOfRevolution& shapeA, const ShapeOfRevolution& shapeB, CircleReparam method,
                        bool sexticInV, bool naive) {
  const JoinSide a = joinSide(shapeA, method, Interface::End, "first");
  const JoinSide b = joinSide(shapeB, method, Interface::Start, "second");
  const int n = a.lon.pieces();
  if (b.lon.pieces() != n) {
    std::ostringstream os;
    os << "the two shapes need the same number of arcs around the axis (" << n << " and " << b.lon.pieces() << ")";
    throw InputError(os.str());
  }
  if (a.lon.closed != b.lon.closed) throw InputError("both shapes need a full turn around the axis, or both a partial one");
  if (naive) return joinNaive(a, b);
  // Fig. 11: across the transition the scalars are averaged, betaT_i = sqrt(beta_i^top beta_i^bottom).
  const Eigen::VectorXd betaT = (a.lon.beta.array() * b.lon.beta.array()).sqrt().matrix();
  C2SexticSpline ca = circleToC2(a.lon, method, betaT), cb = circleToC2(b.lon, method, betaT);
  // Fig. 12: both sides as C2 sextics with the same pieces, so no knot insertion: an arc with
  // one piece on one side and three on the other is cut into thirds.
  std::vector<int> parts(n);
  for (int i = 0; i < n; ++i) {
    parts[i] = std::max(ca.firstPiece[i + 1] - ca.firstPiece[i], cb.firstPiece[i + 1] - cb.firstPiece[i]);
  }
  ca = refineArcs(ca, parts);
  cb = refineArcs(cb, parts);
  const Eigen::VectorXd tA = ca.knots(), tB = cb.knots();
  if (!((tA - tB).cwiseAbs().maxCoeff() <= 1e-9 * tA[tA.size() - 1])) {
    throw std::logic_error("joinShapes: the two sides' u knots differ after refinement");
  }
  BlendComplex out;
  out.knotsU = tA / tA[ca.firstPiece[1]];  // the first arc has length 1, as arcKnots
  out.piecesU = ca.pieces();
  out.closedU = a.lon.closed;
  out.basicC2InV = sexticInV;
  const std::vector<Homogeneous3>& rowsA = sexticInV ? a.profile.sextic : a.profile.cubic;
  const std::vector<Homogeneous3>& rowsB = sexticInV ? b.profile.sextic : b.profile.cubic;
  const int dv = sexticInV ? 6 : 3;
  out.rowsBasic = static_cast<int>(rowsA.size());
  out.rowsFreeForm = static_cast<int>(rowsB.size());
  const Eigen::VectorXd knotsA =
      sexticInV ? a.profile.sexticKnots : Eigen::VectorXd::LinSpaced(out.rowsBasic + 1, 0.0, out.rowsBasic);
  const Eigen::VectorXd knotsB =
      sexticInV ? b.profile.sexticKnots : Eigen::VectorXd::LinSpaced(out.rowsFreeForm + 1, 0.0, out.rowsFreeForm);
  // Scalar 1 across both seams of the strip: strip and b's first row as long as a's last row.
  const double stripLength = knotsA[out.rowsBasic] - knotsA[out.rowsBasic - 1];
  out.knotsV.resize(out.rowsBasic + out.rowsFreeForm + 2);
  out.knotsV.head(out.rowsBasic + 1) = knotsA;
  out.knotsV[out.rowsBasic + 1] = knotsA[out.rowsBasic] + stripLength;
  const double scaleB = stripLength / (knotsB[1] - knotsB[0]);
  for (int j = 1; j <= out.rowsFreeForm; ++j) {
    out.knotsV[out.rowsBasic + 1 + j] = out.knotsV[out.rowsBasic + 1] + scaleB * (knotsB[j] - knotsB[0]);
  }
  for (int k = 0; k < out.piecesU; ++k) {
    Homogeneous4 top, bottom;
    for (int side = 0; side < 2; ++side) {
      const std::vector<Homogeneous3>& rows = side == 0 ? rowsA : rowsB;
      const PointMatrix circle = (side == 0 ? ca : cb).bezier.middleRows(7 * k, 7);
      for (int j = 0; j < static_cast<int>(rows.size()); ++j) {
        TaggedPatch p;
        p.degreeU = 6;
        p.degreeV = dv;
        p.uPiece = k;
        p.vPiece = side == 0 ? j : out.rowsBasic + 1 + j;
        p.bezier = revolveRows(side == 0 ? a.frame : b.frame, circle, rows[j]);
        if (side == 0 && j + 1 == out.rowsBasic) top = p.bezier;
        if (side == 1 && j == 0) bottom = p.bezier;
        out.patches.push_back(std::move(p));
      }
    }
    // Section 4.2, steps 2-3: three layers from each side, degree-raised to (6,5).
    out.patches.push_back(stripPatch(k, out.rowsBasic, 6, top, dv, bottom, dv));
  }
  return out;
}

Eigen::VectorXd ringKnots(const Eigen::VectorXd& longitudes, CircleReparam method) {
  return arcKnots(circleToC2(g2Circle(longitudes), method));
}

TaggedPatch raisePatch(const TaggedPatch& patch, int du, int dv) {
  // Row a (degreeV + 1) + b of a patch is b_ab: each column (fixed b) is a Bézier curve in
  // u, each row (fixed a) one in v; both are raised by bernstein::raise.
  TaggedPatch out = patch;
  if (out.degreeU < du) {
    const int ev = out.degreeV + 1;
    Homogeneous4 raised((du + 1) * ev, 4), column(out.degreeU + 1, 4);
    for (int b = 0; b < ev; ++b) {
      for (int a = 0; a <= out.degreeU; ++a) column.row(a) = out.bezier.row(a * ev + b);
      const Homogeneous4 c = bernstein::raise(column, du);
      for (int a = 0; a <= du; ++a) raised.row(a * ev + b) = c.row(a);
    }
    out.bezier = std::move(raised);
    out.degreeU = du;
  }
  if (out.degreeV < dv) {
    const int ev = out.degreeV + 1;
    Homogeneous4 raised((out.degreeU + 1) * (dv + 1), 4);
    for (int a = 0; a <= out.degreeU; ++a) {
      raised.middleRows(a * (dv + 1), dv + 1) = bernstein::raise(out.bezier.middleRows(a * ev, ev), dv);
    }
    out.bezier = std::move(raised);
    out.degreeV = dv;
  }
  return out;
}

Handle(Geom_BSplineSurface) singleSurface(const BlendComplex& complex, double tolerance, int smoothness) {
  if (smoothness < 0) throw InputError("smoothness must be 0 or more");
  const int rows = complex.rowsBasic + complex.rowsTransition + complex.rowsFreeForm, K = complex.piecesU;
  if (complex.knotsV.size() != rows + 1 || complex.knotsU.size() != K + 1) throw InputError("the complex has no shared knots");
  // Knots OpenCASCADE would call "too close" (arcs or heights a few ulps apart) are refused by name.
  requireSeparateKnots(complex.knotsU, "the complex's u knots (around the axis)");
  requireSeparateKnots(complex.knotsV, "the complex's v knots (along the profile)");
  int d = 0, e = 0;
  for (const TaggedPatch& p : complex.patches) {
    d = std::max(d, p.degreeU);
    e = std::max(e, p.degreeV);
  }
  TColgp_Array2OfPnt poles(1, d * K + 1, 1, e * rows + 1);
  TColStd_Array2OfReal weights(1, d * K + 1, 1, e * rows + 1);
  double size = 0.0;
  int seen = 0;
  for (const TaggedPatch& patch : complex.patches) {
    const TaggedPatch p = raisePatch(patch, d, e);
    ++seen;
    for (int a = 0; a <= d; ++a) {
      for (int b = 0; b <= e; ++b) {
        const auto h = p.bezier.row(a * (e + 1) + b);
        if (!(h[3] > 0)) throw InputError("a patch has a non-positive weight");
        const Eigen::Vector3d point = h.head<3>().transpose() / h[3];
        requireFinite(point, "the single surface of the complex", "poles");
        poles.SetValue(d * p.uPiece + a + 1, e * p.vPiece + b + 1, gp_Pnt(point.x(), point.y(), point.z()));
        weights.SetValue(d * p.uPiece + a + 1, e * p.vPiece + b + 1, h[3]);
        size = std::max(size, h.cwiseAbs().maxCoeff());
      }
    }
  }
  if (seen != K * rows) throw InputError("the complex is not a tensor grid of patches");
  auto knots = [](const Eigen::VectorXd& t, int degree, TColStd_Array1OfReal& k, TColStd_Array1OfInteger& m) {
    for (int i = 0; i < t.size(); ++i) {
      k.SetValue(i + 1, t[i]);
      m.SetValue(i + 1, i == 0 || i + 1 == t.size() ? degree + 1 : degree);
    }
  };
  TColStd_Array1OfReal ku(1, K + 1), kv(1, rows + 1);
  TColStd_Array1OfInteger mu(1, K + 1), mv(1, rows + 1);
  knots(complex.knotsU, d, ku, mu);
  knots(complex.knotsV, e, kv, mv);
  Handle(Geom_BSplineSurface) s;
  try {
    s = new Geom_BSplineSurface(poles, weights, ku, kv, mu, mv, d, e);
  } catch (const Standard_Failure& failure) {
    throw InputError(std::string("OpenCASCADE rejected the single surface of the complex: ") + failure.GetMessageString());
  }
  // C^smoothness where the multiplicities allow it: each interior knot down to degree - smoothness.
  for (int i = 2; i <= K; ++i) {
    if (!s->RemoveUKnot(i, std::max(d - smoothness, 0), tolerance * size)) {
      std::ostringstream os;
      os << "the complex is not C" << smoothness << " across u knot " << i - 1;
      throw InputError(os.str());
    }
  }
  for (int j = 2; j <= rows; ++j) {
    if (!s->RemoveVKnot(j, std::max(e - smoothness, 0), tolerance * size)) {
      std::ostringstream os;
      os << "the complex is not C" << smoothness << " across v knot " << j - 1 << " (basic rows only G2? use sexticInV)";
      throw InputError(os.str());
    }
  }
  for (int i = 1; i <= s->NbUPoles(); ++i) {
    for (int j = 1; j <= s->NbVPoles(); ++j) {
      const gp_Pnt& p = s->Pole(i, j);
      requireFinite(Eigen::Vector4d(p.X(), p.Y(), p.Z(), s->Weight(i, j)), "the single surface of the complex",
                    "poles after the knot removal");
    }
  }
  return s;
}

}  // namespace fairsplines
