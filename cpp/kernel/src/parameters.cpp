#include "fairsplines/parameters.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>

#include "fairsplines/errors.hpp"
#include "finite.hpp"
#include "vectorise.hpp"

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

/// One pass over contiguous (n x D) points: their bounding box, whether all are finite
/// (x - x is 0 exactly for finite x), and the chords |q_{i+1} - q_i|, i < n - 1. The loop
/// has no branch and its reductions are declared to the compiler (OpenMP SIMD: min and
/// max are exact in any order), so it vectorises.
template <int D>
FAIRSPLINES_VECTORISE bool boxAndChords(const double* __restrict data, Eigen::Index n, double* lo, double* hi,
                                        double* __restrict chords) {
  double lx = data[0], ly = data[1], lz = data[D - 1], hx = lx, hy = ly, hz = lz;
  int bad = 0;
#pragma omp simd reduction(min : lx, ly, lz) reduction(max : hx, hy, hz) reduction(| : bad)
  for (Eigen::Index i = 0; i < n - 1; ++i) {
    const double* p = data + D * i;
    const double x = p[0], y = p[1], dx = p[D] - x, dy = p[D + 1] - y;
    lx = std::min(lx, x);
    hx = std::max(hx, x);
    ly = std::min(ly, y);
    hy = std::max(hy, y);
    bad |= (x - x != 0.0) | (y - y != 0.0);
    double squared = dx * dx + dy * dy;
    if constexpr (D == 3) {
      const double z = p[2], dz = p[D + 2] - z;
      lz = std::min(lz, z);
      hz = std::max(hz, z);
      bad |= z - z != 0.0;
      squared += dz * dz;
    }
    chords[i] = std::sqrt(squared);
  }
  const double* last = data + D * (n - 1);
  double l[3] = {lx, ly, lz}, h[3] = {hx, hy, hz};
  for (int c = 0; c < D; ++c) {
    lo[c] = std::min(l[c], last[c]);
    hi[c] = std::max(h[c], last[c]);
    bad |= last[c] - last[c] != 0.0;
  }
  return bad == 0;
}

/// Whether any of the first m chords is <= tol (a reduction without branches).
FAIRSPLINES_VECTORISE bool anyAtMost(const double* __restrict chords, Eigen::Index m, double tol) {
  int close = 0;
#pragma omp simd reduction(| : close)
  for (Eigen::Index i = 0; i < m; ++i) close |= chords[i] <= tol;
  return close != 0;
}

/// Bounding box and finiteness alone (for passes that compute the chords later). The
/// rows are read as one flat array, four points (4 D doubles) at a time: lane j of the
/// block accumulates coordinate j % D, so the loop needs no shuffles. Min and max are
/// exact in any order; v - v is 0 for finite v and NaN otherwise, so a sum of them is 0
/// exactly when every coordinate is finite.
template <int D>
FAIRSPLINES_VECTORISE bool finiteBox(const double* __restrict data, Eigen::Index n, double* lo, double* hi) {
  for (int c = 0; c < D; ++c) lo[c] = hi[c] = data[c];
  double sum = 0.0;
  Eigen::Index i = 0;
#if defined(__GNUC__) && !defined(__clang__)
  // GCC's vector extension: four doubles, D vectors per block of four points.
  typedef double V __attribute__((vector_size(32)));
  V l[D], h[D], bad[D];
  for (int v = 0; v < D; ++v) {
    for (int j = 0; j < 4; ++j) l[v][j] = h[v][j] = data[(4 * v + j) % D];
    bad[v] = V{0.0, 0.0, 0.0, 0.0};
  }
  for (; i + 4 <= n; i += 4) {
    const double* p = data + D * i;
    for (int v = 0; v < D; ++v) {
      V x;
      std::memcpy(&x, p + 4 * v, sizeof x);
      l[v] = x < l[v] ? x : l[v];
      h[v] = x > h[v] ? x : h[v];
      bad[v] += x - x;
    }
  }
  for (int v = 0; v < D; ++v) {
    for (int j = 0; j < 4; ++j) {
      const int c = (4 * v + j) % D;
      lo[c] = std::min(lo[c], l[v][j]);
      hi[c] = std::max(hi[c], h[v][j]);
      sum += bad[v][j];
    }
  }
#endif
  for (; i < n; ++i) {  // the rest (all of it without the vector extension)
    for (int c = 0; c < D; ++c) {
      const double v = data[D * i + c];
      lo[c] = std::min(lo[c], v);
      hi[c] = std::max(hi[c], v);
      sum += v - v;
    }
  }
  return sum == 0.0;
}

/// The bounding-box diagonal, or InputError when all points coincide.
template <int D>
double checkedSize(const double* lo, const double* hi) {
  // Coincidence is judged relative to the size of the data.
  double squared = 0.0, largest = 0.0;
  for (int c = 0; c < D; ++c) {
    squared += (hi[c] - lo[c]) * (hi[c] - lo[c]);
    largest = std::max(largest, std::max(std::abs(lo[c]), std::abs(hi[c])));
  }
  const double size = std::sqrt(squared);
  double spread = 0.0;
  for (int c = 0; c < D; ++c) spread = std::max(spread, hi[c] - lo[c]);
  // Squares that overflow or underflow: the points do not coincide, their size is beyond
  // what this fit's lengths hold as they are.
  if (!(size <= std::numeric_limits<double>::max()) || (size <= 1e-300 && spread > 1e-14 * largest)) {
    std::ostringstream msg;
    msg << "the points' coordinates reach " << largest << " and spread over " << spread
        << ": squares of their distances leave double precision; scale them to between 1e-100 and 1e100";
    throw detail::ExtremeScale(msg.str(), largest);
  }
  if (size <= 1e-300 || size <= 1e-14 * largest) throw InputError("all points coincide");
  return size;
}

/// InputError naming points i and j as coincident.
[[noreturn]] void throwCoincide(Eigen::Index i, Eigen::Index j, bool closed) {
  std::ostringstream msg;
  msg << "points " << i << " and " << j << " coincide";
  if (closed && j == 0) msg << " (the last point repeats the first: leave it out for closed data)";
  throw InputError(msg.str());
}

/// Validation of contiguous rows; chords to `chords` (room for n values). Returns the size.
template <int D>
double validateContiguous(PointsRef q, bool closed, double* chords) {
  const Eigen::Index n = q.rows();
  const double* data = q.data();
  double lo[D], hi[D];
  if (!boxAndChords<D>(data, n, lo, hi, chords)) throwNotFinite(q);
  const double size = checkedSize<D>(lo, hi);
  const double tol = 1e-12 * size;
  const Eigen::Index segments = closed ? n : n - 1;
  if (closed) {
    double last = 0.0;
    for (int c = 0; c < D; ++c) {
      const double d = data[c] - data[D * (n - 1) + c];
      last += d * d;
    }
    chords[n - 1] = std::sqrt(last);
  }
  const bool close = anyAtMost(chords, segments, tol);
  if (close) {  // name the first pair
    for (Eigen::Index i = 0; i < segments; ++i) {
      if (chords[i] <= tol) throwCoincide(i, i + 1 == n ? 0 : i + 1, closed);
    }
  }
  return size;
}

}  // namespace

namespace detail {

namespace {

void checkShape(PointsRef q, bool closed, int minPoints, const char* method) {
  const Eigen::Index n = q.rows();
  if (q.cols() != 2 && q.cols() != 3) {
    std::ostringstream msg;
    msg << "points must have 2 or 3 coordinates, got " << q.cols();
    throw InputError(msg.str());
  }
  if (n < minPoints || n < 1) {
    std::ostringstream msg;
    msg << method << " needs at least " << minPoints << (closed ? " points on a closed curve" : " points") << ", got "
        << n;
    throw InputError(msg.str());
  }
}

}  // namespace

double validateSamplesInto(PointsRef q, bool closed, int minPoints, const char* method, double* chords) {
  checkShape(q, closed, minPoints, method);
  // The passes read rows as one contiguous block (as numpy's C order gives them).
  if (q.outerStride() != q.cols()) return validateSamplesInto(PointMatrix(q), closed, minPoints, method, chords);
  return q.cols() == 2 ? validateContiguous<2>(q, closed, chords) : validateContiguous<3>(q, closed, chords);
}

double openSampleSize(PointsRef q, int minPoints, const char* method) {
  checkShape(q, false, minPoints, method);
  if (q.outerStride() != q.cols()) return openSampleSize(PointMatrix(q), minPoints, method);
  double lo[3], hi[3];
  const bool finite =
      q.cols() == 2 ? finiteBox<2>(q.data(), q.rows(), lo, hi) : finiteBox<3>(q.data(), q.rows(), lo, hi);
  if (!finite) throwNotFinite(q);
  return q.cols() == 2 ? checkedSize<2>(lo, hi) : checkedSize<3>(lo, hi);
}

void throwFirstCoincident(PointsRef q, Eigen::Index from, Eigen::Index to, double size) {
  const double tol = 1e-12 * size;
  for (Eigen::Index i = from; i < to; ++i) {
    double squared = 0.0;
    for (Eigen::Index c = 0; c < q.cols(); ++c) {
      const double d = q(i + 1, c) - q(i, c);
      squared += d * d;
    }
    if (std::sqrt(squared) <= tol) throwCoincide(i, i + 1, false);
  }
  throw InputError("two consecutive points coincide");
}

void requireSeparateParameters(const double* t, Eigen::Index count, Eigen::Index n, bool given, const char* method) {
  const Eigen::Index i = firstCloseKnot(t, count);
  if (i == 0) return;
  std::ostringstream msg;
  msg.precision(17);
  if (given) {
    msg << method << ": parameters " << i - 1 << " and " << i << " (" << t[i - 1] << " and " << t[i]
        << ") are too close together: their gap is below 1e-12 of the parameters' range (" << t[0] << " to "
        << t[count - 1] << "), which the curve's knots cannot hold";
  } else {
    msg << method << ": samples " << i - 1 << " and " << (i == n ? 0 : i)
        << " are too close together along the data: their parameters (" << t[i - 1] << " and " << t[i]
        << ") differ by less than 1e-12 of the parameters' range (0 to " << t[count - 1] << ", over " << count - 1
        << " segments), which the curve's knots cannot hold";
  }
  msg << "; the csr-spline has a knot at every sample, so leave one of them out, or fit the points with the "
         "fair fit (fw.fair_fit), which chooses its points and merges such neighbours";
  throw InputError(msg.str());
}

void parametersInto(const double* chords, Eigen::Index count, Parametrization kind, double* t) {
  t[0] = 0.0;
  // Reads chord i before writing t[i + 1]: chords may be t + 1.
  for (Eigen::Index i = 0; i < count; ++i) {
    double h = 1.0;
    if (kind == Parametrization::Chordal)
      h = chords[i];
    else if (kind == Parametrization::Centripetal)
      h = std::sqrt(chords[i]);
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
