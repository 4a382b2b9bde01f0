// Basic shape to NURBS with a C2 transition strip of degree (6,5): Karčiauskas & Peters,
// Section 4.2 ("Algorithm for combining NURBS and G2 splines"), and the naive baseline of
// Fig. 2a, for the sphere zone, the cone and the torus. The profiles are in
// blend_profile.cpp, the ring in blend_ring.cpp, the grid and its OCCT forms in
// blend_grid.cpp, shape-to-shape joins and edited structures in blend_join.cpp.
#include "fairsplines/blend_surface.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "fairsplines/errors.hpp"
#include "blend_detail.hpp"
#include "blend_surface_detail.hpp"

namespace fairsplines {

using detail::atInterface;
using detail::BasicLayers;
using detail::bezierOf;
using detail::checkedLongitudes;
using detail::defaultRing;
using detail::lineProfile;
using detail::matchRingStrict;
using detail::normalisedRing;
using detail::RevolvedProfile;
using detail::revolveRows;
using detail::ringCuts;
using detail::sphereProfile;
using detail::stripPatch;
using detail::torusProfile;
using detail::withKnots;

// ---------------------------------------------------------------------------------------
// Section 4.2, steps 2-3: the transition strip from three layers on each side

namespace {

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

}  // namespace

namespace detail {

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

// ---------------------------------------------------------------------------------------
// Section 4.2: the complex from the basic side's layers and the ring

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
    out.knotsV[out.rowsBasic + 2 + sp] =
        out.knotsV[out.rowsBasic + 1 + sp] +
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

}  // namespace detail

namespace detail {

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

}  // namespace detail

namespace {

using detail::revolvedLayers;

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
  out.knotsV =
      Eigen::VectorXd::LinSpaced(out.rowsBasic + out.rowsFreeForm + 2, 0.0, out.rowsBasic + out.rowsFreeForm + 1);
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

}  // namespace

// ---------------------------------------------------------------------------------------
// The shapes: sphere zone, cone (cylinder), torus

BlendComplex blendSphereZone(const ShapeFrame& frame, double radius, const Eigen::VectorXd& longitudes,
                             const Eigen::VectorXd& latitudes, CircleReparam method, Handle(Geom_BSplineSurface) ring,
                             bool sexticInV, Interface at) {
  const G2CircleSpline lon = checkedLongitudes(frame, longitudes);
  return blendRevolved(frame, lon, atInterface(sphereProfile(radius, latitudes, method), at, ring.IsNull()), method,
                       ring, sexticInV);
}

BlendComplex blendSphereZoneNaive(const ShapeFrame& frame, double radius, const Eigen::VectorXd& longitudes,
                                  const Eigen::VectorXd& latitudes, Handle(Geom_BSplineSurface) ring, Interface at) {
  const G2CircleSpline lon = checkedLongitudes(frame, longitudes);
  return blendRevolvedNaive(frame, lon,
                            atInterface(sphereProfile(radius, latitudes, CircleReparam::Rho), at, ring.IsNull()), ring);
}

BlendComplex blendCone(const ShapeFrame& frame, double radius0, double slope, const Eigen::VectorXd& angles,
                       const Eigen::VectorXd& heights, CircleReparam method, Handle(Geom_BSplineSurface) ring,
                       bool sexticInV, bool naive, Interface at) {
  if (!std::isfinite(radius0) || !std::isfinite(slope)) throw InputError("a cone needs a finite radius and slope");
  const G2CircleSpline lon = checkedLongitudes(frame, angles);
  const RevolvedProfile p = atInterface(lineProfile(radius0, slope, heights), at, ring.IsNull());
  return naive ? blendRevolvedNaive(frame, lon, p, ring) : blendRevolved(frame, lon, p, method, ring, sexticInV);
}

BlendComplex blendTorus(const ShapeFrame& frame, double R, double r, const Eigen::VectorXd& anglesU,
                        const Eigen::VectorXd& anglesV, CircleReparam method, Handle(Geom_BSplineSurface) ring,
                        bool sexticInV, bool naive, Interface at) {
  const G2CircleSpline lon = checkedLongitudes(frame, anglesU);
  const RevolvedProfile p = atInterface(torusProfile(R, r, anglesV, method), at, ring.IsNull());
  return naive ? blendRevolvedNaive(frame, lon, p, ring) : blendRevolved(frame, lon, p, method, ring, sexticInV);
}

BlendComplex blendShape(const ShapeOfRevolution& shape, CircleReparam method, Handle(Geom_BSplineSurface) ring,
                        bool sexticInV, bool naive, Interface at) {
  const detail::JoinSide side = detail::joinSide(shape, method);
  const RevolvedProfile p = atInterface(side.profile, at, ring.IsNull());
  return naive ? blendRevolvedNaive(side.frame, side.lon, p, ring)
               : blendRevolved(side.frame, side.lon, p, method, ring, sexticInV);
}

}  // namespace fairsplines
