// Decoding of libFuzzer's bytes into the numbers the kernel takes, shared by every harness.
// The bytes are read front to back; past their end every read gives 0, so any input is a
// valid (possibly short) stream. Sizes are bounded by the caller (count), so one input
// runs in milliseconds.
#pragma once
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>

#include <Eigen/Core>

#include "fairsplines/types.hpp"

namespace fairsplines::fuzz {

class FuzzInput {
public:
  FuzzInput(const uint8_t* data, size_t size) : data_(data), size_(size) {}

  bool exhausted() const { return pos_ >= size_; }

  uint8_t byte() { return pos_ < size_ ? data_[pos_++] : 0; }

  uint16_t u16() {
    const uint16_t lo = byte();
    return static_cast<uint16_t>(lo | (byte() << 8));
  }

  bool flag() { return byte() & 1; }

  /// An integer in [lo, hi] (one byte; hi - lo < 256).
  int count(int lo, int hi) { return lo + byte() % (hi - lo + 1); }

  /// One of n choices.
  int choice(int n) { return byte() % n; }

  /// Any double, mostly one a designer could type, often one that breaks numerics:
  ///  3/8  a moderate value in [-8, 8) on a 1/4096 grid (the bulk: typical geometry);
  ///  1/8  a quarter-integer in [-32, 32) (exact repeats: coincident points, equal knots);
  ///  1/8  a special value: 0, -0, +-1, NaN, +-inf, the smallest and largest normals,
  ///       the smallest denormal, 1e-300, 1e300, 1e-12, 1e12, pi, 2 pi, pi / 2, ...;
  ///  1/8  eight raw bytes as an IEEE double (any NaN payload, denormals, anything);
  ///  1/8  a moderate value times 10^e, e in [-320, 308] (huge and tiny, finite or not);
  ///  1/8  the previous number moved by a few ulps or a relative 1e-15..1e-6 (near-coincidence).
  double number() {
    const uint8_t selector = byte();
    double x = 0.0;
    switch (selector >> 5) {
      case 0:
      case 1:
      case 2:
        x = static_cast<int16_t>(u16()) / 4096.0;
        break;
      case 3:
        x = static_cast<int8_t>(byte()) / 4.0;
        break;
      case 4:
        x = special(byte());
        break;
      case 5: {
        uint64_t bits = 0;
        for (int k = 0; k < 8; ++k) bits |= static_cast<uint64_t>(byte()) << (8 * k);
        std::memcpy(&x, &bits, sizeof x);
        break;
      }
      case 6: {
        const double mantissa = static_cast<int16_t>(u16()) / 4096.0;
        x = mantissa * std::pow(10.0, static_cast<int>(u16() % 629) - 320);
        break;
      }
      default: {
        const uint8_t how = byte();
        if (how & 1) {
          x = last_;
          for (int k = 0; k < (how >> 1) % 8 + 1; ++k) x = std::nextafter(x, how & 2 ? INFINITY : -INFINITY);
        } else {
          x = last_ * (1.0 + (how & 2 ? 1.0 : -1.0) * std::pow(10.0, -6 - (how >> 2) % 10));
        }
        break;
      }
    }
    last_ = x;
    return x;
  }

  /// A typical positive size: mostly in (0, 16], sometimes any number (edge cases included).
  double positive() {
    if (byte() < 224) return (u16() + 1) / 4096.0;
    return number();
  }

  /// Mostly a number in [0, 1] (16 bits), sometimes any number.
  double unit() {
    if (byte() < 224) return u16() / 65535.0;
    return number();
  }

  /// n numbers.
  Eigen::VectorXd numbers(Eigen::Index n) {
    Eigen::VectorXd v(n < 0 ? 0 : n);
    for (Eigen::Index i = 0; i < v.size(); ++i) v[i] = number();
    return v;
  }

  /// Increasing values from `start`: start plus cumulative positive() steps (edge
  /// steps included, so not always increasing or finite).
  Eigen::VectorXd increasing(Eigen::Index n, double start = 0.0) {
    Eigen::VectorXd v(n < 0 ? 0 : n);
    double t = start;
    for (Eigen::Index i = 0; i < v.size(); ++i) {
      if (i > 0) t += positive();
      v[i] = t;
    }
    return v;
  }

  // (Reads in sequence: the order of a constructor's arguments is unspecified.)
  Eigen::Vector3d vector3() {
    const double x = number(), y = number(), z = number();
    return Eigen::Vector3d(x, y, z);
  }
  Eigen::Vector2d vector2() {
    const double x = number(), y = number();
    return Eigen::Vector2d(x, y);
  }
  /// A point in the plane z = 0.
  Eigen::Vector3d planar3() {
    const Eigen::Vector2d p = vector2();
    return Eigen::Vector3d(p.x(), p.y(), 0.0);
  }

  static double special(uint8_t k) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    static const double table[] = {0.0,
                                   -0.0,
                                   1.0,
                                   -1.0,
                                   std::numeric_limits<double>::quiet_NaN(),
                                   inf,
                                   -inf,
                                   std::numeric_limits<double>::min(),
                                   -std::numeric_limits<double>::min(),
                                   std::numeric_limits<double>::max(),
                                   -std::numeric_limits<double>::max(),
                                   std::numeric_limits<double>::denorm_min(),
                                   1e-300,
                                   1e300,
                                   -1e300,
                                   1e-12,
                                   1e12,
                                   1e-9,
                                   M_PI,
                                   2 * M_PI,
                                   M_PI / 2,
                                   -M_PI,
                                   4 * M_PI / 3,
                                   0.5,
                                   1e-6,
                                   1.7e308,
                                   0.1,
                                   1.0 + 1e-15,
                                   1e6,
                                   -2.0,
                                   3.0,
                                   10.0};
    return table[k % (sizeof table / sizeof table[0])];
  }

private:
  const uint8_t* data_;
  size_t size_;
  size_t pos_ = 0;
  double last_ = 1.0;
};

/// Sample points for the curve fits: 0..maxPoints rows of 2 or 3 columns (rarely 0, 1, 4
/// or 5), as raw numbers, a random walk, points on a circle at increasing angles, or a
/// walk of moderate steps scaled by any number and moved by any offset (the same shapes
/// at 1e-300 and 1e300).
inline PointMatrix samplePoints(FuzzInput& in, int maxPoints) {
  const int n = in.count(0, maxPoints);
  int dim = 2 + (in.byte() & 1);
  if (in.byte() == 255) dim = in.count(0, 5);
  PointMatrix q = PointMatrix::Zero(n, dim);
  switch (in.choice(4)) {
    case 0:
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < dim; ++j) q(i, j) = in.number();
      break;
    case 1:
      for (int i = 1; i < n; ++i)
        for (int j = 0; j < dim; ++j) q(i, j) = q(i - 1, j) + in.number();
      break;
    case 2: {
      const double r = in.positive();
      double angle = in.number();
      for (int i = 0; i < n; ++i) {
        if (dim > 0) q(i, 0) = r * std::cos(angle);
        if (dim > 1) q(i, 1) = r * std::sin(angle);
        if (dim > 2) q(i, 2) = in.byte() < 128 ? 0.0 : in.number();
        angle += in.positive() / 8.0;
      }
      break;
    }
    default: {
      for (int i = 1; i < n; ++i)
        for (int j = 0; j < dim; ++j) q(i, j) = q(i - 1, j) + static_cast<int16_t>(in.u16()) / 4096.0;
      const double scale = in.number();
      for (int j = 0; j < dim; ++j) {
        const double offset = in.byte() < 128 ? 0.0 : in.number();
        for (int i = 0; i < n; ++i) q(i, j) = q(i, j) * scale + offset;
      }
      break;
    }
  }
  return q;
}

}  // namespace fairsplines::fuzz
