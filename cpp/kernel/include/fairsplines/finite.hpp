// The kernel's one rule at its boundary: no geometry that is not finite leaves it.
// Every hand-over to OpenCASCADE (toOcct, the csr fast route, the blend patches) checks
// its numbers here; inputs whose results overflow or vanish in double precision raise
// InputError naming what was being built, instead of returning NaN poles that Part
// would still call valid.
#pragma once
#include <Eigen/Core>
#include <string>

#include "fairsplines/errors.hpp"

namespace fairsplines {

/// The first item of a (a row of a matrix, an entry of a vector) holding a NaN or an
/// infinity, or -1. Works on any expression (blocks, maps), whatever its storage order.
template <class Derived>
Eigen::Index firstNonFinite(const Eigen::DenseBase<Derived>& a) {
  const bool vector = a.rows() == 1 || a.cols() == 1;
  for (Eigen::Index r = 0; r < a.rows(); ++r) {
    for (Eigen::Index c = 0; c < a.cols(); ++c) {
      const double v = a.derived().coeff(r, c);
      if (!(v - v == 0.0)) return vector ? r + c : r;  // v - v is NaN for NaN and +-inf
    }
  }
  return -1;
}

/// Throw InputError unless every number of a is finite: "<what>: its <part> are not finite
/// (number i, from 0): the input is too large, too small or too close together for double
/// precision".
template <class Derived>
void requireFinite(const Eigen::DenseBase<Derived>& a, const std::string& what, const char* part) {
  const Eigen::Index i = firstNonFinite(a);
  if (i < 0) return;
  throw InputError(what + ": its " + part + " are not finite (number " + std::to_string(i) +
                   ", from 0): the input is too large, too small or too close together for double precision");
}

/// The same for count raw items of `width` doubles each (the csr fast route's scratch arrays).
inline void requireFinite(const double* data, Eigen::Index count, int width, const std::string& what,
                          const char* part) {
  using Rows = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  requireFinite(Eigen::Map<const Rows>(data, count, width), what, part);
}

}  // namespace fairsplines
