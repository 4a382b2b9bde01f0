// Benchmark (issue 5): time to build the blend complex of a sphere zone with 8 x 4 patches
// plus its default free-form ring (kernel only), per reparameterization, and its shell. The GeomPlate G2
// comparison of the issue is not in yet (see docs/BLENDING.md).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#include "fairsplines/blend_c1.hpp"
#include "fairsplines/blend_surface.hpp"
#include "bench_timing.hpp"

using namespace fairsplines;
using fairsplines::bench::medianSeconds;

int main(int argc, char** argv) {
  const int repeats = fairsplines::bench::smokeRun(argc, argv) ? 3 : 200;  // make bench-smoke: 3
  const double pi = std::acos(-1.0);
  const Eigen::VectorXd uniform = Eigen::VectorXd::LinSpaced(9, 0.0, 2 * pi);
  Eigen::VectorXd nonUniform(9);
  nonUniform << 0.0, 0.5, 1.0, 1.5, 2.0, 2.9, 3.3, 4.6, 2 * pi;
  Eigen::VectorXd latitudes(5);
  latitudes << -0.8, -0.3, 0.1, 0.5, 0.9;
  std::printf("sphere zone 8 x 4 + default ring, kernel (median of %d), target <= 1 ms\n", repeats);
  struct Case {
    const char* name;
    const Eigen::VectorXd* lon;
    CircleReparam method;
  };
  const Case cases[] = {{"uniform, rho", &uniform, CircleReparam::Rho},
                        {"non-uniform, rho", &nonUniform, CircleReparam::Rho},
                        {"non-uniform, sigma", &nonUniform, CircleReparam::Sigma},
                        {"non-uniform, mixed", &nonUniform, CircleReparam::Mixed}};
  for (const Case& c : cases) {
    std::size_t patches = 0;
    const double s = medianSeconds(
        [&] { patches = blendSphereZone(ShapeFrame{}, 1.0, *c.lon, latitudes, c.method).patches.size(); }, repeats);
    std::printf("  %-20s %8.3f ms  (%zu patches)\n", c.name, 1e3 * s, patches);
  }
  const double naive = medianSeconds([&] { blendSphereZoneNaive(ShapeFrame{}, 1.0, nonUniform, latitudes); }, repeats);
  std::printf("  %-20s %8.3f ms  (naive baseline, Fig. 2a)\n", "non-uniform, naive", 1e3 * naive);
  // Section 5: the G1 biquadratic zone, eq. (12) around the axis, (4,2) double strip to a
  // biquadratic ring; "(4,4)" converts the latitudes too (the single C1 surface exists).
  for (const bool quarticInV : {false, true}) {
    C1BlendOptions options;
    options.quarticInV = quarticInV;
    std::size_t patches = 0;
    const double c1 = medianSeconds(
        [&] {
          patches = blendC1(g1SphereZone(ShapeFrame{}, 1.0, nonUniform, latitudes), nullptr, options).patches.size();
        },
        repeats);
    std::printf("  %-20s %8.3f ms  (%zu patches, C1 Section 5, basic %s)\n", "non-uniform, C1", 1e3 * c1, patches,
                quarticInV ? "(4,4)" : "(4,2)");
  }
  // The shell from the grid (blendShell: shared edges, no sewing) and the single C2 surface,
  // what fw.blend_basic_shape hands over, for the 8 x 4 zone of bench/bench_blend.py
  // (uniform longitudes, sexticInV as the macro API), and for the steep cone of issue 13.
  const BlendComplex zone = blendSphereZone(ShapeFrame{}, 10.0, uniform, latitudes, CircleReparam::Rho, nullptr, true);
  const double shell = medianSeconds([&] { blendShell(zone); }, repeats);
  const double single = medianSeconds([&] { singleSurface(zone); }, repeats);
  std::printf("  %-20s %8.3f ms  (blendShell, %zu faces)\n", "uniform, shell", 1e3 * shell, zone.patches.size());
  std::printf("  %-20s %8.3f ms  (singleSurface)\n", "uniform, surface", 1e3 * single);
  Eigen::VectorXd thirds(4), heights(3);
  thirds << 0.0, 2 * pi / 3, 4 * pi / 3, 2 * pi;
  heights << 0.0, 1.0, 2.0;
  const double steep = medianSeconds(
      [&] { blendShell(blendCone(ShapeFrame{}, 1.0, 1e12, thirds, heights, CircleReparam::Rho, nullptr, true)); },
      std::min(repeats, 50));
  std::printf("  %-20s %8.3f ms  (cone slope 1e12, complex and shell; sewing took 10-16 s)\n", "steep cone",
              1e3 * steep);
  return 0;
}
