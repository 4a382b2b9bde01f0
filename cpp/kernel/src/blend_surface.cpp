#include "fairsplines/blend_surface.hpp"

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <Standard_Failure.hxx>
#include <TopAbs_ShapeEnum.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <cmath>
#include <sstream>

#include "fairsplines/blend_detail.hpp"
#include "fairsplines/bspline.hpp"
#include "fairsplines/errors.hpp"

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

}  // namespace detail

using detail::bezierOf;
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
};

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
  return p;
}

/// A straight profile rho = radius0 + slope z over increasing heights: degree-raised
/// lines (beta_j = h_j / h_{j-1}, gamma_j = 0), which are already C2 over the heights.
RevolvedProfile lineProfile(double radius0, double slope, const Eigen::VectorXd& heights) {
  const int m = static_cast<int>(heights.size()) - 1;
  if (m < 1) throw InputError("a profile needs at least two heights");
  for (int j = 0; j <= m; ++j) {
    if (!std::isfinite(heights[j])) throw InputError("non-finite height");
    if (j > 0 && !(heights[j] > heights[j - 1])) {
      std::ostringstream os;
      os << "heights must increase: height " << j << " (" << heights[j] << ") is not greater than height " << j - 1;
      throw InputError(os.str());
    }
    if (!(radius0 + slope * heights[j] > 0)) {
      std::ostringstream os;
      os << "the radius at height " << j << " (z = " << heights[j] << ") is not positive";
      throw InputError(os.str());
    }
  }
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
  return p;
}

/// Degree raise in u of a homogeneous patch of degree (du, dv) to degree 6 in u (du = 3).
Homogeneous4 raiseU(const Homogeneous4& patch, int du, int dv) {
  if (du == 6) return patch;
  Homogeneous4 out(7 * (dv + 1), 4);
  for (int b = 0; b <= dv; ++b) {
    PointMatrix column(du + 1, 4);
    for (int a = 0; a <= du; ++a) column.row(a) = patch.row(a * (dv + 1) + b);
    const PointMatrix raised = raiseCubicToSextic(column);
    for (int a = 0; a <= 6; ++a) out.row(a * (dv + 1) + b) = raised.row(a);
  }
  return out;
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

/// Checks the ring against the interface and returns it with its u knots inserted at `cuts`.
Handle(Geom_BSplineSurface) matchRing(const Handle(Geom_BSplineSurface)& ring, const Eigen::VectorXd& arcT,
                                      const Eigen::VectorXd& cuts) {
  const int n = static_cast<int>(arcT.size()) - 1;
  auto mismatch = [](const std::string& why) { return InputError("the free-form net does not match the interface: " + why); };
  if (ring.IsNull()) throw mismatch("no surface");
  if (!ring->IsUPeriodic()) throw mismatch("it must be periodic in u (closed around the axis)");
  if (ring->UDegree() != 3 || ring->VDegree() != 3) throw mismatch("it must be bicubic");
  if (ring->NbUKnots() != n + 1) {
    std::ostringstream os;
    os << "it needs " << n << " knot intervals in u (one per longitude arc), not " << ring->NbUKnots() - 1;
    throw mismatch(os.str());
  }
  const double period = arcT[n] - arcT[0];
  for (int i = 0; i <= n; ++i) {
    if (std::abs(ring->UKnot(i + 1) - arcT[i]) > 1e-9 * period) {
      std::ostringstream os;
      os << "u knot " << i << " is " << ring->UKnot(i + 1) << ", the interface needs " << arcT[i]
         << " (knot intervals in the ratios beta of the longitudes)";
      throw mismatch(os.str());
    }
  }
  if (ring->VMultiplicity(1) != 4) throw mismatch("it must be clamped in v (its first row is the interface)");
  Handle(Geom_BSplineSurface) r = Handle(Geom_BSplineSurface)::DownCast(ring->Copy());
  for (Eigen::Index k = 0; k < cuts.size(); ++k) {
    bool existing = false;
    for (int i = 0; i <= n; ++i) existing = existing || std::abs(cuts[k] - arcT[i]) <= 1e-12 * period;
    if (!existing) r->InsertUKnot(cuts[k], 1, 1e-12 * period);
  }
  return r;
}

}  // namespace

Handle(Geom_BSplineSurface) patchToOcct(const TaggedPatch& patch) {
  const int nu = patch.degreeU + 1, nv = patch.degreeV + 1;
  if (patch.bezier.rows() != nu * nv) throw InputError("a patch needs (degreeU + 1) (degreeV + 1) points");
  TColgp_Array2OfPnt poles(1, nu, 1, nv);
  TColStd_Array2OfReal weights(1, nu, 1, nv);
  for (int a = 0; a < nu; ++a) {
    for (int b = 0; b < nv; ++b) {
      const auto h = patch.bezier.row(a * nv + b);
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
  G2CircleSpline lon = g2Circle(longitudes);
  if (!lon.closed) throw InputError("blending a basic shape needs angles around the axis over a full turn (0 .. 2 pi)");
  return lon;
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
  TColgp_Array2OfPnt poles(1, n, 1, 4);
  BSplineCurve layout;
  for (int j = 0; j < 4; ++j) {
    const Eigen::Vector2d rz = base + j * step * p.tangent;
    PointMatrix row(n, 3);
    for (int i = 0; i < n; ++i) {
      // Pushed out so that the spline passes near the circle of radius rz.x(): a uniform
      // periodic cubic at a knot is (c_{i-1} + 4 c_i + c_{i+1}) / 6.
      const double a = (lon.alpha[(i + n - 1) % n] + lon.alpha[i]) / 2, f = 3.0 / (2.0 + std::cos(a));
      const Eigen::Vector3d q = frame.origin +
                                f * rz.x() * (std::cos(lon.theta[i]) * frame.x + std::sin(lon.theta[i]) * frame.y) +
                                rz.y() * frame.z;
      row.row(i) = q.transpose();
    }
    layout = periodicCubic(row, knotsU);
    for (int i = 0; i < n; ++i) poles.SetValue(i + 1, j + 1, gp_Pnt(layout.poles(i, 0), layout.poles(i, 1), layout.poles(i, 2)));
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
  return new Geom_BSplineSurface(poles, uKnots, vKnots, uMults, vMults, 3, 3, true, false);
}

/// Section 4.2 for a shape of revolution with its interface at the profile's end.
BlendComplex blendRevolved(const ShapeFrame& frame, const G2CircleSpline& lon, const RevolvedProfile& profile,
                           CircleReparam method, Handle(Geom_BSplineSurface) ring, bool sexticInV) {
  if (!(profile.end.x() > 1e-9 * (std::abs(profile.end.y()) + profile.size))) {
    throw InputError("the interface lies on the axis (a pole): there is no ring to join there");
  }
  // Step 1: along the interface the G2 circle becomes the C2 sextic of 4.1 (betaT = beta,
  // the heuristic of Section 3); the basic shape stays exact.
  const C2SexticSpline c2 = circleToC2(lon, method);
  const Eigen::VectorXd T = arcKnots(c2);
  const double scale = T[1] / (c2.knots()[c2.firstPiece[1]]);
  BlendComplex out;
  out.knotsU = c2.knots() * scale;
  out.piecesU = c2.pieces();
  out.basicC2InV = sexticInV;
  // Across the interface: the profile's G2 cubics as they are, or its C2 sextics.
  const std::vector<Homogeneous3>& profiles = sexticInV ? profile.sextic : profile.cubic;
  const Eigen::VectorXd basicKnotsV = sexticInV ? profile.sexticKnots
                                                : Eigen::VectorXd::LinSpaced(profile.cubic.size() + 1, 0.0, profile.cubic.size());
  const int dvBasic = sexticInV ? 6 : 3;
  out.rowsBasic = static_cast<int>(profiles.size());
  if (ring.IsNull()) ring = defaultRing(frame, lon, profile, T);
  const Handle(Geom_BSplineSurface) r = matchRing(ring, T, out.knotsU);
  const int spansV = r->NbVKnots() - 1;
  out.rowsFreeForm = spansV;
  // Shared v parameterization: scalar 1 across both seams of the strip.
  out.knotsV.resize(out.rowsBasic + spansV + 2);
  out.knotsV.head(out.rowsBasic + 1) = basicKnotsV;
  const double stripLength = basicKnotsV[out.rowsBasic] - basicKnotsV[out.rowsBasic - 1];
  out.knotsV[out.rowsBasic + 1] = basicKnotsV[out.rowsBasic] + stripLength;
  for (int sp = 0; sp < spansV; ++sp) {
    out.knotsV[out.rowsBasic + 2 + sp] = out.knotsV[out.rowsBasic + 1 + sp] +
                                         stripLength * (r->VKnot(sp + 2) - r->VKnot(sp + 1)) / (r->VKnot(2) - r->VKnot(1));
  }
  for (int k = 0; k < out.piecesU; ++k) {
    const PointMatrix circle = c2.bezier.middleRows(7 * k, 7);
    Homogeneous4 top;
    for (int j = 0; j < out.rowsBasic; ++j) {
      TaggedPatch p;
      p.role = TaggedPatch::Role::Basic;
      p.degreeU = 6;
      p.degreeV = dvBasic;
      p.uPiece = k;
      p.vPiece = j;
      p.bezier = revolveRows(frame, circle, profiles[j]);
      if (j + 1 == out.rowsBasic) top = p.bezier;
      out.patches.push_back(std::move(p));
    }
    Homogeneous4 ringBottom;
    for (int s = 0; s < spansV; ++s) {
      int du = 0, dv = 0;
      TaggedPatch p;
      p.role = TaggedPatch::Role::FreeForm;
      p.uPiece = k;
      p.vPiece = out.rowsBasic + 1 + s;
      p.bezier = bezierOf(r, out.knotsU[k], out.knotsU[k + 1], r->VKnot(s + 1), r->VKnot(s + 2), du, dv);
      p.degreeU = du;
      p.degreeV = dv;
      if (s == 0) ringBottom = raiseU(p.bezier, du, dv);
      out.patches.push_back(std::move(p));
    }
    // Steps 2-3: three layers of Bézier coefficients on both sides, degree-raised to (6,5).
    TaggedPatch strip;
    strip.role = TaggedPatch::Role::Transition;
    strip.degreeU = 6;
    strip.degreeV = 5;
    strip.uPiece = k;
    strip.vPiece = out.rowsBasic;
    strip.bezier = hermiteStrip(top, dvBasic, ringBottom, 3, 7);
    out.patches.push_back(std::move(strip));
  }
  return out;
}

/// The naive baseline of Fig. 2a for a shape of revolution.
BlendComplex blendRevolvedNaive(const ShapeFrame& frame, const G2CircleSpline& lon, const RevolvedProfile& profile,
                                Handle(Geom_BSplineSurface) ring) {
  if (!(profile.end.x() > 1e-9 * (std::abs(profile.end.y()) + profile.size))) {
    throw InputError("the interface lies on the axis (a pole): there is no ring to join there");
  }
  // The same arc knots as the blend (sigma: one piece per arc).
  const Eigen::VectorXd T = arcKnots(circleToC2(lon, CircleReparam::Sigma));
  if (ring.IsNull()) ring = defaultRing(frame, lon, profile, T);
  const Handle(Geom_BSplineSurface) r = matchRing(ring, T, T);
  BlendComplex out;
  out.knotsU = T;
  out.piecesU = lon.pieces();
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
    TaggedPatch strip;
    strip.role = TaggedPatch::Role::Transition;
    strip.degreeU = 3;
    strip.degreeV = 5;
    strip.uPiece = k;
    strip.vPiece = out.rowsBasic;
    strip.bezier = hermiteStrip(top, 3, ringBottom, 3, 4);
    out.patches.push_back(std::move(strip));
  }
  return out;
}

RevolvedProfile sphereProfile(double radius, const Eigen::VectorXd& latitudes, CircleReparam method) {
  if (!(radius > 0) || !std::isfinite(radius)) throw InputError("a sphere needs a positive radius");
  for (Eigen::Index j = 0; j < latitudes.size(); ++j) {
    if (!(std::abs(latitudes[j]) <= kPi / 2 + 1e-15)) throw InputError("latitudes must lie in [-pi/2, pi/2]");
  }
  if (latitudes.size() < 2 || !(latitudes[latitudes.size() - 1] < kPi / 2 - 1e-9)) {
    throw InputError("the top latitude of a sphere zone to blend must lie below pi/2 (the ring joins there)");
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
  return defaultRing(frame, checkedLongitudes(frame, longitudes), sphereProfile(radius, latitudes, CircleReparam::Rho),
                     knotsU);
}

BlendComplex blendSphereZone(const ShapeFrame& frame, double radius, const Eigen::VectorXd& longitudes,
                             const Eigen::VectorXd& latitudes, CircleReparam method, Handle(Geom_BSplineSurface) ring,
                             bool sexticInV) {
  return blendRevolved(frame, checkedLongitudes(frame, longitudes), sphereProfile(radius, latitudes, method), method,
                       ring, sexticInV);
}

BlendComplex blendSphereZoneNaive(const ShapeFrame& frame, double radius, const Eigen::VectorXd& longitudes,
                                  const Eigen::VectorXd& latitudes, Handle(Geom_BSplineSurface) ring) {
  return blendRevolvedNaive(frame, checkedLongitudes(frame, longitudes),
                            sphereProfile(radius, latitudes, CircleReparam::Rho), ring);
}

BlendComplex blendCone(const ShapeFrame& frame, double radius0, double slope, const Eigen::VectorXd& angles,
                       const Eigen::VectorXd& heights, CircleReparam method, Handle(Geom_BSplineSurface) ring,
                       bool sexticInV, bool naive) {
  if (!std::isfinite(radius0) || !std::isfinite(slope)) throw InputError("a cone needs a finite radius and slope");
  const G2CircleSpline lon = checkedLongitudes(frame, angles);
  const RevolvedProfile p = lineProfile(radius0, slope, heights);
  return naive ? blendRevolvedNaive(frame, lon, p, ring) : blendRevolved(frame, lon, p, method, ring, sexticInV);
}

BlendComplex blendTorus(const ShapeFrame& frame, double R, double r, const Eigen::VectorXd& anglesU,
                        const Eigen::VectorXd& anglesV, CircleReparam method, Handle(Geom_BSplineSurface) ring,
                        bool sexticInV, bool naive) {
  const G2CircleSpline lon = checkedLongitudes(frame, anglesU);
  const RevolvedProfile p = torusProfile(R, r, anglesV, method);
  return naive ? blendRevolvedNaive(frame, lon, p, ring) : blendRevolved(frame, lon, p, method, ring, sexticInV);
}

Eigen::VectorXd ringKnots(const Eigen::VectorXd& longitudes, CircleReparam method) {
  return arcKnots(circleToC2(g2Circle(longitudes), method));
}

TaggedPatch raisePatch(const TaggedPatch& patch, int du, int dv) {
  TaggedPatch out = patch;
  auto at = [](const TaggedPatch& p, int a, int b) { return p.bezier.row(a * (p.degreeV + 1) + b); };
  while (out.degreeU < du) {  // b'_a = a/(n+1) b_{a-1} + (1 - a/(n+1)) b_a
    TaggedPatch next = out;
    const int n = out.degreeU;
    next.degreeU = n + 1;
    next.bezier.resize((n + 2) * (out.degreeV + 1), 4);
    for (int a = 0; a <= n + 1; ++a) {
      for (int b = 0; b <= out.degreeV; ++b) {
        const double f = static_cast<double>(a) / (n + 1);
        Eigen::RowVector4d v = Eigen::RowVector4d::Zero();
        if (a > 0) v += f * at(out, a - 1, b);
        if (a <= n) v += (1 - f) * at(out, a, b);
        next.bezier.row(a * (out.degreeV + 1) + b) = v;
      }
    }
    out = next;
  }
  while (out.degreeV < dv) {
    TaggedPatch next = out;
    const int n = out.degreeV;
    next.degreeV = n + 1;
    next.bezier.resize((out.degreeU + 1) * (n + 2), 4);
    for (int a = 0; a <= out.degreeU; ++a) {
      for (int b = 0; b <= n + 1; ++b) {
        const double f = static_cast<double>(b) / (n + 1);
        Eigen::RowVector4d v = Eigen::RowVector4d::Zero();
        if (b > 0) v += f * at(out, a, b - 1);
        if (b <= n) v += (1 - f) * at(out, a, b);
        next.bezier.row(a * (n + 2) + b) = v;
      }
    }
    out = next;
  }
  return out;
}

Handle(Geom_BSplineSurface) singleSurface(const BlendComplex& complex, double tolerance, int smoothness) {
  if (smoothness < 0) throw InputError("smoothness must be 0 or more");
  const int rows = complex.rowsBasic + complex.rowsTransition + complex.rowsFreeForm, K = complex.piecesU;
  if (complex.knotsV.size() != rows + 1 || complex.knotsU.size() != K + 1) throw InputError("the complex has no shared knots");
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
        poles.SetValue(d * p.uPiece + a + 1, e * p.vPiece + b + 1, gp_Pnt(h[0] / h[3], h[1] / h[3], h[2] / h[3]));
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
  Handle(Geom_BSplineSurface) s = new Geom_BSplineSurface(poles, weights, ku, kv, mu, mv, d, e);
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
  return s;
}

TopoDS_Shape sewnShell(const BlendComplex& complex, double tolerance) {
  double size = 0.0;
  for (const TaggedPatch& p : complex.patches) {
    for (Eigen::Index k = 0; k < p.bezier.rows(); ++k) size = std::max(size, (p.bezier.row(k).head<3>() / p.bezier(k, 3)).norm());
  }
  BRepBuilderAPI_Sewing sewing(tolerance * std::max(size, 1.0));
  for (const TaggedPatch& p : complex.patches) {
    BRepBuilderAPI_MakeFace face(patchToOcct(p), 1e-9 * std::max(size, 1.0));
    if (!face.IsDone()) throw InputError("a patch could not be made into a face");
    sewing.Add(face.Face());
  }
  sewing.Perform();
  TopoDS_Shape shell = sewing.SewedShape();
  if (shell.IsNull() || shell.ShapeType() != TopAbs_SHELL) throw InputError("the patches did not sew into one shell");
  return shell;
}

}  // namespace fairsplines
