// Algorithms 1 and 2 of Karčiauskas & Peters (curves of monotone curvature): the fair
// location of Fig. 3, designMonotone (Algorithm 1), and the normalization, grid search and
// fairest solver of the G2 Hermite curve (Algorithm 2). The certificate is in
// monotone_certificate.cpp, the segment checks in monotone_segments.cpp, the solver's
// analytic centre in analytic_centre.cpp.
#include "fairsplines/monotone.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <vector>

#include "finite.hpp"
#include "monotone_common.hpp"
#include "monotone_detail.hpp"
#include "work_budget.hpp"

namespace fairsplines {

using detail::certifyPlanar;
using detail::inFairLocation;
using detail::PlanarCurve;
using detail::polesOf;

namespace {

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

}  // namespace

// ---------------------------------------------------------------------------------------
// Fair location (Fig. 3) and Algorithm 1.

namespace detail {

bool inFairLocation(const Vec2& q, const Vec2& A, const Vec2& D, double slack) {
  return cross(D, q) >= -slack && cross(q, A) >= -slack && q.dot(q - A) <= slack;
}

}  // namespace detail

namespace {

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
    ec.reason =
        "the end tangents are parallel and p1 is off the start tangent: that needs an inflection or a "
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
    std::string where =
        ec.a <= 0.0 ? "it lies " + num(-ec.a) + " behind p0 along t0" : "it lies " + num(-ec.b) + " beyond p1 along t1";
    if (ec.a <= 0.0 && ec.b <= 0.0) where = "it lies behind p0 along t0 and beyond p1 along t1";
    ec.reason =
        "the tangents' intersection lies outside the admissible wedge: it must lie ahead of p0 along t0 "
        "and before p1 along t1, but " +
        where + " (these ends need an inflection)";
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
    ec.reason = "the tangents' intersection M is too central: |M - p0| = " + num(ec.a) +
                " and |p1 - M| = " + num(ec.b) +
                ", but a curve of this family with monotone curvature needs the shorter of the two at "
                "most the longer times cos(turn) = " +
                num(std::max(ec.a, ec.b) * cosTurn) +
                " (the limit is a parabola from its vertex; these ends ask for a curve nearer to a circular arc)";
  }
  return out;
}

using detail::analyticCentre;
using detail::interiorStart;
using detail::margin;

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
/// Each point tried is a unit of work (detail::WorkBudget; free without a budget).
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
          detail::WorkBudget::spend(1.0);
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
// Algorithm 1.

MonotoneDesign designMonotone(const Eigen::Vector2d& firstVector, PointsRef differences, const Eigen::VectorXd& knotsIn,
                              const Eigen::Vector2d& start) {
  if (!firstVector.allFinite()) throw InputError("the first control vector is not finite");
  if (!(firstVector.cwiseAbs().maxCoeff() > 0.0)) throw InputError("the first control vector is zero");
  if (!start.allFinite()) throw InputError("the start point is not finite");
  if (differences.cols() != 2) throw InputError("the differences dV_i must be 2D vectors (rows of 2 numbers)");
  const Eigen::Index m = differences.rows();
  if (m < 2)
    throw InputError("Algorithm 1 needs at least 2 differences dV_i (4 control points), got " + std::to_string(m));
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
    if (i > 0 && t[i] < t[i - 1])
      throw InputError("knots " + std::to_string(i - 1) + " and " + std::to_string(i) + " decrease");
  }
  for (Eigen::Index i = 0; i + 4 < t.size(); ++i) {
    if (!(t[i + 4] > t[i])) throw InputError("knot " + std::to_string(i) + " has multiplicity above 4");
  }
  for (Eigen::Index i = 0; i < n; ++i) {
    if (!(t[i + 4] > t[i + 1]))
      throw InputError("knots t_" + std::to_string(i + 1) + " .. t_" + std::to_string(i + 4) + " coincide");
    if (i + 1 < n && !(t[i + 4] > t[i + 2])) {
      throw InputError("knots t_" + std::to_string(i + 2) + " .. t_" + std::to_string(i + 4) + " coincide");
    }
  }
  if (!(t[n + 1] > t[3])) throw InputError("the knot vector has an empty domain");

  // Every condition of Algorithm 1 is invariant under scaling, so the vectors are divided by a
  // power of two near their size (exact): differences of 1e307 get their squares without
  // overflow, and the results are scaled back where they leave.
  double size = firstVector.cwiseAbs().maxCoeff();
  for (Eigen::Index i = 0; i < m; ++i) size = std::max(size, differences.row(i).cwiseAbs().maxCoeff());
  const double unit = powerOfTwoScale(size);
  const Vec2 V0 = firstVector / unit;
  auto asGiven = [&](Eigen::Index i) { return Vec2(differences.row(i).transpose() / unit); };
  // Work in V_0's frame, mirrored for a right turn: there every condition is the first quadrant's.
  const Vec2 fx = (firstVector / firstVector.cwiseAbs().maxCoeff()).normalized(), fy(-fx.y(), fx.x());
  auto c1 = [&](Eigen::Index i) { return 3.0 / (t[i + 4] - t[i + 1]); };  // eq. (3)
  auto c2 = [&](Eigen::Index i) { return 2.0 / (t[i + 4] - t[i + 2]); };  // eq. (5)
  const Vec2 dV0 = asGiven(0);
  const Vec2 rawE0 = c2(0) * (c1(1) * (V0 + dV0) - c1(0) * V0);
  const int turn = cross(V0, rawE0) < 0.0 ? -1 : 1;
  auto toLocal = [&](const Vec2& v) { return Vec2(v.dot(fx), turn * v.dot(fy)); };
  auto toGlobal = [&](const Vec2& v) { return Vec2(v.x() * fx + turn * v.y() * fy); };

  MonotoneDesign out;
  out.turn = turn;
  out.differences.resize(m, 2);
  out.moved.resize(m);
  std::vector<Vec2> Vs{toLocal(V0)};
  Vec2 previousE;
  for (Eigen::Index i = 0; i < m; ++i) {
    const Vec2 Vi = Vs.back(), Di = c1(i) * Vi;
    const Vec2 asked = toLocal(asGiven(i));
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
      out.moved[i] = (next - Vi - asked).norm() * unit;
      out.differences.row(i) = unit * toGlobal(next - Vi).transpose();
      Vs.push_back(next);
    }
    previousE = clamped;
  }
  PointMatrix poles(n + 1, 2);
  poles.row(0) = start.transpose();
  for (Eigen::Index i = 0; i < n; ++i) poles.row(i + 1) = poles.row(i) + unit * toGlobal(Vs[i]).transpose();
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

MonotoneSpline monotoneCurvatureSpline(const Eigen::Vector3d& p0, const Eigen::Vector3d& t0, const Eigen::Vector3d& p1,
                                       const Eigen::Vector3d& t1, MonotoneMethod method, double gridStep) {
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
  // The boundary rule (a fuzz finding: nearly straight ends gave an infinite pole once).
  requireValidCurve(out.curve, "Algorithm 2's curve");
  return out;
}

}  // namespace fairsplines
