// Fair fit, fairing (issue 16: "among such curves, the fewest curvature extrema"). Once every
// sample lies within the tolerance, the jumps of the third derivative at the knots are
// removed one knot at a time, largest first, by moving the one pole centred on that knot:
// the cubic case of the knot removal and reinsertion of Sapidis & Farin, "Automatic fairing
// algorithm for B-spline curves", Computer-Aided Design 22(2), 1990 (a knot at which the
// curve is C3 no longer separates two polynomial pieces). Each span of a polynomial spline
// on an arc has its own small curvature hump; where the third derivative runs on, the humps
// of neighbouring spans merge. A move is kept only while every sample of the spans it
// changes stays within the tolerance and their curvature sign changes do not increase.
// docs/FAIR_FIT.md, step 10.
#include <Eigen/Geometry>
#include <Geom_BSplineCurve.hxx>
#include <algorithm>
#include <cmath>
#include <queue>
#include <vector>

#include "fair_fit_detail.hpp"
#include "work_budget.hpp"

namespace fairsplines::detail::fairfit {
namespace {

/// The jump of the third derivative at knot k: span k's minus span k-1's (cyclic when closed).
Vector3d jumpAt(const SpanPolys& P, Index k) {
  const Index left = k > 0 ? k - 1 : P.spans() - 1;
  return 6.0 * (P.c[k][3] - P.c[left][3]);
}

class Fairer {
public:
  Fairer(const Handle(Geom_BSplineCurve)& occ, SpanPolys& P, Fairing& f)
      : occ_(occ), P_(P), f_(f), m_(P.spans()), np_(occ->NbPoles()) {}

  Index run() {
    // Knots with a jump: the interior ones (all of them when closed).
    const Index k0 = P_.closed ? 0 : 1, k1 = m_;
    if (k1 - k0 < 3) return 0;
    offset_ = centreOffset((k0 + k1) / 2);
    projectAll();
    double largest = 0.0;
    for (Index k = k0; k < k1; ++k) largest = std::max(largest, jumpAt(P_, k).norm());
    if (!(largest > 0.0) || !std::isfinite(largest)) return 0;
    const double floor = 1e-6 * largest;
    version_.assign(m_, 0);
    for (Index k = k0; k < k1; ++k) queue_.push({jumpAt(P_, k).norm(), k, 0});
    Index moves = 0;
    while (moves < f_.maxMoves && !queue_.empty()) {
      const Entry e = queue_.top();
      queue_.pop();
      if (e.version != version_[e.k]) continue;  // superseded by a newer jump there
      if (e.jump <= floor) break;
      if (move(e.k)) {
        ++moves;
        for (Index d = -3; d <= 3; ++d) {
          const Index k = knot(e.k + d);
          if (k < k0 || k >= k1) continue;
          queue_.push({jumpAt(P_, k).norm(), k, ++version_[k]});
        }
      }
    }
    if (moves > 0) f_.maxDeviation = verify();
    return moves;
  }

private:
  struct Entry {
    double jump;
    Index k;
    int version;
    bool operator<(const Entry& o) const { return jump < o.jump; }
  };

  /// Every sample's curve point: given, or found from its chord-length position in its span.
  void projectAll() {
    const Samples& S = *f_.samples;
    const std::vector<Index>& at = f_.at;
    const Index slots = at.back() - at.front() + 1;
    if (static_cast<Index>(f_.feet.size()) == slots) {
      feet_ = std::move(f_.feet);  // from the fit's last distance check, on this curve
    } else {
      feet_.assign(slots, Foot{0, 0.0, HUGE_VAL});
      for (Index j = 0; j < m_; ++j) {
        const double sa = S.arc(at[j]), sb = S.arc(at[j + 1]), h = P_.h(j);
        for (Index k = at[j]; k <= at[j + 1]; ++k) {
          const double x = sb > sa ? (S.arc(k) - sa) / (sb - sa) * h : 0.0;
          const Foot foot = projectFoot(P_, S.p[S.wrap(k)], j, x);
          Foot& slot = feet_[k - at.front()];
          if (foot.d < slot.d) slot = foot;
        }
      }
    }
    updates_.reserve(slots);  // (pages are only touched as it fills: no growth by copying)
    worst_.assign(m_, 0);
    for (Index j = 0; j < m_; ++j) worst_[j] = worstOf(j);
  }

  /// The slot of span j's sample farthest from the curve (checked first when the span moves:
  /// most rejected moves are rejected there).
  Index worstOf(Index j) const {
    Index w = f_.at[j] - f_.at.front();
    for (Index q = f_.at[j]; q <= f_.at[j + 1]; ++q)
      if (feet_[q - f_.at.front()].d > feet_[w].d) w = q - f_.at.front();
    return w;
  }

  /// The moved curve's distance bound for the sample in `slot` (at its recorded curve point,
  /// or projected again from it when that is past the tolerance).
  Foot moved(Index slot) const {
    const Foot& foot = feet_[slot];
    const Index q = slot + f_.at.front(), n = f_.samples->n;
    const Vector3d& p = f_.samples->p[q < n ? q : q - n];
    const auto& c = P_.c[foot.span];
    const double u = foot.x;
    Foot m{foot.span, u, (((c[3] * u + c[2]) * u + c[1]) * u + c[0] - p).norm()};
    if (!(m.d <= f_.tolerance)) m = projectFoot(P_, p, foot.span, u);
    return m;
  }

  /// The largest distance of the samples to the faired curve, an upper bound: each sample's
  /// recorded curve point is evaluated again on the final spans (projected again from there
  /// when past the tolerance), so a curve point that near exists for every sample.
  double verify() {
    const Samples& S = *f_.samples;
    double worst = 0.0;
    for (Index k = f_.at.front(); k <= f_.at.back(); ++k) {
      Foot& foot = feet_[k - f_.at.front()];
      const Vector3d& p = S.p[S.wrap(k)];
      const auto& c = P_.c[foot.span];
      const double u = foot.x;
      foot.d = (((c[3] * u + c[2]) * u + c[1]) * u + c[0] - p).norm();
      if (!(foot.d <= f_.tolerance)) foot = projectFoot(P_, p, foot.span, u);
      worst = std::max(worst, std::isfinite(foot.d) ? foot.d : HUGE_VAL);
    }
    return worst;
  }

  /// Knot or span index j: wrapped when closed, -1 outside an open curve.
  Index knot(Index j) const {
    if (P_.closed) return ((j % m_) + m_) % m_;
    return j >= 0 && j < m_ ? j : -1;
  }
  /// OCCT pole number (from 1) of kernel pole i, or 0 when i is outside an open curve.
  int pole(Index i) const {
    if (P_.closed) return static_cast<int>(((i % np_) + np_) % np_) + 1;
    return i >= 0 && i < np_ ? static_cast<int>(i) + 1 : 0;
  }

  /// The third-derivative jump at knot k after moving pole i by d (span polynomials of the
  /// two spans around k recomputed; the pole is put back).
  Vector3d jumpWithMoved(Index k, int i, const gp_Vec& d) {
    const gp_Pnt old = occ_->Pole(i);
    occ_->SetPole(i, old.Translated(d));
    const Index left = knot(k - 1) >= 0 ? knot(k - 1) : k;
    const Vector3d j = 6.0 * (spanPoly(occ_, P_.t, k)[3] - spanPoly(occ_, P_.t, left)[3]);
    occ_->SetPole(i, old);
    return j;
  }

  /// A length to probe pole i's influence with: its distance to a neighbouring pole (the
  /// jump is linear in the pole, so any length works; this one keeps the data's scale).
  double probeLength(int i) const {
    const int n = static_cast<int>(np_);
    for (int d : {1, -1, 2, -2}) {
      const int o = P_.closed ? ((i - 1 + d) % n + n) % n + 1 : i + d;
      if (o < 1 || o > n) continue;
      const double L = occ_->Pole(i).Distance(occ_->Pole(o));
      if (L > 0.0 && std::isfinite(L)) return L;
    }
    return 1.0;
  }

  /// Which pole is centred on knot k (its B-spline has the largest third-derivative jump
  /// there: pole k + 1 of a clamped cubic), found once by moving the poles around a knot.
  Index centreOffset(Index k) {
    const Vector3d j0 = jumpAt(P_, k);
    double best = -1.0;
    Index offset = 1;
    for (Index d = -4; d <= 5; ++d) {
      const int i = pole(k + d);
      if (i == 0) continue;
      const double L = probeLength(i);
      const double w = std::abs((jumpWithMoved(k, i, gp_Vec(L, 0.0, 0.0)) - j0).x()) / L;
      if (w > best) best = w, offset = d;
    }
    return offset;
  }

  /// Whether span j is one of those recomputed for a move at knot k (k-3 .. k+2).
  bool changed(Index j, Index k) const {
    Index d = j - k;
    if (P_.closed && (d < -3 || d > 2)) d = ((d % m_) + m_ + m_ / 2) % m_ - m_ / 2;
    return d >= -3 && d <= 2;
  }

  /// Curvature sign changes over spans k-3 .. k+2 (16 samples a span), planar curves only.
  int signChanges(Index k) const {
    if (!f_.normal) return 0;
    std::vector<Index> spans;
    for (Index d = -3; d <= 2; ++d)
      if (knot(k + d) >= 0) spans.push_back(knot(k + d));
    return signChangesOver(P_, spans, *f_.normal, f_.zeroKappa);
  }

  /// Zero the jump at knot k by moving its centre pole (or move it half or a quarter of the
  /// way when the whole way leaves the tolerance); whether a move was kept.
  bool move(Index k) {
    const int i = pole(k + offset_);
    if (i == 0) return false;
    const Index ci = i - 1;
    if (!P_.closed && (ci < f_.fixedStart || ci >= np_ - f_.fixedEnd)) return false;
    const Vector3d J = jumpAt(P_, k);
    // The jump is linear in the pole: J + w d for a move d.
    const double L = probeLength(i);
    const double w = (jumpWithMoved(k, i, gp_Vec(L, 0.0, 0.0)) - J).x() / L;
    if (!(std::abs(w) > 0.0) || !std::isfinite(w)) return false;
    const Vector3d full = -J / w;
    const int before = signChanges(k);
    const gp_Pnt old = occ_->Pole(i);
    std::vector<Index> spans;
    for (Index d = -3; d <= 2; ++d)
      if (knot(k + d) >= 0 && std::find(spans.begin(), spans.end(), knot(k + d)) == spans.end())
        spans.push_back(knot(k + d));
    std::vector<std::pair<Index, Foot>>& updates = updates_;  // reused: no allocation per move
    std::vector<std::array<Vector3d, 4>> kept;
    for (Index j : spans) kept.push_back(P_.c[j]);
    for (double alpha : {1.0, 0.5, 0.25}) {
      const Vector3d d = alpha * full;
      if (!d.allFinite()) continue;
      occ_->SetPole(i, old.Translated(gp_Vec(d.x(), d.y(), d.z())));
      for (Index j : spans) P_.c[j] = spanPoly(occ_, P_.t, j);
      // Samples whose curve point lies in a changed span: the same point on the moved curve
      // bounds their distance; past the tolerance they are projected again from it.
      // (Samples of the changed spans; one whose curve point is in a changed span but whose
      // own span is not is caught by verify(), which evaluates every sample at the end.)
      bool ok = signChanges(k) <= before;
      // The curve moves by at most |d| (the B-splines are a partition of unity), so a sample
      // within tolerance - |d| of its curve point stays within the tolerance of it; only the
      // others are evaluated on the moved spans.
      const double shift = d.norm();
      auto bound = [&](Index slot) {
        if (feet_[slot].d + shift <= f_.tolerance) return Foot{feet_[slot].span, feet_[slot].x, feet_[slot].d + shift};
        return moved(slot);
      };
      for (Index j : spans) {
        if (ok && changed(feet_[worst_[j]].span, k) && !(bound(worst_[j]).d <= f_.tolerance)) ok = false;
      }
      updates.clear();
      worstNew_.clear();
      for (Index j : spans) {
        if (!ok) break;
        Index w = f_.at[j] - f_.at.front();
        double wd = -1.0;
        for (Index q = f_.at[j]; ok && q <= f_.at[j + 1]; ++q) {
          const Index slot = q - f_.at.front();
          double d = feet_[slot].d;
          if (changed(feet_[slot].span, k)) {
            const Foot m = bound(slot);
            if (!(m.d <= f_.tolerance)) ok = false;
            updates.push_back({slot, m});
            d = m.d;
          }
          if (d > wd) wd = d, w = slot;
        }
        worstNew_.push_back(w);
      }
      if (ok) {
        for (const auto& [slot, foot] : updates) feet_[slot] = foot;
        for (std::size_t s = 0; s < spans.size(); ++s) worst_[spans[s]] = worstNew_[s];
        return true;
      }
    }
    occ_->SetPole(i, old);
    for (std::size_t s = 0; s < spans.size(); ++s) P_.c[spans[s]] = kept[s];
    return false;
  }

  const Handle(Geom_BSplineCurve)& occ_;
  SpanPolys& P_;
  Fairing& f_;
  Index m_, np_;
  Index offset_ = 1;
  std::vector<int> version_;
  std::vector<std::pair<Index, Foot>> updates_;
  std::vector<Foot> feet_;
  std::vector<Index> worst_;     // per span: worstOf
  std::vector<Index> worstNew_;  // per sample at[0] .. at[m]: a curve point and its distance
  std::priority_queue<Entry> queue_;
};

}  // namespace

Index fairThirdDerivativeJumps(const Handle(Geom_BSplineCurve)& occ, SpanPolys& P, Fairing& f) {
  return Fairer(occ, P, f).run();
}

}  // namespace fairsplines::detail::fairfit
