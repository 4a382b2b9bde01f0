// The kernel's one rule at its boundary: no geometry that is not finite leaves it.
// Every hand-over to OpenCASCADE (toOcct, the csr fast route, the blend patches) checks
// its numbers here; inputs whose results overflow or vanish in double precision raise
// InputError naming what was being built, instead of returning NaN poles that Part
// would still call valid. Shapes are the last step: requireValidShape (finite.cpp) refuses
// a shape that BRepCheck calls not valid where it leaves the kernel.
#pragma once
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include "fairsplines/errors.hpp"
#include "fairsplines/types.hpp"

class TopoDS_Shape;

namespace fairsplines {

/// Throw InputError unless OCCT's BRepCheck_Analyzer calls the shape valid (the shapes the
/// kernel hands over: the blend shells and faces, csr edges): "<what>: ... is not a valid
/// shape (BRepCheck: <status>) ...", naming the first sub-shape at fault and the scale of
/// the input that put it there. Defined in finite.cpp.
void requireValidShape(const TopoDS_Shape& shape, const std::string& what);

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

/// Throw InputError("<name> is not finite") unless every coordinate of the input v (a point,
/// a direction) is finite.
template <class Derived>
void requireFiniteInput(const Eigen::DenseBase<Derived>& v, const std::string& name) {
  if (firstNonFinite(v) >= 0) throw InputError(name + " is not finite");
}

/// The same for count raw items of `width` doubles each (the csr fast route's scratch arrays).
inline void requireFinite(const double* data, Eigen::Index count, int width, const std::string& what,
                          const char* part) {
  using Rows = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  requireFinite(Eigen::Map<const Rows>(data, count, width), what, part);
}

/// Continuity scalars (beta, betaT: ratios of parameter speeds) are dimensionless: outside
/// [1 / kMaxScalarRatio, kMaxScalarRatio] the reparameterizations they define degenerate in
/// double precision (0/0 or overflow in the composed Bezier points).
constexpr double kMaxScalarRatio = 1e12;

/// A number for a message: all 17 digits, so that two close knots print differently.
inline std::string exactNumber(double v) {
  std::ostringstream out;
  out.precision(17);
  out << v;
  return out.str();
}

/// Knots closer than this fraction of the knot range (or than a few units in the last place
/// of their size) are "too close": OpenCASCADE refuses those at one ulp, and spans that
/// short carry no digits of their own. Relative, so that 1e-300 and 1e300 are alike.
constexpr double kRelativeKnotGap = 1e-12;

/// The first i with knots[i - 1] and knots[i] too close together (or not increasing): a gap
/// of at most kRelativeKnotGap of their range, of at most 8 ulps of their size, or denormal
/// (OCCT's knot check, gp::Resolution, the smallest normal double, calls those too close);
/// 0 if every gap is wider. The knots must be finite.
inline Eigen::Index firstCloseKnot(const double* knots, Eigen::Index count) {
  if (count < 2) return 0;
  const double range = knots[count - 1] - knots[0];
  for (Eigen::Index i = 1; i < count; ++i) {
    const double a = knots[i - 1], b = knots[i], size = std::max(std::abs(a), std::abs(b));
    const double ulp = std::nextafter(size, HUGE_VAL) - size;
    const double gap = b - a;
    if (!(gap > kRelativeKnotGap * range) || !(gap > 8.0 * ulp) || !(gap > std::numeric_limits<double>::min())) {
      return i;
    }
  }
  return 0;
}

/// Throw InputError unless the distinct knots increase by more than kRelativeKnotGap of
/// their range and by more than 8 ulps of their size, naming the first pair too close.
inline void requireSeparateKnots(const Eigen::VectorXd& knots, const std::string& what) {
  requireFinite(knots, what, "knots");
  const Eigen::Index i = firstCloseKnot(knots.data(), knots.size());
  if (i == 0) return;
  throw InputError(what + ": knots " + std::to_string(i - 1) + " and " + std::to_string(i) + " (" +
                   exactNumber(knots[i - 1]) + " and " + exactNumber(knots[i]) +
                   ") are too close together (or not increasing): their span is below the precision of the knots");
}

/// Throw InputError unless the curve is one OpenCASCADE accepts and can work with: rows of 2
/// or 3 finite coordinates, at least 2 poles, degree >= 1, one multiplicity per knot (each
/// from 1 to degree + 1), separate finite knots, positive finite weights, and, if periodic,
/// at least as many poles as its degree: OCCT accepts fewer, then reads out of bounds
/// (Geom_BSplineCurve::Copy, SetNotPeriodic). A periodic cubic of 3 poles (the closed
/// csr-spline of 3 points) is fine.
inline void requireValidCurve(const BSplineCurve& curve, const std::string& what) {
  const Eigen::Index n = curve.poles.rows(), k = curve.knots.size();
  if (curve.dimension() != 2 && curve.dimension() != 3) {
    throw InputError(what + ": its poles are rows of 2 or 3 coordinates, not " + std::to_string(curve.dimension()));
  }
  if (n < 2) throw InputError(what + ": a B-spline needs at least 2 poles, got " + std::to_string(n));
  if (curve.degree < 1) throw InputError(what + ": the degree must be >= 1, got " + std::to_string(curve.degree));
  if (k < 2) throw InputError(what + ": a B-spline needs at least 2 knots, got " + std::to_string(k));
  if (curve.mults.size() != k) throw InputError(what + ": a B-spline needs one multiplicity per knot");
  if (curve.isRational() && curve.weights.size() != n) {
    throw InputError(what + ": a rational B-spline needs one weight per pole");
  }
  if (curve.periodic && curve.degree > n) {
    throw InputError(what + ": a periodic B-spline of degree " + std::to_string(curve.degree) + " needs at least " +
                     std::to_string(curve.degree) + " poles, got " + std::to_string(n));
  }
  for (Eigen::Index i = 0; i < k; ++i) {
    if (curve.mults[i] < 1 || curve.mults[i] > curve.degree + 1) {
      throw InputError(what + ": multiplicity " + std::to_string(i) + " is " + std::to_string(curve.mults[i]) +
                       ", not from 1 to degree + 1 = " + std::to_string(curve.degree + 1));
    }
  }
  requireFinite(curve.poles, what, "poles");
  requireFinite(curve.weights, what, "weights");
  if (curve.isRational() && !(curve.weights.minCoeff() > 0.0)) throw InputError(what + ": its weights must be > 0");
  requireSeparateKnots(curve.knots, what);
}

/// A power of two s with size / s in [0.5, 2) (`size` > 0 and finite; 1 otherwise): dividing
/// by it is exact, so numerics run on data of size about 1 give the same digits as before,
/// but no square or cube of a length overflows or underflows (1e300 and 1e-300 are handled
/// by meaning, not by accident).
inline double powerOfTwoScale(double size) {
  if (!(size > 0.0) || !std::isfinite(size)) return 1.0;
  int exponent = 0;
  std::frexp(size, &exponent);  // size = m 2^exponent, m in [0.5, 1)
  return std::ldexp(1.0, std::min(exponent, std::numeric_limits<double>::max_exponent - 1));  // 2^1024 is inf
}

/// Is `spread` (how far the points move) lost in the rounding of coordinates as large as
/// `magnitude`? Then the points do not move, to double precision.
inline bool belowRounding(double spread, double magnitude) {
  return !(spread > 64.0 * std::numeric_limits<double>::epsilon() * magnitude) || !(spread > 0.0);
}

/// Throw InputError unless every scalar is finite and within [1 / kMaxScalarRatio,
/// kMaxScalarRatio], naming "<what> <i>".
inline void requireModerateScalars(const Eigen::VectorXd& scalars, const std::string& what) {
  for (Eigen::Index i = 0; i < scalars.size(); ++i) {
    const double v = scalars[i];
    if (!(v >= 1.0 / kMaxScalarRatio && v <= kMaxScalarRatio)) {
      throw InputError(what + " " + std::to_string(i) + " is " + exactNumber(v) + ": it must be from 1e-12 to 1e12 " +
                       "(a ratio of parameter speeds; beyond that the reparameterization degenerates)");
    }
  }
}

}  // namespace fairsplines
