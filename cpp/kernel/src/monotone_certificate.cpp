// The exact certificate of monotone curvature (Karčiauskas & Peters, curves of monotone
// curvature): kappa' of every Bézier span of a planar (rational) B-spline as a polynomial
// N in Bernstein form, signed by its coefficients and subdivision; and the curvature
// variation. Algorithms 1 and 2 are in monotone_design.cpp.
#include "fairsplines/monotone.hpp"

#include <Eigen/Dense>
#include <Geom_BSplineCurve.hxx>
#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "fairsplines/analysis.hpp"
#include "fairsplines/occt.hpp"
#include "bernstein.hpp"
#include "finite.hpp"
#include "monotone_common.hpp"

namespace fairsplines {

using detail::PlanarCurve;
using detail::planarCurve;

namespace {

// ---------------------------------------------------------------------------------------
// Bernstein polynomials on [0, 1]: coefficient vectors, degree = size - 1.

using Poly = Eigen::VectorXd;

/// The certificate's names for the shared Bernstein algebra (bernstein.hpp).
Poly mul(const Poly& a, const Poly& b) { return bernstein::product(a, b); }

Poly diff(const Poly& a) {
  const int n = static_cast<int>(a.size()) - 1;
  if (n == 0) return Poly::Zero(1);
  return n * (a.tail(n) - a.head(n));
}

Poly sub(const Poly& a, const Poly& b) {
  const int degree = static_cast<int>(std::max(a.size(), b.size())) - 1;
  return bernstein::raise(a, degree) - bernstein::raise(b, degree);
}

Poly add(const Poly& a, const Poly& b) { return sub(a, -b); }

double eval(const Poly& a, double t) { return bernstein::value(a, t)[0]; }

using bernstein::bisectRoot;
using bernstein::Bound;
using bernstein::certifyLower;
using bernstein::kMaxDepth;

// ---------------------------------------------------------------------------------------
// Planar Bezier arcs of a B-spline, and the certificate on them.

/// One span in Bezier form, homogeneous planar coordinates (w x, w y, w).
struct Arc {
  Poly x, y, w;
  bool rational = false;
  double u0 = 0.0, u1 = 0.0;
};

/// de Boor's algorithm with one argument per level: the blossom of the span's polynomial.
Vec3 blossom(std::vector<Vec3> d, const double* U, int p, const double* args) {
  for (int r = 1; r <= p; ++r) {
    for (int i = p; i >= r; --i) {
      const double left = U[i - 1], right = U[i + p - r];
      const double alpha = (args[r - 1] - left) / (right - left);
      d[i] = (1.0 - alpha) * d[i - 1] + alpha * d[i];
    }
  }
  return d[p];
}

std::vector<Arc> bezierArcs(const PlanarCurve& c) {
  const int p = c.degree, n = static_cast<int>(c.poles.rows()) - 1;
  const bool rational = c.weights.size() > 0;
  std::vector<Arc> arcs;
  std::vector<Vec3> local(p + 1);
  std::vector<double> args(p);
  for (int j = p; j <= n; ++j) {
    const double a = c.flat[j], b = c.flat[j + 1];
    if (!(b > a)) continue;
    for (int i = 0; i <= p; ++i) {
      const int k = j - p + i;
      const double w = rational ? c.weights[k] : 1.0;
      local[i] = Vec3(w * c.poles(k, 0), w * c.poles(k, 1), w);
    }
    Arc arc;
    arc.rational = rational;
    arc.u0 = a;
    arc.u1 = b;
    arc.x.resize(p + 1);
    arc.y.resize(p + 1);
    arc.w.resize(p + 1);
    for (int i = 0; i <= p; ++i) {  // b_i = blossom(a^(p-i), b^i)
      for (int r = 0; r < p; ++r) args[r] = r < p - i ? a : b;
      const Vec3 q = blossom(local, c.flat.data() + (j - p + 1), p, args.data());
      arc.x[i] = q.x();
      arc.y[i] = q.y();
      arc.w[i] = q.z();
    }
    arcs.push_back(std::move(arc));
  }
  return arcs;
}

/// The polynomials of a span: B (direction of P'), its derivatives, W, and N (sign of kappa').
struct SpanPolys {
  Poly bx, by, b1x, b1y, w, speed2, n;
  double scale = 0.0;  // bound of the two terms of N from their factors' coefficients
};

/// max_t |(x(t), y(t))| <= the largest coefficient norm (convex hull property).
double bound(const Poly& x, const Poly& y) { return (x.array().square() + y.array().square()).sqrt().maxCoeff(); }

SpanPolys spanPolys(const Arc& arc) {
  SpanPolys s;
  Poly bx, by;
  Poly w1;
  if (arc.rational) {
    w1 = diff(arc.w);
    bx = sub(mul(diff(arc.x), arc.w), mul(arc.x, w1));
    by = sub(mul(diff(arc.y), arc.w), mul(arc.y, w1));
    s.w = arc.w;
  } else {
    bx = diff(arc.x);
    by = diff(arc.y);
    s.w = Poly::Ones(1);
  }
  const Poly b1x = diff(bx), b1y = diff(by), b2x = diff(b1x), b2y = diff(b1y);
  const Poly crossB1 = sub(mul(bx, b1y), mul(by, b1x));  // B x B'
  const Poly crossB2 = sub(mul(bx, b2y), mul(by, b2x));  // B x B''
  const Poly dotB1 = mul(bx, b1x) + mul(by, b1y);        // B . B'
  s.speed2 = mul(bx, bx) + mul(by, by);                  // |B|^2
  // The scale bounds N's two terms and their first-order change when every factor moves
  // by its rounding size: a derivative of degree-d data of coordinates up to X moves by up
  // to 2d X per order (per relTol), the weights by their size. Rounding of the poles, and N
  // vanishing by cancellation (a line, a circle), stay below relTol times it. The rounding
  // sizes enter once per term, not as factors of the magnitudes: a short span far from the
  // origin has derivatives much smaller than X, and a product of such sizes would swamp N.
  const double X = std::max(arc.x.cwiseAbs().maxCoeff(), arc.y.cwiseAbs().maxCoeff());
  const double growth = 2.0 * static_cast<double>(bx.size());
  const double mW = arc.rational ? arc.w.cwiseAbs().maxCoeff() : 1.0;
  const double rB = growth * X * mW, rB1 = growth * rB, rB2 = growth * rB1;
  const double mB = bound(bx, by), mB1 = bound(b1x, b1y), mB2 = bound(b2x, b2y);
  Poly first, second;
  if (arc.rational) {
    first = mul(add(2.0 * mul(w1, crossB1), mul(arc.w, crossB2)), s.speed2);
    second = 3.0 * mul(mul(arc.w, crossB1), dotB1);
    const double mW1 = w1.cwiseAbs().maxCoeff(), rW = mW, rW1 = growth * mW;
    const double inner = 2.0 * mW1 * mB * mB1 + mW * mB * mB2;
    const double dInner =
        2.0 * (rW1 * mB * mB1 + mW1 * rB * mB1 + mW1 * mB * rB1) + (rW * mB * mB2 + mW * rB * mB2 + mW * mB * rB2);
    const double firstScale = inner * mB * mB + dInner * mB * mB + inner * 2.0 * mB * rB;
    const double secondScale = 3.0 * (mW * mB * mB * mB1 * mB1 + rW * mB * mB * mB1 * mB1 +
                                      2.0 * mW * rB * mB * mB1 * mB1 + 2.0 * mW * mB * mB * rB1 * mB1);
    s.scale = firstScale + secondScale;
  } else {
    first = mul(crossB2, s.speed2);      // (P' x P''') |P'|^2
    second = 3.0 * mul(crossB1, dotB1);  // 3 (P' x P'') (P' . P'')
    const double firstScale = mB * mB2 * mB * mB + 3.0 * rB * mB * mB * mB2 + rB2 * mB * mB * mB;
    const double secondScale = 3.0 * (mB * mB * mB1 * mB1 + 2.0 * rB * mB * mB1 * mB1 + 2.0 * mB * mB * rB1 * mB1);
    s.scale = firstScale + secondScale;
  }
  s.n = sub(first, second);
  s.bx = std::move(bx);
  s.by = std::move(by);
  s.b1x = b1x;
  s.b1y = b1y;
  return s;
}

/// Signed curvature W^2 (B x B') / |B|^3 at t.
double kappaAt(const SpanPolys& s, double t) {
  const Vec2 b(eval(s.bx, t), eval(s.by, t)), b1(eval(s.b1x, t), eval(s.b1y, t));
  const double w = eval(s.w, t);
  return w * w * cross(b, b1) / std::pow(b.norm(), 3);
}

Vec2 unitTangent(const SpanPolys& s, double t) {
  const Vec2 b(eval(s.bx, t), eval(s.by, t));
  return b / b.norm();
}

double paramAt(const Arc& arc, double t) { return arc.u0 + t * (arc.u1 - arc.u0); }

/// `scale`: the PlanarCurve's; curvatures are reported in the curve's own units (kappa' / scale).
SpanCertificate certifySpan(const Arc& arc, const SpanPolys& s, double relTol, double scale) {
  SpanCertificate c;
  c.u0 = arc.u0;
  c.u1 = arc.u1;
  c.degree = static_cast<int>(s.n.size()) - 1;
  // Regularity: |B|^2 > 0 on the span (else the curvature is undefined somewhere).
  const double speedTol = 1e-20 * s.speed2.cwiseAbs().maxCoeff();
  const Bound regular = certifyLower(s.speed2 - Poly::Constant(s.speed2.size(), 2.0 * speedTol), 0.0);
  if (!regular.holds || regular.undecided || !(s.speed2.cwiseAbs().maxCoeff() > 0.0)) {
    c.trend = CurvatureTrend::Singular;
    c.at = paramAt(arc, regular.witness);
    c.reason = "the derivative vanishes near u = " + num(c.at, 6) + ": the curvature is undefined there";
    return c;
  }
  c.kappa0 = kappaAt(s, 0.0) / scale;
  c.kappa1 = kappaAt(s, 1.0) / scale;
  const double tol = relTol * s.scale;
  const Bound up = certifyLower(s.n, tol);     // N >= -tol: kappa nondecreasing
  const Bound down = certifyLower(-s.n, tol);  // N <= tol: kappa nonincreasing
  const bool upOk = up.holds && !up.undecided, downOk = down.holds && !down.undecided;
  c.pieces = std::max(up.pieces, down.pieces);
  const std::string coefficients =
      "the " + std::to_string(s.n.size()) + " Bernstein coefficients of N (degree " + std::to_string(c.degree) + ")";
  auto how = [&](const Bound& b) {
    return b.pieces <= 1 ? coefficients : "N on all " + std::to_string(b.pieces) + " pieces after subdivision";
  };
  if (upOk && downOk) {
    c.trend = CurvatureTrend::Constant;
    c.reason = "kappa' = 0: " + coefficients + " vanish (within rounding): constant curvature " + num(c.kappa0, 6);
  } else if (upOk) {
    c.trend = CurvatureTrend::Increasing;
    c.pieces = up.pieces;
    c.reason =
        "kappa' >= 0: " + how(up) + " are >= 0; kappa rises from " + num(c.kappa0, 6) + " to " + num(c.kappa1, 6);
  } else if (downOk) {
    c.trend = CurvatureTrend::Decreasing;
    c.pieces = down.pieces;
    c.reason =
        "kappa' <= 0: " + how(down) + " are <= 0; kappa falls from " + num(c.kappa0, 6) + " to " + num(c.kappa1, 6);
  } else if (!up.holds && !down.holds) {
    // Witnesses of both signs: N(up.witness) < -tol, N(down.witness) > tol.
    const double tNeg = up.witness, tPos = down.witness;
    const double t = bisectRoot(s.n, std::min(tNeg, tPos), std::max(tNeg, tPos));
    c.trend = CurvatureTrend::Extremum;
    c.maximum = tPos < tNeg;  // kappa rises, then falls
    c.at = paramAt(arc, t);
    c.kappaAt = kappaAt(s, t) / scale;
    c.reason = std::string("curvature ") + (c.maximum ? "maximum" : "minimum") + " kappa = " + num(c.kappaAt, 6) +
               " at u = " + num(c.at, 6) + ": kappa' changes sign (N(u = " + num(paramAt(arc, tPos), 6) +
               ") = " + num(eval(s.n, tPos), 3) + " > 0, N(u = " + num(paramAt(arc, tNeg), 6) +
               ") = " + num(eval(s.n, tNeg), 3) + " < 0)";
  } else {
    c.trend = CurvatureTrend::Undecided;
    c.at = paramAt(arc, up.undecided ? up.witness : down.witness);
    c.reason = "kappa' stays within rounding of 0 near u = " + num(c.at, 6) + " and could not be signed after " +
               std::to_string(kMaxDepth) + " subdivisions";
  }
  return c;
}

}  // namespace

namespace detail {

MonotonicityCertificate certifyPlanar(const PlanarCurve& curve, double relTol) {
  MonotonicityCertificate cert;
  cert.normal = curve.normal;
  const std::vector<Arc> arcs = bezierArcs(curve);
  if (arcs.empty()) throw InputError("the curve has no non-empty knot span");
  std::vector<SpanPolys> polys;
  polys.reserve(arcs.size());
  for (const Arc& arc : arcs) {
    polys.push_back(spanPolys(arc));
    cert.spans.push_back(certifySpan(arc, polys.back(), relTol, curve.scale));
  }
  cert.kappaStart = cert.spans.front().kappa0;
  cert.kappaEnd = cert.spans.back().kappa1;

  // Curvatures below 1e-12 / size are zero when compared at joints (size in the curve's units).
  const Eigen::Vector2d lo = curve.poles.colwise().minCoeff(), hi = curve.poles.colwise().maxCoeff();
  const double kappaFloor = 1e-12 / std::max((hi - lo).norm(), 1e-300) / curve.scale;
  std::string problem;  // the first reason that makes the curve non-monotone
  for (size_t i = 0; i < cert.spans.size() && problem.empty(); ++i) {
    const SpanCertificate& s = cert.spans[i];
    if (s.trend == CurvatureTrend::Singular || s.trend == CurvatureTrend::Extremum ||
        s.trend == CurvatureTrend::Undecided) {
      problem = "span " + std::to_string(i) + ": " + s.reason;
    }
  }
  // Joints: a corner, or a curvature jump at a knot of lower continuity.
  bool jumpUp = false, jumpDown = false;
  std::string jumpUpAt, jumpDownAt;
  const size_t joints = curve.closed ? arcs.size() : arcs.size() - 1;
  for (size_t i = 0; i < joints && problem.empty(); ++i) {
    const size_t k = (i + 1) % arcs.size();
    const SpanCertificate &left = cert.spans[i], &right = cert.spans[k];
    const Vec2 tl = unitTangent(polys[i], 1.0), tr = unitTangent(polys[k], 0.0);
    const double turn = std::atan2(std::abs(cross(tl, tr)), tl.dot(tr));
    const double u = arcs[i].u1;
    if (turn > 1e-9) {
      problem = "corner at u = " + num(u, 6) + ": the tangent turns by " + num(degrees(turn)) + " deg there";
      break;
    }
    const double jump = right.kappa0 - left.kappa1;
    const double jumpTol = 1e-9 * std::max(std::abs(left.kappa1), std::abs(right.kappa0)) + kappaFloor;
    if (jump > jumpTol && !jumpUp) {
      jumpUp = true;
      jumpUpAt =
          "the curvature jumps up from " + num(left.kappa1, 6) + " to " + num(right.kappa0, 6) + " at u = " + num(u, 6);
    } else if (jump < -jumpTol && !jumpDown) {
      jumpDown = true;
      jumpDownAt = "the curvature jumps down from " + num(left.kappa1, 6) + " to " + num(right.kappa0, 6) +
                   " at u = " + num(u, 6);
    }
  }
  if (problem.empty()) {
    int firstUp = -1, firstDown = -1;
    for (size_t i = 0; i < cert.spans.size(); ++i) {
      if (cert.spans[i].trend == CurvatureTrend::Increasing && firstUp < 0) firstUp = static_cast<int>(i);
      if (cert.spans[i].trend == CurvatureTrend::Decreasing && firstDown < 0) firstDown = static_cast<int>(i);
    }
    cert.increasing = firstDown < 0 && !jumpDown;
    cert.decreasing = firstUp < 0 && !jumpUp;
    if (!cert.increasing && !cert.decreasing) {
      auto where = [&](int span, bool up) {
        return (up ? "increases on span " : "decreases on span ") + std::to_string(span) + " (u in [" +
               num(cert.spans[span].u0, 6) + ", " + num(cert.spans[span].u1, 6) + "])";
      };
      const std::string ups = firstUp >= 0 ? "the curvature " + where(firstUp, true) : jumpUpAt;
      const std::string downs = firstDown >= 0 ? "the curvature " + where(firstDown, false) : jumpDownAt;
      problem = ups + " but " + (firstDown >= 0 ? "it " + where(firstDown, false) : downs);
    }
  }
  const std::string count = std::to_string(cert.spans.size()) + (cert.spans.size() == 1 ? " span" : " spans");
  if (!problem.empty()) {
    cert.monotone = cert.increasing = cert.decreasing = false;
    cert.reason = "not monotone: " + problem;
  } else {
    cert.monotone = true;
    if (cert.increasing && cert.decreasing) {
      cert.reason = "constant curvature " + num(cert.kappaStart, 6) + " (certified on " + count + ")";
    } else {
      cert.reason = std::string("monotone: the curvature ") + (cert.increasing ? "increases" : "decreases") + " from " +
                    num(cert.kappaStart, 6) + " to " + num(cert.kappaEnd, 6) + " (certified on " + count + ")";
    }
  }
  return cert;
}

}  // namespace detail

using detail::certifyPlanar;

namespace {

/// An orthonormal basis of the plane with normal n; the coordinate axis nearest the
/// plane becomes e1, so curves in the XY plane keep their coordinates.
void planeBasis(const Vec3& n, Vec3& e1, Vec3& e2) {
  int axis = 0;
  for (int k = 1; k < 3; ++k) {
    if (std::abs(n[k]) < std::abs(n[axis])) axis = k;
  }
  e1 = Vec3::Unit(axis) - n[axis] * n;
  e1.normalize();
  e2 = n.cross(e1);
}

}  // namespace

namespace detail {

PlanarCurve planarCurve(const BSplineCurve& input) {
  requireValidCurve(input, "the curve");
  BSplineCurve curve = input;
  Handle(Geom_BSplineCurve) occt = toOcct(input);
  PlanarCurve out;
  if (input.periodic) {  // a non-periodic copy over one period; the seam is checked as a joint
    occt = Handle(Geom_BSplineCurve)::DownCast(occt->Copy());
    occt->SetNotPeriodic();
    curve = fromOcct(occt);
    out.closed = true;
  }
  Vec3 n = Vec3::UnitZ();
  if (curve.dimension() == 3) {
    const std::optional<gp_Vec> normal = planeNormal(occt);
    if (!normal) throw InputError("the curve is not planar: its poles do not lie in one plane");
    n = Vec3(normal->X(), normal->Y(), normal->Z());
  }
  out.normal = n;
  Vec3 e1, e2;
  planeBasis(n, e1, e2);
  // Scale-invariant numerics: the poles are moved to the first and divided by a power of two
  // near their spread (exact), so that |B|^5 and the like in the certificate neither
  // overflow for a curve 1e300 in size nor underflow for one of 1e-300. Curvatures are
  // scaled back where they leave (certifyMonotoneCurvature).
  const Eigen::RowVectorXd origin = curve.poles.row(0);
  const double half = ((0.5 * curve.poles).rowwise() - 0.5 * origin).cwiseAbs().maxCoeff();
  if (belowRounding(half, 0.5 * curve.poles.cwiseAbs().maxCoeff())) {
    throw InputError("the curve does not move: all its poles coincide to double precision");
  }
  out.scale = powerOfTwoScale(half);
  out.poles.resize(curve.poles.rows(), 2);
  for (Eigen::Index i = 0; i < curve.poles.rows(); ++i) {
    Vec3 p = Vec3::Zero();
    for (int k = 0; k < curve.dimension(); ++k) p[k] = curve.poles(i, k) / out.scale - origin[k] / out.scale;
    out.poles.row(i) << p.dot(e1), p.dot(e2);
  }
  out.weights = curve.weights;
  out.flat = flatKnots(curve);
  out.degree = curve.degree;
  return out;
}

}  // namespace detail

// ---------------------------------------------------------------------------------------
// The certificate.

MonotonicityCertificate certifyMonotoneCurvature(const BSplineCurve& curve, double relTol) {
  if (!(relTol >= 0.0)) throw InputError("the tolerance must be >= 0");
  const MonotonicityCertificate cert = certifyPlanar(planarCurve(curve), relTol);
  // The boundary rule: no NaN curvature leaves; a curve whose curvatures overflow (or
  // vanish into 0/0) in double precision is refused by name.
  const char* overflow =
      "the curve's curvature is not finite in double precision: its poles are too large, too small or too close together";
  requireFinite(cert.normal, "the curve", "plane normal");
  if (!std::isfinite(cert.kappaStart) || !std::isfinite(cert.kappaEnd)) throw InputError(overflow);
  for (const SpanCertificate& span : cert.spans) {
    if (!std::isfinite(span.kappa0) || !std::isfinite(span.kappa1) || !std::isfinite(span.kappaAt) ||
        !std::isfinite(span.u0) || !std::isfinite(span.u1) || !std::isfinite(span.at)) {
      throw InputError(overflow);
    }
  }
  return cert;
}

double curvatureVariation(const BSplineCurve& curve) {
  static const double gx[8] = {0.0950125098376374, 0.2816035507792589, 0.4580167776572274, 0.6178762444026438,
                               0.7554044083550030, 0.8656312023878318, 0.9445750230732326, 0.9894009349916499};
  static const double gw[8] = {0.1894506104550685, 0.1826034150449236, 0.1691565193950025, 0.1495959888165767,
                               0.1246289712555339, 0.0951585116824928, 0.0622535239386479, 0.0271524594117541};
  const PlanarCurve pc = planarCurve(curve);
  double length = 0.0, energy = 0.0;
  for (const Arc& arc : bezierArcs(pc)) {
    const SpanPolys s = spanPolys(arc);
    for (int k = 0; k < 16; ++k) {
      const double t = 0.5 + (k < 8 ? -0.5 : 0.5) * gx[k % 8], w = 0.5 * gw[k % 8];
      const double speed = std::sqrt(eval(s.speed2, t));  // |B|, and ds/dt = |B| / W^2
      const double weight = eval(s.w, t);
      const double ds = speed / (weight * weight);
      const double dkappa = weight * eval(s.n, t) / std::pow(speed, 5);  // kappa' = W N / |B|^5
      length += w * ds;
      energy += w * dkappa * dkappa / ds;
    }
  }
  const double variation = energy * length * length * length;
  if (!std::isfinite(variation)) {
    throw InputError(
        "the curve's curvature variation is not finite in double precision: its poles are too large, too small or too close together");
  }
  return variation;
}

}  // namespace fairsplines
