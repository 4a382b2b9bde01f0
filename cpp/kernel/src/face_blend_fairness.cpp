// Fair cross sections of a face blend (issue 29; docs/FACE_BLENDS.md section 3): each section is a
// rational Bezier in s whose end magnitudes (alpha, beta of each side) are searched for the fewest
// curvature extrema, then the least scale-free variation L^3 int (dkappa/ds)^2 ds.
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

#include "fairsplines/errors.hpp"
#include "face_blend_detail.hpp"

namespace fairsplines::face_blend_detail {

// ---------------------------------------------------------------------------------------
// Cross sections: rational Bezier curves in s

Net sectionNet(const SectionData& d, const Magnitudes& ma, const Magnitudes& mb, int kA, int kB) {
  const int n = kA + kB + 1;
  Net c(n + 1, 4);
  const auto ra = sideRows<Vec4>(d.a0, d.a1, d.a2, ma, n), rb = sideRows<Vec4>(d.b0, d.b1, d.b2, mb, n);
  for (int i = 0; i <= kA; ++i) c.row(i) = ra[i];
  for (int i = 0; i <= kB; ++i) c.row(n - i) = rb[i];
  return c;
}

/// Value and first two derivatives of a Bezier of degree n <= 5 (rows of `c`) at s, by de
/// Casteljau: the last three levels give the derivatives (n (b1 - b0) and n (n - 1) (a2 - 2 a1 + a0)).
std::array<Vec4, 3> bezierJet(const Net& c, double s) {
  const int n = static_cast<int>(c.rows()) - 1;
  std::array<Vec4, 6> b;
  for (int i = 0; i <= n; ++i) b[i] = c.row(i).transpose();
  std::array<Vec4, 3> level2;  // the points of level n - 2
  for (int r = 1; r <= n; ++r) {
    if (r == n - 1)
      for (int i = 0; i < 3; ++i) level2[i] = b[i];
    for (int i = 0; i + r <= n; ++i) b[i] = (1 - s) * b[i] + s * b[i + 1];
  }
  // Level n - 1 from level n - 2.
  const Vec4 b0 = (1 - s) * level2[0] + s * level2[1], b1 = (1 - s) * level2[1] + s * level2[2];
  return {b[0], n * (b1 - b0), n * (n - 1.0) * (level2[2] - 2.0 * level2[1] + level2[0])};
}

Sampled sampleSection(const Net& c, int samples, bool selfApproach) {
  std::array<double, kSamples + 1> kappa, arc;
  std::array<Vec3, kSamples + 1> points;
  double length = 0.0;
  Vec3 previous;
  for (int i = 0; i <= samples; ++i) {
    const double s = static_cast<double>(i) / samples;
    const auto h = bezierJet(c, s);
    const double W = h[0][3], W1 = h[1][3], W2 = h[2][3];
    const Vec3 C = h[0].head<3>() / W;
    const Vec3 C1 = (h[1].head<3>() - W1 * C) / W;
    const Vec3 C2 = (h[2].head<3>() - 2.0 * W1 * C1 - W2 * C) / W;
    const double speed = C1.norm();
    kappa[i] = speed > 0 ? C1.cross(C2).norm() / (speed * speed * speed) : std::numeric_limits<double>::infinity();
    if (i > 0) length += (C - previous).norm();
    arc[i] = length;
    points[i] = C;
    previous = C;
  }
  Sampled out;
  out.kappaMin = *std::min_element(kappa.begin(), kappa.begin() + samples + 1);
  out.kappaMax = *std::max_element(kappa.begin(), kappa.begin() + samples + 1);
  if (!std::isfinite(out.kappaMax) || !(length > 0)) {
    out.folded = true;
    return out;
  }
  const double flat = 1e-9 * std::max(out.kappaMax, 1.0 / length);
  int sign = 0;
  for (int i = 1; i <= samples; ++i) {
    const double dk = kappa[i] - kappa[i - 1], ds = arc[i] - arc[i - 1];
    if (ds > 0) out.variation += dk * dk / ds;
    if (std::abs(dk) <= flat) continue;
    const int now = dk > 0 ? 1 : -1;
    if (sign != 0 && now != sign) ++out.extrema;
    sign = now;
  }
  out.variation *= length * length * length;
  // Self-approach: two samples far apart along the section but close in space.
  if (!selfApproach) return out;
  const double step = length / samples;
  for (int i = 0; i <= samples && !out.folded; ++i)
    for (int j = i + 4; j <= samples; ++j) {
      if ((points[i] - points[j]).norm() < 0.25 * step) {
        out.folded = true;
        break;
      }
    }
  return out;
}

// ---------------------------------------------------------------------------------------
// The search

double Search::cost(const std::array<double, 4>& x) {
  ++evaluations;
  const Magnitudes ma = magnitudes(x[0], x[1], alpha0A), mb = magnitudes(x[2], x[3], alpha0B);
  if (!positiveWeights(A, ma, kA) || !positiveWeights(B, mb, kB)) return std::numeric_limits<double>::infinity();
  double total = 0.0;
  for (const SectionData& d : sections) {
    const Sampled s = sampleSection(sectionNet(d, ma, mb, kA, kB), kSearchSamples, false);
    if (s.folded) return std::numeric_limits<double>::infinity();
    total += 1000.0 * s.extrema + s.variation;
  }
  return total;
}

std::array<double, 4> searchMagnitudes(Search& search, const FaceBlendOptions& o) {
  const bool fixedA = o.scaleA > 0, fixedB = o.scaleB > 0;
  std::array<double, 4> best{fixedA ? o.scaleA : 1.0, 0.0, fixedB ? o.scaleB : 1.0, 0.0};
  double bestCost = search.cost(best);
  // A coarse grid of the two magnitudes, then a pattern search of all four scalars.
  const double grid[] = {0.3, 0.45, 0.65, 0.9, 1.2, 1.6, 2.2};
  for (double ga : grid)
    for (double gb : grid) {
      std::array<double, 4> x{fixedA ? o.scaleA : ga, 0.0, fixedB ? o.scaleB : gb, 0.0};
      if ((fixedA && ga != grid[0]) || (fixedB && gb != grid[0])) continue;
      const double c = search.cost(x);
      if (c < bestCost) {
        bestCost = c;
        best = x;
      }
    }
  std::array<double, 4> step{0.2, 0.5, 0.2, 0.5};
  // The bend (beta / alpha) moves the section only where the side is G2 (row 2 is set).
  std::array<bool, 4> free{!fixedA, search.kA == 2 && !fixedA, !fixedB, search.kB == 2 && !fixedB};
  for (int round = 0; round < 6; ++round) {
    bool improved = false;
    for (int k = 0; k < 4; ++k) {
      if (!free[k]) continue;
      for (double sign : {1.0, -1.0}) {
        std::array<double, 4> x = best;
        x[k] = k % 2 == 0 ? x[k] * (1.0 + sign * step[k]) : x[k] + sign * step[k];
        if (k % 2 == 1 && std::abs(x[k]) > 4.0) continue;
        const double c = search.cost(x);
        if (c < bestCost) {
          bestCost = c;
          best = x;
          improved = true;
          break;
        }
      }
    }
    if (!improved)
      for (double& s : step) s *= 0.5;
  }
  if (!std::isfinite(bestCost))
    throw InputError(
        "the blend would cross itself: every cross section tried folds back on itself (or a rational face's weights "
        "would turn negative)");
  return best;
}

}  // namespace fairsplines::face_blend_detail
