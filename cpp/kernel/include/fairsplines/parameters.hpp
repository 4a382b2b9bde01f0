// Parameters t_i for samples q_i: chordal, centripetal, uniform.
#pragma once
#include <string>
#include "fairsplines/errors.hpp"
#include "fairsplines/types.hpp"

namespace fairsplines {

enum class Parametrization { Chordal, Centripetal, Uniform };

/// Parses "chordal", "centripetal" or "uniform"; throws InputError otherwise.
Parametrization parseParametrization(const std::string& name);

/// What validation learns about the samples on the way.
struct SampleInfo {
  Eigen::VectorXd chords;  ///< |q_{i+1} - q_i|, one more (back to q_0) for closed data
  double size = 0.0;       ///< diagonal of the bounding box
};

/// Checks samples for the spline constructions: at least `minPoints` rows, 2 or 3
/// columns, finite values, not all coincident, no two consecutive (cyclically
/// consecutive when `closed`) coincident. Throws InputError naming the problem.
SampleInfo validateSamples(PointsRef q, bool closed, int minPoints, const char* method);

/// Parameters from chord lengths: t_0 = 0 and t_{i+1} - t_i = chord_i^a with a = 1
/// (chordal), 1/2 (centripetal) or 0 (uniform). Size: one more than the chords.
/// Throws nothing; the chords must be finite and positive (validateSamples ensures it).
Eigen::VectorXd parameters(const Eigen::VectorXd& chords, Parametrization kind);

/// Parameters for samples (n values, n + 1 for closed data: t_n closes the loop).
/// Throws nothing; q must be samples validateSamples accepts (not checked here).
Eigen::VectorXd parameters(PointsRef q, Parametrization kind, bool closed);

/// Checks user-given parameters: n values (n + 1 when closed), finite, strictly
/// increasing. Returns them; throws InputError naming the first bad one.
Eigen::VectorXd validatedParameters(const Eigen::VectorXd& t, Eigen::Index n, bool closed);

namespace detail {

/// The InputError of validateSamples for points whose size squared overflows or underflows
/// (largest coordinate about 1e154 or more, or a spread of 1e-300 or less that is not a
/// coincidence): fits that can rescale catch it and fit the points divided by a power of two
/// (exact); others pass it on, its message naming the size.
class ExtremeScale : public InputError {
public:
  ExtremeScale(const std::string& what, double largest) : InputError(what), largest(largest) {}
  double largest;  ///< the largest magnitude of a coordinate
};

/// validateSamples writing the chords to `chords` (room for one per segment: n - 1, or n
/// when closed) instead of a new vector. Returns the bounding-box diagonal.
/// Throws InputError as validateSamples.
double validateSamplesInto(PointsRef q, bool closed, int minPoints, const char* method, double* chords);

/// The knots a cubic with a knot at each of n samples gets from its parameters t (count =
/// n, n + 1 when closed: t[n] closes the loop) must be separate (finite.hpp's rule: a gap
/// above 1e-12 of the parameter range and above 8 ulps of its size). Checked before the
/// knots are used: throws InputError naming the two samples (or, when `given`, the two
/// parameters) too close together along the data, and suggesting the fair fit, which merges
/// such neighbours. Data that wander back and forth get there while no two consecutive
/// samples come near coinciding in the bounding box (validateSamples' test).
void requireSeparateParameters(const double* t, Eigen::Index count, Eigen::Index n, bool given, const char* method);

/// parameters() into t (count + 1 values); chords may be t + 1 (computed in place).
/// Throws nothing, as parameters().
void parametersInto(const double* chords, Eigen::Index count, Parametrization kind, double* t);

/// The checks of validateSamplesInto for open data in two parts, so that a pass can
/// stream: openSampleSize makes every check but the coincidence of consecutive points
/// (those before it, in the same order) and returns the bounding-box diagonal, the size.
/// A chord of at most 1e-12 size is a coincidence: throwFirstCoincident throws the
/// InputError of validateSamplesInto for the first in segments from..to-1.
double openSampleSize(PointsRef q, int minPoints, const char* method);
[[noreturn]] void throwFirstCoincident(PointsRef q, Eigen::Index from, Eigen::Index to, double size);

}  // namespace detail

}  // namespace fairsplines
