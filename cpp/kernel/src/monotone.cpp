#include "fairsplines/monotone.hpp"

#include <Eigen/Dense>
#include <Geom_BSplineCurve.hxx>
#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <limits>
#include <optional>
#include <sstream>

#include "fairsplines/analysis.hpp"
#include "fairsplines/occt.hpp"
#include "finite.hpp"
#include "monotone_detail.hpp"

namespace fairsplines {

namespace {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
constexpr double kPi = 3.14159265358979323846;

double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }
double degrees(double radians) { return radians * 180.0 / kPi; }

std::string num(double v, int digits = 4) {
  std::ostringstream out;
  out << std::setprecision(digits) << v;
  return out.str();
}

// The knot vector (0, 0, 0, 0, 1, 2, 2, 2, 2) of Algorithm 2's five poles (docs/READINGS.md, monotone paper).
constexpr double kAlg2Knots[9] = {0, 0, 0, 0, 1, 2, 2, 2, 2};

BSplineCurve alg2Curve(PointMatrix poles) {
  BSplineCurve curve;
  curve.degree = 3;
  curve.poles = std::move(poles);
  curve.knots.resize(3);
  curve.knots << 0.0, 1.0, 2.0;
  curve.mults.resize(3);
  curve.mults << 4, 1, 4;
  return curve;
}

// ---------------------------------------------------------------------------------------
// Bernstein polynomials on [0, 1]: coefficient vectors, degree = size - 1.

using Poly = Eigen::VectorXd;

double binomial(int n, int k) {
  static std::vector<std::vector<double>> rows;
  if (static_cast<int>(rows.size()) <= n) {
    for (int r = static_cast<int>(rows.size()); r <= n; ++r) {
      std::vector<double> row(r + 1, 1.0);
      for (int i = 1; i < r; ++i) row[i] = rows[r - 1][i - 1] + rows[r - 1][i];
      rows.push_back(std::move(row));
    }
  }
  return rows[n][k];
}

Poly mul(const Poly& a, const Poly& b) {
  const int m = static_cast<int>(a.size()) - 1, n = static_cast<int>(b.size()) - 1;
  Poly c = Poly::Zero(m + n + 1);
  for (int i = 0; i <= m; ++i) {
    const double ai = binomial(m, i) * a[i];
    for (int j = 0; j <= n; ++j) c[i + j] += ai * binomial(n, j) * b[j];
  }
  for (int k = 0; k <= m + n; ++k) c[k] /= binomial(m + n, k);
  return c;
}

Poly diff(const Poly& a) {
  const int n = static_cast<int>(a.size()) - 1;
  if (n == 0) return Poly::Zero(1);
  return n * (a.tail(n) - a.head(n));
}

Poly elevate(const Poly& a, int degree) {
  Poly c = a;
  for (int n = static_cast<int>(c.size()) - 1; n < degree; ++n) {
    Poly e(n + 2);
    e[0] = c[0];
    e[n + 1] = c[n];
    for (int i = 1; i <= n; ++i) e[i] = (i * c[i - 1] + (n + 1 - i) * c[i]) / (n + 1);
    c = std::move(e);
  }
  return c;
}

Poly sub(const Poly& a, const Poly& b) {
  const int degree = static_cast<int>(std::max(a.size(), b.size())) - 1;
  return elevate(a, degree) - elevate(b, degree);
}

Poly add(const Poly& a, const Poly& b) { return sub(a, -b); }

double eval(const Poly& a, double t) {
  Poly c = a;
  for (Eigen::Index r = c.size() - 1; r > 0; --r) {
    for (Eigen::Index i = 0; i < r; ++i) c[i] = (1.0 - t) * c[i] + t * c[i + 1];
  }
  return c[0];
}

/// de Casteljau at 1/2: the two halves.
void split(const Poly& a, Poly& left, Poly& right) {
  const Eigen::Index n = a.size() - 1;
  Poly c = a;
  left.resize(n + 1);
  right.resize(n + 1);
  left[0] = c[0];
  right[n] = c[n];
  for (Eigen::Index r = 1; r <= n; ++r) {
    for (Eigen::Index i = 0; i + r <= n; ++i) c[i] = 0.5 * (c[i] + c[i + 1]);
    left[r] = c[0];
    right[n - r] = c[n - r];
  }
}

/// Result of trying to certify a(t) >= -tol on [0, 1] by coefficients and subdivision.
struct Bound {
  bool holds = true;
  bool undecided = false;
  double witness = 0.0;  ///< where a(witness) < -tol (a certified violation), or the undecided spot
  int pieces = 0;
};

constexpr int kMaxDepth = 48;
constexpr int kMaxPieces = 20000;

void certifyLower(const Poly& a, double lo, double hi, double tol, int depth, Bound& out) {
  if (!out.holds || out.undecided) return;
  const Eigen::Index n = a.size() - 1;
  if (a.minCoeff() >= -tol) {
    ++out.pieces;
    return;
  }
  if (a[0] < -tol || a[n] < -tol) {  // an end coefficient is the exact value there
    out.holds = false;
    out.witness = a[0] < -tol ? lo : hi;
    return;
  }
  if (depth >= kMaxDepth || out.pieces >= kMaxPieces) {
    out.undecided = true;
    out.witness = 0.5 * (lo + hi);
    return;
  }
  Poly left, right;
  split(a, left, right);
  const double mid = 0.5 * (lo + hi);
  certifyLower(left, lo, mid, tol, depth + 1, out);
  certifyLower(right, mid, hi, tol, depth + 1, out);
}

Bound certifyLower(const Poly& a, double tol) {
  Bound out;
  certifyLower(a, 0.0, 1.0, tol, 0, out);
  return out;
}

/// A root of a between t0 and t1 (a(t0), a(t1) of opposite signs), by bisection.
double bisectRoot(const Poly& a, double t0, double t1) {
  double f0 = eval(a, t0);
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (t0 + t1), fm = eval(a, mid);
    if ((fm < 0) == (f0 < 0)) {
      t0 = mid;
      f0 = fm;
    } else {
      t1 = mid;
    }
  }
  return 0.5 * (t0 + t1);
}

// ---------------------------------------------------------------------------------------
// Planar Bezier arcs of a B-spline, and the certificate on them.

/// One span in Bezier form, homogeneous planar coordinates (w x, w y, w).
struct Arc {
  Poly x, y, w;
  bool rational = false;
  double u0 = 0.0, u1 = 0.0;
};

/// Planar data of a curve: 2D poles in the plane basis, weights, flat knots.
struct PlanarCurve {
  PointMatrix poles;  // n x 2
  Eigen::VectorXd weights;
  Eigen::VectorXd flat;
  int degree = 3;
  bool closed = false;  // periodic: the seam is a joint too
  Vec3 normal = Vec3::UnitZ();
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
  const Poly crossB1 = sub(mul(bx, b1y), mul(by, b1x));   // B x B'
  const Poly crossB2 = sub(mul(bx, b2y), mul(by, b2x));   // B x B''
  const Poly dotB1 = mul(bx, b1x) + mul(by, b1y);         // B . B'
  s.speed2 = mul(bx, bx) + mul(by, by);                   // |B|^2
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
    const double dInner = 2.0 * (rW1 * mB * mB1 + mW1 * rB * mB1 + mW1 * mB * rB1) +
                          (rW * mB * mB2 + mW * rB * mB2 + mW * mB * rB2);
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

SpanCertificate certifySpan(const Arc& arc, const SpanPolys& s, double relTol) {
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
  c.kappa0 = kappaAt(s, 0.0);
  c.kappa1 = kappaAt(s, 1.0);
  const double tol = relTol * s.scale;
  const Bound up = certifyLower(s.n, tol);     // N >= -tol: kappa nondecreasing
  const Bound down = certifyLower(-s.n, tol);  // N <= tol: kappa nonincreasing
  const bool upOk = up.holds && !up.undecided, downOk = down.holds && !down.undecided;
  c.pieces = std::max(up.pieces, down.pieces);
  const std::string coefficients = "the " + std::to_string(s.n.size()) + " Bernstein coefficients of N (degree " +
                                   std::to_string(c.degree) + ")";
  auto how = [&](const Bound& b) {
    return b.pieces <= 1 ? coefficients
                         : "N on all " + std::to_string(b.pieces) + " pieces after subdivision";
  };
  if (upOk && downOk) {
    c.trend = CurvatureTrend::Constant;
    c.reason = "kappa' = 0: " + coefficients + " vanish (within rounding): constant curvature " + num(c.kappa0, 6);
  } else if (upOk) {
    c.trend = CurvatureTrend::Increasing;
    c.pieces = up.pieces;
    c.reason = "kappa' >= 0: " + how(up) + " are >= 0; kappa rises from " + num(c.kappa0, 6) + " to " + num(c.kappa1, 6);
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
    c.kappaAt = kappaAt(s, t);
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

MonotonicityCertificate certifyPlanar(const PlanarCurve& curve, double relTol) {
  MonotonicityCertificate cert;
  cert.normal = curve.normal;
  const std::vector<Arc> arcs = bezierArcs(curve);
  if (arcs.empty()) throw InputError("the curve has no non-empty knot span");
  std::vector<SpanPolys> polys;
  polys.reserve(arcs.size());
  for (const Arc& arc : arcs) {
    polys.push_back(spanPolys(arc));
    cert.spans.push_back(certifySpan(arc, polys.back(), relTol));
  }
  cert.kappaStart = cert.spans.front().kappa0;
  cert.kappaEnd = cert.spans.back().kappa1;

  // Curvatures below 1e-12 / size are zero when compared at joints.
  const Eigen::Vector2d lo = curve.poles.colwise().minCoeff(), hi = curve.poles.colwise().maxCoeff();
  const double kappaFloor = 1e-12 / std::max((hi - lo).norm(), 1e-300);
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
      jumpUpAt = "the curvature jumps up from " + num(left.kappa1, 6) + " to " + num(right.kappa0, 6) + " at u = " + num(u, 6);
    } else if (jump < -jumpTol && !jumpDown) {
      jumpDown = true;
      jumpDownAt =
          "the curvature jumps down from " + num(left.kappa1, 6) + " to " + num(right.kappa0, 6) + " at u = " + num(u, 6);
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
      cert.reason = std::string("monotone: the curvature ") + (cert.increasing ? "increases" : "decreases") +
                    " from " + num(cert.kappaStart, 6) + " to " + num(cert.kappaEnd, 6) + " (certified on " + count +
                    ")";
    }
  }
  return cert;
}

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
  out.poles.resize(curve.poles.rows(), 2);
  const Eigen::RowVectorXd origin = curve.poles.row(0);
  for (Eigen::Index i = 0; i < curve.poles.rows(); ++i) {
    Vec3 p = Vec3::Zero();
    for (int k = 0; k < curve.dimension(); ++k) p[k] = curve.poles(i, k) - origin[k];
    out.poles.row(i) << p.dot(e1), p.dot(e2);
  }
  out.weights = curve.weights;
  out.flat = flatKnots(curve);
  out.degree = curve.degree;
  return out;
}

// ---------------------------------------------------------------------------------------
// Fair location (Fig. 3) and Algorithm 1.

/// Is q in the fair location of A (= C^2_{j-3}) and D (= C^1_{j-2}), up to slack (squared length)?
bool inFairLocation(const Vec2& q, const Vec2& A, const Vec2& D, double slack) {
  return cross(D, q) >= -slack && cross(q, A) >= -slack && q.dot(q - A) <= slack;
}

/// Nearest point of the fair location: the wedge between rays OD and OA, inside the circle
/// with diameter OA. A convex set: the nearest of the projections onto its sides.
Vec2 projectFairLocation(const Vec2& q, const Vec2& A, const Vec2& D) {
  if (A.squaredNorm() == 0.0) return Vec2::Zero();
  if (inFairLocation(q, A, D, 0.0)) return q;
  std::vector<Vec2> candidates;
  candidates.push_back(std::clamp(q.dot(A) / A.squaredNorm(), 0.0, 1.0) * A);  // the diameter OA
  const Vec2 d = D.normalized();
  const double reach = std::max(0.0, d.dot(A));  // ray OD meets the circle at distance A . d (Thales)
  candidates.push_back(std::clamp(q.dot(d), 0.0, reach) * d);
  const Vec2 centre = 0.5 * A, off = q - centre;
  if (off.squaredNorm() > 0.0) {
    const Vec2 onCircle = centre + 0.5 * A.norm() * off.normalized();
    if (cross(D, onCircle) >= 0.0 && cross(onCircle, A) >= 0.0) candidates.push_back(onCircle);
  }
  Vec2 best = candidates.front();
  for (const Vec2& c : candidates) {
    if ((c - q).squaredNorm() < (best - q).squaredNorm()) best = c;
  }
  return best;
}

// ---------------------------------------------------------------------------------------
// Algorithm 2: normalization.

/// End conditions in the normalized frame: p0 at the origin, t0 along +x, |p1 - p0| = 1,
/// p1 above the x-axis (so a mirror image is handled by the frame's orientation).
struct Normalized {
  Vec3 p0, p1, d0, d1, e1, e2;  // data, unit tangents, plane frame (e1 = d0)
  double L = 0.0;               // |p1 - p0|
  Vec2 P, T;                    // p1 and t1 in the frame
};

struct Classified {
  EndConditions ec;
  Normalized n;
};

/// Classifies the end conditions (no orientation choice yet: a, b as seen from p0).
Classified classify(const Vec3& p0, const Vec3& t0, const Vec3& p1, const Vec3& t1) {
  requireFiniteInput(p0, "p0");
  requireFiniteInput(t0, "t0");
  requireFiniteInput(p1, "p1");
  requireFiniteInput(t1, "t1");
  if (t0.norm() == 0.0) throw InputError("t0 is zero: give the start tangent direction");
  if (t1.norm() == 0.0) throw InputError("t1 is zero: give the end tangent direction");
  Classified out;
  EndConditions& ec = out.ec;
  Normalized& n = out.n;
  n.p0 = p0;
  n.p1 = p1;
  const Vec3 chord = p1 - p0;
  n.L = chord.norm();
  if (!(n.L > 4 * std::numeric_limits<double>::epsilon() * std::max(p0.norm(), p1.norm()))) {
    throw InputError("p0 and p1 coincide");
  }
  n.d0 = t0.normalized();
  n.d1 = t1.normalized();
  const Vec3 c = chord / n.L;
  Vec3 normal = n.d0.cross(c);
  if (normal.norm() <= 1e-12) {  // p1 on the start tangent line
    normal = n.d0.cross(n.d1);
    if (normal.norm() <= 1e-12) {  // everything parallel
      if (n.d0.dot(c) > 0 && n.d1.dot(c) > 0) {
        ec.admissible = ec.straight = true;
        return out;
      }
      ec.reason = n.d0.dot(c) < 0 ? "p1 lies behind p0 on the line of t0: the curve would have to turn back"
                                  : "t1 points back towards p0: the curve would have to turn back";
      return out;
    }
  }
  normal.normalize();
  const double outOfPlane = std::asin(std::min(1.0, std::abs(n.d1.dot(normal))));
  if (outOfPlane > 1e-9) {
    ec.reason = "the end conditions are not planar: t1 leaves the plane of t0 and p1 - p0 by " +
                num(degrees(outOfPlane)) + " deg";
    return out;
  }
  n.e1 = n.d0;
  n.e2 = normal.cross(n.e1);
  n.P = Vec2(c.dot(n.e1), c.dot(n.e2));
  n.T = Vec2(n.d1.dot(n.e1), n.d1.dot(n.e2)).normalized();
  ec.turn = std::atan2(n.T.y(), n.T.x());
  if (std::abs(n.T.y()) <= 1e-14) {
    ec.reason = "the end tangents are parallel and p1 is off the start tangent: that needs an inflection or a "
                "U-turn, but curves of this family turn less than 90 deg one way";
    return out;
  }
  const double sinTurn = n.T.y();
  ec.a = cross(n.P, n.T) / sinTurn * n.L;  // M = p0 + a t0
  ec.b = n.P.y() / sinTurn * n.L;          // p1 = M + b t1
  if (ec.b <= 0.0 && n.P.y() <= 1e-14) {
    ec.reason = "p1 lies on the start tangent, so the tangents meet at p1: the curve would need a corner";
    return out;
  }
  if (ec.a <= 0.0 || ec.b <= 0.0) {
    std::string where = ec.a <= 0.0 ? "it lies " + num(-ec.a) + " behind p0 along t0"
                                    : "it lies " + num(-ec.b) + " beyond p1 along t1";
    if (ec.a <= 0.0 && ec.b <= 0.0) where = "it lies behind p0 along t0 and beyond p1 along t1";
    ec.reason = "the tangents' intersection lies outside the admissible wedge: it must lie ahead of p0 along t0 "
                "and before p1 along t1, but " + where + " (these ends need an inflection)";
    return out;
  }
  if (n.T.x() <= 0.0) {
    ec.reason = "the tangent turns by " + num(degrees(ec.turn)) +
                " deg, but curves of this family turn by less than 90 deg (Theorem 2 keeps every tangent in the "
                "first quadrant of the start frame)";
    return out;
  }
  const double cosTurn = n.T.x(), slack = 1e-12;
  if (ec.a <= ec.b * cosTurn * (1 + slack)) {
    ec.admissible = true;
  } else if (ec.b <= ec.a * cosTurn * (1 + slack)) {
    ec.admissible = ec.reversed = true;
  } else {
    ec.reason = "the tangents' intersection M is too central: |M - p0| = " + num(ec.a) + " and |p1 - M| = " +
                num(ec.b) + ", but a curve of this family with monotone curvature needs the shorter of the two at "
                "most the longer times cos(turn) = " + num(std::max(ec.a, ec.b) * cosTurn) +
                " (the limit is a parabola from its vertex; these ends ask for a curve nearer to a circular arc)";
  }
  return out;
}

// ---------------------------------------------------------------------------------------
// Algorithm 2: the hodograph of the five-pole curve and the Theorem 2 slacks.
//
// With knots (0,0,0,0,1,2,2,2,2), eqs. (3) and (5) give C^1 = (3 V0, 1.5 V1, 1.5 V2, 3 V3)
// =: (w0, D1, D2, D3) and C^2 = (E0, E1, E2) with D1 = w0 + E0/2, D2 = D1 + E1,
// D3 = D2 + E2/2, and C4 - C0 = 2 w0 + (5 E0 + 6 E1 + E2)/6. In the normalized frame
// w0 = (s, 0) and D3 = lambda T; the unknowns x = (s, lambda, E1) fix E0 and E2 linearly.

/// Forward-mode jet with gradient and Hessian in the four unknowns.
struct Jet {
  double v = 0.0;
  Eigen::Vector4d g = Eigen::Vector4d::Zero();
  Eigen::Matrix4d h = Eigen::Matrix4d::Zero();
  Jet() = default;
  Jet(double value) : v(value) {}  // NOLINT: constants
};

Jet operator+(const Jet& a, const Jet& b) {
  Jet r;
  r.v = a.v + b.v;
  r.g = a.g + b.g;
  r.h = a.h + b.h;
  return r;
}
Jet operator-(const Jet& a, const Jet& b) {
  Jet r;
  r.v = a.v - b.v;
  r.g = a.g - b.g;
  r.h = a.h - b.h;
  return r;
}
Jet operator*(const Jet& a, const Jet& b) {
  Jet r;
  r.v = a.v * b.v;
  r.g = a.v * b.g + b.v * a.g;
  r.h = a.v * b.h + b.v * a.h + a.g * b.g.transpose() + b.g * a.g.transpose();
  return r;
}
Jet operator*(double s, const Jet& a) {
  Jet r;
  r.v = s * a.v;
  r.g = s * a.g;
  r.h = s * a.h;
  return r;
}
Jet operator*(const Jet& a, double s) { return s * a; }
/// f(a) with f, f', f'' at a.v.
Jet chain(const Jet& a, double f, double f1, double f2) {
  Jet r;
  r.v = f;
  r.g = f1 * a.g;
  r.h = f1 * a.h + f2 * a.g * a.g.transpose();
  return r;
}
Jet operator/(const Jet& a, const Jet& b) { return a * chain(b, 1.0 / b.v, -1.0 / (b.v * b.v), 2.0 / (b.v * b.v * b.v)); }
Jet sqrt(const Jet& a) {
  const double s = std::sqrt(a.v);
  return chain(a, s, 0.5 / s, -0.25 / (s * a.v));
}
Jet log(const Jet& a) { return chain(a, std::log(a.v), 1.0 / a.v, -1.0 / (a.v * a.v)); }
Jet atan2(const Jet& y, const Jet& x) {
  const double r2 = x.v * x.v + y.v * y.v, r4 = r2 * r2;
  const double fy = x.v / r2, fx = -y.v / r2;
  const double fyy = -2.0 * x.v * y.v / r4, fxx = 2.0 * x.v * y.v / r4, fxy = (y.v * y.v - x.v * x.v) / r4;
  Jet r;
  r.v = std::atan2(y.v, x.v);
  r.g = fy * y.g + fx * x.g;
  r.h = fy * y.h + fx * x.h + fyy * y.g * y.g.transpose() + fxx * x.g * x.g.transpose() +
        fxy * (x.g * y.g.transpose() + y.g * x.g.transpose());
  return r;
}

using std::atan2;
using std::log;
using std::sqrt;

template <class T>
struct V {
  T x, y;
};
template <class T>
V<T> operator+(const V<T>& a, const V<T>& b) { return {a.x + b.x, a.y + b.y}; }
template <class T>
V<T> operator-(const V<T>& a, const V<T>& b) { return {a.x - b.x, a.y - b.y}; }
template <class T>
V<T> operator*(double s, const V<T>& a) { return {s * a.x, s * a.y}; }
template <class T>
T crossT(const V<T>& a, const V<T>& b) { return a.x * b.y - a.y * b.x; }
template <class T>
T dotT(const V<T>& a, const V<T>& b) { return a.x * b.x + a.y * b.y; }
/// Angle from a to b, in (-pi, pi].
template <class T>
T angle(const V<T>& a, const V<T>& b) { return atan2(crossT(a, b), dotT(a, b)); }

constexpr int kSlacks = 10;

/// The hodograph of x = (s, lambda, E1x, E1y) for the end conditions (P, T).
template <class T>
struct Hodograph {
  V<T> w0, E0, E1, E2, D1, D2;
};

template <class T>
Hodograph<T> hodograph(const T* x, const Vec2& P, const Vec2& Tan) {
  const T& s = x[0];
  const T& lambda = x[1];
  Hodograph<T> h;
  h.w0 = {s, T(0.0)};
  h.E1 = {x[2], x[3]};
  const V<T> lt{lambda * Tan.x(), lambda * Tan.y()};
  const V<T> R1 = 2.0 * (lt - h.w0) - 2.0 * h.E1;                          // E0 + E2
  const V<T> R2 = 6.0 * (V<T>{T(P.x()) - 2.0 * s, T(P.y())}) - 6.0 * h.E1;  // 5 E0 + E2
  h.E0 = 0.25 * (R2 - R1);
  h.E2 = R1 - h.E0;
  h.D1 = h.w0 + 0.5 * h.E0;
  h.D2 = h.D1 + h.E1;
  return h;
}

/// The ten Theorem 2 slacks: C^2_0 = E0 within the first quadrant (2 angles); for each
/// span, C^2 within its fair location: 2 angles to its sides, 2 radial fractions.
template <class T>
void slacks(const T* x, const Vec2& P, const Vec2& Tan, T* m) {
  const Hodograph<T> h = hodograph(x, P, Tan);
  const V<T> ex{T(1.0), T(0.0)}, ey{T(0.0), T(1.0)};
  m[0] = angle(ex, h.E0);  // psi0 >= 0
  m[1] = angle(h.E0, ey);  // psi0 <= pi/2
  const T r0 = sqrt(dotT(h.E0, h.E0)), r1 = sqrt(dotT(h.E1, h.E1)), r2 = sqrt(dotT(h.E2, h.E2));
  m[2] = angle(h.D1, h.E1);                               // arg C^1_1 <= arg C^2_1 (Lemma 3)
  m[3] = angle(h.E1, h.E0);                               // arg C^2_1 <= arg C^2_0 (Lemma 3)
  m[4] = r1 / r0;                                         // |C^2_1| > 0
  m[5] = (dotT(h.E0, h.E1) - dotT(h.E1, h.E1)) / (r0 * r1);  // inside the circle (Lemma 2)
  m[6] = angle(h.D2, h.E2);
  m[7] = angle(h.E2, h.E1);
  m[8] = r2 / r1;
  m[9] = (dotT(h.E1, h.E2) - dotT(h.E2, h.E2)) / (r1 * r2);
}

bool interior(const double* m) {
  for (int i = 0; i < kSlacks; ++i) {
    if (!(m[i] > 0.0) || !std::isfinite(m[i])) return false;
  }
  for (int i : {0, 1, 2, 3, 6, 7}) {
    if (!(m[i] < kPi)) return false;
  }
  return true;
}

}  // namespace

namespace detail {

/// -sum log(slacks), +inf outside.
double barrier(const Eigen::Vector4d& x, const Vec2& P, const Vec2& Tan) {
  double m[kSlacks];
  slacks(x.data(), P, Tan, m);
  if (!interior(m)) return std::numeric_limits<double>::infinity();
  double f = 0.0;
  for (double v : m) f -= std::log(v);
  return f;
}

Jet barrierJet(const Eigen::Vector4d& x, const Vec2& P, const Vec2& Tan) {
  Jet xj[4];
  for (int k = 0; k < 4; ++k) {
    xj[k].v = x[k];
    xj[k].g[k] = 1.0;
  }
  Jet m[kSlacks];
  slacks(xj, P, Tan, m);
  Jet f(0.0);
  for (const Jet& v : m) f = f - log(v);
  return f;
}

/// Normalized margin: the slacks as fractions of the intervals they live in.
double margin(const Eigen::Vector4d& x, const Vec2& P, const Vec2& Tan) {
  double m[kSlacks];
  slacks(x.data(), P, Tan, m);
  const double fractions[] = {m[0] / (0.5 * kPi), m[1] / (0.5 * kPi), m[2] / (m[2] + m[3]), m[3] / (m[2] + m[3]),
                              m[4] / (m[4] + m[5]), m[5] / (m[4] + m[5]), m[6] / (m[6] + m[7]), m[7] / (m[6] + m[7]),
                              m[8] / (m[8] + m[9]), m[9] / (m[8] + m[9])};
  return *std::min_element(std::begin(fractions), std::end(fractions));
}

std::optional<Eigen::Vector4d> geometricStart(const Vec2& P, const Vec2& Tan, double k, double theta) {
  const Eigen::Matrix2d I = Eigen::Matrix2d::Identity();
  const double q = k * std::cos(theta);
  Eigen::Matrix2d R;
  R << std::cos(theta), std::sin(theta), -std::sin(theta), std::cos(theta);  // rotation by -theta
  const Eigen::Matrix2d qR = q * R, q2R2 = qR * qR;
  const Eigen::Matrix2d L = (5.0 * I + 6.0 * qR + q2R2) / 6.0;  // C4 - C0 = 2 s ex + L E0
  const Eigen::Matrix2d K = (I + 2.0 * qR + q2R2) / 2.0;        // D3 = s ex + K E0
  Eigen::Matrix3d A;
  A << 2.0, L(0, 0), L(0, 1), 0.0, L(1, 0), L(1, 1), Tan.y(), K(0, 0) * Tan.y() - K(1, 0) * Tan.x(),
      K(0, 1) * Tan.y() - K(1, 1) * Tan.x();
  const Eigen::Vector3d sol = A.partialPivLu().solve(Eigen::Vector3d(P.x(), P.y(), 0.0));
  const Vec2 E0 = sol.tail<2>();
  const Vec2 E1 = qR * E0;
  const double lambda = (Vec2(sol[0], 0.0) + K * E0).dot(Tan);
  const Eigen::Vector4d x(sol[0], lambda, E1.x(), E1.y());
  double m[kSlacks];
  slacks(x.data(), P, Tan, m);
  if (x.allFinite() && interior(m)) return x;
  return std::nullopt;
}

std::optional<Eigen::Vector4d> interiorStart(const Vec2& P, const Vec2& Tan) {
  static const double ks[] = {0.8, 0.95, 0.99, 0.997, 0.999, 0.9997, 0.9999, 0.99997, 0.99999, 0.999997, 0.999999};
  static const double thetas[] = {0.3, 0.1, 0.03, 0.01, 0.003, 1e-3, 3e-4, 1e-4, 3e-5, 1e-5, 3e-6, 1e-6};
  for (double k : ks) {
    for (double theta : thetas) {
      if (std::optional<Eigen::Vector4d> x = geometricStart(P, Tan, k, theta)) return x;
    }
  }
  return std::nullopt;
}

Eigen::Vector4d analyticCentre(Eigen::Vector4d x, const Vec2& P, const Vec2& Tan, int& iterations) {
  double f = barrier(x, P, Tan);
  for (iterations = 0; iterations < 100; ++iterations) {
    const Jet j = barrierJet(x, P, Tan);
    if (!j.g.allFinite() || !j.h.allFinite()) break;
    Eigen::Matrix4d H = j.h;
    Eigen::LDLT<Eigen::Matrix4d> ldlt(H);
    double shift = 1e-12 * std::max(1.0, H.diagonal().cwiseAbs().maxCoeff());
    while (ldlt.info() != Eigen::Success || !(ldlt.vectorD().minCoeff() > 0.0)) {  // not convex here: regularize
      H = j.h + shift * Eigen::Matrix4d::Identity();
      ldlt.compute(H);
      shift *= 10.0;
    }
    const Eigen::Vector4d d = -ldlt.solve(j.g);
    // Newton decrement squared: about twice f - min f. Below f's rounding the steps only
    // wander along flat directions.
    const double decrement = -j.g.dot(d);
    if (!(decrement > 1e-18 * std::max(1.0, std::abs(f)))) break;
    double t = 1.0;
    bool moved = false;
    for (int k = 0; k < 60; ++k, t *= 0.5) {
      const Eigen::Vector4d next = x + t * d;
      const double fn = barrier(next, P, Tan);
      if (fn <= f - 0.25 * t * decrement && fn < f) {
        x = next;
        f = fn;
        moved = true;
        break;
      }
    }
    if (!moved) break;
  }
  return x;
}

}  // namespace detail

namespace {

using detail::analyticCentre;
using detail::interiorStart;
using detail::margin;

/// The normalized poles C0..C4 of x.
std::array<Vec2, 5> polesOf(const Eigen::Vector4d& x, const Vec2& P, const Vec2& Tan) {
  const Hodograph<double> h = hodograph(x.data(), P, Tan);
  std::array<Vec2, 5> c;
  c[0] = Vec2::Zero();
  c[1] = Vec2(x[0] / 3.0, 0.0);                              // V0 = w0 / 3
  c[2] = c[1] + Vec2(h.D1.x, h.D1.y) / 1.5;                  // V1 = D1 / 1.5
  c[3] = P - x[1] / 3.0 * Tan;                               // V3 = D3 / 3 = lambda T / 3
  c[4] = P;
  return c;
}

bool theorem1Both(const std::array<Vec2, 5>& c) {
  const SegmentCheck first = checkSegment(c.data(), kAlg2Knots + 1);
  if (!first.theorem1() || first.turn != 1) return false;
  const SegmentCheck second = checkSegment(c.data() + 1, kAlg2Knots + 2);
  return second.theorem1() && second.turn == 1;
}

/// The certificate of a normalized five-pole curve (the planar path, no OCCT).
MonotonicityCertificate certifyNormalized(const std::array<Vec2, 5>& c) {
  PlanarCurve pc;
  pc.poles.resize(5, 2);
  for (int i = 0; i < 5; ++i) pc.poles.row(i) = c[i].transpose();
  pc.flat = Eigen::Map<const Eigen::VectorXd>(kAlg2Knots, 9);
  pc.degree = 3;
  return certifyPlanar(pc, 1e-12);
}

/// The paper's grid search (Algorithm 2) in the normalized frame; M = (a, 0).
/// Reading (README): C_1 = (t_1 C4.x, 0), i.e. the bounds 0 < t_1 < 1/6 and 3 t_1 < t_2x are
/// in units of C4.x, the foot of C4 on the start tangent (with C_1 = t_1 M no t_1 < 1/6 works).
std::optional<std::array<Vec2, 5>> gridSearch(const Vec2& P, double a, double step, int& tried) {
  const Vec2 M(a, 0.0);
  const double eps = 1e-12;
  tried = 0;
  for (int i1 = 0; i1 * step <= 1.0 / 6.0 + eps; ++i1) {
    const double t1 = i1 * step;
    const Vec2 C1(t1 * P.x(), 0.0);
    for (int i3 = 0; i3 * step <= 0.8 + eps; ++i3) {
      const double t3 = i3 * step;
      const Vec2 C3 = (1.0 - t3) * M + t3 * P;
      for (int ix = 0; 3.0 * t1 + ix * step <= C3.x() / P.x() + eps; ++ix) {
        const double t2x = 3.0 * t1 + ix * step;
        for (int iy = 0; iy * step <= 0.5 * t3 + eps; ++iy) {
          const double t2y = iy * step;
          const std::array<Vec2, 5> c = {Vec2::Zero(), C1, Vec2(t2x * P.x(), t2y * P.y()), C3, P};
          ++tried;
          if (theorem1Both(c)) return c;
        }
      }
    }
  }
  return std::nullopt;
}

/// Normalized poles to model space: C1 on the start tangent, C3 on the end tangent exactly.
PointMatrix toModel(const std::array<Vec2, 5>& c, const Normalized& n) {
  PointMatrix poles(5, 3);
  const double a = c[1].x(), b = (c[4] - c[3]).norm();
  poles.row(0) = n.p0.transpose();
  poles.row(1) = (n.p0 + n.L * a * n.d0).transpose();
  poles.row(2) = (n.p0 + n.L * (c[2].x() * n.e1 + c[2].y() * n.e2)).transpose();
  poles.row(3) = (n.p1 - n.L * b * n.d1).transpose();
  poles.row(4) = n.p1.transpose();
  return poles;
}

}  // namespace

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
  if (cubic.degree != 3) throw InputError("eqs. (3) and (5) are for cubic B-splines, got degree " + std::to_string(cubic.degree));
  if (cubic.isRational()) throw InputError("eqs. (3) and (5) are for non-rational B-splines");
  requireValidCurve(cubic, "the cubic");
  const Eigen::VectorXd t = flatKnots(cubic);
  const Eigen::Index n = cubic.poles.rows();
  DerivativePolygons out;
  out.first.resize(n - 1, cubic.poles.cols());
  for (Eigen::Index i = 0; i + 1 < n; ++i) {
    const double h = t[i + 4] - t[i + 1];
    if (!(h > 0)) throw InputError("knots t_" + std::to_string(i + 1) + " and t_" + std::to_string(i + 4) + " coincide");
    out.first.row(i) = 3.0 / h * (cubic.poles.row(i + 1) - cubic.poles.row(i));  // eq. (3)
  }
  out.second.resize(std::max<Eigen::Index>(n - 2, 0), cubic.poles.cols());
  for (Eigen::Index i = 0; i + 2 < n; ++i) {
    const double h = t[i + 4] - t[i + 2];
    if (!(h > 0)) throw InputError("knots t_" + std::to_string(i + 2) + " and t_" + std::to_string(i + 4) + " coincide");
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

// ---------------------------------------------------------------------------------------
// Algorithm 1.

MonotoneDesign designMonotone(const Eigen::Vector2d& firstVector, PointsRef differences,
                              const Eigen::VectorXd& knotsIn, const Eigen::Vector2d& start) {
  if (!firstVector.allFinite()) throw InputError("the first control vector is not finite");
  if (!(firstVector.norm() > 0.0)) throw InputError("the first control vector is zero");
  if (!start.allFinite()) throw InputError("the start point is not finite");
  if (differences.cols() != 2) throw InputError("the differences dV_i must be 2D vectors (rows of 2 numbers)");
  const Eigen::Index m = differences.rows();
  if (m < 2) throw InputError("Algorithm 1 needs at least 2 differences dV_i (4 control points), got " + std::to_string(m));
  for (Eigen::Index i = 0; i < m; ++i) {
    if (!differences.row(i).allFinite()) throw InputError("dV_" + std::to_string(i) + " is not finite");
  }
  const Eigen::Index n = m + 1;  // poles C_0..C_n
  Eigen::VectorXd t = knotsIn;
  if (t.size() == 0) {  // clamped, uniform inside
    t.resize(n + 5);
    for (Eigen::Index i = 0; i < n + 5; ++i) t[i] = static_cast<double>(std::clamp<Eigen::Index>(i - 3, 0, n - 2));
  }
  if (t.size() != n + 5) {
    throw InputError("the knot vector needs " + std::to_string(n + 5) + " knots for " + std::to_string(n + 1) +
                     " control points, got " + std::to_string(t.size()));
  }
  for (Eigen::Index i = 0; i < t.size(); ++i) {
    if (!std::isfinite(t[i])) throw InputError("knot " + std::to_string(i) + " is not finite");
    if (i > 0 && t[i] < t[i - 1]) throw InputError("knots " + std::to_string(i - 1) + " and " + std::to_string(i) + " decrease");
  }
  for (Eigen::Index i = 0; i + 4 < t.size(); ++i) {
    if (!(t[i + 4] > t[i])) throw InputError("knot " + std::to_string(i) + " has multiplicity above 4");
  }
  for (Eigen::Index i = 0; i < n; ++i) {
    if (!(t[i + 4] > t[i + 1])) throw InputError("knots t_" + std::to_string(i + 1) + " .. t_" + std::to_string(i + 4) + " coincide");
    if (i + 1 < n && !(t[i + 4] > t[i + 2])) {
      throw InputError("knots t_" + std::to_string(i + 2) + " .. t_" + std::to_string(i + 4) + " coincide");
    }
  }
  if (!(t[n + 1] > t[3])) throw InputError("the knot vector has an empty domain");

  // Work in V_0's frame, mirrored for a right turn: there every condition is the first quadrant's.
  const Vec2 fx = firstVector.normalized(), fy(-fx.y(), fx.x());
  auto c1 = [&](Eigen::Index i) { return 3.0 / (t[i + 4] - t[i + 1]); };  // eq. (3)
  auto c2 = [&](Eigen::Index i) { return 2.0 / (t[i + 4] - t[i + 2]); };  // eq. (5)
  const Vec2 dV0 = differences.row(0).transpose();
  const Vec2 rawE0 = c2(0) * (c1(1) * (firstVector + dV0) - c1(0) * firstVector);
  const int turn = cross(firstVector, rawE0) < 0.0 ? -1 : 1;
  auto toLocal = [&](const Vec2& v) { return Vec2(v.dot(fx), turn * v.dot(fy)); };
  auto toGlobal = [&](const Vec2& v) { return Vec2(v.x() * fx + turn * v.y() * fy); };

  MonotoneDesign out;
  out.turn = turn;
  out.differences.resize(m, 2);
  out.moved.resize(m);
  std::vector<Vec2> Vs{toLocal(firstVector)};
  Vec2 previousE;
  for (Eigen::Index i = 0; i < m; ++i) {
    const Vec2 Vi = Vs.back(), Di = c1(i) * Vi;
    const Vec2 asked = toLocal(differences.row(i).transpose());
    const Vec2 E = c2(i) * (c1(i + 1) * (Vi + asked) - Di);
    // dV_0: C^2_0 in the first quadrant; later dV_i: C^2_i in its fair location (Theorem 2).
    // Kept as given when in place up to rounding (so a clamped value given back stays put).
    const double slack = 1e-12 * (E.squaredNorm() + (i == 0 ? 0.0 : previousE.squaredNorm()));
    const bool inPlace = i == 0 ? E.minCoeff() >= -1e-12 * E.norm()
                                : inFairLocation(E, previousE, previousE.norm() * Di.normalized(), slack);
    const Vec2 clamped = inPlace ? E : (i == 0 ? E.cwiseMax(0.0) : projectFairLocation(E, previousE, Di));
    if (inPlace) {
      out.moved[i] = 0.0;
      out.differences.row(i) = differences.row(i);
      Vs.push_back(Vi + asked);
    } else {
      const Vec2 next = (clamped / c2(i) + Di) / c1(i + 1);
      out.moved[i] = (next - Vi - asked).norm();
      out.differences.row(i) = toGlobal(next - Vi).transpose();
      Vs.push_back(next);
    }
    previousE = clamped;
  }
  PointMatrix poles(n + 1, 2);
  poles.row(0) = start.transpose();
  for (Eigen::Index i = 0; i < n; ++i) poles.row(i + 1) = poles.row(i) + toGlobal(Vs[i]).transpose();
  // Distinct knots and multiplicities (OCCT layout).
  std::vector<double> knots;
  std::vector<int> mults;
  for (Eigen::Index i = 0; i < t.size(); ++i) {
    if (knots.empty() || t[i] > knots.back()) {
      knots.push_back(t[i]);
      mults.push_back(1);
    } else {
      ++mults.back();
    }
  }
  out.curve.degree = 3;
  out.curve.poles = std::move(poles);
  out.curve.knots = Eigen::Map<Eigen::VectorXd>(knots.data(), knots.size());
  out.curve.mults = Eigen::Map<Eigen::VectorXi>(mults.data(), mults.size());
  // The boundary rule: differences or knots whose design overflows, or knots too close
  // for OpenCASCADE, are refused by name.
  requireFinite(out.differences, "Algorithm 1's design", "differences");
  requireFinite(out.moved, "Algorithm 1's design", "moves");
  requireValidCurve(out.curve, "Algorithm 1's design");
  return out;
}

// ---------------------------------------------------------------------------------------
// Algorithm 2.

EndConditions analyzeEndConditions(const Eigen::Vector3d& p0, const Eigen::Vector3d& t0, const Eigen::Vector3d& p1,
                                   const Eigen::Vector3d& t1) {
  return classify(p0, t0, p1, t1).ec;
}

MonotoneSpline monotoneCurvatureSpline(const Eigen::Vector3d& p0, const Eigen::Vector3d& t0,
                                       const Eigen::Vector3d& p1, const Eigen::Vector3d& t1, MonotoneMethod method,
                                       double gridStep) {
  // The search visits up to (0.5 / step)^4 points: the lower bound keeps it within seconds.
  if (method == MonotoneMethod::PaperGrid && !(gridStep >= kMinGridStep && gridStep <= 0.5)) {
    throw InputError("the grid step must be in [" + num(kMinGridStep) + ", 0.5] (the search grows as step^-4), got " +
                     num(gridStep));
  }
  const Classified forward = classify(p0, t0, p1, t1);
  if (!forward.ec.admissible) throw NoMonotoneSolution("no monotone-curvature curve: " + forward.ec.reason);
  MonotoneSpline out;
  if (forward.ec.straight) {  // the straight segment (curvature 0), parametrized uniformly
    PointMatrix poles(5, 3);
    const double f[5] = {0.0, 1.0 / 6.0, 0.5, 5.0 / 6.0, 1.0};
    for (int i = 0; i < 5; ++i) poles.row(i) = (p0 + f[i] * (p1 - p0)).transpose();
    poles.row(4) = p1.transpose();
    out.curve = alg2Curve(std::move(poles));
    out.boundary = true;
    return out;
  }
  // Solve in the orientation where the curvature decreases from the start (a <= b cos(turn)).
  out.reversed = forward.ec.reversed;
  const Classified c = out.reversed ? classify(p1, -t1, p0, -t0) : forward;
  const Normalized& n = c.n;
  const double a = c.ec.a / n.L;

  std::optional<std::array<Vec2, 5>> poles;
  if (method == MonotoneMethod::PaperGrid) {
    poles = gridSearch(n.P, a, gridStep, out.iterations);
    if (!poles) {
      throw NoMonotoneSolution("the paper's grid search (step " + num(gridStep) + ", " +
                               std::to_string(out.iterations) +
                               " points) found no curve for these admissible end conditions; the fairest solver "
                               "finds one");
    }
  } else if (const std::optional<Eigen::Vector4d> start = interiorStart(n.P, n.T)) {
    const Eigen::Vector4d x = analyticCentre(*start, n.P, n.T, out.iterations);
    poles = polesOf(x, n.P, n.T);
    out.margin = margin(x, n.P, n.T);
    if (!theorem1Both(*poles)) poles.reset();  // rounding at the edge of a thin set: use the boundary
  }
  if (!poles) {  // the parabola: the quadratic Bezier (C0, M, C4), on the family's boundary
    const Vec2 M(a, 0.0);
    const Vec2 E = 0.5 * (n.P - 2.0 * M);  // constant second derivative
    const Eigen::Vector4d x(a, (n.P - M).norm(), E.x(), E.y());
    poles = polesOf(x, n.P, n.T);
    out.boundary = true;
    out.margin = 0.0;
  }
  const MonotonicityCertificate cert = certifyNormalized(*poles);
  if (!theorem1Both(*poles) || !cert.monotone || !cert.decreasing) {
    throw NoMonotoneSolution("no verified monotone-curvature curve (" + cert.reason + ")");
  }
  PointMatrix model = toModel(*poles, n);
  if (out.reversed) model = model.colwise().reverse().eval();
  out.curve = alg2Curve(std::move(model));
  return out;
}

// ---------------------------------------------------------------------------------------
// The certificate.

MonotonicityCertificate certifyMonotoneCurvature(const BSplineCurve& curve, double relTol) {
  if (!(relTol >= 0.0)) throw InputError("the tolerance must be >= 0");
  const MonotonicityCertificate cert = certifyPlanar(planarCurve(curve), relTol);
  // The boundary rule: no NaN curvature leaves; a curve whose curvatures overflow (or
  // vanish into 0/0) in double precision is refused by name.
  const char* overflow = "the curve's curvature is not finite in double precision: its poles are too large, too small or too close together";
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
    throw InputError("the curve's curvature variation is not finite in double precision: its poles are too large, too small or too close together");
  }
  return variation;
}

}  // namespace fairsplines
