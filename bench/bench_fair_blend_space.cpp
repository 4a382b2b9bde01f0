// Fair blends in space (issue 28): the 1000 G1 and 1000 G2 cases of the tests
// (cpp/tests/space_spirals.hpp: ends cut from space curves of linear curvature and torsion,
// approximated by OCCT), solved by fairBlendSpace: success rate (certified monotone), median
// and p99 time, spans, curvature extrema and torsion sign changes; and, on the same ends, the
// quintic Bézier that matches the end 2-jets (what CurvesWB's blend curve and
// Surface_BlendCurve build), certified the same way. `bench_fair_blend_space smoke`: 25 cases.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <random>
#include <vector>

#include "fairsplines/fair_blend.hpp"
#include "fairsplines/monotone.hpp"
#include "bench_timing.hpp"
#include "space_spirals.hpp"

using namespace fairsplines;
using Eigen::Vector3d;
using fairsplines::bench::Clock;

namespace {

double seconds(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

double quantile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<size_t>(q * static_cast<double>(v.size())))];
}

/// The quintic Bézier with the ends' 2-jets, speed the chord length r at both ends:
/// c'(0) = 5 (P1 - P0) = r t0, c''(0) = 20 (P2 - 2 P1 + P0) = r^2 K0, and the same at the end.
BSplineCurve quinticBezier(const SpaceBlendEnds& e) {
  const double r = (e.p1 - e.p0).norm();
  const Vector3d t0 = e.t0.normalized(), t1 = e.t1.normalized();
  BSplineCurve c;
  c.degree = 5;
  c.poles.resize(6, 3);
  const Vector3d P1 = e.p0 + r / 5.0 * t0, P4 = e.p1 - r / 5.0 * t1;
  c.poles.row(0) = e.p0.transpose();
  c.poles.row(1) = P1.transpose();
  c.poles.row(2) = (2.0 * P1 - e.p0 + r * r / 20.0 * e.K0).transpose();
  c.poles.row(3) = (2.0 * P4 - e.p1 + r * r / 20.0 * e.K1).transpose();
  c.poles.row(4) = P4.transpose();
  c.poles.row(5) = e.p1.transpose();
  c.knots.resize(2);
  c.knots << 0.0, 1.0;
  c.mults.resize(2);
  c.mults << 6, 6;
  return c;
}

struct Stats {
  int monotone = 0, cases = 0, withTorsionFlip = 0;
  long extrema = 0, torsionChanges = 0;
  std::vector<double> perCase;  // curvature extrema of each case
  void add(const SpaceCurvatureCertificate& c) {
    ++cases;
    perCase.push_back(static_cast<double>(c.extrema.size()));
    monotone += c.monotone;
    extrema += static_cast<long>(c.extrema.size());
    torsionChanges += static_cast<long>(c.torsionSignChanges.size());
    withTorsionFlip += !c.torsionSignChanges.empty();
  }
};

void row(const char* name, const Stats& s, const char* time) {
  std::printf("| %-32s | %5.1f%% | %6.2f / %g | %6.2f | %5.1f%% | %s |\n", name, 100.0 * s.monotone / s.cases,
              static_cast<double>(s.extrema) / s.cases, quantile(s.perCase, 0.5),
              static_cast<double>(s.torsionChanges) / s.cases, 100.0 * s.withTorsionFlip / s.cases, time);
}

}  // namespace

int main(int argc, char** argv) {
  const int count = fairsplines::bench::smokeRun(argc, argv) ? 25 : 1000;
  std::printf("Fair blends in space: %d G1 + %d G2 cases (ends of space curves with linear curvature and torsion)\n\n",
              count, count);
  std::printf(
      "| %-32s | monotone | curvature extrema: mean / median | torsion flips/case | cases with a flip | time |\n",
      "blend");
  std::printf("|---|---|---|---|---|---|\n");
  for (const bool g2 : {false, true}) {
    std::mt19937 rng(g2 ? 2802 : 2801);  // the tests' cases
    Stats ours, quintic;
    std::vector<double> times;
    std::vector<double> spans;
    int failed = 0;
    for (int i = 0; i < count; ++i) {
      const test::SpaceCase sc = test::randomSpaceCase(rng);
      SpaceBlendEnds e = sc.ends;
      if (!g2) e.K0 = e.K1 = Vector3d::Constant(std::nan(""));
      double best = 1e300;
      SpaceFairBlend b;
      try {
        for (int r = 0; r < 3; ++r) {
          const auto t0 = Clock::now();
          b = fairBlendSpace(e);
          best = std::min(best, seconds(t0));
        }
      } catch (const InputError&) {
        ++failed;
        continue;
      }
      times.push_back(best);
      spans.push_back(b.spans);
      ours.add(b.certificate);
      quintic.add(certifySpaceCurvature(quinticBezier(sc.ends)));
    }
    char time[160];
    std::snprintf(time, sizeof time, "median %.2f ms, p99 %.2f ms, median %g spans%s", 1e3 * quantile(times, 0.5),
                  1e3 * quantile(times, 0.99), quantile(spans, 0.5), failed ? " (some refused)" : "");
    row(g2 ? "fairBlendSpace, G2" : "fairBlendSpace, G1", ours, time);
    row(g2 ? "quintic Bézier of the 2-jets, G2" : "quintic Bézier of the 2-jets (G2 data)", quintic, "-");
  }
  return 0;
}
