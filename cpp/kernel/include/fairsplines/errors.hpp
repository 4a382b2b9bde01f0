// Typed errors of the FairSplines kernel.
#pragma once
#include <stdexcept>
#include <string>

namespace fairsplines {

/// Input a designer can correct (too few points, NaN, coincident points, ...).
/// The message names the problem and, where there is one, the offending index.
class InputError : public std::invalid_argument {
public:
  using std::invalid_argument::invalid_argument;
};

}  // namespace fairsplines
