// Monotone spirals for G2 ends; see spiral.hpp.
#include "spiral.hpp"

#include "fairsplines/errors.hpp"
#include "clothoid.hpp"
#include "work_budget.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

#include <Eigen/Dense>

namespace fairsplines::detail {
namespace {

/// Spiral::point's budget of Gauss panels (each turning by at most 0.5 rad): far beyond
/// the turning of any spiral the G2 solver tries, well within int.
constexpr double kMaxSpiralPanels = 1 << 20;

std::string num(double v) {
  std::ostringstream out;
  out.precision(4);
  out << v;
  return out.str();
}

}  // namespace

// ---------------------------------------------------------------------------------------
// The spiral.

double Spiral::kappa(double s) const {
  const double t = s / length;
  return k0 + (k1 - k0) * t + t * (1.0 - t) * (a + b * (1.0 - 2.0 * t));
}

double Spiral::dkappa(double tau) const {
  // With v = 1 - 2 tau: d kappa / d tau = (k1 - k0 - b/2) + a v + (3b/2) v^2.
  const double v = 1.0 - 2.0 * tau;
  return (k1 - k0 - 0.5 * b) + a * v + 1.5 * b * v * v;
}

double Spiral::theta(double s) const {
  // theta0 + L int_0^tau kappa.
  const double t = s / length, t2 = t * t;
  const double bump = a * (0.5 * t2 - t2 * t / 3.0) + b * (0.5 * t2 - t2 * t + 0.5 * t2 * t2);
  return theta0 + length * (k0 * t + 0.5 * (k1 - k0) * t2 + bump);
}

Eigen::Vector2d Spiral::point(double s) const {
  // Composite 8-point Gauss in panels over which the tangent turns by at most 0.5 rad.
  const double rate = length * (std::abs(k0) + std::abs(k1 - k0) + 0.25 * (std::abs(a) + std::abs(b)));
  const double tau1 = s / length;
  // The work budget: at most kMaxSpiralPanels panels (a tangent turning by more than
  // kMaxSpiralPanels / 2 rad is no blend); a NaN or overflowing count is refused before the
  // cast to int, which would be undefined.
  const double wanted = std::ceil(rate * std::abs(tau1) / 0.5);
  if (!(wanted <= kMaxSpiralPanels)) {
    throw InputError("the spiral's tangent turns by " + num(rate * std::abs(tau1)) +
                     " rad (curvatures k0 = " + num(k0) + ", k1 = " + num(k1) +
                     " times the chord): more than the solver's budget of " + num(0.5 * kMaxSpiralPanels) + " rad");
  }
  const int panels = std::max(1, static_cast<int>(wanted));
  WorkBudget::spend(panels);
  const double h = s / panels;
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  for (int p = 0; p < panels; ++p) {
    const double mid = (p + 0.5) * h;
    for (int k = 0; k < 8; ++k) {
      const double x = mid + (k < 4 ? -0.5 : 0.5) * h * kGaussX[k % 4];
      const double th = theta(x);
      sum += (0.5 * h * kGaussW[k % 4]) * Eigen::Vector2d(std::cos(th), std::sin(th));
    }
  }
  return start + sum;
}

double Spiral::minSlope() const {
  // The least of sign(k1 - k0) d kappa / d tau over [0, 1], over |k1 - k0|: the quadratic
  // g(v) = alpha + a v + beta v^2 at v = +-1 and at its vertex.
  const double dk = k1 - k0;
  if (dk == 0.0) return a == 0.0 && b == 0.0 ? 0.0 : -HUGE_VAL;  // constant, or not monotone
  const double sign = dk > 0.0 ? 1.0 : -1.0, alpha = sign * (dk - 0.5 * b), la = sign * a, beta = sign * 1.5 * b;
  double m = std::min(alpha + la + beta, alpha - la + beta);
  if (beta > 0.0) {
    const double v = -la / (2.0 * beta);
    if (std::abs(v) <= 1.0) m = std::min(m, alpha - la * la / (4.0 * beta));
  }
  return m / std::abs(dk);
}

double Spiral::variation() const {
  // L^2 int_0^1 (d kappa / d tau)^2 = L^2 (alpha^2 + a^2/3 + beta^2/5 + 2 alpha beta / 3),
  // alpha = k1 - k0 - b/2, beta = 3b/2.
  const double alpha = (k1 - k0) - 0.5 * b, beta = 1.5 * b;
  return length * length * (alpha * alpha + a * a / 3.0 + beta * beta / 5.0 + 2.0 * alpha * beta / 3.0);
}

// ---------------------------------------------------------------------------------------
// The clothoid spline.

double ClothoidSpline::kappa(double s) const {
  const int n = pieces();
  const double x = std::clamp(s / length, 0.0, 1.0) * n;
  const int i = std::min(n - 1, static_cast<int>(x));
  const double f = x - i;
  return k0 + (k1 - k0) * ((1.0 - f) * C[i] + f * C[i + 1]);
}

double ClothoidSpline::theta(double s) const {
  const int n = pieces();
  const double h = length / n, x = std::clamp(s / length, 0.0, 1.0) * n;
  const int last = std::min(n - 1, static_cast<int>(x));
  double th = theta0;
  for (int i = 0; i < last; ++i) th += h * (k0 + (k1 - k0) * 0.5 * (C[i] + C[i + 1]));
  const double f = x - last, ka = k0 + (k1 - k0) * C[last], kb = k0 + (k1 - k0) * C[last + 1];
  return th + h * f * (ka + 0.5 * f * (kb - ka));
}

Eigen::Vector2d ClothoidSpline::point(double s) const {
  // Piece by piece: each a clothoid arc, by the Fresnel moments.
  const int n = pieces();
  const double h = length / n, x = std::clamp(s / length, 0.0, 1.0) * n;
  WorkBudget::spend(n);  // at most n Fresnel moments
  Eigen::Vector2d p = Eigen::Vector2d::Zero();
  double th = theta0;
  for (int i = 0; i < n && i < x; ++i) {
    const double f = std::min(1.0, x - i), ka = k0 + (k1 - k0) * C[i], kb = k0 + (k1 - k0) * C[i + 1];
    const double dk = (kb - ka) / h, sl = f * h;
    const FresnelMoments m = fresnelMoments(dk * sl * sl, ka * sl, th);
    p += sl * Eigen::Vector2d(m.X[0], m.Y[0]);
    th += sl * (ka + 0.5 * dk * sl);
  }
  return p;
}

double ClothoidSpline::minSlope() const {
  double m = HUGE_VAL;
  for (int i = 0; i < pieces(); ++i) m = std::min(m, pieces() * (C[i + 1] - C[i]));
  return m;
}

double ClothoidSpline::variation() const {
  double sum = 0.0;
  for (int i = 0; i < pieces(); ++i) sum += (C[i + 1] - C[i]) * (C[i + 1] - C[i]);
  return length * length * (k1 - k0) * (k1 - k0) * pieces() * sum;
}

// ---------------------------------------------------------------------------------------
// The G2 problem.

/// The turning rule for curvature of one sign (C-shaped ends; one end may be straight), over
/// arcs that turn less than a full turn. Vogt's theorem: on a convex arc (one side of its
/// chord, turning less than pi) whose curvature grows from one end to the other, the tangent
/// meets the chord at a larger angle at the end of larger curvature. The same holds, as
/// |theta_strong| > |theta_weak| with the principal angles to the chord, for every arc of
/// monotone curvature of one sign that turns less than 2 pi: docs/FAIR_BLENDS.md section 5,
/// from docs/research/G2_FEASIBILITY.md (the extension past Vogt's convex case is checked
/// numerically there and by the kernel tests, not proved). Where it fails, the one turning the
/// data allows within the window is infeasible, and the least turning left is one full turn
/// more. "" when the rule holds. `proved` (if given) tells whether the refusal is Vogt's
/// convex case, a theorem, rather than the numerically checked extension.
static std::string turningRuleReason(double theta0, double k0, double theta1, double k1, bool* proved = nullptr) {
  if (proved != nullptr) *proved = false;
  const bool growsToEnd = std::abs(k1) > std::abs(k0);
  const double strong = std::abs(growsToEnd ? theta1 : theta0), weak = std::abs(growsToEnd ? theta0 : theta1);
  if (strong > weak) return "";
  // The turning of the curvature's sign s that the tangents allow within one turn, then one
  // turn more.
  const double s = (k0 + k1) > 0.0 ? 1.0 : -1.0, delta = normalizeAngle(theta1 - theta0);
  const double within = delta * s > 0.0 ? delta : delta + 2.0 * kPi * s;
  const double degrees = 180.0 / kPi;
  const bool convex = -s * theta0 > 0.0 && s * theta1 > 0.0 && std::abs(within) < kPi;
  if (proved != nullptr) *proved = convex;
  return std::string("the curvature grows towards the ") + (growsToEnd ? "end" : "start") +
         ", so the tangent must meet the chord at a larger angle there" +
         (convex ? " (Vogt's theorem)" : " (Vogt's theorem, extended to arcs of up to a full turn)") +
         ", but it meets it at " + num(strong * degrees) + " degrees there and " + num(weak * degrees) +
         " at the other end: a curve whose curvature runs one way between these ends turns at least " +
         num(std::abs(within + 2.0 * kPi * s) * degrees) + " degrees, more than a full turn";
}

/// The circle tests: the osculating circles at the ends of a curve whose curvature runs one
/// way are nested without inflection, disjoint across one inflection, and clear of a
/// straight end's tangent line (Tait-Kneser). With the research note's invariant
/// Q = (K0/2 + sin theta0)(K1/2 - sin theta1) + sin^2((theta0 + theta1)/2) (chord units)
/// they fail exactly where Q >= 0; proved for every turning. "" when they hold.
static std::string circleReason(double theta0, double k0, double theta1, double k1) {
  const Eigen::Vector2d p0(0.0, 0.0), p1(1.0, 0.0);
  const Eigen::Vector2d n0(-std::sin(theta0), std::cos(theta0)), n1(-std::sin(theta1), std::cos(theta1));
  const bool inflection = (k0 < 0.0 && k1 > 0.0) || (k0 > 0.0 && k1 < 0.0);
  if (k0 != 0.0 && k1 != 0.0) {
    const Eigen::Vector2d c0 = p0 + n0 / k0, c1 = p1 + n1 / k1;
    const double r0 = 1.0 / std::abs(k0), r1 = 1.0 / std::abs(k1), d = (c1 - c0).norm();
    if (!inflection && !(d < std::abs(r0 - r1))) {
      return "the osculating circles at the ends (radii " + num(r0) + " and " + num(r1) + " chord lengths, centres " +
             num(d) +
             " apart) are not nested: along a curve whose curvature runs one way without inflection each "
             "osculating circle lies inside the one before (Tait-Kneser)";
    }
    if (inflection && !(d > r0 + r1)) {
      return "the osculating circles at the ends (radii " + num(r0) + " and " + num(r1) + " chord lengths, centres " +
             num(d) +
             " apart) overlap: a curve whose curvature runs one way through one inflection has them on the "
             "two sides of its inflection tangent";
    }
    return "";
  }
  if (k0 == 0.0 && k1 == 0.0) return "";  // handled as equal curvatures
  // One end straight: the other end's osculating circle lies on the side the curve turns to,
  // clear of the straight end's tangent line.
  const bool startStraight = k0 == 0.0;
  const Eigen::Vector2d p = startStraight ? p0 : p1, n = startStraight ? n0 : n1, q = startStraight ? p1 : p0;
  const Eigen::Vector2d nq = startStraight ? n1 : n0;
  const double k = startStraight ? k1 : k0;
  const Eigen::Vector2d centre = q + nq / k;
  const double signedDistance = (centre - p).dot(n) * (k > 0.0 ? 1.0 : -1.0);
  if (!(signedDistance > 1.0 / std::abs(k))) {
    return std::string("the osculating circle at the ") + (startStraight ? "end" : "start") +
           " crosses the tangent line of the straight " + (startStraight ? "start" : "end") +
           ": a curve whose curvature runs one way from 0 keeps its osculating circles on one side of that line "
           "(Tait-Kneser)";
  }
  return "";
}

std::string g2Refusal(double theta0, double k0, double theta1, double k1) {
  std::string why = circleReason(theta0, k0, theta1, k1);
  if (why.empty() && k0 * k1 >= 0.0) why = turningRuleReason(theta0, k0, theta1, k1);
  return why;
}

namespace {

struct Candidate {
  Spiral spiral;
  bool converged = false;
};

/// Newton on (L, b) for the end point, with a from the turning; damped by backtracking.
Candidate newton(Spiral s, double Theta) {
  // The turning L (k0 + (k1 - k0)/2 + a/6) = Theta gives a from L.
  auto shapeFor = [&](double L) { return 6.0 * (Theta / L - s.k0 - 0.5 * (s.k1 - s.k0)); };
  auto residual = [&](double L, double b) {
    Spiral t = s;
    t.length = L;
    t.a = shapeFor(L);
    t.b = b;
    return (t.point(L) - Eigen::Vector2d(1.0, 0.0)).eval();
  };
  double L = s.length, b = s.b;
  Eigen::Vector2d F = residual(L, b);
  Candidate out;
  for (int it = 0; it < 40; ++it) {
    if (F.norm() < 1e-13) {
      out.converged = true;
      break;
    }
    const double hL = 1e-7 * L, hb = 1e-7 * (1.0 + std::abs(b));
    Eigen::Matrix2d J;
    J.col(0) = (residual(L + hL, b) - residual(L - hL, b)) / (2.0 * hL);
    J.col(1) = (residual(L, b + hb) - residual(L, b - hb)) / (2.0 * hb);
    const Eigen::Vector2d step = J.fullPivLu().solve(F);
    if (!step.allFinite()) break;
    double lambda = 1.0;
    bool improved = false;
    for (int k = 0; k < 20; ++k, lambda *= 0.5) {
      const double nL = L - lambda * step[0], nb = b - lambda * step[1];
      if (!(nL > 1.0) || std::abs(nb) > 50.0 * (1.0 + std::abs(s.k1 - s.k0) + std::abs(s.k0))) continue;
      const Eigen::Vector2d nF = residual(nL, nb);
      if (nF.norm() < F.norm()) {
        L = nL, b = nb, F = nF;
        improved = true;
        break;
      }
    }
    if (!improved) break;
  }
  if (!out.converged && F.norm() < 1e-11) out.converged = true;
  out.spiral = s;
  out.spiral.length = L;
  out.spiral.a = shapeFor(L);
  out.spiral.b = b;
  return out;
}

/// Levenberg-Marquardt on (log(L - 1), z_1 .. z_{n-1}) (L > 1: longer than the chord) with the node steps C_i - C_{i-1} the
/// softmax of (0, z): monotone by construction. Residuals: the end point, the turning, and
/// sqrt(mu) (n step_i - 1), which pulls towards the clothoid (equal steps); mu goes to 1e-12
/// so that the ends are met to rounding. The start has equal steps (profile 0), steps growing
/// towards the end (1) or the start (2), or steps at the two ends (3, like a triarc). A weak
/// pull (mu from 1e-4 to 1e-8) lets the steps go far from equal: the last resort, for ends
/// whose curvature must change almost all at once. nullopt where it does not reach the ends.
std::optional<ClothoidSpline> clothoidSpline(double theta0, double k0, double k1, double Theta, double L0, int n,
                                             int profile, bool weakPull) {
  const int m = n;                             // parameters
  constexpr double kFloor = 1.25 * kMinSlope;  // every step at least kFloor / n: n step >= kFloor
  auto build = [&](const Eigen::VectorXd& x) {
    ClothoidSpline c;
    c.theta0 = theta0, c.k0 = k0, c.k1 = k1, c.length = 1.0 + std::exp(x[0]);
    Eigen::VectorXd w(n);
    w[0] = 1.0;
    const double top = std::max(0.0, x.tail(n - 1).maxCoeff());
    w[0] = std::exp(-top);
    for (int i = 1; i < n; ++i) w[i] = std::exp(x[i] - top);
    w = (1.0 - kFloor) * w / w.sum() + Eigen::VectorXd::Constant(n, kFloor / n);
    c.C.assign(n + 1, 0.0);
    for (int i = 0; i < n; ++i) c.C[i + 1] = c.C[i] + w[i];
    c.C[n] = 1.0;
    return c;
  };
  auto residuals = [&](const Eigen::VectorXd& x, double mu) {
    Eigen::VectorXd r(3 + n);
    if (!x.allFinite() || !(x[0] < std::log(1e4)) || x.tail(n - 1).cwiseAbs().maxCoeff() > 40.0) {
      r.setConstant(1e150);  // outside the sane region: shorter than 1e4 chords, sane steps
      return r;
    }
    const ClothoidSpline c = build(x);
    const Eigen::Vector2d end = c.point(c.length);
    r[0] = end.x() - 1.0;
    r[1] = end.y();
    r[2] = c.theta(c.length) - theta0 - Theta;
    for (int i = 0; i < n; ++i) r[3 + i] = std::sqrt(mu) * (n * (c.C[i + 1] - c.C[i]) - 1.0);
    return r;
  };
  Eigen::VectorXd x = Eigen::VectorXd::Zero(m);
  x[0] = std::log(std::max(L0 - 1.0, 1e-6));
  for (int i = 1; i < n; ++i) {
    if (profile == 1) x[i] = 3.0 * i / (n - 1.0);
    if (profile == 2) x[i] = -3.0 * i / (n - 1.0);
    if (profile == 3) x[i] = i == n - 1 ? 0.0 : -3.0;
  }
  const std::array<double, 3> pulls =
      weakPull ? std::array<double, 3>{1e-4, 1e-6, 1e-8} : std::array<double, 3>{1e-2, 1e-4, 1e-6};
  for (double mu : pulls) {
    double lambda = 1e-3;
    Eigen::VectorXd r = residuals(x, mu);
    for (int it = 0; it < 60; ++it) {
      Eigen::MatrixXd J(r.size(), m);
      for (int j = 0; j < m; ++j) {
        Eigen::VectorXd y = x;
        const double h = 1e-7 * (1.0 + std::abs(x[j]));
        y[j] += h;
        J.col(j) = (residuals(y, mu) - r) / h;
      }
      const Eigen::MatrixXd A = J.transpose() * J;
      const Eigen::VectorXd g = J.transpose() * r;
      bool improved = false;
      for (int k = 0; k < 12; ++k) {
        Eigen::MatrixXd D = A;
        D.diagonal() += lambda * (A.diagonal().array() + 1e-12).matrix();
        const Eigen::VectorXd step = D.ldlt().solve(-g);
        if (!step.allFinite()) break;
        const Eigen::VectorXd y = x + step;
        if (!(y[0] < std::log(1e4)) || y.tail(m - 1).cwiseAbs().maxCoeff() > 40.0) {
          lambda *= 4.0;
          continue;
        }
        const Eigen::VectorXd ry = residuals(y, mu);
        if (ry.squaredNorm() < r.squaredNorm()) {
          x = y, r = ry, lambda = std::max(lambda / 3.0, 1e-12);
          improved = true;
          break;
        }
        lambda *= 4.0;
      }
      if (!improved || r.head(3).norm() < 1e-14) break;
    }
  }
  // Polish: Gauss-Newton on the three end conditions alone, with minimum-norm steps, which
  // move the profile as little as the ends need.
  Eigen::VectorXd r = residuals(x, 0.0).head(3);
  for (int it = 0; it < 8 && r.norm() > 1e-14; ++it) {
    Eigen::MatrixXd J(3, m);
    for (int j = 0; j < m; ++j) {
      Eigen::VectorXd y = x;
      const double h = 1e-7 * (1.0 + std::abs(x[j]));
      y[j] += h;
      J.col(j) = (residuals(y, 0.0).head(3) - r) / h;
    }
    const Eigen::VectorXd step = J.transpose() * (J * J.transpose()).ldlt().solve(-r);
    if (!step.allFinite()) break;
    const Eigen::VectorXd y = x + step, ry = residuals(y, 0.0).head(3);
    if (!(ry.norm() < r.norm())) break;
    x = y, r = ry;
  }
  const ClothoidSpline c = build(x);
  if (!(r.norm() < 1e-12)) return std::nullopt;
  return c;
}

}  // namespace

SpiralSolution solveG2Spiral(double theta0, double k0, double theta1, double k1) {
  SpiralSolution out;
  const double delta = normalizeAngle(theta1 - theta0);
  const double kmax = std::max(std::abs(k0), std::abs(k1));
  const bool equal = std::abs(k1 - k0) <= 1e-12 * std::max(1.0, kmax);
  const Clothoid g1 = clothoidG1(Eigen::Vector2d::Zero(), theta0, Eigen::Vector2d(1.0, 0.0), theta1);
  const double g1Turning = g1.theta(g1.length) - g1.theta0;
  std::vector<Candidate> found;
  bool proven = false;  // a circle test or Vogt's theorem failed: nothing monotone exists
  // Curvature of one sign turns the tangent that way: other windings cannot be monotone.
  const bool cShaped = k0 * k1 >= 0.0;
  auto signAllowed = [&](double Theta) { return !cShaped || Theta * (k0 + k1) > 0.0; };
  // Newton from the length L (a from the turning, b = 0); true when it ends monotone.
  auto tryLength = [&](double Theta, double L) {
    if (!(std::abs(Theta) < 2.0 * kPi)) return false;  // a blend turns less than a full turn
    if (!(L > 1.0 && L < 1e4)) return false;           // longer than the chord, and not absurdly long
    Spiral s;
    s.theta0 = theta0, s.k0 = k0, s.k1 = k1, s.length = L;
    const Candidate c = newton(s, Theta);
    if (!c.converged) return false;
    found.push_back(c);
    return c.spiral.minSlope() >= kMinSlope;
  };
  if (equal) {
    // Equal end curvatures: a monotone curve between them is a circle arc (or a segment).
    const double k = 0.5 * (k0 + k1);
    for (int n = -1; n <= 1; ++n) {
      const double Theta = delta + 2.0 * kPi * n;
      if (!(std::abs(Theta) < 2.0 * kPi)) continue;
      if (k == 0.0 ? Theta != 0.0 : !(Theta / k > 0.0)) continue;
      Spiral s;
      s.theta0 = theta0, s.k0 = s.k1 = k;
      s.length = k == 0.0 ? 1.0 : Theta / k;
      if ((s.point(s.length) - Eigen::Vector2d(1.0, 0.0)).norm() < 1e-9) {
        out.monotone = s;
        return out;
      }
    }
    out.reason = "the end curvatures are equal (" + num(k) +
                 " per chord length), so a curve whose curvature runs "
                 "one way between them is a circle arc, and no circle of that curvature meets both ends";
    // The fairest curve with one bump of curvature between them, for the report.
    for (double L : {g1.length, 1.05, 1.3, 2.0}) tryLength(g1Turning, L);
  } else {
    out.reason = circleReason(theta0, k0, theta1, k1);
    proven = !out.reason.empty();
    // Refused by Vogt's theorem (convex case): as proven as the circle tests, so no clothoid
    // spline is searched for (that search cost 0.5 s here, 7 s sanitized: a fuzz finding).
    if (!proven && cShaped) out.reason = turningRuleReason(theta0, k0, theta1, k1, &proven);
    // Starts: the length at which a profile of shape a = (k1 - k0) aStart (b = 0) has the
    // turning. First the clothoid (aStart = 0) in every winding, and the G1 clothoid's
    // length; only where none of those is monotone, the other shapes, per winding until one
    // converges to a monotone solution. Of all solutions found the fairest is kept.
    auto tryShape = [&](double Theta, double aStart) {
      return tryLength(Theta, Theta / (k0 + (k1 - k0) * (0.5 + aStart / 6.0)));
    };
    bool any = tryLength(g1Turning, g1.length);
    for (int n : {0, 1, -1}) any = tryShape(delta + 2.0 * kPi * n, 0.0) || any;
    if (!any) {
      for (int n : {0, 1, -1}) {
        for (double aStart : {0.5, -0.5, 1.0, -1.0, 1.5, -1.5}) {
          if (tryShape(delta + 2.0 * kPi * n, aStart)) break;
        }
      }
    }
  }
  for (const Candidate& c : found) {
    const Spiral& s = c.spiral;
    if (s.minSlope() >= kMinSlope) {
      if (!out.monotone || s.variation() < out.monotone->variation()) out.monotone = s;
    } else if (!out.fallback || s.variation() < out.fallback->variation()) {
      out.fallback = s;
    }
  }
  if (!out.monotone && !equal && !proven) {
    // The cubic profiles do not reach these ends monotonically: clothoid splines, which do
    // wherever a piecewise-linear monotone curvature does.
    // Starts: the G1 clothoid's length in its winding, then a nearly straight curve and
    // two longer ones; per winding until one is monotone.
    for (int n : {0, 1, -1}) {
      const double Theta = delta + 2.0 * kPi * n;
      if (!(std::abs(Theta) < 2.0 * kPi) || !signAllowed(Theta)) continue;
      std::vector<double> starts{1.02, 1.5, 3.0, 1.003};
      if (std::abs(g1Turning - Theta) < 1e-9) starts.insert(starts.begin(), g1.length);
      bool done = false;
      // 8 pieces, then 16, then 8 with a weak pull towards equal steps.
      for (int attempt = 0; attempt < 12 && !done; ++attempt) {
        const int profile = attempt % 4, pieces = attempt >= 4 && attempt < 8 ? 16 : 8;
        for (double L0 : starts) {
          const std::optional<ClothoidSpline> c =
              clothoidSpline(theta0, k0, k1, Theta, L0, pieces, profile, attempt >= 8);
          if (!c || c->minSlope() < kMinSlope) continue;
          if (!out.spline || c->variation() < out.spline->variation()) out.spline = c;
          done = true;
          break;
        }
      }
    }
  }
  if (out.monotone || out.spline) out.reason.clear();
  return out;
}

}  // namespace fairsplines::detail
