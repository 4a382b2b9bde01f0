// The derivative polygons of a cubic B-spline (eqs. (3), (5) of Karčiauskas & Peters,
// curves of monotone curvature) and the segment checks of Lemmas 1-3 and Theorems 1 and 2.
#include "fairsplines/monotone.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "fairsplines/errors.hpp"
#include "finite.hpp"
#include "monotone_common.hpp"

namespace fairsplines {

using detail::inFairLocation;
using detail::PlanarCurve;
using detail::planarCurve;

// ---------------------------------------------------------------------------------------
// Eqs. (3), (5).

Eigen::VectorXd flatKnots(const BSplineCurve& curve) {
  if (curve.periodic) throw InputError("flat knots of a periodic curve: make it non-periodic first");
  if (curve.knots.size() != curve.mults.size()) throw InputError("a B-spline needs one multiplicity per knot");
  const int total = curve.mults.sum();
  if (total != curve.poles.rows() + curve.degree + 1) {
    throw InputError("the multiplicities must add up to the number of poles + degree + 1");
  }
  Eigen::VectorXd flat(total);
  int k = 0;
  for (Eigen::Index i = 0; i < curve.knots.size(); ++i) {
    for (int m = 0; m < curve.mults[i]; ++m) flat[k++] = curve.knots[i];
  }
  return flat;
}

DerivativePolygons derivativePolygons(const BSplineCurve& cubic) {
  if (cubic.degree != 3)
    throw InputError("eqs. (3) and (5) are for cubic B-splines, got degree " + std::to_string(cubic.degree));
  if (cubic.isRational()) throw InputError("eqs. (3) and (5) are for non-rational B-splines");
  requireValidCurve(cubic, "the cubic");
  const Eigen::VectorXd t = flatKnots(cubic);
  const Eigen::Index n = cubic.poles.rows();
  DerivativePolygons out;
  out.first.resize(n - 1, cubic.poles.cols());
  for (Eigen::Index i = 0; i + 1 < n; ++i) {
    const double h = t[i + 4] - t[i + 1];
    if (!(h > 0))
      throw InputError("knots t_" + std::to_string(i + 1) + " and t_" + std::to_string(i + 4) + " coincide");
    out.first.row(i) = 3.0 / h * (cubic.poles.row(i + 1) - cubic.poles.row(i));  // eq. (3)
  }
  out.second.resize(std::max<Eigen::Index>(n - 2, 0), cubic.poles.cols());
  for (Eigen::Index i = 0; i + 2 < n; ++i) {
    const double h = t[i + 4] - t[i + 2];
    if (!(h > 0))
      throw InputError("knots t_" + std::to_string(i + 2) + " and t_" + std::to_string(i + 4) + " coincide");
    out.second.row(i) = 2.0 / h * (out.first.row(i + 1) - out.first.row(i));  // eq. (5)
  }
  // Poles far apart over short knot spans overflow the derivatives' control points.
  requireFinite(out.first, "the cubic's first-derivative polygon (eq. (3))", "control points");
  requireFinite(out.second, "the cubic's second-derivative polygon (eq. (5))", "control points");
  return out;
}

// ---------------------------------------------------------------------------------------
// Lemmas 1-3, Theorems 1 and 2.

SegmentCheck checkSegment(const Eigen::Vector2d c[4], const double u[6], double tol) {
  SegmentCheck r;
  const Vec2 V0 = c[1] - c[0], V1 = c[2] - c[1], V2 = c[3] - c[2];
  const double n0 = V0.norm();
  if (!(n0 > 0.0)) {
    r.degenerate = true;
    return r;
  }
  // Eq. (3): C^1_{j-3..j-1}; eq. (5): C^2_{j-3..j-2} (local knots u = t_{j-2}..t_{j+3}).
  const Vec2 D0 = 3.0 / (u[3] - u[0]) * V0, D1 = 3.0 / (u[4] - u[1]) * V1, D2 = 3.0 / (u[5] - u[2]) * V2;
  const Vec2 E0 = 2.0 / (u[3] - u[1]) * (D1 - D0), E1 = 2.0 / (u[4] - u[2]) * (D2 - D1);
  // Local frame: x along the first control vector; y its left normal. Comparisons are
  // relative to the segment's largest derivative control point (rounding of a vanishing C^2
  // must not count as leaving the quadrant).
  const Vec2 fx = V0 / n0, fy(-fx.y(), fx.x());
  const Vec2* points[4] = {&D1, &D2, &E0, &E1};
  const double scale = std::max({D0.norm(), D1.norm(), D2.norm(), E0.norm(), E1.norm()});
  const double s = tol * scale, s2 = tol * scale * scale;
  bool above = false, below = false;
  for (const Vec2* p : points) {
    const double y = p->dot(fy);
    above = above || y > s;
    below = below || y < -s;
  }
  const int turn = below && !above ? -1 : 1;  // check a right turn as its mirror image
  auto local = [&](const Vec2& v) { return Vec2(v.dot(fx), turn * v.dot(fy)); };
  const Vec2 d1 = local(D1), e0 = local(E0), e1 = local(E1);
  r.lemma1 = true;
  for (int k = 0; k < 4; ++k) {
    const Vec2 p = local(*points[k]);
    if (p.x() < -s || p.y() < -s) {
      r.lemma1 = false;
      r.offQuadrant = k;
      break;
    }
  }
  r.turn = r.lemma1 ? turn : 0;
  // Lemma 2: angle O C^2_{j-2} C^2_{j-3} >= 90 deg, i.e. e1 . (e1 - e0) <= 0.
  // (pi when C^2_{j-2} = O, pi/2 when C^2_{j-2} = C^2_{j-3}: on the circle)
  r.angle = e1.squaredNorm() == 0.0                 ? kPi
            : (e0 - e1).norm() <= 1e-12 * e0.norm() ? 0.5 * kPi
                                                    : std::atan2(std::abs(cross(-e1, e0 - e1)), (-e1).dot(e0 - e1));
  r.lemma2 = e1.dot(e1 - e0) <= s2;
  // Lemma 3 (read from Theorem 2 and Fig. 4): slope(O C^1_{j-2}) <= slope(O C^2_{j-2}) <= slope(O C^2_{j-3}).
  const bool first = cross(d1, e1) >= -s2;
  const bool second = cross(e1, e0) >= -s2;
  r.lemma3 = first && second;
  r.slopeOrder = !first ? 1 : (!second ? 2 : 0);
  // Theorem 2: (i) C^2_{j-2} in the fair location of Fig. 3, (ii) slope(O C^1_{j-2}) <= slope(O C^2_{j-3}),
  // (iii) the quadrant condition.
  r.fairLocation = inFairLocation(e1, e0, d1, s2);
  const bool slopes = cross(d1, e0) >= -s2;
  r.theorem2 = r.fairLocation && slopes && r.lemma1;
  return r;
}

std::string describe(const SegmentCheck& check) {
  if (check.degenerate) return "the segment's first control vector is zero: no local frame";
  static const char* names[] = {"C^1_{j-2}", "C^1_{j-1}", "C^2_{j-3}", "C^2_{j-2}"};
  if (!check.lemma1) {
    return std::string("Lemma 1 fails: ") + names[check.offQuadrant] +
           " leaves the quadrant of the other derivative control points (local frame)";
  }
  if (!check.lemma2) {
    return "Lemma 2 fails: the angle O C^2_{j-2} C^2_{j-3} is " + num(degrees(check.angle)) +
           " deg < 90 deg, so |P''| may grow";
  }
  if (!check.lemma3) {
    return check.slopeOrder == 1 ? "Lemma 3 fails: slope(O C^1_{j-2}) > slope(O C^2_{j-2})"
                                 : "Lemma 3 fails: slope(O C^2_{j-2}) > slope(O C^2_{j-3})";
  }
  return std::string("Theorem 1 holds (") + (check.turn > 0 ? "left" : "right") +
         " turn): |kappa| does not increase on the segment" +
         (check.theorem2 ? "; C^2_{j-2} is in its fair location (Theorem 2)" : "");
}

std::vector<SegmentReport> checkSegments(const BSplineCurve& cubic) {
  if (cubic.degree != 3 || cubic.isRational() || cubic.periodic) {
    throw InputError("the paper's conditions are for non-periodic, non-rational cubic B-splines");
  }
  const PlanarCurve pc = planarCurve(cubic);
  std::vector<SegmentReport> out;
  const int n = static_cast<int>(pc.poles.rows()) - 1;
  for (int j = 3; j <= n; ++j) {
    if (!(pc.flat[j + 1] > pc.flat[j])) continue;
    Vec2 c[4];
    for (int i = 0; i < 4; ++i) c[i] = pc.poles.row(j - 3 + i).transpose();
    SegmentReport report;
    report.u0 = pc.flat[j];
    report.u1 = pc.flat[j + 1];
    report.check = checkSegment(c, pc.flat.data() + (j - 2));
    out.push_back(report);
  }
  return out;
}

}  // namespace fairsplines
