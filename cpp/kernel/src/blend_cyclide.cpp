// Dupin cyclides, the abstract's "generalized tori" (Karčiauskas & Peters, Section 2: a basic
// shape as a 4-tuple of trigonometric polynomials, translated into rational form by the G2
// circle pieces of eq. (2)). Both families of curvature lines are circles, and the standard
// parameterization is bilinear in (cos theta, sin theta, 1) and (cos psi, sin psi, 1), so the
// bicubic G2 model carries it exactly, without raising degrees (docs/READINGS.md).
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <cmath>
#include <string>

#include "fairsplines/blend_shapes.hpp"
#include "fairsplines/blend_surface.hpp"
#include "fairsplines/bspline.hpp"
#include "fairsplines/errors.hpp"
#include "blend_detail.hpp"
#include "blend_surface_detail.hpp"
#include "finite.hpp"

namespace fairsplines {

namespace {

/// The cyclide's homogeneous point from the homogeneous points (X1, Y1, W1) of the theta
/// circle and (X2, Y2, W2) of the psi circle, in frame coordinates: the standard form
///   x = (mu (c - a cos theta cos psi) + b^2 cos theta) / D,  y = b sin theta (a - mu cos psi) / D,
///   z = b sin psi (c cos theta - mu) / D,  D = a - c cos theta cos psi,
/// multiplied through by W1 W2 (every term is bilinear).
Eigen::Vector4d cyclidePoint(double a, double b, double c, double mu, const Eigen::RowVector3d& p1,
                             const Eigen::RowVector3d& p2) {
  const double X1 = p1[0], Y1 = p1[1], W1 = p1[2], X2 = p2[0], Y2 = p2[1], W2 = p2[2];
  return {mu * (c * W1 * W2 - a * X1 * X2) + b * b * X1 * W2, b * Y1 * (a * W2 - mu * X2), b * Y2 * (c * X1 - mu * W1),
          a * W1 * W2 - c * X1 * X2};
}

/// The checks of dupinCyclide on a, c, mu; returns b = sqrt(a^2 - c^2).
double cyclideB(double a, double c, double mu) {
  if (!std::isfinite(a) || !std::isfinite(c) || !std::isfinite(mu)) {
    throw InputError("a Dupin cyclide needs finite a, c and mu");
  }
  if (!(c >= 0) || !(a > c)) {
    throw InputError("a Dupin cyclide with a = " + exactNumber(a) + ", c = " + exactNumber(c) +
                     " has no real surface: it needs a > c >= 0 (b^2 = a^2 - c^2 > 0)");
  }
  if (!(mu > c && mu < a)) {
    throw InputError("the Dupin cyclide with mu = " + exactNumber(mu) +
                     " is not a ring cyclide (c = " + exactNumber(c) + " < mu < a = " + exactNumber(a) +
                     "): it has singular points (a spindle or horn cyclide)");
  }
  return std::sqrt(a * a - c * c);
}

/// The homogeneous world point (w p, w) of a frame point given in homogeneous frame coordinates.
Eigen::RowVector4d inFrame(const ShapeFrame& f, const Eigen::Vector4d& h) {
  const Eigen::Vector3d p = h[0] * f.x + h[1] * f.y + h[2] * f.z + h[3] * f.origin;
  return {p.x(), p.y(), p.z(), h[3]};
}

/// The cyclide's default ring on the arc knots T (a full turn): around u the poles of the
/// revolution's default ring on the unit theta circle, along v 4 rows on the psi circle's
/// tangent beyond the last v angle, each mapped by the cyclide's bilinear form (rational).
Handle(Geom_BSplineSurface) cyclideRing(const ShapeFrame& frame, double a, double b, double c, double mu,
                                        const G2CircleSpline& lon, const Eigen::VectorXd& anglesV,
                                        const Eigen::VectorXd& T) {
  // The default ring in the same tensor form: around u the poles of the revolution's default
  // ring on the unit theta circle (pushed out so that the cubic passes near it), along v 4
  // rows on the psi circle's tangent beyond the interface; each pole mapped by the cyclide's
  // bilinear form, so the ring is rational and continues the cyclide.
  const int n = lon.pieces();
  const double phi = anglesV[anglesV.size() - 1], h = anglesV[anglesV.size() - 1] - anglesV[anglesV.size() - 2];
  TColgp_Array2OfPnt poles(1, n, 1, 4);
  TColStd_Array2OfReal weights(1, n, 1, 4);
  for (int j = 0; j < 4; ++j) {
    const double s = h * (0.5 + 0.25 * j);
    const Eigen::RowVector3d q(std::cos(phi) - s * std::sin(phi), std::sin(phi) + s * std::cos(phi), 1.0);
    PointMatrix row(n, 4);
    for (int i = 0; i < n; ++i) {
      const double spread = (lon.alpha[(i + n - 1) % n] + lon.alpha[i]) / 2, f = 3.0 / (2.0 + std::cos(spread));
      const Eigen::RowVector3d p1(f * std::cos(lon.theta[i]), f * std::sin(lon.theta[i]), 1.0);
      // row i + 2: the ring's span k between longitudes k and k + 1 (see defaultRing)
      row.row((i + 2) % n) = inFrame(frame, cyclidePoint(a, b, c, mu, p1, q));
      if (!(row((i + 2) % n, 3) > 0)) throw InputError("the cyclide's default ring has a weight that is not positive");
    }
    const BSplineCurve layout = periodicCubic(row, T);
    for (int i = 0; i < n; ++i) {
      const double w = layout.poles(i, 3);
      poles.SetValue(i + 1, j + 1, gp_Pnt(layout.poles(i, 0) / w, layout.poles(i, 1) / w, layout.poles(i, 2) / w));
      weights.SetValue(i + 1, j + 1, w);
    }
  }
  TColStd_Array1OfReal uKnots(1, static_cast<int>(T.size())), vKnots(1, 2);
  TColStd_Array1OfInteger uMults(1, static_cast<int>(T.size())), vMults(1, 2);
  for (Eigen::Index k = 0; k < T.size(); ++k) {
    uKnots.SetValue(static_cast<int>(k) + 1, T[k]);
    uMults.SetValue(static_cast<int>(k) + 1, 1);
  }
  vKnots.SetValue(1, 0.0);
  vKnots.SetValue(2, 1.0);
  vMults.Init(4);
  return new Geom_BSplineSurface(poles, weights, uKnots, vKnots, uMults, vMults, 3, 3, true, false);
}

}  // namespace

G2Surface dupinCyclide(const ShapeFrame& frame, double a, double c, double mu, const Eigen::VectorXd& anglesU,
                       const Eigen::VectorXd& anglesV) {
  frame.check();
  const double b = cyclideB(a, c, mu);
  const G2CircleSpline cu = g2Circle(anglesU), cv = g2Circle(anglesV);
  G2Surface s;
  s.nu = cu.pieces();
  s.nv = cv.pieces();
  s.closedU = cu.closed;
  s.closedV = cv.closed;
  s.betaU = cu.beta;
  s.gammaU = cu.gamma;
  s.betaV = cv.beta;
  s.gammaV = cv.gamma;
  s.bezier.resize(16 * s.nu * s.nv, 4);
  for (int I = 0; I < s.nu; ++I) {
    for (int J = 0; J < s.nv; ++J) {
      for (int r = 0; r < 4; ++r) {
        for (int q = 0; q < 4; ++q) {
          const Eigen::Vector4d h = cyclidePoint(a, b, c, mu, cu.cubic.row(4 * I + r), cv.cubic.row(4 * J + q));
          if (!(h[3] > 0)) {
            throw InputError("the Dupin cyclide's patch (" + std::to_string(I) + ", " + std::to_string(J) +
                             ") has a control weight that is not positive (c / a = " + exactNumber(c / a) +
                             " with arcs this wide): use more, shorter arcs");
          }
          s.point(I, J, r, q) = inFrame(frame, h);
        }
      }
    }
  }
  requireFinite(s.bezier, "the Dupin cyclide (its sizes are too large for double precision)",
                "homogeneous control points");
  return s;
}

BlendComplex blendCyclide(const ShapeFrame& frame, double a, double c, double mu, const Eigen::VectorXd& anglesU,
                          const Eigen::VectorXd& anglesV, CircleReparam method) {
  dupinCyclide(frame, a, c, mu, anglesU, anglesV);  // the shape's checks, positive weights
  const double b = cyclideB(a, c, mu);
  const G2CircleSpline lon = detail::checkedLongitudes(frame, anglesU);
  if (!lon.closed) throw InputError("the cyclide's blend needs a full turn of angles_u");
  // Step 1 of Section 4.2: the theta circle becomes the C2 sextic of Section 4.1; the psi
  // circle's pieces are the profile (its sextic rows: circleToC2 along v too). The map to
  // the cyclide is linear in each circle's homogeneous points, so the layers stay C2 in u
  // and the cyclide stays exact.
  const C2SexticSpline c2 = circleToC2(lon, method);
  const detail::RevolvedProfile psi = detail::circleProfile(0.0, 1.0, anglesV, method);
  detail::BasicLayers basic;
  basic.rows = static_cast<int>(psi.sextic.size());
  basic.dv = 6;
  basic.knotsV = psi.sexticKnots;
  basic.c2InV = true;
  for (int J = 0; J < basic.rows; ++J) {
    for (int sv = 0; sv <= 6; ++sv) {
      C2SexticSpline layer = c2;
      layer.bezier.resize(c2.bezier.rows(), 4);  // homogeneous points in space: (w p, w)
      for (Eigen::Index k = 0; k < c2.bezier.rows(); ++k) {
        const Eigen::RowVector3d p1(c2.bezier(k, 0), c2.bezier(k, 1), c2.bezier(k, 2));
        layer.bezier.row(k) = inFrame(frame, cyclidePoint(a, b, c, mu, p1, psi.sextic[J].row(sv)));
      }
      basic.layers.push_back(std::move(layer));
    }
  }
  const Handle(Geom_BSplineSurface) ring = cyclideRing(frame, a, b, c, mu, lon, anglesV, arcKnots(c2));
  return detail::assembleBlend(frame, lon, psi, std::move(basic), ring);
}

BlendComplex blendCyclideNaive(const ShapeFrame& frame, double a, double c, double mu, const Eigen::VectorXd& anglesU,
                               const Eigen::VectorXd& anglesV) {
  const G2Surface shape = dupinCyclide(frame, a, c, mu, anglesU, anglesV);
  const double b = cyclideB(a, c, mu);
  const G2CircleSpline lon = detail::checkedLongitudes(frame, anglesU);
  if (!lon.closed) throw InputError("the cyclide's naive blend needs a full turn of angles_u");
  // As blendRevolvedNaive: the arc knots of the blend (sigma: one piece per arc), the exact
  // G2 patches, the ring, and Fig. 2a's direct Hermite strip of degree (3,5) between them.
  const Eigen::VectorXd T = arcKnots(circleToC2(lon, CircleReparam::Sigma));
  const Handle(Geom_BSplineSurface) r =
      detail::matchRingStrict(cyclideRing(frame, a, b, c, mu, lon, anglesV, T), T, T, 3, true);
  BlendComplex out;
  out.knotsU = T;
  out.piecesU = shape.nu;
  out.closedU = true;
  out.rowsBasic = shape.nv;
  out.rowsFreeForm = r->NbVKnots() - 1;
  out.knotsV =
      Eigen::VectorXd::LinSpaced(out.rowsBasic + out.rowsFreeForm + 2, 0.0, out.rowsBasic + out.rowsFreeForm + 1);
  for (int k = 0; k < out.piecesU; ++k) {
    Homogeneous4 top, ringBottom;
    for (int j = 0; j < out.rowsBasic; ++j) {
      TaggedPatch p;
      p.uPiece = k;
      p.vPiece = j;
      p.bezier = shape.bezier.middleRows((k * shape.nv + j) * 16, 16);
      if (j + 1 == out.rowsBasic) top = p.bezier;
      out.patches.push_back(std::move(p));
    }
    for (int s = 0; s < out.rowsFreeForm; ++s) {
      int du = 0, dv = 0;
      TaggedPatch p;
      p.role = TaggedPatch::Role::FreeForm;
      p.uPiece = k;
      p.vPiece = out.rowsBasic + 1 + s;
      p.bezier = detail::bezierOf(r, T[k], T[k + 1], r->VKnot(s + 1), r->VKnot(s + 2), du, dv);
      if (s == 0) ringBottom = p.bezier;
      out.patches.push_back(std::move(p));
    }
    out.patches.push_back(detail::stripPatch(k, out.rowsBasic, 3, top, 3, ringBottom, 3));
  }
  return out;
}

}  // namespace fairsplines
