#include "fairsplines/blend_c1.hpp"

#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "fairsplines/errors.hpp"
#include "fairsplines/g1_to_c1.hpp"
#include "blend_detail.hpp"
#include "blend_surface_detail.hpp"

namespace fairsplines {

using detail::bezierOf;
using detail::revolveRows;

namespace {

const double kPi = std::acos(-1.0);

/// Increasing, finite angles whose arcs open less than pi (a rational quadratic arc needs
/// its middle weight cos(alpha/2) > 0); the message names the offending arc.
void checkArcs(const Eigen::VectorXd& angles, const char* what) {
  if (angles.size() < 2) {
    std::ostringstream os;
    os << "the " << what << " partition needs at least two angles";
    throw InputError(os.str());
  }
  for (Eigen::Index i = 0; i < angles.size(); ++i) {
    if (!std::isfinite(angles[i])) throw InputError(std::string("non-finite ") + what + " angle");
    if (i == 0) continue;
    if (!(angles[i] > angles[i - 1])) {
      std::ostringstream os;
      os << what << " angles must increase: angle " << i << " is not greater than angle " << i - 1;
      throw InputError(os.str());
    }
    if (angles[i] - angles[i - 1] >= kPi - 1e-12) {
      std::ostringstream os;
      os << what << " arc " << i - 1 << " (from " << angles[i - 1] << " to " << angles[i] << ") opens "
         << angles[i] - angles[i - 1]
         << ", pi or more: a rational quadratic arc must open less than pi (its weight cos(alpha/2) must be positive)";
      throw InputError(os.str());
    }
  }
}

/// Eq. (12)'s arc-level knots: the first arc of length 1, then ratios betaT; the product of
/// betaT over a closed turn must be 1 (else the closing join cannot have scalar betaT_0).
Eigen::VectorXd arcKnotsC1(const Eigen::VectorXd& betaT, bool closed) {
  const Eigen::Index n = betaT.size();
  Eigen::VectorXd T(n + 1);
  T[0] = 0.0;
  double L = 1.0;
  for (Eigen::Index i = 0; i < n; ++i) {
    if ((i > 0 || closed) && !(betaT[i] > 0 && std::isfinite(betaT[i]))) {
      std::ostringstream os;
      os << "betaT " << i << " (" << betaT[i] << ") must be positive";
      throw InputError(os.str());
    }
    if (i > 0) L *= betaT[i];
    T[i + 1] = T[i] + L;
  }
  if (closed && std::abs(L * betaT[0] - 1.0) > 1e-9) {
    std::ostringstream os;
    os << "the scalars betaT must multiply to 1 around the full turn (they give the knot-interval ratios), not "
       << L * betaT[0];
    throw InputError(os.str());
  }
  return T;
}

/// A circle profile: centre (rhoOffset, 0), radius r, partition `angles`, as rational
/// quadratics (x, y, w) -> (rhoOffset w + r x, r y, w).
void circleProfile(G1RevolvedShape& s, double rhoOffset, double r, const Eigen::VectorXd& angles, const char* what) {
  checkArcs(angles, what);
  PointMatrix q;
  bool closed = false;
  g1Circle(angles, q, s.profileBeta, closed);
  if (closed) throw InputError("a closed profile circle has no boundary to blend at; give an open range of angles");
  const int m = static_cast<int>(q.rows() / 3);
  for (int j = 0; j < m; ++j) {
    Homogeneous3 piece(3, 3);
    for (int k = 0; k < 3; ++k) {
      const auto h = q.row(3 * j + k);
      piece.row(k) << rhoOffset * h[2] + r * h[0], r * h[1], h[2];
    }
    s.profile.push_back(piece);
  }
  s.profileKnots = Eigen::VectorXd::LinSpaced(m + 1, 0.0, m);
  const double phi = angles[m];
  s.end << rhoOffset + r * std::cos(phi), r * std::sin(phi);
  s.tangent << -std::sin(phi), std::cos(phi);
  s.size = r * (angles[m] - angles[m - 1]);
  s.start << rhoOffset + r * std::cos(angles[0]), r * std::sin(angles[0]);
  s.startTangent << std::sin(angles[0]), -std::cos(angles[0]);
  s.startSize = r * (angles[1] - angles[0]);
}

void aroundAxis(G1RevolvedShape& s, const ShapeFrame& frame, const Eigen::VectorXd& angles) {
  frame.check();
  s.frame = frame;
  checkArcs(angles, "longitude");
  s.theta = angles;
  g1Circle(angles, s.circle, s.beta, s.closedU);
}

/// Negative control: arc i split at its middle, each half degree-raised to a quartic (the
/// identity map in the form of composeQuadratic2), no eta.
PointMatrix splitAndRaise(const PointMatrix& quadratics) {
  const int n = static_cast<int>(quadratics.rows() / 3);
  PointMatrix out(10 * n, quadratics.cols());
  Reparam2 left, right;
  left << 0.0, 1.0, 0.25, 1.0, 0.5, 1.0;
  right << 0.5, 1.0, 0.75, 1.0, 1.0, 1.0;
  for (int i = 0; i < n; ++i) {
    const PointMatrix q = quadratics.middleRows(3 * i, 3);
    out.middleRows(10 * i, 5) = composeQuadratic2(q, left);
    out.middleRows(10 * i + 5, 5) = composeQuadratic2(q, right);
  }
  return out;
}

/// The rows of a G1 shape along its profile: the quadratics as they are (lines are C1 over
/// the heights, circle arcs only G1), or (quarticInV, circle profiles) the C1 quartics of
/// eq. (12) along the profile too.
struct ProfileRows {
  std::vector<Homogeneous3> rows;
  Eigen::VectorXd knots;
  int degree = 2;
  bool c1 = false;
};

ProfileRows profileRows(const G1RevolvedShape& shape, bool quarticInV) {
  ProfileRows out;
  const int m = shape.piecesV();
  if (quarticInV && !shape.profileIsLine && !shape.profileIsCurve) {
    PointMatrix stacked(3 * m, 3);
    for (int j = 0; j < m; ++j) stacked.middleRows(3 * j, 3) = shape.profile[j];
    const C1QuarticSpline c1 = g1ToC1(stacked, shape.profileBeta, shape.profileBeta, false);
    const Eigen::VectorXd Tv = arcKnotsC1(shape.profileBeta, false);
    out.knots.resize(2 * m + 1);
    for (int j = 0; j < m; ++j) {
      out.rows.push_back(Homogeneous3(c1.bezier.middleRows(10 * j, 5)));
      out.rows.push_back(Homogeneous3(c1.bezier.middleRows(10 * j + 5, 5)));
      out.knots[2 * j] = Tv[j];
      out.knots[2 * j + 1] = (Tv[j] + Tv[j + 1]) / 2;
    }
    out.knots[2 * m] = Tv[m];
    out.degree = 4;
    out.c1 = true;
  } else {
    out.rows = shape.profile;
    out.knots = shape.profileKnots;
    out.c1 = shape.profileIsLine;
    out.degree = static_cast<int>(shape.profile.front().rows()) - 1;
  }
  return out;
}

/// Eq. (12)'s piece knots from the arc knots T: two quartics of half the arc's interval per
/// arc (they join with scalar 1).
Eigen::VectorXd halfArcKnots(const Eigen::VectorXd& T) {
  const int n = static_cast<int>(T.size()) - 1;
  Eigen::VectorXd out(2 * n + 1);
  for (int i = 0; i < n; ++i) {
    out[2 * i] = T[i];
    out[2 * i + 1] = (T[i] + T[i + 1]) / 2;
  }
  out[2 * n] = T[n];
  return out;
}

/// An empty Section 5 complex over the piece knots `knotsU`: smoothness 1, two strip rows,
/// closed in u for a full turn.
BlendComplex c1Complex(const Eigen::VectorXd& knotsU, bool closed) {
  BlendComplex out;
  out.smoothness = 1;
  out.rowsTransition = 2;
  out.closedU = closed;
  out.piecesU = static_cast<int>(knotsU.size()) - 1;
  out.knotsU = knotsU;
  return out;
}

/// Section 5's double strip of u-piece k, rows vPiece and vPiece + 1, degree (4,2): the lower
/// row takes the first-order Hermite data (two layers) of `below` (degree dvBelow in v, its
/// top), the upper row those of `above` (degree dvAbove, its bottom), both rows as long as
/// the row below; the shared centre line, the average of the two inner layers, makes the
/// double strip C1 (with equal v-intervals it is the only choice).
void doubleStrip(int k, int vPiece, const Homogeneous4& below, int dvBelow, const Homogeneous4& above, int dvAbove,
                 std::vector<TaggedPatch>& patches) {
  TaggedPatch lower, upper;
  lower.role = upper.role = TaggedPatch::Role::Transition;
  lower.degreeU = upper.degreeU = 4;
  lower.degreeV = upper.degreeV = 2;
  lower.uPiece = upper.uPiece = k;
  lower.vPiece = vPiece;
  upper.vPiece = vPiece + 1;
  lower.bezier.resize(15, 4);
  upper.bezier.resize(15, 4);
  for (int a = 0; a <= 4; ++a) {
    // Same v-derivative over the same length: 2 (b_1 - b_0) = dvBelow (top - the layer before).
    const Eigen::RowVector4d b0 = below.row(a * (dvBelow + 1) + dvBelow);
    const Eigen::RowVector4d b1 = b0 + dvBelow / 2.0 * (b0 - below.row(a * (dvBelow + 1) + dvBelow - 1));
    const Eigen::RowVector4d c2 = above.row(a * (dvAbove + 1));
    const Eigen::RowVector4d c1 = c2 - dvAbove / 2.0 * (above.row(a * (dvAbove + 1) + 1) - c2);
    const Eigen::RowVector4d centre = (b1 + c1) / 2;
    lower.bezier.row(a * 3) = b0;
    lower.bezier.row(a * 3 + 1) = b1;
    lower.bezier.row(a * 3 + 2) = centre;
    upper.bezier.row(a * 3) = centre;
    upper.bezier.row(a * 3 + 1) = c1;
    upper.bezier.row(a * 3 + 2) = c2;
  }
  patches.push_back(std::move(lower));
  patches.push_back(std::move(upper));
}

}  // namespace

TaggedPatch G1RevolvedShape::patch(int i, int j) const {
  if (i < 0 || i >= piecesU() || j < 0 || j >= piecesV()) throw InputError("no such patch");
  TaggedPatch p;
  p.degreeU = 2;
  p.degreeV = static_cast<int>(profile[j].rows()) - 1;
  p.uPiece = i;
  p.vPiece = j;
  p.bezier = revolveRows(frame, circle.middleRows(3 * i, 3), profile[j]);
  return p;
}

G1RevolvedShape g1SphereZone(const ShapeFrame& frame, double radius, const Eigen::VectorXd& longitudes,
                             const Eigen::VectorXd& latitudes) {
  if (!(radius > 0) || !std::isfinite(radius)) throw InputError("a sphere needs a positive radius");
  for (Eigen::Index j = 0; j < latitudes.size(); ++j) {
    if (!(std::abs(latitudes[j]) <= kPi / 2 + 1e-15)) throw InputError("latitudes must lie in [-pi/2, pi/2]");
  }
  G1RevolvedShape s;
  aroundAxis(s, frame, longitudes);
  circleProfile(s, 0.0, radius, latitudes, "latitude");
  return s;
}

G1RevolvedShape g1Cone(const ShapeFrame& frame, double radius0, double slope, const Eigen::VectorXd& angles,
                       const Eigen::VectorXd& heights) {
  if (!std::isfinite(radius0) || !std::isfinite(slope)) throw InputError("a cone needs a finite radius and slope");
  G1RevolvedShape s;
  aroundAxis(s, frame, angles);
  detail::checkHeights(heights, radius0, slope);
  const int m = static_cast<int>(heights.size()) - 1;
  // Lines degree-raised to 2: C1 over the heights as they are (beta_j = h_j / h_{j-1}).
  s.profileBeta = Eigen::VectorXd::Ones(m);
  for (int j = 0; j < m; ++j) {
    Homogeneous3 q(3, 3);
    for (int k = 0; k < 3; ++k) {
      const double z = heights[j] + (heights[j + 1] - heights[j]) * k / 2.0;
      q.row(k) << radius0 + slope * z, z, 1.0;
    }
    s.profile.push_back(q);
    if (j > 0) s.profileBeta[j] = (heights[j + 1] - heights[j]) / (heights[j] - heights[j - 1]);
  }
  s.profileIsLine = true;
  s.profileKnots = heights.array() - heights[0];
  detail::setLineEnds(s, radius0, slope, heights);
  return s;
}

G1RevolvedShape reversedProfile(const G1RevolvedShape& shape) {
  G1RevolvedShape r = shape;
  const int m = shape.piecesV();
  r.profile.clear();
  for (int j = m - 1; j >= 0; --j) r.profile.push_back(shape.profile[j].colwise().reverse());
  // beta'_j joins reversed pieces j - 1 and j, i.e. original pieces m - j and m - j - 1.
  r.profileBeta = Eigen::VectorXd::Ones(m);
  for (int j = 1; j < m; ++j) r.profileBeta[j] = 1.0 / shape.profileBeta[m - j];
  for (int j = 0; j <= m; ++j) r.profileKnots[j] = shape.profileKnots[m] - shape.profileKnots[m - j];
  std::swap(r.end, r.start);
  std::swap(r.tangent, r.startTangent);
  std::swap(r.size, r.startSize);
  return r;
}

G1RevolvedShape g1Torus(const ShapeFrame& frame, double R, double r, const Eigen::VectorXd& anglesU,
                        const Eigen::VectorXd& anglesV) {
  if (!(r > 0) || !(R > r) || !std::isfinite(R)) throw InputError("a torus needs radii 0 < r < R");
  G1RevolvedShape s;
  aroundAxis(s, frame, anglesU);
  circleProfile(s, R, r, anglesV, "tube");
  return s;
}

Eigen::VectorXd ringKnotsC1(const Eigen::VectorXd& angles, const Eigen::VectorXd& betaT) {
  checkArcs(angles, "longitude");
  PointMatrix q;
  Eigen::VectorXd beta;
  bool closed = false;
  g1Circle(angles, q, beta, closed);
  if (betaT.size() != 0 && betaT.size() != beta.size()) throw InputError("betaT needs one scalar per arc");
  return arcKnotsC1(betaT.size() ? betaT : beta, closed);
}

Handle(Geom_BSplineSurface) defaultRingC1(const G1RevolvedShape& shape, const Eigen::VectorXd& knotsU) {
  const int n = shape.piecesU();
  if (knotsU.size() != n + 1) throw InputError("the ring needs one knot per arc around the axis, plus one");
  const detail::RingRows rows = detail::defaultRingRows(shape.end, shape.tangent, shape.size, 3, "interface");
  const Eigen::Vector2d base = shape.end + rows.offset * shape.tangent;
  const double step = rows.step;
  const ShapeFrame& f = shape.frame;
  const bool closed = shape.closedU;
  // Full turn: periodic, one pole per arc. Partial turn: clamped, n + 2 poles, the end ones
  // on the circle at the first and last angle.
  const int poleCount = closed ? n : n + 2;
  TColgp_Array2OfPnt poles(1, poleCount, 1, 3);
  for (int j = 0; j < 3; ++j) {
    const Eigen::Vector2d rz = base + j * step * shape.tangent;
    auto at = [&](double theta, double rho) {
      const Eigen::Vector3d q = f.origin + rho * (std::cos(theta) * f.x + std::sin(theta) * f.y) + rz.y() * f.z;
      return gp_Pnt(q.x(), q.y(), q.z());
    };
    for (int i = 0; i < n; ++i) {
      // The arc's tangent intersection (the quadratic circle's middle control point); OCCT's
      // periodic span i is governed by poles i, i+1, i+2: arc i's pole is pole i + 1 (the
      // clamped one's, after the end pole, too).
      const double alpha = shape.theta[i + 1] - shape.theta[i], mid = shape.theta[i] + alpha / 2;
      poles.SetValue(closed ? (i + 1) % n + 1 : i + 2, j + 1, at(mid, rz.x() / std::cos(alpha / 2)));
    }
    if (!closed) {
      poles.SetValue(1, j + 1, at(shape.theta[0], rz.x()));
      poles.SetValue(n + 2, j + 1, at(shape.theta[n], rz.x()));
    }
  }
  TColStd_Array1OfReal uKnots(1, n + 1), vKnots(1, 2);
  TColStd_Array1OfInteger uMults(1, n + 1), vMults(1, 2);
  for (int k = 0; k <= n; ++k) {
    uKnots.SetValue(k + 1, knotsU[k]);
    uMults.SetValue(k + 1, closed || (k > 0 && k < n) ? 1 : 3);
  }
  vKnots.SetValue(1, 0.0);
  vKnots.SetValue(2, 1.0);
  vMults.Init(3);
  return new Geom_BSplineSurface(poles, uKnots, vKnots, uMults, vMults, 2, 2, closed, false);
}

BlendComplex blendC1(const G1RevolvedShape& shape, Handle(Geom_BSplineSurface) ring, const C1BlendOptions& options) {
  shape.frame.check();
  const int n = shape.piecesU(), m = shape.piecesV();
  if (n < 1 || m < 1) throw InputError("the shape has no patches");
  if (!(shape.end.x() > 1e-9 * (std::abs(shape.end.y()) + shape.size))) {
    throw InputError("the interface lies on the axis (a pole): there is no ring to join there");
  }
  if (options.betaT.size() != 0 && options.betaT.size() != n) throw InputError("betaT needs one scalar per arc");
  const Eigen::VectorXd betaT = options.betaT.size() ? options.betaT : shape.beta;
  const bool closed = shape.closedU;
  const Eigen::VectorXd T = arcKnotsC1(betaT, closed);

  // Step 1, eq. (12): every quadratic arc around the axis becomes two C1 quartics
  // q^i∘eta^{i,0}, q^i∘eta^{i,1} (Appendix 7.3), exactly on the circle (a full turn or part
  // of one: an open circle's end arcs keep the identity's speed at their free ends).
  const PointMatrix quartics =
      options.withoutEta ? splitAndRaise(shape.circle) : g1ToC1(shape.circle, shape.beta, betaT, closed).bezier;
  BlendComplex out = c1Complex(halfArcKnots(T), closed);

  // Along the profile: the quadratics as they are, or (quarticInV, circles) eq. (12) too.
  const ProfileRows profile = profileRows(shape, options.quarticInV);
  const std::vector<Homogeneous3>& rows = profile.rows;
  const Eigen::VectorXd& basicKnotsV = profile.knots;
  const int dvBasic = profile.degree;
  out.basicC2InV = profile.c1;
  out.rowsBasic = static_cast<int>(rows.size());

  // Step 2: the ring with the half-arc knots, its patches raised to degree 4 in u. A user
  // ring may have any knots: its period is mapped onto the circle's, the quartic pieces are
  // split at its knots (de Casteljau, exact; the C1 joins keep their scalars as lengths),
  // and it gets theirs, so that both sides share one C1 parameterization.
  PointMatrix circlePieces = quartics;
  Handle(Geom_BSplineSurface) r;
  if (ring.IsNull()) {
    r = defaultRingC1(shape, T);
  } else {
    r = detail::normalisedRing(ring, shape.frame, T[n] - T[0], 2, shape.theta[n] - shape.theta[0]);
    const std::vector<std::vector<double>> cuts = detail::ringCuts(r, out.knotsU);
    if (std::any_of(cuts.begin(), cuts.end(), [](const std::vector<double>& c) { return !c.empty(); })) {
      const detail::SplitPieces split = detail::splitBezierPieces(quartics, 5, out.knotsU, cuts);
      circlePieces = split.bezier;
      out.knotsU = split.knots;
      out.piecesU = static_cast<int>(split.knots.size()) - 1;
    }
  }
  r = detail::withKnots(r, out.knotsU);
  const int spansV = r->NbVKnots() - 1;
  out.rowsFreeForm = spansV;

  // Shared v parameterization: both strip rows as long as the top basic row, the ring's
  // first span that length again (scalar 1 across all three seams of the double strip).
  const double h = basicKnotsV[out.rowsBasic] - basicKnotsV[out.rowsBasic - 1];
  out.knotsV.resize(out.rowsBasic + 2 + spansV + 1);
  out.knotsV.head(out.rowsBasic + 1) = basicKnotsV;
  out.knotsV[out.rowsBasic + 1] = basicKnotsV[out.rowsBasic] + h;
  out.knotsV[out.rowsBasic + 2] = basicKnotsV[out.rowsBasic] + 2 * h;
  for (int sp = 0; sp < spansV; ++sp) {
    out.knotsV[out.rowsBasic + 3 + sp] =
        out.knotsV[out.rowsBasic + 2 + sp] + h * (r->VKnot(sp + 2) - r->VKnot(sp + 1)) / (r->VKnot(2) - r->VKnot(1));
  }

  for (int k = 0; k < out.piecesU; ++k) {
    const PointMatrix circle = circlePieces.middleRows(5 * k, 5);
    Homogeneous4 top;
    for (int j = 0; j < out.rowsBasic; ++j) {
      TaggedPatch p;
      p.role = TaggedPatch::Role::Basic;
      p.degreeU = 4;
      p.degreeV = dvBasic;
      p.uPiece = k;
      p.vPiece = j;
      p.bezier = revolveRows(shape.frame, circle, rows[j]);
      if (j + 1 == out.rowsBasic) top = p.bezier;
      out.patches.push_back(std::move(p));
    }
    TaggedPatch ringBottom;
    for (int s = 0; s < spansV; ++s) {
      TaggedPatch p;
      p.role = TaggedPatch::Role::FreeForm;
      p.uPiece = k;
      p.vPiece = out.rowsBasic + 2 + s;
      p.bezier = bezierOf(r, out.knotsU[k], out.knotsU[k + 1], r->VKnot(s + 1), r->VKnot(s + 2), p.degreeU, p.degreeV);
      if (s == 0) ringBottom = raisePatch(p, 4, 2);
      out.patches.push_back(std::move(p));
    }
    // Step 3 (Section 5): first-order Hermite data across the boundary, two layers per side,
    // fill the double strip of degree (4,2).
    doubleStrip(k, out.rowsBasic, top, dvBasic, ringBottom.bezier, 2, out.patches);
  }
  return out;
}

G1RevolvedShape g1Revolution(const ShapeFrame& frame, const Eigen::VectorXd& angles, const Homogeneous3& cubic,
                             const Eigen::VectorXd& knots) {
  G1RevolvedShape s;
  aroundAxis(s, frame, angles);
  // The C2 profile's pieces and interface data (curveProfile); the cubic pieces are kept here.
  const detail::RevolvedProfile p = detail::curveProfile(cubic, knots);
  const int m = static_cast<int>(p.cubic.size());
  s.profile = p.cubic;
  s.profileBeta = Eigen::VectorXd::Ones(m);
  for (int j = 1; j < m; ++j) s.profileBeta[j] = (knots[j + 1] - knots[j]) / (knots[j] - knots[j - 1]);
  s.profileKnots = knots.array() - knots[0];
  s.profileIsCurve = true;
  // C1 in homogeneous space across every knot (the B-spline's simple and double knots).
  s.profileIsLine = true;
  for (int j = 1; j < m; ++j) {
    const double h0 = knots[j] - knots[j - 1], h1 = knots[j + 1] - knots[j];
    s.profileIsLine = s.profileIsLine && detail::joinsHomogeneousC(1, p.cubic[j - 1], p.cubic[j], h0, h1);
  }
  s.end = p.end;
  s.tangent = p.tangent;
  s.size = p.size;
  s.start = p.start;
  s.startTangent = p.startTangent;
  s.startSize = p.startSize;
  return s;
}

G1RevolvedShape g1Shape(const ShapeOfRevolution& shape) {
  switch (shape.kind) {
    case ShapeOfRevolution::Kind::Revolution:
      return g1Revolution(shape.frame, shape.around, shape.curve, shape.profile);
    case ShapeOfRevolution::Kind::SphereZone:
      return g1SphereZone(shape.frame, shape.size0, shape.around, shape.profile);
    case ShapeOfRevolution::Kind::Cone:
      return g1Cone(shape.frame, shape.size0, shape.size1, shape.around, shape.profile);
    case ShapeOfRevolution::Kind::Torus:
      break;
  }
  return g1Torus(shape.frame, shape.size0, shape.size1, shape.around, shape.profile);
}

BlendComplex joinShapesC1(const G1RevolvedShape& a, const G1RevolvedShape& b, bool quarticInV) {
  a.frame.check();
  b.frame.check();
  const int n = a.piecesU();
  if (a.closedU != b.closedU) throw InputError("both shapes need a full turn around the axis, or both a partial one");
  const bool closed = a.closedU;
  if (!(a.end.x() > 1e-9 * (std::abs(a.end.y()) + a.size))) {
    throw InputError("the first shape's profile meets the axis (a pole) at the join");
  }
  const Homogeneous3& start = b.profile.front();
  if (!(start(0, 0) / start(0, 2) > 1e-9 * (std::abs(start(0, 1) / start(0, 2)) + b.size))) {
    throw InputError("the second shape's profile meets the axis (a pole) at the join");
  }
  PointMatrix quarticsA, quarticsB;
  Eigen::VectorXd knotsU;
  if (b.piecesU() == n) {
    // Averaged scalars across the transition (Fig. 11): betaT_i = sqrt(beta_i^a beta_i^b);
    // their product around the turn is 1 as each side's is. Eq. (12) on both circles with
    // these betaT gives both sides the same knots: two quartics of half the arc's interval.
    const Eigen::VectorXd betaT = (a.beta.array() * b.beta.array()).sqrt().matrix();
    knotsU = halfArcKnots(arcKnotsC1(betaT, closed));
    quarticsA = g1ToC1(a.circle, a.beta, betaT, closed).bezier;
    quarticsB = g1ToC1(b.circle, b.beta, betaT, closed).bezier;
  } else {
    // Different partitions (the T-joints of Figs. 14, 15e): each circle by eq. (12) with its
    // own scalars, both knot vectors over one period, and "the transversal 1-jets split to
    // the finest partition on either side" (Section 5): each side's quartics split at the
    // other's knots (de Casteljau: the same C1 curve). The basic rows are split with them,
    // so the shell stays a tensor grid (the paper keeps the coarser side's patches whole).
    Eigen::VectorXd kA = halfArcKnots(arcKnotsC1(a.beta, closed)), kB = halfArcKnots(arcKnotsC1(b.beta, closed));
    kA /= kA[kA.size() - 1];
    kB /= kB[kB.size() - 1];
    const detail::SplitPieces sA =
        detail::splitBezierPieces(g1ToC1(a.circle, a.beta, a.beta, closed).bezier, 5, kA, detail::knotCuts(kB, kA));
    const detail::SplitPieces sB =
        detail::splitBezierPieces(g1ToC1(b.circle, b.beta, b.beta, closed).bezier, 5, kB, detail::knotCuts(kA, kB));
    if (sA.knots.size() != sB.knots.size() || !((sA.knots - sB.knots).cwiseAbs().maxCoeff() <= 1e-9)) {
      throw std::logic_error("joinShapesC1: the merged knots of the two sides differ");
    }
    knotsU = sA.knots;
    quarticsA = sA.bezier;
    quarticsB = sB.bezier;
  }
  BlendComplex out = c1Complex(knotsU, closed);
  const ProfileRows rowsA = profileRows(a, quarticInV), rowsB = profileRows(b, quarticInV);
  out.basicC2InV = rowsA.c1 && rowsB.c1;
  out.rowsBasic = static_cast<int>(rowsA.rows.size());
  out.rowsFreeForm = static_cast<int>(rowsB.rows.size());
  // Both strip rows and b's first row as long as a's last row (scalar 1 across three seams).
  const double h = rowsA.knots[out.rowsBasic] - rowsA.knots[out.rowsBasic - 1];
  out.knotsV.resize(out.rowsBasic + 2 + out.rowsFreeForm + 1);
  out.knotsV.head(out.rowsBasic + 1) = rowsA.knots;
  out.knotsV[out.rowsBasic + 1] = rowsA.knots[out.rowsBasic] + h;
  out.knotsV[out.rowsBasic + 2] = rowsA.knots[out.rowsBasic] + 2 * h;
  const double scaleB = h / (rowsB.knots[1] - rowsB.knots[0]);
  for (int j = 1; j <= out.rowsFreeForm; ++j) {
    out.knotsV[out.rowsBasic + 2 + j] = out.knotsV[out.rowsBasic + 2] + scaleB * (rowsB.knots[j] - rowsB.knots[0]);
  }
  const int da = rowsA.degree, db = rowsB.degree;
  for (int k = 0; k < out.piecesU; ++k) {
    Homogeneous4 top, bottom;
    for (int side = 0; side < 2; ++side) {
      const ProfileRows& rows = side == 0 ? rowsA : rowsB;
      const PointMatrix circle = (side == 0 ? quarticsA : quarticsB).middleRows(5 * k, 5);
      for (int j = 0; j < static_cast<int>(rows.rows.size()); ++j) {
        TaggedPatch p;
        p.degreeU = 4;
        p.degreeV = rows.degree;
        p.uPiece = k;
        p.vPiece = side == 0 ? j : out.rowsBasic + 2 + j;
        p.bezier = revolveRows(side == 0 ? a.frame : b.frame, circle, rows.rows[j]);
        if (side == 0 && j + 1 == out.rowsBasic) top = p.bezier;
        if (side == 1 && j == 0) bottom = p.bezier;
        out.patches.push_back(std::move(p));
      }
    }
    // Section 5: first-order Hermite data of both sides (two layers each) fill the double
    // strip of degree (4,2).
    doubleStrip(k, out.rowsBasic, top, da, bottom, db, out.patches);
  }
  return out;
}

}  // namespace fairsplines
