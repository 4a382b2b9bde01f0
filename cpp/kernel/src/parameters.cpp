#include "fairsplines/parameters.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "fairsplines/errors.hpp"
#include "fairsplines/vectorise.hpp"

namespace fairsplines {

Parametrization parseParametrization(const std::string& name) {
  if (name == "chordal") return Parametrization::Chordal;
  if (name == "centripetal") return Parametrization::Centripetal;
  if (name == "uniform") return Parametrization::Uniform;
  throw InputError("unknown parametrization '" + name + "': use 'chordal', 'centripetal' or 'uniform'");
}

namespace {

/// Throws InputError naming the first point that is not finite.
[[noreturn]] void throwNotFinite(PointsRef q) {
  for (Eigen::Index i = 0; i < q.rows(); ++i) {
    if (!q.row(i).allFinite()) {
      std::ostringstream msg;
      msg << "point " << i << " is not finite (NaN or infinity)";
      throw InputError(msg.str());
    }
  }
  throw InputError("a point is not finite (NaN or infinity)");
}

/// Finiteness and bounding box of contiguous (n x D) points in one pass. The loops are
/// branch-free so that they vectorise: four points at a time, each with its own
/// running minimum and maximum, and a point is flagged when x - x is not 0 (NaN, inf).
template <int D>
FAIRSPLINES_VECTORISE bool finiteBox(const double* __restrict data, Eigen::Index n, double* lo, double* hi) {
  constexpr int L = 4 * D;  // four points per step
  double l[L], h[L];
  for (int c = 0; c < L; ++c) l[c] = h[c] = data[c % D];
  int bad = 0;
  Eigen::Index i = 0;
  for (; i + 4 <= n; i += 4) {
    const double* p = data + D * i;
    for (int c = 0; c < L; ++c) {
      l[c] = p[c] < l[c] ? p[c] : l[c];
      h[c] = p[c] > h[c] ? p[c] : h[c];
      bad |= !(p[c] - p[c] == 0.0);
    }
  }
  for (; i < n; ++i) {
    for (int c = 0; c < D; ++c) {
      const double x = data[D * i + c];
      l[c] = x < l[c] ? x : l[c];
      h[c] = x > h[c] ? x : h[c];
      bad |= !(x - x == 0.0);
    }
  }
  for (int c = 0; c < D; ++c) {
    lo[c] = l[c];
    hi[c] = h[c];
    for (int k = 1; k < 4; ++k) {
      lo[c] = std::min(lo[c], l[k * D + c]);
      hi[c] = std::max(hi[c], h[k * D + c]);
    }
  }
  return bad == 0;
}

/// Chord lengths |q_{i+1} - q_i| of contiguous (n x D) points, i < n - 1, in a loop
/// without branches (it vectorises). Says whether any is <= tol.
template <int D>
FAIRSPLINES_VECTORISE bool openChords(const double* __restrict data, Eigen::Index n, double tol,
                                      double* __restrict chords) {
  int close = 0;
  for (Eigen::Index i = 0; i + 1 < n; ++i) {
    double squared = 0.0;
    for (int c = 0; c < D; ++c) {
      const double d = data[D * (i + 1) + c] - data[D * i + c];
      squared += d * d;
    }
    chords[i] = std::sqrt(squared);
    close |= chords[i] <= tol;
  }
  return close != 0;
}

/// Validation of contiguous rows; chords to `chords` (room for n values). Returns the size.
template <int D>
double validateContiguous(PointsRef q, bool closed, double* chords) {
  const Eigen::Index n = q.rows();
  const double* data = q.data();
  double lo[D], hi[D];
  if (!finiteBox<D>(data, n, lo, hi)) throwNotFinite(q);
  // Coincidence is judged relative to the size of the data.
  double squared = 0.0, largest = 0.0;
  for (int c = 0; c < D; ++c) {
    squared += (hi[c] - lo[c]) * (hi[c] - lo[c]);
    largest = std::max(largest, std::max(std::abs(lo[c]), std::abs(hi[c])));
  }
  const double size = std::sqrt(squared);
  if (size <= 1e-300 || size <= 1e-14 * largest) throw InputError("all points coincide");
  const double tol = 1e-12 * size;
  const Eigen::Index segments = closed ? n : n - 1;
  bool close = openChords<D>(data, n, tol, chords);
  if (closed) {
    double last = 0.0;
    for (int c = 0; c < D; ++c) {
      const double d = data[c] - data[D * (n - 1) + c];
      last += d * d;
    }
    chords[n - 1] = std::sqrt(last);
    close |= chords[n - 1] <= tol;
  }
  if (close) {  // name the first pair
    for (Eigen::Index i = 0; i < segments; ++i) {
      if (chords[i] <= tol) {
        const Eigen::Index j = i + 1 == n ? 0 : i + 1;
        std::ostringstream msg;
        msg << "points " << i << " and " << j << " coincide";
        if (closed && j == 0) msg << " (the last point repeats the first: leave it out for closed data)";
        throw InputError(msg.str());
      }
    }
  }
  return size;
}

}  // namespace

namespace detail {

double validateSamplesInto(PointsRef q, bool closed, int minPoints, const char* method, double* chords) {
  const Eigen::Index n = q.rows();
  if (q.cols() != 2 && q.cols() != 3) {
    std::ostringstream msg;
    msg << "points must have 2 or 3 coordinates, got " << q.cols();
    throw InputError(msg.str());
  }
  if (n < minPoints || n < 1) {
    std::ostringstream msg;
    msg << method << " needs at least " << minPoints << (closed ? " points on a closed curve" : " points")
        << ", got " << n;
    throw InputError(msg.str());
  }
  // The passes read rows as one contiguous block (as numpy's C order gives them).
  if (q.outerStride() != q.cols()) return validateSamplesInto(PointMatrix(q), closed, minPoints, method, chords);
  return q.cols() == 2 ? validateContiguous<2>(q, closed, chords) : validateContiguous<3>(q, closed, chords);
}

void parametersInto(const double* chords, Eigen::Index count, Parametrization kind, double* t) {
  // Reads chord i before writing t[i + 1]: chords may be t + 1.
  t[0] = 0.0;
  for (Eigen::Index i = 0; i < count; ++i) {
    double h = 1.0;
    if (kind == Parametrization::Chordal) h = chords[i];
    else if (kind == Parametrization::Centripetal) h = std::sqrt(chords[i]);
    t[i + 1] = t[i] + h;
  }
}

}  // namespace detail

SampleInfo validateSamples(PointsRef q, bool closed, int minPoints, const char* method) {
  SampleInfo info;
  info.chords.resize(std::max<Eigen::Index>(closed ? q.rows() : q.rows() - 1, 0));
  info.size = detail::validateSamplesInto(q, closed, minPoints, method, info.chords.data());
  return info;
}

Eigen::VectorXd parameters(const Eigen::VectorXd& chords, Parametrization kind) {
  Eigen::VectorXd t(chords.size() + 1);
  detail::parametersInto(chords.data(), chords.size(), kind, t.data());
  return t;
}

Eigen::VectorXd parameters(PointsRef q, Parametrization kind, bool closed) {
  const Eigen::Index n = q.rows(), segments = closed ? n : n - 1;
  Eigen::VectorXd chords(segments);
  for (Eigen::Index i = 0; i < segments; ++i) chords[i] = (q.row(i + 1 == n ? 0 : i + 1) - q.row(i)).norm();
  return parameters(chords, kind);
}

Eigen::VectorXd validatedParameters(const Eigen::VectorXd& t, Eigen::Index n, bool closed) {
  const Eigen::Index expected = closed ? n + 1 : n;
  if (t.size() != expected) {
    std::ostringstream msg;
    msg << "expected " << expected << " parameters" << (closed ? " (one more than points, closing the loop)" : "")
        << ", got " << t.size();
    throw InputError(msg.str());
  }
  for (Eigen::Index i = 0; i < t.size(); ++i) {
    if (!std::isfinite(t[i])) {
      std::ostringstream msg;
      msg << "parameter " << i << " is not finite";
      throw InputError(msg.str());
    }
    if (i > 0 && !(t[i] > t[i - 1])) {
      std::ostringstream msg;
      msg << "parameters must increase strictly: t[" << i << "] = " << t[i] << " <= t[" << i - 1 << "] = " << t[i - 1];
      throw InputError(msg.str());
    }
  }
  return t;
}

}  // namespace fairsplines
