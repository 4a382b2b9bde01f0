// The exact certificate of monotone curvature for space curves (issue 28): the planar
// certificate of Karčiauskas & Peters (curves of monotone curvature, eq. (5); see
// monotone_certificate.cpp) carried to 3D through kappa^2 = |c' x c''|^2 / |c'|^6, which
// is smooth where kappa^2 is and has the same monotonicity as kappa. Per Bézier span:
//   polynomial:  sign d(kappa^2)/dt = sign N,
//                N = 2 (c' x c'').(c' x c''') |c'|^2 - 6 |c' x c''|^2 (c'.c''),
//   rational:    c = X / W, B = X' W - X W' (so c' = B / W^2), D = B x B',
//                kappa^2 = W^4 |D|^2 / |B|^6,
//                N = 2 W (D.(B x B'')) |B|^2 + 4 W' |D|^2 |B|^2 - 6 W |D|^2 (B.B'),
//                the derivative of kappa^2 times |B|^8 / W^3 > 0 (docs/FAIR_BLENDS.md
//                section 8 has the derivation).
// The torsion tau = det(c', c'', c''') / |c' x c''|^2 has the sign of det(B, B', B'')
// (for a polynomial cubic, det(c', c'', c''') = 2 det(a, b, c) with c' = a + b t + c t^2: a
// constant per span). Both polynomials are formed exactly in Bernstein form (bernstein.hpp)
// and signed by their coefficients and subdivision.
#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "fairsplines/monotone.hpp"
#include "bernstein.hpp"
#include "finite.hpp"
#include "monotone_common.hpp"

namespace fairsplines {
namespace {

using Poly = Eigen::VectorXd;
using PolyVec = std::array<Poly, 3>;  // a vector of polynomials: x, y, z

Poly mul(const Poly& a, const Poly& b) { return bernstein::product(a, b); }
Poly diff(const Poly& a) {
  const int n = static_cast<int>(a.size()) - 1;
  if (n == 0) return Poly::Zero(1);
  return n * (a.tail(n) - a.head(n));
}
Poly add(const Poly& a, const Poly& b) {
  const Eigen::Index degree = std::max(a.size(), b.size()) - 1;
  return bernstein::raise(a, degree) + bernstein::raise(b, degree);
}
Poly sub(const Poly& a, const Poly& b) { return add(a, -b); }
double eval(const Poly& a, double t) { return bernstein::value(a, t)[0]; }

PolyVec diff(const PolyVec& a) { return {diff(a[0]), diff(a[1]), diff(a[2])}; }
Poly dot(const PolyVec& a, const PolyVec& b) { return add(add(mul(a[0], b[0]), mul(a[1], b[1])), mul(a[2], b[2])); }
PolyVec cross(const PolyVec& a, const PolyVec& b) {
  return {sub(mul(a[1], b[2]), mul(a[2], b[1])), sub(mul(a[2], b[0]), mul(a[0], b[2])),
          sub(mul(a[0], b[1]), mul(a[1], b[0]))};
}
Vec3 eval(const PolyVec& a, double t) { return {eval(a[0], t), eval(a[1], t), eval(a[2], t)}; }
/// max_t |a(t)| <= the largest coefficient norm (convex hull).
double bound(const PolyVec& a) {
  return (a[0].array().square() + a[1].array().square() + a[2].array().square()).sqrt().maxCoeff();
}

/// The magnitude of a product of factors of sizes m plus its first-order change when each
/// factor moves by its rounding size r (the planar certificate's tolerance policy).
double termScale(std::initializer_list<std::pair<double, double>> factors) {
  double product = 1.0, change = 0.0;
  for (const auto& [m, r] : factors) {
    change = change * m + product * r;
    product *= m;
  }
  return product + change;
}

// ---------------------------------------------------------------------------------------
// Bézier spans of a (rational) space B-spline in homogeneous form (w x, w y, w z, w).

struct Arc {
  PolyVec x;
  Poly w;
  bool rational = false;
  double u0 = 0.0, u1 = 0.0;
};

/// de Boor's algorithm with one argument per level: the blossom of the span's polynomial.
Eigen::Vector4d blossom(std::vector<Eigen::Vector4d> d, const double* U, int p, const double* args) {
  for (int r = 1; r <= p; ++r) {
    for (int i = p; i >= r; --i) {
      const double left = U[i - 1], right = U[i + p - r];
      const double alpha = (args[r - 1] - left) / (right - left);
      d[i] = (1.0 - alpha) * d[i - 1] + alpha * d[i];
    }
  }
  return d[p];
}

struct SpaceData {
  PointMatrix poles;  // n x 3, moved to the first pole and divided by scale
  Eigen::VectorXd weights, flat;
  int degree = 3;
  double scale = 1.0;
};

SpaceData spaceData(const BSplineCurve& input) {
  requireValidCurve(input, "the curve");
  if (input.periodic) throw InputError("the space certificate takes non-periodic curves");
  SpaceData out;
  const Eigen::Index n = input.poles.rows();
  PointMatrix p = PointMatrix::Zero(n, 3);
  p.leftCols(std::min(3, input.dimension())) = input.poles.leftCols(std::min(3, input.dimension()));
  const Eigen::RowVectorXd origin = p.row(0);
  const double half = ((0.5 * p).rowwise() - 0.5 * origin).cwiseAbs().maxCoeff();
  if (belowRounding(half, 0.5 * p.cwiseAbs().maxCoeff())) {
    throw InputError("the curve does not move: all its poles coincide to double precision");
  }
  out.scale = powerOfTwoScale(half);
  out.poles.resize(n, 3);
  for (Eigen::Index i = 0; i < n; ++i) {
    for (int k = 0; k < 3; ++k) out.poles(i, k) = p(i, k) / out.scale - origin[k] / out.scale;
  }
  out.weights = input.weights;
  out.flat = flatKnots(input);
  out.degree = input.degree;
  return out;
}

std::vector<Arc> bezierArcs(const SpaceData& c) {
  const int p = c.degree, n = static_cast<int>(c.poles.rows()) - 1;
  const bool rational = c.weights.size() > 0;
  std::vector<Arc> arcs;
  std::vector<Eigen::Vector4d> local(p + 1);
  std::vector<double> args(p);
  for (int j = p; j <= n; ++j) {
    const double a = c.flat[j], b = c.flat[j + 1];
    if (!(b > a)) continue;
    for (int i = 0; i <= p; ++i) {
      const int k = j - p + i;
      const double w = rational ? c.weights[k] : 1.0;
      local[i] << w * c.poles(k, 0), w * c.poles(k, 1), w * c.poles(k, 2), w;
    }
    Arc arc;
    arc.rational = rational;
    arc.u0 = a;
    arc.u1 = b;
    for (int k = 0; k < 3; ++k) arc.x[k].resize(p + 1);
    arc.w.resize(p + 1);
    for (int i = 0; i <= p; ++i) {  // b_i = blossom(a^(p-i), b^i)
      for (int r = 0; r < p; ++r) args[r] = r < p - i ? a : b;
      const Eigen::Vector4d q = blossom(local, c.flat.data() + (j - p + 1), p, args.data());
      for (int k = 0; k < 3; ++k) arc.x[k][i] = q[k];
      arc.w[i] = q[3];
    }
    // Moved to the span's first point (c - P = (X - W P) / W, exact in the rational case too):
    // the derivatives do not change, and the rounding sizes below scale with the span, not
    // with its distance from the curve's first pole. With that distance instead, a short span
    // far away (a refined blend's end spans) got a tolerance larger than N itself and passed a
    // curvature that fell by 4e-6 as constant (test FairBlendSpace.G1ThousandSpaceSpiralCases).
    for (int k = 0; k < 3; ++k) {
      const double origin = arc.x[k][0] / arc.w[0];
      arc.x[k] -= origin * arc.w;
    }
    arcs.push_back(std::move(arc));
  }
  return arcs;
}

// ---------------------------------------------------------------------------------------
// The polynomials of a span.

struct SpanPolys {
  PolyVec B, B1;
  Poly w, speed2, n, det;
  double scale = 0.0, detScale = 0.0;
};

SpanPolys spanPolys(const Arc& arc) {
  SpanPolys s;
  Poly w1 = Poly::Zero(1);
  if (arc.rational) {  // B = X' W - X W': c' = B / W^2
    w1 = diff(arc.w);
    for (int k = 0; k < 3; ++k) s.B[k] = sub(mul(diff(arc.x[k]), arc.w), mul(arc.x[k], w1));
    s.w = arc.w;
  } else {
    s.B = diff(arc.x);
    s.w = Poly::Ones(1);
  }
  s.B1 = diff(s.B);
  const PolyVec B2 = diff(s.B1);
  const PolyVec D = cross(s.B, s.B1), D1 = cross(s.B, B2);  // D = B x B', D' = B x B''
  s.speed2 = dot(s.B, s.B);
  const Poly DD = dot(D, D), DD1 = dot(D, D1), BB1 = dot(s.B, s.B1);
  // Tolerance scale as the planar certificate's: each term's size plus its first-order
  // change when every derivative factor moves by the rounding size its order allows.
  const double X =
      std::max({arc.x[0].cwiseAbs().maxCoeff(), arc.x[1].cwiseAbs().maxCoeff(), arc.x[2].cwiseAbs().maxCoeff()});
  const double growth = 2.0 * static_cast<double>(s.B[0].size());
  const double mW = arc.w.cwiseAbs().maxCoeff();
  const double rB = growth * X * mW, rB1 = growth * rB, rB2 = growth * rB1;
  const double mB = bound(s.B), mB1 = bound(s.B1), mB2 = bound(B2);
  const std::pair<double, double> b{mB, rB}, b1{mB1, rB1}, b2{mB2, rB2};
  if (arc.rational) {
    const double mW1 = w1.cwiseAbs().maxCoeff();
    const std::pair<double, double> W{mW, mW}, W1{mW1, growth * mW};
    s.n = add(sub(2.0 * mul(mul(arc.w, DD1), s.speed2), 6.0 * mul(mul(arc.w, DD), BB1)),
              4.0 * mul(mul(w1, DD), s.speed2));
    s.scale = 2.0 * termScale({W, b, b, b, b, b1, b2}) + 4.0 * termScale({W1, b, b, b, b, b1, b1}) +
              6.0 * termScale({W, b, b, b, b1, b1, b1});
  } else {
    s.n = sub(2.0 * mul(DD1, s.speed2), 6.0 * mul(DD, BB1));  // the N
    s.scale = 2.0 * termScale({b, b, b, b, b1, b2}) + 6.0 * termScale({b, b, b, b1, b1, b1});
  }
  s.det = dot(s.B, cross(s.B1, B2));  // det(B, B', B''): the sign of the torsion
  s.detScale = termScale({b, b1, b2});
  return s;
}

/// Curvature W^2 |B x B'| / |B|^3 at t.
double kappaAt(const SpanPolys& s, double t) {
  const Vec3 b = eval(s.B, t), b1 = eval(s.B1, t);
  const double w = eval(s.w, t);
  return w * w * b.cross(b1).norm() / std::pow(b.norm(), 3);
}

double paramAt(const Arc& arc, double t) { return arc.u0 + t * (arc.u1 - arc.u0); }

/// Where a changes sign beyond tol on [0, 1]: 64 samples, then bisection.
std::vector<double> signChanges(const Poly& a, double tol) {
  std::vector<double> roots;
  double tPrev = 0.0;
  int sPrev = 0;
  for (int i = 0; i <= 64; ++i) {
    const double t = i / 64.0, v = eval(a, t);
    const int sg = v > tol ? 1 : (v < -tol ? -1 : 0);
    if (sg == 0) continue;
    if (sPrev != 0 && sg != sPrev) roots.push_back(bernstein::bisectRoot(a, tPrev, t));
    sPrev = sg;
    tPrev = t;
  }
  return roots;
}

SpaceSpanCertificate certifySpan(const Arc& arc, const SpanPolys& s, double relTol, double scale,
                                 std::vector<std::tuple<double, double, bool>>& extrema) {
  SpaceSpanCertificate c;
  c.u0 = arc.u0;
  c.u1 = arc.u1;
  c.degree = static_cast<int>(s.n.size()) - 1;
  const double speedTol = 1e-20 * s.speed2.cwiseAbs().maxCoeff();
  const bernstein::Bound regular =
      bernstein::certifyLower(s.speed2 - Poly::Constant(s.speed2.size(), 2.0 * speedTol), 0.0);
  if (!regular.holds || regular.undecided || !(s.speed2.cwiseAbs().maxCoeff() > 0.0)) {
    c.trend = CurvatureTrend::Singular;
    c.at = paramAt(arc, regular.witness);
    c.reason = "the derivative vanishes near u = " + num(c.at, 6) + ": the curvature is undefined there";
    return c;
  }
  c.kappa0 = kappaAt(s, 0.0) / scale;
  c.kappa1 = kappaAt(s, 1.0) / scale;
  // The torsion's sign.
  const double detTol = relTol * s.detScale;
  const bernstein::Bound tPos = bernstein::certifyLower(s.det, detTol), tNeg = bernstein::certifyLower(-s.det, detTol);
  const bool posOk = tPos.holds && !tPos.undecided, negOk = tNeg.holds && !tNeg.undecided;
  if (posOk && negOk) {
    c.torsionSign = 0;
  } else if (posOk || negOk) {
    c.torsionSign = posOk ? 1 : -1;
  } else {
    for (double t : signChanges(s.det, detTol)) c.torsionChanges.push_back(paramAt(arc, t));
    c.torsionSign = eval(s.det, 1.0) > 0.0 ? 1 : -1;  // the sign it leaves the span with
  }
  // The curvature's trend.
  const double tol = relTol * s.scale;
  const bernstein::Bound up = bernstein::certifyLower(s.n, tol), down = bernstein::certifyLower(-s.n, tol);
  const bool upOk = up.holds && !up.undecided, downOk = down.holds && !down.undecided;
  const std::string coefficients =
      "the " + std::to_string(s.n.size()) + " Bernstein coefficients of N (degree " + std::to_string(c.degree) + ")";
  if (upOk && downOk) {
    c.trend = CurvatureTrend::Constant;
    c.reason = "kappa' = 0: " + coefficients + " vanish (within rounding)";
  } else if (upOk) {
    c.trend = CurvatureTrend::Increasing;
    c.reason = "kappa' >= 0: kappa rises from " + num(c.kappa0, 6) + " to " + num(c.kappa1, 6);
  } else if (downOk) {
    c.trend = CurvatureTrend::Decreasing;
    c.reason = "kappa' <= 0: kappa falls from " + num(c.kappa0, 6) + " to " + num(c.kappa1, 6);
  } else if (!up.holds && !down.holds) {
    // Witnesses of both signs: every sign change of N beyond the tolerance is an extremum.
    c.trend = CurvatureTrend::Extremum;
    std::vector<double> roots = signChanges(s.n, tol);
    if (roots.empty()) {
      roots.push_back(
          bernstein::bisectRoot(s.n, std::min(up.witness, down.witness), std::max(up.witness, down.witness)));
    }
    for (double t : roots) {
      const bool maximum = eval(s.n, std::max(0.0, t - 1e-6)) > 0.0;
      extrema.emplace_back(paramAt(arc, t), kappaAt(s, t) / scale, maximum);
    }
    c.at = std::get<0>(extrema[extrema.size() - roots.size()]);
    c.kappaAt = std::get<1>(extrema[extrema.size() - roots.size()]);
    c.maximum = std::get<2>(extrema[extrema.size() - roots.size()]);
    c.reason = std::string("curvature ") + (c.maximum ? "maximum" : "minimum") + " kappa = " + num(c.kappaAt, 6) +
               " at u = " + num(c.at, 6) + " (" + std::to_string(roots.size()) + " in the span)";
  } else {
    c.trend = CurvatureTrend::Undecided;
    c.at = paramAt(arc, up.undecided ? up.witness : down.witness);
    c.reason = "kappa' stays within rounding of 0 near u = " + num(c.at, 6) + " and could not be signed";
  }
  return c;
}

}  // namespace

SpaceCurvatureCertificate certifySpaceCurvature(const BSplineCurve& curve, double relTol) {
  if (!(relTol >= 0.0)) throw InputError("the tolerance must be >= 0");
  const SpaceData data = spaceData(curve);
  const std::vector<Arc> arcs = bezierArcs(data);
  if (arcs.empty()) throw InputError("the curve has no non-empty knot span");
  SpaceCurvatureCertificate cert;
  std::vector<SpanPolys> polys;
  std::vector<std::vector<std::tuple<double, double, bool>>> inside(arcs.size());
  for (size_t i = 0; i < arcs.size(); ++i) {
    polys.push_back(spanPolys(arcs[i]));
    cert.spans.push_back(certifySpan(arcs[i], polys.back(), relTol, data.scale, inside[i]));
  }
  cert.kappaStart = cert.spans.front().kappa0;
  cert.kappaEnd = cert.spans.back().kappa1;
  const char* overflow =
      "the curve's curvature is not finite in double precision: its poles are too large, too small or too close together";
  for (const SpaceSpanCertificate& s : cert.spans) {
    if (!std::isfinite(s.kappa0) || !std::isfinite(s.kappa1) || !std::isfinite(s.kappaAt)) throw InputError(overflow);
  }

  std::string problem;
  // Extrema: inside spans, and at knots where the trend turns (a curvature jump counts as
  // a step the way it goes).
  const Eigen::Vector3d lo = data.poles.colwise().minCoeff(), hi = data.poles.colwise().maxCoeff();
  const double kappaFloor = 1e-12 / std::max((hi - lo).norm(), 1e-300) / data.scale;
  int direction = 0;  // +1 rising, -1 falling, 0 not yet known
  auto step = [&](int entering, int leaving, double u, double kappa) {
    if (entering != 0 && direction != 0 && entering != direction) cert.extrema.emplace_back(u, kappa, direction > 0);
    if (leaving != 0) direction = leaving;
  };
  for (size_t i = 0; i < cert.spans.size(); ++i) {
    const SpaceSpanCertificate& s = cert.spans[i];
    if (i > 0) {
      const SpaceSpanCertificate& left = cert.spans[i - 1];
      const Vec3 tl = eval(polys[i - 1].B, 1.0).normalized(), tr = eval(polys[i].B, 0.0).normalized();
      const double turn = std::atan2(tl.cross(tr).norm(), tl.dot(tr));
      if (turn > 1e-9 && problem.empty()) {
        problem = "corner at u = " + num(s.u0, 6) + ": the tangent turns by " + num(degrees(turn)) + " deg there";
      }
      const double jump = s.kappa0 - left.kappa1;
      const double jumpTol = 1e-9 * std::max(left.kappa1, s.kappa0) + kappaFloor;
      if (std::abs(jump) > jumpTol) {
        const int d = jump > 0.0 ? 1 : -1;
        step(d, d, s.u0, left.kappa1);
      }
    }
    if (s.trend == CurvatureTrend::Singular || s.trend == CurvatureTrend::Undecided) {
      if (problem.empty()) problem = "span " + std::to_string(i) + ": " + s.reason;
      continue;
    }
    if (s.trend == CurvatureTrend::Increasing) step(1, 1, s.u0, s.kappa0);
    if (s.trend == CurvatureTrend::Decreasing) step(-1, -1, s.u0, s.kappa0);
    if (s.trend == CurvatureTrend::Extremum) {
      const auto& first = inside[i].front();
      const auto& last = inside[i].back();
      step(std::get<2>(first) ? 1 : -1, 0, s.u0, s.kappa0);
      for (const auto& e : inside[i]) cert.extrema.push_back(e);
      direction = std::get<2>(last) ? -1 : 1;
    }
  }
  std::sort(cert.extrema.begin(), cert.extrema.end());
  if (problem.empty() && !cert.extrema.empty()) {
    const auto& e = cert.extrema.front();
    problem = std::to_string(cert.extrema.size()) + " curvature extrema, the first a " +
              (std::get<2>(e) ? "maximum" : "minimum") + " kappa = " + num(std::get<1>(e), 6) +
              " at u = " + num(std::get<0>(e), 6);
  }
  // Torsion sign changes: inside spans, and at knots between spans of opposite signs.
  int sign = 0;
  bool planar = true;
  for (const SpaceSpanCertificate& s : cert.spans) {
    if (s.torsionSign == 0 && s.torsionChanges.empty()) continue;
    planar = false;
    const int entering =
        s.torsionChanges.empty() ? s.torsionSign : -s.torsionSign * (s.torsionChanges.size() % 2 ? 1 : -1);
    if (sign != 0 && entering != sign) cert.torsionSignChanges.push_back(s.u0);
    for (double u : s.torsionChanges) cert.torsionSignChanges.push_back(u);
    sign = s.torsionSign;
  }
  cert.planar = planar;
  const std::string count = std::to_string(cert.spans.size()) + (cert.spans.size() == 1 ? " span" : " spans");
  if (!problem.empty()) {
    cert.reason = "not monotone: " + problem;
    return cert;
  }
  cert.increasing = direction >= 0;
  cert.decreasing = direction <= 0;
  cert.monotone = true;
  cert.reason = direction == 0
                    ? "constant curvature (certified on " + count + ")"
                    : std::string("monotone: the curvature ") + (direction > 0 ? "increases" : "decreases") + " from " +
                          num(cert.kappaStart, 6) + " to " + num(cert.kappaEnd, 6) + " (certified on " + count + ")";
  return cert;
}

}  // namespace fairsplines
