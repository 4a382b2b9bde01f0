// Fair fit, thinning (issue 16: "uses as few poles as it can"). The refinement of step 8
// inserts subset samples in the middle of every interval beyond the tolerance, so an interval
// a little beyond it ends as two well within it: the fit has up to twice the knots it needs.
// Once every sample lies within the tolerance, interior knots are removed one at a time, the
// cheapest first, by the knot removal of a cubic B-spline (three poles around the knot become
// two; OCCT's Geom_BSplineCurve::RemoveKnot, Tiller's algorithm as in Piegl & Tiller, The
// NURBS Book, 5.4), with the samples, not the curve before, as the bound: a removal is kept
// only when every sample near the six spans it changes stays within the tolerance and their
// curvature sign changes do not increase. The curve stays cubic and C2 with simple knots.
// docs/FAIR_FIT.md, step 10.
#include <Geom_BSplineCurve.hxx>
#include <Standard_Failure.hxx>
#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>
#include <vector>

#include "fair_fit_detail.hpp"

namespace fairsplines::detail::fairfit {
namespace {

class Thinner {
public:
  Thinner(const Handle(Geom_BSplineCurve)& occ, Thinning& t) : occ_(occ), t_(t), S_(*t.samples) {}

  Handle(Geom_BSplineCurve) run() {
    P_.closed = occ_->IsPeriodic();
    for (int i = 1; i <= occ_->NbKnots(); ++i) P_.t.push_back(occ_->Knot(i));
    const Index m = static_cast<Index>(P_.t.size()) - 1;
    const Index slots = t_.at.empty() ? 0 : t_.at.back() - t_.at.front() + 1;
    if (m < 2 || static_cast<Index>(t_.at.size()) != m + 1 || static_cast<Index>(t_.feet.size()) != slots) return occ_;
    P_.c.resize(m);
    for (Index j = 0; j < m; ++j) P_.c[j] = spanPoly(occ_, P_.t, j);
    // Each sample's curve point as a parameter: unchanged by removing a knot elsewhere.
    U_.resize(slots), D_.resize(slots);
    moved_.reserve(slots);  // (pages are only touched as it fills: no growth by copying)
    for (Index s = 0; s < slots; ++s) U_[s] = P_.t[t_.feet[s].span] + t_.feet[s].x, D_[s] = t_.feet[s].d;
    const std::vector<Index> at0 = t_.at;
    budget_ = 20.0 * static_cast<double>(S_.n) + 1e6;  // sample evaluations and pole copies
    bool removed = false;
    for (int pass = 0; pass < 3 && budget_ > 0.0; ++pass) {
      // The cheapest first: the error of removing knot k grows with its third-derivative
      // jump times the cube of the spans around it.
      std::vector<std::pair<double, double>> order;  // (estimated error, knot)
      for (Index k = 1; k < P_.spans(); ++k) {
        const double h = 0.5 * (P_.h(k - 1) + P_.h(k));
        const double cost = (P_.c[k][3] - P_.c[k - 1][3]).norm() * h * h * h;
        order.push_back({cost >= 0.0 ? cost : HUGE_VAL, P_.t[k]});  // (0 x inf at 1e300: last)
      }
      std::sort(order.begin(), order.end());
      bool any = false;
      for (const auto& [cost, u] : order) {
        if (budget_ <= 0.0) break;
        const auto it = std::lower_bound(P_.t.begin(), P_.t.end(), u);
        if (it != P_.t.end() && *it == u && remove(static_cast<Index>(it - P_.t.begin()))) any = removed = true;
      }
      if (!any) break;
    }
    if (!removed) return occ_;
    // Every sample evaluated again on the final curve (an upper bound of its distance, as in
    // step 7); a sample beyond the tolerance (one whose curve point moved from outside the
    // windows checked) gives back the curve before thinning.
    double worst = 0.0;
    for (Index s = 0; s < slots; ++s) {
      t_.feet[s] = footOf(s);
      worst = std::max(worst, std::isfinite(t_.feet[s].d) ? t_.feet[s].d : HUGE_VAL);
    }
    if (!(worst <= t_.tolerance)) {
      t_.at = at0;
      t_.feet.clear();
      return original_;
    }
    t_.maxDeviation = worst;
    return occ_;
  }

private:
  /// Span j (cyclic when closed) of the current curve, or -1 outside an open one.
  Index span(Index j) const {
    const Index m = P_.spans();
    if (P_.closed) return ((j % m) + m) % m;
    return j >= 0 && j < m ? j : -1;
  }

  /// The sample in slot s (its index minus at[0]) and its distance to the current curve at
  /// its recorded parameter, projected again from there when that is beyond the tolerance.
  Foot footOf(Index s) {
    const Vector3d& p = S_.p[S_.wrap(s + t_.at.front())];
    const double u = U_[s];
    const Index j = std::clamp<Index>(
        static_cast<Index>(std::upper_bound(P_.t.begin(), P_.t.end(), u) - P_.t.begin()) - 1, 0, P_.spans() - 1);
    const double x = u - P_.t[j];
    const auto& c = P_.c[j];
    Foot f{j, x, (((c[3] * x + c[2]) * x + c[1]) * x + c[0] - p).norm()};
    budget_ -= 1.0;
    if (!(f.d <= t_.tolerance)) {
      f = projectFoot(P_, p, j, x);
      budget_ -= 4.0;
    }
    return f;
  }

  /// Remove knot k (0 < k < m) if the samples allow it; whether it was removed.
  bool remove(Index k) {
    const Index m = P_.spans();
    // Removing t_k changes poles k .. k+2 (the support [t_(k-3), t_(k+3)]): open curves keep
    // their fixed end poles (and the knots their end conditions depend on); a periodic cubic
    // keeps at least 5 poles.
    if (P_.closed ? (k < 1 || k > m - 1 || m - 1 < 5)
                  : (k < std::max<Index>(1, t_.fixedStart) || k > m - std::max<Index>(1, t_.fixedEnd))) {
      return false;
    }
    budget_ -= static_cast<double>(occ_->NbPoles());
    Handle(Geom_BSplineCurve) removed = Handle(Geom_BSplineCurve)::DownCast(occ_->Copy());
    try {
      if (!removed->RemoveKnot(static_cast<int>(k) + 1, 0, HUGE_VAL)) return false;
    } catch (const Standard_Failure&) {
      return false;
    }
    if (removed->NbKnots() != static_cast<int>(m)) return false;
    // How far the curve moved: the poles of the thinned curve with t_k inserted again (the
    // same knots as before) against the poles before; the B-splines are a partition of unity,
    // so no point of the curve moved farther than the largest difference.
    Handle(Geom_BSplineCurve) again = Handle(Geom_BSplineCurve)::DownCast(removed->Copy());
    double shift = HUGE_VAL;
    try {
      again->InsertKnot(P_.t[k]);
      if (again->NbPoles() == occ_->NbPoles()) {
        shift = 0.0;
        for (int i = 1; i <= again->NbPoles(); ++i) shift = std::max(shift, again->Pole(i).Distance(occ_->Pole(i)));
      }
    } catch (const Standard_Failure&) {
      shift = HUGE_VAL;
    }
    budget_ -= 2.0 * static_cast<double>(occ_->NbPoles());
    if (!std::isfinite(shift)) shift = HUGE_VAL;
    // The samples of the spans around the changed ones (slot ranges), and the curvature
    // signs there.
    std::vector<Index> around;
    ranges_.clear();
    for (Index d = -4; d <= 3; ++d) {
      const Index j = span(k + d);
      if (j < 0 || std::find(around.begin(), around.end(), j) != around.end()) continue;
      around.push_back(j);
      ranges_.push_back({t_.at[j] - t_.at.front(), t_.at[j + 1] - t_.at.front()});
    }
    const int before = t_.normal ? signChangesOver(P_, around, *t_.normal, t_.zeroKappa) : 0;
    // The curve without t_k: its spans k-3 .. k+1 recomputed, the others renumbered.
    std::vector<std::pair<Index, std::array<Vector3d, 4>>> kept;
    for (Index d = -3; d <= 2; ++d)
      if (const Index j = span(k + d); j >= 0) kept.push_back({j, P_.c[j]});
    const double tk = P_.t[k];
    P_.t.erase(P_.t.begin() + k);
    P_.c.erase(P_.c.begin() + k);
    for (Index d = -3; d <= 1; ++d)
      if (const Index j = span(k + d); j >= 0) P_.c[j] = spanPoly(removed, P_.t, j);
    // Samples within the tolerance however the curve moved keep their curve point (their
    // bound grows by the shift); the others are evaluated on the new spans, every 64th first:
    // most removals that fail, fail there.
    bool ok = true;
    moved_.clear();
    for (Index pass = 0; pass < 2 && ok; ++pass) {
      for (const auto& [first, last] : ranges_) {
        for (Index s = first; ok && s <= last; ++s) {
          if ((pass == 0) != ((s - first) % 64 == 0) || D_[s] + shift <= t_.tolerance) continue;
          const Foot f = footOf(s);
          if (!(f.d <= t_.tolerance)) ok = false;
          moved_.push_back({s, P_.t[f.span] + f.x, f.d});
        }
      }
    }
    if (ok && t_.normal) {
      std::vector<Index> after;
      for (Index j : around) after.push_back(j < k ? j : j == k ? k - 1 : j - 1);
      after.erase(std::unique(after.begin(), after.end()), after.end());
      for (Index& j : after) j = span(j);
      ok = signChangesOver(P_, after, *t_.normal, t_.zeroKappa) <= before;
    }
    if (!ok) {
      P_.t.insert(P_.t.begin() + k, tk);
      P_.c.insert(P_.c.begin() + k, std::array<Vector3d, 4>{});
      for (const auto& [j, c] : kept) P_.c[j] = c;
      return false;
    }
    if (original_.IsNull()) original_ = occ_;
    occ_ = removed;
    for (const auto& [first, last] : ranges_)
      for (Index s = first; s <= last; ++s) D_[s] += shift;
    for (const auto& [s, u, d] : moved_) U_[s] = u, D_[s] = d;
    t_.at.erase(t_.at.begin() + k);
    return true;
  }

  Handle(Geom_BSplineCurve) occ_, original_;
  Thinning& t_;
  const Samples& S_;
  SpanPolys P_;
  std::vector<double> U_;  // per sample slot: the parameter of its curve point
  std::vector<double> D_;  // per sample slot: an upper bound of its distance to that point
  std::vector<std::tuple<Index, double, double>> moved_;  // (slot, parameter, bound) of a removal
  std::vector<std::pair<Index, Index>> ranges_;           // the slots a removal checks
  double budget_ = 0.0;
};

}  // namespace

Handle(Geom_BSplineCurve) removeKnots(const Handle(Geom_BSplineCurve)& occ, Thinning& t) {
  return Thinner(occ, t).run();
}

}  // namespace fairsplines::detail::fairfit
