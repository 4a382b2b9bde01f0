// Benchmark: Algorithm 2 with the fairest solver (analytic centre, Newton) against the
// paper's grid search (step 0.02, first hit), on the same 1000 random admissible end
// conditions; both verify their result with Theorem 1 and the exact certificate.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

#include "fairsplines/monotone.hpp"
#include "bench_timing.hpp"
#include "test_support.hpp"

using namespace fairsplines;
using Clock = std::chrono::steady_clock;

namespace {

struct Run {
  std::vector<double> seconds;     // per condition, best of the repeats
  std::vector<double> solved;      // the same, for the conditions solved
  std::vector<double> variation;   // curvatureVariation of each result (NaN: no result)
  std::vector<double> iterations;  // Newton iterations or grid points tried, when solved
  int successes = 0, boundary = 0;
};

Run run(const std::vector<test::EndCondition>& ends, MonotoneMethod method, int repeats) {
  Run out;
  for (const test::EndCondition& e : ends) {
    double best = 1e300;
    bool ok = false;
    MonotoneSpline result;
    for (int r = 0; r < repeats; ++r) {
      const auto t0 = Clock::now();
      try {
        result = monotoneCurvatureSpline(e.p0, e.t0, e.p1, e.t1, method);
        ok = true;
      } catch (const NoMonotoneSolution&) {
        ok = false;
      }
      best = std::min(best, std::chrono::duration<double>(Clock::now() - t0).count());
    }
    out.seconds.push_back(best);
    out.variation.push_back(ok ? curvatureVariation(result.curve) : std::nan(""));
    out.successes += ok;
    if (ok) {
      out.solved.push_back(best);
      out.iterations.push_back(result.iterations);
      out.boundary += result.boundary;
    }
  }
  return out;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? std::nan("") : v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  const int count = fairsplines::bench::smokeRun(argc, argv) ? 25 : 1000;  // make bench-smoke: 25 conditions
  const std::vector<test::EndCondition> ends = test::randomAdmissibleEnds(count, 20261124);
  std::printf(
      "Algorithm 2 on %d random admissible end conditions (random positions, orientations, mirror\n"
      "images, scales; half in 3D planes), one core, best of 3 runs per condition\n\n",
      count);
  const Run fair = run(ends, MonotoneMethod::Fairest, 3);
  const Run grid = run(ends, MonotoneMethod::PaperGrid, 1);  // milliseconds: one run is enough
  const double tf = median(fair.seconds), tg = median(grid.seconds);
  std::printf("%-27s %12s %14s %9s %16s\n", "method", "median [us]", "median solved", "success", "median iterations");
  std::printf("%-27s %12.2f %14.2f %8.1f%% %16.0f\n", "fairest (analytic centre)", tf * 1e6, median(fair.solved) * 1e6,
              100.0 * fair.successes / count, median(fair.iterations));
  std::printf("%-27s %12.2f %14.2f %8.1f%% %16.0f\n", "paper's grid (step 0.02)", tg * 1e6, median(grid.solved) * 1e6,
              100.0 * grid.successes / count, median(grid.iterations));
  std::printf(
      "\n(median [us]: over all %d conditions; median solved: over the ones the method solved;\n"
      " iterations: Newton steps, or grid points tried)\n",
      count);
  std::printf("\nratio of medians (grid / fairest): %.0fx\n", tg / tf);
  int gridOnly = 0;
  std::vector<double> ratios;
  for (int i = 0; i < count; ++i) {
    const bool f = !std::isnan(fair.variation[i]), g = !std::isnan(grid.variation[i]);
    gridOnly += g && !f;
    if (f && g) ratios.push_back(fair.variation[i] / grid.variation[i]);
  }
  std::printf("conditions the grid solves and the fairest does not: %d\n", gridOnly);
  std::printf("fairest results on the family's boundary (the parabola, no interior): %d\n", fair.boundary);
  std::printf("curvature variation L^3 int (dkappa/ds)^2 ds, fairest / grid, median over both solved: %.3f\n",
              median(ratios));
  return gridOnly == 0 && fair.successes == count ? 0 : 1;
}
