// Fair fit (issue 16): the csr-spline of Karčiauskas & Peters, "Curvature-sensitive splines
// and design with basic curves", Section 4, eq. (6), built on an adaptive subset of
// noise-smoothed samples and refined until every sample lies within the tolerance.
// The method, its guarantees and its heuristics: docs/FAIR_FIT.md.
#include "fairsplines/fair_fit.hpp"

#include <Eigen/Dense>
#include <Geom_BSplineCurve.hxx>
#include <algorithm>
#include <array>
#include <cmath>
#include <gp_Pnt.hxx>
#include <limits>
#include <sstream>
#include <vector>

#include "fairsplines/analysis.hpp"
#include "fairsplines/csr.hpp"
#include "fairsplines/errors.hpp"
#include "fairsplines/occt.hpp"
#include "fairsplines/parameters.hpp"
#include "fair_fit_detail.hpp"
#include "finite.hpp"
#include "work_budget.hpp"

namespace fairsplines {
namespace {

using namespace detail::fairfit;  // the fit's own internals (fair_fit_detail.hpp)

// ---------------------------------------------------------------------------------------
// The fit

struct Subset {
  std::vector<Index> index;  // sample indices, increasing
  std::vector<char> raw;     // use q_i itself (ends of open data; where smoothing fails)
  std::vector<char> pinned;  // the curve passes through q_i at its knot (step 8's fall-back)
};

class FairFitter {
public:
  FairFitter(PointsRef q, const FairFitOptions& o) : FairFitter(q, o, readSamples(q, o.closed)) {}
  /// With the samples read and the noise estimated already (fitInput needs them for the
  /// corners).
  FairFitter(PointsRef q, const FairFitOptions& o, Samples S, std::optional<double> estimated = std::nullopt)
      : q_(q), o_(o), S_(std::move(S)), dim_(q.cols()), estimated_(estimated) {
    const Ends ends = readOptions(o, dim_);
    startT_ = ends.startT, endT_ = ends.endT, startK_ = ends.startK, endK_ = ends.endK;
  }

  /// The end conditions of `o` as unit tangents and curvature vectors (across the tangent),
  /// after checking every option (InputError naming the first that is wrong).
  struct Ends {
    std::optional<Vector3d> startT, endT, startK, endK;
  };
  static Ends readOptions(const FairFitOptions& o, Index dim) {
    if (!(o.tolerance > 0.0) || !std::isfinite(o.tolerance)) {
      throw InputError("the fair fit's tolerance must be positive and finite, got " + exactNumber(o.tolerance));
    }
    if (o.noise && (!(*o.noise >= 0.0) || !std::isfinite(*o.noise))) {
      throw InputError("the fair fit's noise must be zero or positive and finite, got " + exactNumber(*o.noise));
    }
    if (o.closed && (o.startTangent || o.endTangent || o.startCurvature || o.endCurvature)) {
      throw InputError("closed data have no ends: end tangents and curvatures are for open data only");
    }
    Ends e;
    e.startT = direction(o.startTangent, dim, "the start tangent");
    e.endT = direction(o.endTangent, dim, "the end tangent");
    e.startK = curvatureVector(o.startCurvature, e.startT, dim, "the start curvature", "start");
    e.endK = curvatureVector(o.endCurvature, e.endT, dim, "the end curvature", "end");
    return e;
  }

  FairFitResult run() {
    const double tau = o_.tolerance;
    sigma_ = o_.noise ? *o_.noise : estimated_ ? *estimated_ : estimateNoise(S_, static_cast<int>(dim_));
    plane_ = dataPlane(S_, static_cast<int>(dim_), std::max(0.5 * tau, 6.0 * sigma_));
    // Samples whose noise is below 1/100 of the tolerance are used as they are (on noise-free
    // data the "noise" estimated is the local quadratics' model error; smoothing would only
    // add bias). Straight runs are put on their lines either way.
    smooth_ = sigma_ > 0.01 * tau;
    // Position window: the centre estimate of a quadratic fit over M samples has a standard
    // deviation of about 1.5 sigma / sqrt(M); M is chosen so that it is at most tolerance / 8.
    // (Clamped as a double: noise far above the tolerance makes M infinite.)
    const double M = 2.25 * std::pow(8.0 * sigma_ / tau, 2.0);
    const double halfWindow = std::ceil((M - 1.0) / 2.0);
    kPos_ = halfWindow >= 64.0 ? 64 : halfWindow >= 2.0 ? static_cast<Index>(halfWindow) : 2;
    // Curvature window: 1/64 of the samples (at least 8, at most 4096 each side).
    kCurv_ = std::clamp<Index>(S_.n / 64, std::max<Index>(8, 2 * kPos_), 4096);
    kCurv_ = std::max<Index>(1, std::min<Index>(kCurv_, (S_.n - 1) / 4));
    // Where the curvature is near 0 the estimates' noise decides its sign, not the tolerance:
    // the position window is widened to a quarter of the curvature window (its noise drops
    // with the square root of its samples; its bias at a curvature jump, quadratic in its
    // length, is bounded by the tolerance check).
    kPos_ = std::max<Index>(kPos_, kCurv_ / 4);

    FairFitResult result;
    result.noise = sigma_;
    if (plane_.planar) {
      if (dim_ != 2) {  // 2D data are in their plane's coordinates already (planarPoints)
        planar_.resize(S_.n);
        for (Index i = 0; i < S_.n; ++i) {
          const Vector3d d = S_.p[i] - plane_.origin;
          planar_[i] = Vector3d(d.dot(plane_.e1), d.dot(plane_.e2), 0.0);
        }
      }
      shape_ = dataShape(S_, planarPoints(), sigma_, tau, kCurv_, dim_ == 2);
    }
    result.dataSignChanges = shape_.signChanges;
    if (plane_.planar) normal_ = dim_ == 2 ? Vector3d::UnitZ() : plane_.e1.cross(plane_.e2).normalized();

    detail::WorkBudget budget(400.0 * static_cast<double>(S_.n) + 1e6, "the fair fit of these points",
                              "the tolerance needs more refinement passes than the data's size allows");
    Subset sub = initialSubset();
    BSplineCurve curve;
    double maxDev = 0.0;
    std::vector<Foot> feet;  // of the samples on `curve`, for fairing
    auto fitWithin = [&]() {
      for (;;) {
        ++result.iterations;
        curve = build(sub);
        std::vector<double> dev;
        maxDev = deviations(curve, sub, dev, &feet, tau);
        if (maxDev <= tau) break;
        refine(sub, dev);
      }
    };
    fitWithin();
    Handle(Geom_BSplineCurve) occ = toOcct(curve);
    CurvatureProfile profile = profileOf(curve, occ);
    int changes = curvatureSignChanges(profile);
    // Unsupported inflections, first remedy: a csr span depends on the 8 subset points
    // around it (eq. (6): c_i on f_{i-1}, f_i, f_{i+1}), so a straight run with fewer has no
    // exactly straight span, and the small curvatures leaking in from both of its ends may
    // cross 0 in the middle. Runs get 8 points (collinear estimates) and the fit is redone.
    if (changes > shape_.signChanges && densifyStraightRuns(sub)) {
      fitWithin();
      occ = toOcct(curve);
      profile = profileOf(curve, occ);
      changes = curvatureSignChanges(profile);
    }
    // Second remedy: try removing a subset point next to each extra sign change while the
    // tolerance holds (heuristic, bounded).
    for (int attempt = 0; attempt < 24 && changes > shape_.signChanges;) {
      bool improved = false;
      for (double u : signChangeParameters(profile)) {
        for (Index j : nearestInterior(curve, sub, u)) {
          if (++attempt > 24) break;
          Subset fewer = sub;
          fewer.index.erase(fewer.index.begin() + j);
          fewer.raw.erase(fewer.raw.begin() + j);
          fewer.pinned.erase(fewer.pinned.begin() + j);
          const BSplineCurve candidate = build(fewer);
          std::vector<double> dev;
          std::vector<Foot> cFeet;
          const double d = deviations(candidate, fewer, dev, &cFeet, tau);
          if (!(d <= tau)) continue;
          const Handle(Geom_BSplineCurve) cOcc = toOcct(candidate);
          const CurvatureProfile cProfile = profileOf(candidate, cOcc);
          const int cChanges = curvatureSignChanges(cProfile);
          if (cChanges < changes) {
            sub = std::move(fewer), curve = candidate, occ = cOcc, profile = cProfile, changes = cChanges, maxDev = d;
            feet = std::move(cFeet);
            improved = true;
            break;
          }
        }
        if (improved) break;
      }
      if (!improved) break;
    }
    int extrema = static_cast<int>(curvatureExtrema(profile).size());
    if (o_.fairing) polish(curve, sub, std::move(feet), maxDev, changes, extrema, profile);
    requireValidCurve(curve, "the fair fit of these points");
    result.curve = std::move(curve);
    result.maxDeviation = maxDev;
    result.signChanges = changes;
    if (imposed_) result.dataSignChanges = *imposed_;  // the pattern step 11 imposed
    result.curvatureExtrema = extrema;
    result.pinned = static_cast<int>(std::count(sub.pinned.begin(), sub.pinned.end(), 1));
    return result;
  }

private:
  static std::optional<Vector3d> unitOf(const Eigen::VectorXd& v, Index dim, const std::string& name) {
    if (v.size() != dim) {
      throw InputError(name + " must have " + std::to_string(dim) + " coordinates, like the points, not " +
                       std::to_string(v.size()));
    }
    requireFiniteInput(v, name);
    Vector3d x = Vector3d::Zero();
    x.head(dim) = v;
    return x;
  }
  static std::optional<Vector3d> direction(const std::optional<Eigen::VectorXd>& v, Index dim,
                                           const std::string& name) {
    if (!v) return std::nullopt;
    Vector3d x = *unitOf(*v, dim, name);
    const double len = x.stableNorm();
    if (!(len > 0.0) || !std::isfinite(len)) throw InputError(name + " is the zero vector: it needs a direction");
    return x / len;
  }
  static std::optional<Vector3d> curvatureVector(const std::optional<Eigen::VectorXd>& v,
                                                 const std::optional<Vector3d>& t, Index dim, const std::string& name,
                                                 const char* end) {
    if (!v) return std::nullopt;
    if (!t) throw InputError(name + " needs the " + std::string(end) + " tangent too (G2 is tangent and curvature)");
    const Vector3d k = *unitOf(*v, dim, name);
    return k - k.dot(*t) * *t;
  }

  Subset initialSubset() const {
    Subset sub;
    const Index m = std::min<Index>(S_.n, S_.closed ? 8 : 9);
    for (Index j = 0; j < m; ++j) {
      const Index i = S_.closed ? (j * S_.n) / m : (j * (S_.n - 1)) / (m - 1);
      if (sub.index.empty() || sub.index.back() != i) sub.index.push_back(i);
    }
    sub.raw.assign(sub.index.size(), 0);
    sub.pinned.assign(sub.index.size(), 0);
    if (!S_.closed) sub.raw.front() = sub.raw.back() = 1;  // the end points are interpolated
    return sub;
  }

  /// Give every straight run at least 8 subset points (evenly spread over it); whether any
  /// were added.
  bool densifyStraightRuns(Subset& sub) const {
    constexpr Index kPerRun = 8;
    std::vector<Index> extra;
    for (const StraightRun& r : shape_.straight) {
      const Index inside =
          std::count_if(sub.index.begin(), sub.index.end(), [&](Index i) { return i >= r.first && i <= r.last; });
      if (inside >= kPerRun || r.last - r.first < 2 * kPerRun) continue;
      for (Index j = 0; j < kPerRun; ++j) extra.push_back(r.first + (j * (r.last - r.first)) / (kPerRun - 1));
    }
    if (extra.empty()) return false;
    Subset next;
    std::vector<std::array<Index, 3>> all;  // sample, raw, pinned
    for (std::size_t j = 0; j < sub.index.size(); ++j) all.push_back({sub.index[j], sub.raw[j], sub.pinned[j]});
    for (Index i : extra) all.push_back({i, 0, 0});
    std::sort(all.begin(), all.end(),
              [](const auto& a, const auto& b) { return a[0] < b[0] || (a[0] == b[0] && a[1] + a[2] > b[1] + b[2]); });
    for (const auto& [i, raw, pinned] : all) {
      if (!next.index.empty() && next.index.back() == i) continue;  // keeps the flags of the first (flagged first)
      next.index.push_back(i);
      next.raw.push_back(static_cast<char>(raw));
      next.pinned.push_back(static_cast<char>(pinned));
    }
    if (next.index.size() == sub.index.size()) return false;
    sub = std::move(next);
    return true;
  }

  /// The estimate of sample i: itself (raw, or noise-free data), its projection onto the
  /// line of its straight run, or the local quadratic fit over 2 kPos + 1 samples.
  Vector3d estimate(Index i, bool raw) const {
    if (raw) return S_.p[i];
    for (const StraightRun& r : shape_.straight) {
      if (i >= r.first && i <= r.last) {
        const Vector3d xp = S_.p[i] - r.c;
        return r.c + xp.dot(r.e) * r.e;
      }
    }
    if (!smooth_) return S_.p[i];
    const LocalFit f = localFit(S_.p, S_.n, S_.closed, i, kPos_, dim_ == 2 ? &kPlaneZ : nullptr);
    return f.ok ? f.point : S_.p[i];
  }

  /// The csr-spline (eq. (6), chordal parameters) of the subset's estimates, with the
  /// end conditions set on its end poles.
  BSplineCurve build(Subset& sub) const {
    const Index m = static_cast<Index>(sub.index.size());
    PointMatrix Q(m, dim_);
    for (int pass = 0; pass < 2; ++pass) {
      for (Index j = 0; j < m; ++j) Q.row(j) = estimate(sub.index[j], sub.raw[j]).head(dim_).transpose();
      // Estimates of neighbouring samples that nearly coincide fall back to the samples.
      bool changed = false;
      for (Index j = 0; j + 1 < m + (S_.closed ? 1 : 0); ++j) {
        const Index jn = (j + 1) % m;
        if ((Q.row(jn) - Q.row(j)).norm() <= 1e-9 * S_.size && !(sub.raw[j] && sub.raw[jn])) {
          sub.raw[j] = sub.raw[jn] = 1;
          changed = true;
        }
      }
      if (!changed) break;
    }
    CsrOptions co;
    co.closed = S_.closed;
    BSplineCurve curve = csrSpline(Q, co);
    if (!S_.closed) endConditions(curve);
    pin(curve, sub);
    return curve;
  }

  /// Step 8's fall-back: where even the csr-spline of neighbouring samples stays beyond the
  /// tolerance (it relaxes away from samples of high curvature, eq. (6)), the curve is made
  /// to pass through them at their knots (pinAtKnots), the end conditions' poles kept.
  void pin(BSplineCurve& curve, const Subset& sub) const {
    const Index m = static_cast<Index>(sub.index.size());
    std::vector<std::pair<Index, Vector3d>> pins;
    for (Index j = 0; j < m; ++j) {
      if (!sub.pinned[j] || (!S_.closed && (j == 0 || j == m - 1))) continue;  // open ends: interpolated already
      pins.push_back({j, S_.p[sub.index[j]]});
    }
    if (pins.empty()) return;
    SplineSpace space{std::vector<double>(curve.knots.data(), curve.knots.data() + curve.knots.size()), S_.closed};
    Eigen::MatrixX3d P = polesOf(curve);
    if (!pinAtKnots(space, P, pins, fixedPoles(P.rows()))) return;
    setPoles(curve, P);
  }

  /// The poles an open curve's end conditions set: P_0 (the end point), P_1 with a tangent,
  /// P_2 with a curvature (mirrored at the end); none when closed.
  std::vector<char> fixedPoles(Index np) const {
    std::vector<char> fixed(np, 0);
    if (S_.closed) return fixed;
    const Index a = startK_ ? 3 : startT_ ? 2 : 1, b = endK_ ? 3 : endT_ ? 2 : 1;
    for (Index i = 0; i < a && i < np; ++i) fixed[i] = 1;
    for (Index i = 0; i < b && i < np; ++i) fixed[np - 1 - i] = 1;
    return fixed;
  }

  /// Open ends: pole 1 on the given tangent (the leg length kept), pole 2 moved across it
  /// so that the curvature vector is the given one. With knots t_0 (x4), t_1, t_2:
  /// C'(t_0) = 3 (P1 - P0) / h0, C''(t_0) = 6 / h0 ((P2 - P1) / (t_2 - t_0) - (P1 - P0) / h0),
  /// so the curvature vector is (P2 - P1)_perp 6 h0 / (9 a^2 (t_2 - t_0)) with a = |P1 - P0|.
  void endConditions(BSplineCurve& c) const {
    const Index np = c.poles.rows(), nk = c.knots.size();
    auto pole = [&](Index r) {
      Vector3d x = Vector3d::Zero();
      x.head(dim_) = c.poles.row(r).transpose();
      return x;
    };
    auto set = [&](Index r, const Vector3d& x) { c.poles.row(r) = x.head(dim_).transpose(); };
    auto apply = [&](Index i0, Index i1, Index i2, double h0, double h02, const std::optional<Vector3d>& T,
                     const std::optional<Vector3d>& K, double sign) {
      if (!T) return;
      const Vector3d P0 = pole(i0), P2 = pole(i2);
      double a = (pole(i1) - P0).norm();
      if (!(a > 0.0)) a = (P2 - P0).norm() / 2.0;
      const Vector3d P1 = P0 + sign * a * *T;
      set(i1, P1);
      if (K) {
        const Vector3d d = P2 - P1;
        set(i2, P1 + d.dot(*T) * *T + 1.5 * a * a * h02 / h0 * *K);
      }
    };
    apply(0, 1, 2, c.knots[1] - c.knots[0], c.knots[2] - c.knots[0], startT_, startK_, 1.0);
    apply(np - 1, np - 2, np - 3, c.knots[nk - 1] - c.knots[nk - 2], c.knots[nk - 1] - c.knots[nk - 3], endT_, endK_,
          -1.0);
  }

  /// The largest distance of the samples of subset interval j (span j of P) to the curve,
  /// an upper bound (see projectDistance): each sample is projected from its chord-length
  /// position between the subset samples around it. Past `stopAbove` the first such distance
  /// is returned (refine() asks only which intervals exceed the tolerance), except on an
  /// interval of adjacent samples, whose largest distance its message names.
  /// With `feet`: the curve point found for each sample (at sample index - sub.index[0]); an
  /// interval's first sample is its predecessor's last, and keeps the nearer foot.
  double intervalDeviation(const SpanPolys& P, const Subset& sub, Index j, std::vector<Foot>* feet = nullptr,
                           double stopAbove = HUGE_VAL) const {
    const Index m = static_cast<Index>(sub.index.size());
    const Index a = sub.index[j], b = j + 1 < m ? sub.index[j + 1] : sub.index[0] + S_.n;
    detail::WorkBudget::spend(static_cast<double>(b - a + 1));
    const double sa = S_.arc(a), sb = S_.arc(b), h = P.h(j);
    const bool mayStop = b - a >= 2;
    double d = 0.0;
    for (Index k = a; k <= b; ++k) {
      const double x = sb > sa ? (S_.arc(k) - sa) / (sb - sa) * h : 0.0;
      const Foot foot = projectFoot(P, S_.p[k < S_.n ? k : k - S_.n], j, x);  // a <= k < 2n
      d = std::max(d, foot.d);
      if (feet) {
        Foot& f = (*feet)[k - sub.index[0]];
        if (k > a || j == 0 || foot.d < f.d) f = foot;
      }
      if (mayStop && d > stopAbove) break;
    }
    return std::isfinite(d) ? d : HUGE_VAL;
  }

  /// Every subset interval's distance to the curve (intervalDeviation); returns the largest.
  /// O(n). With `feet`: every sample's curve point (fair() starts from them), valid when the
  /// largest is within `stopAbove` (an interval beyond it stops at its first sample beyond).
  double deviations(const BSplineCurve& curve, const Subset& sub, std::vector<double>& dev,
                    std::vector<Foot>* feet = nullptr, double stopAbove = HUGE_VAL) const {
    const Handle(Geom_BSplineCurve) occ = toOcct(curve);
    const SpanPolys P = spanPolys(curve, occ);
    const Index m = static_cast<Index>(sub.index.size()), intervals = S_.closed ? m : m - 1;
    dev.assign(intervals, 0.0);
    // Every slot is written below (no fill: 10^6 feet are 24 MB).
    if (feet) feet->resize((S_.closed ? S_.n : sub.index.back() - sub.index.front()) + 1);
    double worst = 0.0;
    for (Index j = 0; j < intervals; ++j) {
      dev[j] = intervalDeviation(P, sub, j, feet, stopAbove);
      worst = std::max(worst, dev[j]);
    }
    return worst;
  }

  /// Step 10 (docs/FAIR_FIT.md): thinning (fair_fit_thinning.cpp), then fairing
  /// (fair_fit_fairing.cpp), each verified over all samples on its final curve. The thinned
  /// curve replaces the fit when it has no more curvature sign changes (the profile of
  /// step 9); the faired one when it has no more sign changes and fewer curvature extrema.
  void polish(BSplineCurve& curve, const Subset& sub, std::vector<Foot> feet, double& maxDev, int& changes,
              int& extrema, CurvatureProfile& profile) const {
    Polishing bounds;
    bounds.tolerance = o_.tolerance;
    bounds.samples = &S_;
    bounds.at = sub.index;
    if (S_.closed) bounds.at.push_back(sub.index.front() + S_.n);
    bounds.fixedStart = startK_ ? 3 : 2, bounds.fixedEnd = endK_ ? 3 : 2;
    bounds.normal = normal_;
    bounds.zeroKappa = profile.kappa.size() > 0 ? 1e-6 * profile.kappa.cwiseAbs().maxCoeff() : 0.0;

    // Step 11 may go back to the fit before thinning (a copy only where it may run: a fit
    // without sign changes never gets one, and 10^6 samples' feet are worth not copying).
    const bool mayImpose = signsMayBeImposed(changes);
    const BSplineCurve unthinned = mayImpose ? curve : BSplineCurve{};
    const std::vector<Foot> unthinnedFeet = mayImpose ? feet : std::vector<Foot>{};
    Thinning th = bounds;
    th.feet = std::move(feet);  // given back as they were when no knot is removed
    const Handle(Geom_BSplineCurve) occ = toOcct(curve);
    const Handle(Geom_BSplineCurve) thinned = removeKnots(occ, th);
    if (thinned != occ) {
      BSplineCurve c = fromOcct(thinned);
      c.poles = c.poles.leftCols(dim_).eval();
      CurvatureProfile tProfile = profileOf(c, thinned);
      const int tChanges = curvatureSignChanges(tProfile);
      if (th.maxDeviation <= o_.tolerance && c.poles.allFinite() && tChanges <= changes) {
        curve = std::move(c), maxDev = th.maxDeviation, changes = tChanges, profile = std::move(tProfile);
        extrema = static_cast<int>(curvatureExtrema(profile).size());
        bounds.at = std::move(th.at);
      } else {
        th.feet.clear();  // on the thinned curve, not this one: the fairings project the samples themselves
      }
    }
    fairConstrained(curve, th.feet, bounds.at.front(), maxDev, changes, extrema, profile);
    bool withSigns = imposeSigns(curve, th.feet, bounds.at.front(), maxDev, changes, extrema, profile);
    if (!withSigns && mayImpose && curve.poles.rows() < unthinned.poles.rows()) {
      // The thinned knots may be too few for the signs (next to a hairpin): the fit's own.
      BSplineCurve c = unthinned;
      std::vector<Foot> cFeet = unthinnedFeet;
      if (imposeSigns(c, cFeet, sub.index.front(), maxDev, changes, extrema, profile)) {
        curve = std::move(c), th.feet = std::move(cFeet), bounds.at = sub.index;
        withSigns = true;
      }
    }
    if (withSigns) {
      // Knots may have been inserted: the samples at each knot from the samples' feet.
      const Index m = curve.knots.size() - 1, nq = static_cast<Index>(th.feet.size()), at0 = bounds.at.front();
      bounds.at.assign(m + 1, at0 + nq - 1);
      Index k = 0;
      for (Index j = 0; j < m; ++j) {
        while (k + 1 < nq && th.feet[k].span < j) ++k;
        bounds.at[j] = at0 + k;
      }
      bounds.at[0] = at0;
    }
    Fairing f{bounds};
    f.feet = std::move(th.feet);
    fair(curve, f, maxDev, changes, extrema, profile);
  }

  /// Fairing under the tolerance (fair_fit_constrained.cpp): the poles move towards the least
  /// bending and third-derivative jump energy while every sample stays within the tolerance
  /// at its foot.
  /// Verified over every sample (projected again from its foot on the new curve); taken when
  /// it has no more curvature sign changes and no more extrema. `feet` (at sample index -
  /// at0) become the new curve's when taken.
  void fairConstrained(BSplineCurve& curve, std::vector<Foot>& feet, Index at0, double& maxDev, int& changes,
                       int& extrema, CurvatureProfile& profile) const {
    ConstrainedFairing cf;
    cf.tolerance = o_.tolerance;
    cf.q = &S_.p;
    cf.fixed = fixedPoles(curve.poles.rows());

    // Every sample measured within the tolerance (else the rest are checked later on).
    for (const Foot& foot : feet)
      if (!(foot.d <= o_.tolerance)) return;
    cf.sample.resize(feet.size());
    for (std::size_t k = 0; k < feet.size(); ++k) cf.sample[k] = S_.wrap(at0 + static_cast<Index>(k));
    cf.feet.swap(feet);       // given back below unless a faired curve is taken (no copy of 10^6 feet)
    std::vector<Foot> given;  // the feet as given, once a pass has moved cf.feet on
    const SplineSpace space{std::vector<double>(curve.knots.data(), curve.knots.data() + curve.knots.size()),
                            S_.closed};
    // Outer passes: the constraints hold each sample at its foot's parameter, so a pass may
    // not slide the curve along itself; the samples are projected again (their new feet) and
    // the next pass starts from there, while the energy still drops by 1 %.
    const int passes = cf.feet.size() > 100000 ? 1 : 3;
    BSplineCurve best = curve;
    bool faired = false;
    double bestDev = maxDev, lastEnergy = HUGE_VAL;
    for (int pass = 0; pass < passes; ++pass) {
      Eigen::MatrixX3d P = polesOf(best);
      fairUnderTolerance(space, P, cf);
      if (!(cf.energyAfter < cf.energyBefore) || !P.allFinite()) break;
      BSplineCurve next = best;
      setPoles(next, P);
      const Handle(Geom_BSplineCurve) occ = toOcct(next);
      const SpanPolys SP = spanPolys(next, occ);
      std::vector<Foot> moved(cf.feet.size());
      double d = 0.0;
      for (std::size_t k = 0; k < cf.feet.size(); ++k) {
        moved[k] = projectFoot(SP, S_.p[cf.sample[k]], cf.feet[k].span, cf.feet[k].x);
        d = std::max(d, moved[k].d);
      }
      if (!(d <= o_.tolerance)) break;
      if (!faired) given = std::move(cf.feet);
      best = std::move(next), bestDev = d, cf.feet = std::move(moved), faired = true;
      const bool converged = cf.energyAfter > 0.99 * std::min(lastEnergy, cf.energyBefore);
      lastEnergy = cf.energyAfter;
      if (converged) break;
    }
    if (!faired) {
      feet.swap(cf.feet);
      return;
    }
    const SpanPolys SP = spanPolys(best, toOcct(best));
    CurvatureProfile fProfile = spanProfile(SP, normal_, 16);
    const int fChanges = curvatureSignChanges(fProfile);
    const int fExtrema = static_cast<int>(curvatureExtrema(fProfile).size());
    if (fChanges > changes || fExtrema > extrema) {
      feet = std::move(given);
      return;
    }
    curve = std::move(best), maxDev = bestDev, changes = fChanges, extrema = fExtrema, profile = std::move(fProfile);
    feet = std::move(cf.feet);
  }

  /// Step 11 (fair_fit_signs.cpp): where the fit still has more curvature sign changes than
  /// the data support, the fairness energy is minimised again under the tolerance with the
  /// data's sign pattern imposed span by span (turningPattern: a sign per span, one switch span
  /// between runs of opposite signs), linearised about the present poles and repeated about
  /// the new ones (up to 8 rounds, the samples projected again each time). Taken at the first
  /// round whose curve has the data's sign changes with every sample within the tolerance
  /// (verified by projection). `feet` (at sample index - at0) become the new curve's.
  /// Where step 11 runs: open planar data of at most 50000 samples whose fit has a sign
  /// change. End tangents and curvatures may force turns the data lack (their fit keeps its
  /// signs); denser data are left to the straight runs of step 4 (roads of 44,000 samples
  /// take 1.3-2 s here; at 170,000 the rounds took 20-30 s and failed).
  bool signsMayBeImposed(int changes) const {
    return changes > 0 && plane_.planar && !S_.closed && !startT_ && !endT_ && S_.n <= 50000;
  }

  bool imposeSigns(BSplineCurve& curve, std::vector<Foot>& feet, Index at0, double& maxDev, int& changes, int& extrema,
                   CurvatureProfile& profile) const {
    if (!signsMayBeImposed(changes) || feet.empty()) return false;
    const std::vector<SignSwitch> pattern = turningPattern(planarPoints(), S_.s, sigma_);
    const int target = static_cast<int>(pattern.size()) - 1;
    if (pattern.empty() || changes <= target) return false;
    const double tau = o_.tolerance;
    BSplineCurve c = curve;
    std::vector<Foot> cFeet = feet;
    for (const Foot& ft : cFeet)
      if (!(ft.d <= tau)) return false;
    // Its own work bound, in QP rows times interior point iterations: about 100 sample
    // projections per sample (the QPs fail past it and the fit keeps its signs).
    double work = 100.0 * static_cast<double>(S_.n) + 1e6;
    std::vector<char> held;  // samples whose curve point may not slide (sf.hold)
    int retries = 0, insertions = 0;
    for (int round = 0; round < 8; ++round) {
      SplineSpace space{std::vector<double>(c.knots.data(), c.knots.data() + c.knots.size()), false};
      const Index m = space.spans();
      // The switches' parameters (their samples' feet), then each span's signs at its ends.
      std::vector<double> u;
      for (std::size_t s = 1; s < pattern.size(); ++s) {
        const Foot& ft = cFeet[pattern[s].at - at0];
        u.push_back(space.t[ft.span] + ft.x);
      }
      // New knots (the curve unchanged), the feet moved to their spans.
      auto insertKnots = [&](const std::vector<double>& at) {
        Handle(Geom_BSplineCurve) occ = toOcct(c);
        for (double x : at) occ->InsertKnot(x);
        c = fromOcct(occ);
        c.poles = c.poles.leftCols(dim_).eval();
        for (Foot& ft : cFeet) {
          const double v = space.t[ft.span] + ft.x;
          const auto it = std::upper_bound(c.knots.data(), c.knots.data() + c.knots.size() - 1, v);
          ft.span = std::max<Index>(0, (it - c.knots.data()) - 1);
          ft.x = v - c.knots[ft.span];
        }
      };
      SignedFairing sf;
      sf.spanSign.assign(m, {0, 0});
      std::size_t next = 0;
      std::vector<double> between;  // knots between two switches in one span
      for (Index j = 0; j < m; ++j) {
        while (next < u.size() && u[next] <= space.t[j]) ++next;
        const int s0 = pattern[next].sign;
        std::size_t inside = next;
        while (inside < u.size() && u[inside] < space.t[j + 1]) ++inside;
        for (std::size_t k = next; k + 1 < inside; ++k) between.push_back(0.5 * (u[k] + u[k + 1]));
        sf.spanSign[j] = {s0, pattern[inside].sign};
      }
      if (!between.empty()) {
        if (++insertions > 6) return false;
        insertKnots(between);
        --round;
        continue;
      }
      sf.tolerance = tau;
      sf.q = &S_.p;
      sf.fixed = fixedPoles(c.poles.rows());
      sf.e1 = plane_.e1, sf.e2 = plane_.e2;
      // The signs with a margin of 100 times what the sign count calls 0 (1e-6 of the largest
      // curvature): the linearisation's error then cannot flip a sign where the optimum is
      // straight.
      sf.margin = 1e-4 * spanProfile(spanPolys(c, toOcct(c)), normal_, 16).kappa.cwiseAbs().maxCoeff();
      // The samples the QP holds: every stride-th (about 2000), those held, and those beyond
      // half the tolerance, every nearStride-th of these so that they are about 8000 at most
      // (dense data have tens of thousands there); the rest are verified below.
      const Index nq = static_cast<Index>(cFeet.size()), stride = std::max<Index>(1, nq / 2000);
      if (held.empty()) held.assign(nq, 0);
      Index near = 0;
      for (const Foot& ft : cFeet) near += ft.d > 0.5 * tau ? 1 : 0;
      const Index nearStride = std::max<Index>(1, near / 8000);
      for (Index k = 0; k < nq; ++k) {
        if (k % stride != 0 && !(cFeet[k].d > 0.5 * tau && k % nearStride == 0) && !held[k]) continue;
        sf.sample.push_back(S_.wrap(at0 + k));
        sf.feet.push_back(cFeet[k]);
        sf.hold.push_back(held[k]);
      }
      Eigen::MatrixX3d P = polesOf(c);
      sf.work = work;
      const bool solved = fairWithSigns(space, P, sf);
      work = sf.work;
      if (!solved) return false;
      if (std::count(sf.violated.begin(), sf.violated.end(), 1) > 0) {
        // The signs cannot be met on these spans with these knots (next to a hairpin): each
        // gets a knot in its middle (the curve unchanged), and the round is done again.
        if (++insertions > 6) return false;
        std::vector<double> middles;
        for (Index j = 0; j < m; ++j)
          if (sf.violated[j]) middles.push_back(0.5 * (space.t[j] + space.t[j + 1]));
        insertKnots(middles);
        --round;
        continue;
      }
      BSplineCurve moved = c;
      setPoles(moved, P);
      const SpanPolys SP = spanPolys(moved, toOcct(moved));
      std::vector<Foot> nFeet(nq);
      double d = 0.0;
      bool more = false;
      for (Index k = 0; k < nq; ++k) {
        nFeet[k] = projectFoot(SP, S_.p[S_.wrap(at0 + k)], cFeet[k].span, cFeet[k].x);
        d = std::max(d, nFeet[k].d);
        if (nFeet[k].d > tau) {
          // Slid too far where the curve bends: it and its neighbours slide less next time.
          for (Index r = std::max<Index>(0, k - 1); r <= std::min(nq - 1, k + 1); ++r)
            more |= held[r] < 4, held[r] = static_cast<char>(std::min(4, held[r] + 1));
        }
      }
      if (!(d <= tau)) {
        if (!more || ++retries > 6) return false;
        --round;
        continue;
      }
      c = std::move(moved), cFeet = std::move(nFeet);
      CurvatureProfile cProfile = spanProfile(SP, normal_, 16);
      const int cChanges = curvatureSignChanges(cProfile);
      if (cChanges > target) continue;
      curve = std::move(c), maxDev = d, changes = cChanges, profile = std::move(cProfile);
      extrema = static_cast<int>(curvatureExtrema(profile).size());
      feet = std::move(cFeet);
      imposed_ = target;
      return true;
    }
    return false;
  }

  /// Fairing (fair_fit_fairing.cpp). The faired curve replaces the fit when every sample is
  /// still within the tolerance (verified over all samples on the faired curve), it has no
  /// more curvature sign changes and fewer curvature extrema.
  void fair(BSplineCurve& curve, Fairing& f, double& maxDev, int& changes, int& extrema,
            CurvatureProfile& profile) const {
    const Handle(Geom_BSplineCurve) occ = toOcct(curve);
    SpanPolys P = spanPolys(curve, occ);
    f.maxMoves = 4 * P.spans();
    if (fairThirdDerivativeJumps(occ, P, f) == 0) return;
    BSplineCurve faired = curve;
    for (Index i = 0; i < faired.poles.rows(); ++i) {
      const gp_Pnt x = occ->Pole(static_cast<int>(i) + 1);
      const Vector3d v(x.X(), x.Y(), x.Z());
      faired.poles.row(i) = v.head(dim_).transpose();
    }
    if (!faired.poles.allFinite()) return;
    const double d = f.maxDeviation;
    if (!(d <= o_.tolerance)) return;
    CurvatureProfile fProfile = profileOf(faired, toOcct(faired));
    const int fChanges = curvatureSignChanges(fProfile);
    const int fExtrema = static_cast<int>(curvatureExtrema(fProfile).size());
    if (fChanges > changes || fExtrema >= extrema) return;
    curve = std::move(faired), maxDev = d, changes = fChanges, extrema = fExtrema, profile = std::move(fProfile);
  }

  /// The curve's curvature profile from its span polynomials (16 samples a span; signed
  /// about the data's plane when the data are planar): O(spans), where OCCT's evaluation
  /// (curvatureProfile) costs O(knots) per point on a curve with a knot per chosen sample.
  CurvatureProfile profileOf(const BSplineCurve& curve, const Handle(Geom_BSplineCurve)& occ) const {
    return spanProfile(spanPolys(curve, occ), normal_, 16);
  }

  /// Intervals beyond the tolerance get their middle sample; intervals of neighbouring
  /// samples fall back to the samples themselves, and past that the tolerance is out of reach.
  void refine(Subset& sub, const std::vector<double>& dev) const {
    const Index m = static_cast<Index>(sub.index.size());
    const std::vector<char> built = sub.pinned;  // the pins the curve was built with
    Subset next;
    for (Index j = 0; j < m; ++j) {
      next.index.push_back(sub.index[j]);
      next.raw.push_back(sub.raw[j]);
      next.pinned.push_back(sub.pinned[j]);
      if (j >= static_cast<Index>(dev.size()) || dev[j] <= o_.tolerance) continue;
      const Index a = sub.index[j], b = j + 1 < m ? sub.index[j + 1] : sub.index[0] + S_.n;
      if (b - a >= 2) {
        next.index.push_back(S_.wrap((a + b) / 2));
        next.raw.push_back(0);
        next.pinned.push_back(0);
        continue;
      }
      const Index jn = (j + 1) % m;
      if (sub.raw[j] && sub.raw[jn] && !(built[j] && built[jn])) {
        // The csr-spline of the samples themselves relaxes beyond the tolerance here: the
        // curve is pinned to both (it then passes through them; step 8's fall-back).
        next.pinned.back() = 1;
        if (jn == 0)
          next.pinned.front() = 1;
        else
          sub.pinned[jn] = 1;
        continue;
      }
      if (sub.raw[j] && sub.raw[jn]) {
        std::ostringstream msg;
        msg << "the fair fit cannot keep within the tolerance " << o_.tolerance << " near sample " << a
            << ": even the csr-spline of the samples themselves is " << dev[j] << " away there (the noise is " << sigma_
            << (o_.noise ? ", as given" : ", estimated")
            << "; a tolerance below about 3 times the noise cannot be met)";
        throw InputError(msg.str());
      }
      next.raw.back() = 1;
      if (jn == 0)
        next.raw.front() = 1;
      else
        sub.raw[jn] = 1;
    }
    // Sort closed subsets whose inserted middle wrapped past the seam.
    if (S_.closed && next.index.size() > 1 && next.index.back() < next.index[next.index.size() - 2]) {
      next.index.insert(next.index.begin(), next.index.back());
      next.raw.insert(next.raw.begin(), next.raw.back());
      next.pinned.insert(next.pinned.begin(), next.pinned.back());
      next.index.pop_back();
      next.raw.pop_back();
      next.pinned.pop_back();
    }
    sub = std::move(next);
  }

  /// Parameters where the curve's signed curvature changes sign (as curvatureSignChanges
  /// counts them: samples of |kappa| <= 1e-6 max |kappa| skipped).
  static std::vector<double> signChangeParameters(const CurvatureProfile& p) {
    std::vector<double> u;
    if (!p.isSigned || p.kappa.size() == 0) return u;
    const double zero = 1e-6 * p.kappa.cwiseAbs().maxCoeff();
    int last = 0;
    for (Index i = 0; i < p.kappa.size(); ++i) {
      const double k = p.kappa[i];
      if (std::abs(k) <= zero) continue;
      const int s = k > 0.0 ? 1 : -1;
      if (last != 0 && s != last) u.push_back(p.u[i]);
      last = s;
    }
    return u;
  }

  /// Interior subset positions whose knots are nearest to u (up to three), nearest first.
  std::vector<Index> nearestInterior(const BSplineCurve& c, const Subset& sub, double u) const {
    const Index m = static_cast<Index>(sub.index.size());
    if (m <= 4) return {};
    std::vector<std::pair<double, Index>> d;
    for (Index j = S_.closed ? 0 : 1; j < (S_.closed ? m : m - 1); ++j) d.push_back({std::abs(c.knots[j] - u), j});
    std::sort(d.begin(), d.end());
    std::vector<Index> out;
    for (std::size_t i = 0; i < d.size() && i < 3; ++i) out.push_back(d[i].second);
    return out;
  }

  PointsRef q_;
  FairFitOptions o_;
  Samples S_;
  Index dim_;
  std::optional<double> estimated_;  // the noise, when estimated before
  std::optional<Vector3d> startT_, endT_, startK_, endK_;
  double sigma_ = 0.0;
  bool smooth_ = false;
  Index kPos_ = 2, kCurv_ = 8;
  Plane plane_;
  std::optional<Vector3d> normal_;  // the data's plane normal, for the signs of curvature (planar data)
  std::vector<Vector3d> planar_;    // 3D data in their plane's coordinates (planarPoints)
  /// The samples in their plane's coordinates (z = 0): 2D data as they are.
  const std::vector<Vector3d>& planarPoints() const { return dim_ == 2 ? S_.p : planar_; }
  DataShape shape_;
  mutable std::optional<int> imposed_;  // the sign changes of the data's pattern, when step 11 imposed it
};

// ---------------------------------------------------------------------------------------
// Real input: merged points, closed data, corners (fair_fit_input.cpp; docs/FAIR_FIT.md, step 0)

/// The points of one stretch between corners (rows a .. b of q, b past the end wrapping round
/// closed data), with midpoints added between the widest neighbours up to 4 points.
PointMatrix stretch(PointsRef q, Index a, Index b) {
  const Index n = q.rows();
  std::vector<Eigen::RowVectorXd> rows;
  for (Index i = a; i <= b; ++i) rows.push_back(q.row(i % n));
  while (rows.size() < 4) {
    std::size_t widest = 0;
    for (std::size_t i = 1; i + 1 < rows.size(); ++i)
      if ((rows[i + 1] - rows[i]).norm() > (rows[widest + 1] - rows[widest]).norm()) widest = i;
    rows.insert(rows.begin() + static_cast<std::ptrdiff_t>(widest) + 1, 0.5 * (rows[widest] + rows[widest + 1]));
  }
  PointMatrix out(static_cast<Index>(rows.size()), q.cols());
  for (std::size_t i = 0; i < rows.size(); ++i) out.row(static_cast<Index>(i)) = rows[i];
  return out;
}

/// The fit of the input as given (units already scaled): coincident neighbours merged,
/// closed data recognised, the order checked, corners refused, kept or smoothed over.
FairFitResult fitInput(PointsRef q, const FairFitOptions& options) {
  const bool ends = options.startTangent || options.endTangent || options.startCurvature || options.endCurvature;
  // End conditions ask for open data: a last point repeating the first stays an end.
  const MergedInput M = mergeCoincident(q, options.closed, options.tolerance, !ends);
  FairFitOptions o = options;
  o.closed = M.closed;
  o.tolerance = options.tolerance - M.offset;  // a dropped point is within offset of the one kept
  const PointsRef Q = M.samples(q);
  Samples S = readSamples(Q, M.closed);
  const double sigma = options.noise ? *options.noise : estimateNoise(S, static_cast<int>(q.cols()));
  if (o.tolerance < sigma) {
    // A curve that close to every sample follows the noise: the fit would be met (step 8
    // pins it) but not fair. About 3 times the noise is the least a smooth curve keeps.
    std::ostringstream msg;
    msg << "the tolerance " << options.tolerance << " is below the noise of the points (" << sigma
        << (options.noise ? ", as given" : ", estimated") << "): a curve that close follows the noise. A tolerance of "
        << 3.0 * sigma << " (3 times the noise) or more can be met";
    throw InputError(msg.str());
  }
  const std::vector<Index> corners = findCorners(S, sigma, M);
  auto finish = [&](FairFitResult r) {
    r.mergedPoints = M.merged;
    r.closed = M.closed;
    r.recognisedClosed = M.recognisedClosed;
    for (Index c : corners) r.corners.push_back(M.inputRow(c));
    if (M.merged > 0) r.maxDeviation += M.offset;
    return r;
  };
  using Corners = FairFitOptions::Corners;
  if (corners.empty() || options.corners == Corners::Smooth) {
    return finish(FairFitter(Q, o, std::move(S), sigma).run());
  }
  if (options.corners == Corners::Refuse && !(M.closed && corners.size() == 1)) {
    std::ostringstream msg;
    msg << "the points have a sharp corner at point " << M.inputRow(corners.front());
    if (corners.size() > 1) msg << " (and " << corners.size() - 1 << " more)";
    msg << " (numbered from 0): a smooth curve would round it off. corners='keep' fits each stretch between "
           "corners on its own, corners='smooth' fits one smooth curve through them";
    throw InputError(msg.str());
  }
  // Keep: the stretches between corners (closed data: round from the first corner to it).
  std::vector<std::pair<Index, Index>> spans;
  const Index n = Q.rows();
  if (M.closed) {
    for (std::size_t c = 0; c < corners.size(); ++c)
      spans.push_back({corners[c], c + 1 < corners.size() ? corners[c + 1] : corners.front() + n});
  } else {
    Index a = 0;
    for (Index c : corners) spans.push_back({a, c}), a = c;
    spans.push_back({a, n - 1});
  }
  FairFitResult all;
  all.noise = sigma;
  for (std::size_t p = 0; p < spans.size(); ++p) {
    FairFitOptions op = o;
    op.closed = false;
    op.noise = sigma;
    if (p > 0) op.startTangent.reset(), op.startCurvature.reset();
    if (p + 1 < spans.size()) op.endTangent.reset(), op.endCurvature.reset();
    const FairFitResult r = FairFitter(stretch(Q, spans[p].first, spans[p].second), op).run();
    all.pieces.push_back(r.curve);
    all.maxDeviation = std::max(all.maxDeviation, r.maxDeviation);
    all.signChanges += r.signChanges, all.dataSignChanges += r.dataSignChanges;
    all.curvatureExtrema += r.curvatureExtrema, all.iterations += r.iterations, all.pinned += r.pinned;
  }
  all.curve = all.pieces.front();
  return finish(std::move(all));
}

}  // namespace

FairFitResult fairFitReport(PointsRef q, const FairFitOptions& options) {
  // Scale-free: the fit runs on the points divided by a power of two near their largest
  // coordinate (exact, so the same digits as at that size), with the tolerance, noise and end
  // curvatures in the same units, and the curve is scaled back (exact). So samples 1e300 or
  // 1e-300 in size fit as those of size 1 do, not "points coincide" from an overflowing or
  // underflowing square. The options are checked as given first, for messages in the user's
  // numbers. Data between 1e-100 and 1e100 fit as they are.
  double largest = 0.0;
  for (Eigen::Index i = 0; i < q.rows(); ++i)
    for (Eigen::Index c = 0; c < q.cols(); ++c)
      if (std::isfinite(q(i, c))) largest = std::max(largest, std::abs(q(i, c)));
  if (!(largest > 1e100 || (largest > 0.0 && largest < 1e-100)) || (q.cols() != 2 && q.cols() != 3)) {
    FairFitter::readOptions(options, q.cols());
    return fitInput(q, options);
  }
  FairFitter::readOptions(options, q.cols());
  const double scale = powerOfTwoScale(largest);
  FairFitOptions o = options;
  // A tolerance beyond the data's reach in either direction stays beyond it (not 0 or inf).
  o.tolerance = std::clamp(options.tolerance / scale, std::numeric_limits<double>::min(), 1e300);
  if (o.noise) o.noise = std::min(*o.noise / scale, 1e300);
  if (o.startCurvature) *o.startCurvature *= scale;
  if (o.endCurvature) *o.endCurvature *= scale;
  const PointMatrix unit = q / scale;
  FairFitResult r = fitInput(unit, o);
  r.curve.poles *= scale;  // the knots stay those of size 1: parameters OCCT's tolerances suit
  for (BSplineCurve& piece : r.pieces) piece.poles *= scale;
  r.maxDeviation *= scale;
  r.noise *= scale;
  requireValidCurve(r.curve, "the fair fit of these points");
  for (const BSplineCurve& piece : r.pieces) requireValidCurve(piece, "the fair fit of these points");
  return r;
}

BSplineCurve fairFit(PointsRef q, const FairFitOptions& options) { return fairFitReport(q, options).curve; }

}  // namespace fairsplines
