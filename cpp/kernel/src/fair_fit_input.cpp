// Fair fit, real input (issue 25): scanners and exports repeat points, files list closed
// loops with the first point again at the end, points come out of order, and profiles have
// corners (an airfoil's sharp trailing edge). The fit merges the first, recognises the
// second, refuses the third by name, and finds the fourth so that a corner is kept as one
// and never smoothed over silently. docs/FAIR_FIT.md, step 0.
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "fairsplines/errors.hpp"
#include "fairsplines/parameters.hpp"
#include "fair_fit_detail.hpp"

namespace fairsplines::detail::fairfit {

// ---------------------------------------------------------------------------------------
// Coincident points and closed data

MergedInput mergeCoincident(PointsRef q, bool closed, double tolerance, bool mayClose) {
  const Index n = q.rows(), dim = q.cols();
  if (n < 4 || (dim != 2 && dim != 3) || !q.allFinite()) {
    validateSamples(q, closed, 4, "the fair fit");  // throws, naming what is wrong
  }
  const Eigen::RowVectorXd lo = q.colwise().minCoeff(), hi = q.colwise().maxCoeff();
  const double size = (hi - lo).norm();
  const double delta = std::max(2e-12 * size, std::min(1e-9 * size, 1e-3 * tolerance));
  MergedInput out;
  out.closed = closed;
  // The kept rows' input numbers, built only from the first merge on (clean data: none).
  std::vector<Index>& keep = out.origin;
  Index kept = 0, run = 0;  // kept rows so far; the first point of the present run
  for (Index i = 0; i < n; ++i) {
    if (i > 0) {
      const double d = (q.row(i) - q.row(run)).norm();
      if (d <= delta) {
        if (keep.empty()) {
          keep.reserve(n);
          for (Index j = 0; j < i; ++j) keep.push_back(j);
        }
        out.offset = std::max(out.offset, d);
        ++out.merged;
        continue;
      }
    }
    run = i;
    if (!keep.empty()) keep.push_back(i);
    ++kept;
  }
  // The last point repeating the first: closed data (the repeat dropped).
  if (kept > 2 && (closed || mayClose)) {
    const Index last = keep.empty() ? kept - 1 : keep.back();
    const double d = (q.row(last) - q.row(0)).norm();
    if (d <= delta) {
      out.offset = std::max(out.offset, d);
      ++out.merged;
      --kept;
      if (!keep.empty()) keep.pop_back();
      out.recognisedClosed = !closed;
      out.closed = true;
    }
  }
  if (kept < 4 && out.merged > 0) {
    if (kept == 1) throw InputError("the fair fit needs points that do not all coincide: all points coincide");
    throw InputError("the fair fit needs at least 4 distinct points: after merging coincident neighbours, " +
                     std::to_string(kept) + " distinct points remain");
  }
  out.rows = kept;
  if (!keep.empty()) {
    out.kept.resize(kept, dim);
    for (Index j = 0; j < kept; ++j) out.kept.row(j) = q.row(keep[static_cast<std::size_t>(j)]);
  }
  return out;
}

// ---------------------------------------------------------------------------------------
// Order and corners

std::vector<Index> findCorners(const Samples& S, double sigma, const MergedInput& M) {
  const Index n = S.n;
  std::vector<Index> corners;
  if (n < 5) return corners;
  // The stride: chords q_i q_(i+k) of at least 20 noise deviations (the direction of a shorter
  // chord is the noise's, not the curve's): k doubles until their median (at up to 2000 i) is.
  auto at = [&](Index i) -> const Vector3d& { return S.p[S.wrap(i)]; };
  Index k = 1;
  for (;;) {
    if (4 * k >= n) return corners;  // too few samples above the noise to tell
    std::vector<double> chords;
    const Index last = S.closed ? n : n - k, step = std::max<Index>(1, last / 2000);
    for (Index i = 0; i < last; i += step) chords.push_back((at(i + k) - at(i)).norm());
    std::nth_element(chords.begin(), chords.begin() + chords.size() / 2, chords.end());
    if (chords[chords.size() / 2] >= 20.0 * sigma) break;
    k *= 2;
  }
  auto inside = [&](Index i) { return S.closed || (i - k >= 0 && i + k <= n - 1); };
  // turn(i): the angle between the chords q_(i-k) -> q_i and q_i -> q_(i+k) (0 at the ends
  // of open data); beyond(i, c): whether it exceeds the angle whose cosine is c, from the
  // chords' dot product alone (most samples turn little: no angle, no square root for them).
  auto turn = [&](Index i) {
    if (!inside(i)) return 0.0;
    const Vector3d a = at(i) - at(i - k), b = at(i + k) - at(i);
    if (!(a.squaredNorm() > 0.0 && b.squaredNorm() > 0.0)) return 0.0;
    return std::atan2(a.cross(b).norm(), a.dot(b));
  };
  auto beyond = [&](Index i, double c) {
    if (!inside(i)) return false;
    const Vector3d a = at(i) - at(i - k), b = at(i + k) - at(i);
    const double dot = a.dot(b), aa = a.squaredNorm(), bb = b.squaredNorm();
    if (!(aa > 0.0 && bb > 0.0)) return false;
    return c >= 0.0 ? dot < 0.0 || dot * dot < c * c * aa * bb : dot < 0.0 && dot * dot > c * c * aa * bb;
  };
  // Points out of order: the data run back along themselves at two consecutive samples
  // (stride 1, chords above the noise).
  if (k == 1) {
    const double back = std::cos(135.0 * M_PI / 180.0);
    for (Index i = 0; i + 1 < n; ++i) {
      if (beyond(i, back) && beyond(i + 1, back)) {
        std::ostringstream msg;
        msg << "the points are not in order along the curve: the data run back on themselves at points "
            << M.inputRow(S.wrap(i)) << " and " << M.inputRow(S.wrap(i + 1))
            << " (numbered from 0), as a pair of points out of order does; sort the points along the curve";
        throw InputError(msg.str());
      }
    }
  }
  // Corners: a turn of at least 30 degrees, at least 5 times the turns a stride away, and
  // the largest within half a stride (the angles themselves only past a 29 degree screen).
  const double minTurn = 30.0 * M_PI / 180.0, screen = std::cos(29.0 * M_PI / 180.0);
  for (Index i = 0; i < n; ++i) {
    if (!beyond(i, screen)) continue;
    const double ti = turn(i);
    if (ti < minTurn) continue;
    const double left = inside(i - k) ? turn(S.wrap(i - k)) : 0.0, right = inside(i + k) ? turn(S.wrap(i + k)) : 0.0;
    if (!(ti >= 5.0 * std::max(left, right))) continue;
    bool largest = true;
    for (Index d = -(k / 2); d <= k / 2 && largest; ++d) {
      if (d == 0 || !inside(i + d)) continue;
      const double other = turn(S.wrap(i + d));
      if (other > ti || (other == ti && d < 0)) largest = false;
    }
    if (largest) corners.push_back(i);
  }
  return corners;
}

}  // namespace fairsplines::detail::fairfit
