// Timing helpers shared by the C++ benchmarks: wall time of a callable over repeats.
#pragma once
#include <algorithm>
#include <chrono>
#include <cstring>
#include <vector>

namespace fairsplines::bench {

/// `make bench-smoke` runs every benchmark with the argument "smoke": its smallest size with
/// few repeats, only to show that it still runs to its end (the figures mean nothing then).
inline bool smokeRun(int argc, char** argv) { return argc > 1 && std::strcmp(argv[1], "smoke") == 0; }

using Clock = std::chrono::steady_clock;

/// Seconds of each of `repeats` calls of f.
template <class F>
std::vector<double> timings(F&& f, int repeats) {
  std::vector<double> t;
  for (int r = 0; r < repeats; ++r) {
    const auto t0 = Clock::now();
    f();
    t.push_back(std::chrono::duration<double>(Clock::now() - t0).count());
  }
  return t;
}

/// The median of `repeats` calls (robust to a noisy machine).
template <class F>
double medianSeconds(F&& f, int repeats) {
  std::vector<double> t = timings(f, repeats);
  std::nth_element(t.begin(), t.begin() + repeats / 2, t.end());
  return t[repeats / 2];
}

/// The fastest of `repeats` calls.
template <class F>
double bestSeconds(F&& f, int repeats) {
  const std::vector<double> t = timings(f, repeats);
  return *std::min_element(t.begin(), t.end());
}

}  // namespace fairsplines::bench
