// Benchmark: the fair fit against the csr-spline and OCCT's GeomAPI_PointsToBSpline (what
// FreeCAD's approximate calls), plain and with its smoothing weights, on the same noisy
// samples in the same run, one core.
//
// Data: a half circle joined C1 to a flat parabola (convex: 0 curvature sign changes in
// truth), uniform noise of 1e-4 of its size; tolerance 1e-3 of its size for every method.
// Columns per method: poles; the largest deviation (GeomAPI_ProjectPointOnCurve from at most
// 20000 samples evenly spread over all, the same samples for every method; for the
// csr-spline onto the spans around each sample's own knot); curvature sign
// changes and curvature extrema (the kernel's OCCT-evaluated profile, 8 samples per span,
// zero band 1e-6 of the largest curvature); time (best of several runs; one run from 1e5 on).
// Each OCCT fit runs in a child process, stopped after 60 s of wall time ("skipped (> 60 s)").
#include <GeomAPI_PointsToBSpline.hxx>
#include <GeomAPI_ProjectPointOnCurve.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Standard_Failure.hxx>
#include <Standard_Type.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "fairsplines/analysis.hpp"
#include "fairsplines/csr.hpp"
#include "fairsplines/errors.hpp"
#include "fairsplines/fair_fit.hpp"
#include "fairsplines/occt.hpp"
#include "bench_timing.hpp"

using namespace fairsplines;
using fairsplines::bench::bestSeconds;

namespace {

PointMatrix samples(int n, double noise, unsigned seed) {
  PointMatrix q(n, 3);
  const int m1 = n / 2;
  for (int i = 0; i < m1; ++i) {
    const double th = M_PI + M_PI * i / m1;
    q.row(i) << std::cos(th), std::sin(th), 0.0;
  }
  for (int i = m1; i < n; ++i) {
    const double y = 1.5 * (i - m1) / double(n - m1 - 1);
    q.row(i) << 1.0 - 0.1 * y * y, y, 0.0;
  }
  const double size = (q.colwise().maxCoeff() - q.colwise().minCoeff()).norm();
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-noise * size, noise * size);
  for (int i = 0; i < n; ++i) q(i, 0) += u(rng), q(i, 1) += u(rng);
  return q;
}

struct Row {
  int poles = 0;
  double deviation = 0, seconds = 0;
  int signChanges = 0, extrema = 0;
  std::string note;
};

/// `knotPerSample`: the curve's knot i belongs to sample i (the csr-spline), so each sample
/// is projected onto the spans around its own knot (a projection onto the whole of a curve of
/// 10^6 spans costs 10^6 span tests); otherwise onto the whole curve.
Row measure(const Handle(Geom_BSplineCurve)& c, const PointMatrix& q, double seconds, bool knotPerSample = false) {
  Row r;
  r.seconds = seconds;
  r.poles = c->NbPoles();
  const int stride = std::max(1, static_cast<int>(q.rows() / 20000));
  for (int i = 0; i < q.rows(); i += stride) {
    const gp_Pnt p(q(i, 0), q(i, 1), q(i, 2));
    GeomAPI_ProjectPointOnCurve proj;
    if (knotPerSample) {
      const int k = i + 1;  // OCCT numbers knots from 1
      proj.Init(p, c, c->Knot(std::max(1, k - 2)), c->Knot(std::min(c->NbKnots(), k + 2)));
    } else {
      proj.Init(p, c);
    }
    double d = std::min(p.Distance(c->StartPoint()), p.Distance(c->EndPoint()));
    if (proj.NbPoints() > 0) d = std::min(d, proj.LowerDistance());
    if (knotPerSample) d = std::min(d, p.Distance(c->Value(c->Knot(std::min(c->NbKnots(), i + 1)))));
    r.deviation = std::max(r.deviation, d);
  }
  const CurvatureProfile profile = curvatureProfile(c, 0, 8);
  r.signChanges = curvatureSignChanges(profile);
  r.extrema = static_cast<int>(curvatureExtrema(profile).size());
  return r;
}

void print(const char* method, const Row& r) {
  if (!r.note.empty()) {
    std::printf("  %-26s %s\n", method, r.note.c_str());
    return;
  }
  std::printf("  %-26s %8d %12.3g %8d %8d %12.2f\n", method, r.poles, r.deviation, r.signChanges, r.extrema,
              1e3 * r.seconds);
}

/// An OCCT approximation, run in a child process that is stopped after 60 s ("skipped (> 60 s)"):
/// the child measures and sends back its Row.
Row occt(const std::function<Handle(Geom_BSplineCurve)()>& fit, const PointMatrix& q, int repeats) {
  Row r;
  int fds[2];
  if (pipe(fds) != 0) {
    r.note = "failed: no pipe";
    return r;
  }
  const pid_t child = fork();
  if (child == 0) {
    close(fds[0]);
    Row c;
    char why[160] = "";
    try {
      Handle(Geom_BSplineCurve) curve;
      const double t = bestSeconds([&] { curve = fit(); }, repeats);
      c = measure(curve, q, t);
    } catch (const Standard_Failure& e) {
      c.poles = -1;
      std::snprintf(why, sizeof why, "%s: %s", e.DynamicType()->Name(), e.GetMessageString());
    }
    const double out[5] = {double(c.poles), c.deviation, c.seconds, double(c.signChanges), double(c.extrema)};
    if (write(fds[1], out, sizeof out) != static_cast<ssize_t>(sizeof out)) _exit(1);
    if (write(fds[1], why, sizeof why) != static_cast<ssize_t>(sizeof why)) _exit(1);
    _exit(0);
  }
  close(fds[1]);
  const auto t0 = fairsplines::bench::Clock::now();
  int status = 0;
  bool done = false;
  while (!done) {
    done = waitpid(child, &status, WNOHANG) == child;
    if (done) break;
    if (std::chrono::duration<double>(fairsplines::bench::Clock::now() - t0).count() > 60.0) {
      kill(child, SIGKILL);
      waitpid(child, &status, 0);
      close(fds[0]);
      r.note = "skipped (> 60 s)";
      return r;
    }
    usleep(20000);
  }
  double in[5];
  char why[160] = "";
  const bool ok = read(fds[0], in, sizeof in) == static_cast<ssize_t>(sizeof in) &&
                  read(fds[0], why, sizeof why) == static_cast<ssize_t>(sizeof why);
  close(fds[0]);
  why[sizeof why - 1] = '\0';
  if (!ok) {
    r.note = WIFSIGNALED(status) ? "failed: the child died (signal " + std::to_string(WTERMSIG(status)) + ")"
                                 : "failed: no result from the child";
    return r;
  }
  if (in[0] < 0) {
    r.note = std::string("failed: OCCT raised ") + why;
    return r;
  }
  r.poles = int(in[0]), r.deviation = in[1], r.seconds = in[2], r.signChanges = int(in[3]), r.extrema = int(in[4]);
  return r;
}

/// A NACA 4-digit airfoil of chord 1 (cosine spacing, n points a side), as a Selig file lists
/// it: trailing edge, upper side, nose, lower side, trailing edge (2 n - 1 points); blunt
/// trailing edge (the formula's -0.1015).
PointMatrix naca4(double m, double p, double t, int n) {
  PointMatrix q(2 * n - 1, 3);
  auto side = [&](double x, double sign) {
    const double yt =
        5 * t * (0.2969 * std::sqrt(x) - 0.1260 * x - 0.3516 * x * x + 0.2843 * x * x * x - 0.1015 * x * x * x * x);
    double yc = 0, dyc = 0;
    if (m > 0) {
      yc = x < p ? m / (p * p) * (2 * p * x - x * x) : m / ((1 - p) * (1 - p)) * ((1 - 2 * p) + 2 * p * x - x * x);
      dyc = x < p ? 2 * m / (p * p) * (p - x) : 2 * m / ((1 - p) * (1 - p)) * (p - x);
    }
    const double th = std::atan(dyc);
    return Eigen::RowVector3d(x - sign * yt * std::sin(th), yc + sign * yt * std::cos(th), 0.0);
  };
  for (int i = 0; i < n; ++i) {
    const double x = 0.5 * (1 - std::cos(M_PI * i / (n - 1)));
    q.row(n - 1 - i) = side(x, 1.0);
    if (i > 0) q.row(n - 1 + i) = side(x, -1.0);
  }
  return q;
}

/// A road of lines, clothoids and arcs with two hairpins (170 deg on radii 8 and 9 m) and a
/// reverse curve, sampled every 10 m, Gaussian noise 5 cm per coordinate (as the tests'
/// hairpin_road).
PointMatrix hairpinRoad(unsigned seed) {
  struct Piece {
    double length, k0, k1;
  };
  const double r1 = 8, r2 = 9, sweep = 170 * M_PI / 180, L = 30;
  const std::vector<Piece> plan = {{120, 0, 0},
                                   {8, 0, 1 / r1},
                                   {sweep * r1 - 8, 1 / r1, 1 / r1},
                                   {8, 1 / r1, 0},
                                   {150, 0, 0},
                                   {L, 0, -1.0 / 100},
                                   {60, -0.01, -0.01},
                                   {L, -0.01, 0},
                                   {40, 0, 0},
                                   {L, 0, 1.0 / 120},
                                   {50, 1.0 / 120, 1.0 / 120},
                                   {L, 1.0 / 120, 0},
                                   {130, 0, 0},
                                   {8, 0, -1 / r2},
                                   {sweep * r2 - 8, -1 / r2, -1 / r2},
                                   {8, -1 / r2, 0},
                                   {120, 0, 0}};
  std::vector<Eigen::Vector2d> pts{{0, 0}};
  Eigen::Vector2d pos(0, 0);
  double heading = 0, s = 0, next = 10;
  const double ds = 0.01;
  for (const Piece& pc : plan) {
    const int steps = static_cast<int>(std::round(pc.length / ds));
    for (int i = 0; i < steps; ++i) {
      const double k = pc.k0 + (pc.k1 - pc.k0) * (i + 0.5) / steps, h = pc.length / steps;
      heading += 0.5 * k * h;
      pos += h * Eigen::Vector2d(std::cos(heading), std::sin(heading));
      heading += 0.5 * k * h;
      s += h;
      if (s >= next) pts.push_back(pos), next += 10;
    }
  }
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, 0.05);
  PointMatrix q(static_cast<Eigen::Index>(pts.size()), 3);
  for (std::size_t i = 0; i < pts.size(); ++i) q.row(i) << pts[i].x() + noise(rng), pts[i].y() + noise(rng), 0.0;
  return q;
}

/// The fair fit and OCCT's approximation (Part's approximate: PointsToBSpline, degree 3..8,
/// C2) of the same data at the same tolerance.
void realDataRow(const char* name, const PointMatrix& q, double tol) {
  FairFitOptions o;
  o.tolerance = tol;
  BSplineCurve fair;
  std::string refused;
  double t = 0;
  try {
    t = bestSeconds([&] { fair = fairFit(q, o); }, 20);
  } catch (const InputError& e) {
    refused = e.what();
  }
  std::printf("%s, tolerance %.3g\n", name, tol);
  if (refused.empty()) {
    print("fair fit", measure(toOcct(fair), q, t));
  } else {
    std::printf("  %-26s refused: %.90s\n", "fair fit", refused.c_str());
  }
  TColgp_Array1OfPnt pts(1, static_cast<int>(q.rows()));
  for (int i = 0; i < q.rows(); ++i) pts.SetValue(i + 1, gp_Pnt(q(i, 0), q(i, 1), q(i, 2)));
  print("OCCT PointsToBSpline",
        occt([&] { return GeomAPI_PointsToBSpline(pts, 3, 8, GeomAbs_C2, tol).Curve(); }, q, 3));
}

/// The rate of exact sign changes (the plan's 3) over `seeds` seeds of the hairpin road, fair fit
/// and OCCT's approximation at the same tolerance (the kernel's OCCT-evaluated profile).
void roadRate(double tol, int seeds) {
  int fair = 0, occ = 0;
  double worstFair = 0.0, fairSeconds = 0.0;
  for (int seed = 0; seed < seeds; ++seed) {
    const PointMatrix q = hairpinRoad(static_cast<unsigned>(seed));
    FairFitOptions o;
    o.tolerance = tol;
    BSplineCurve c;
    const double t = bestSeconds([&] { c = fairFit(q, o); }, 1);
    const Row r = measure(toOcct(c), q, t);
    fair += r.signChanges == 3, worstFair = std::max(worstFair, r.deviation), fairSeconds += t;
    TColgp_Array1OfPnt pts(1, static_cast<int>(q.rows()));
    for (int i = 0; i < q.rows(); ++i) pts.SetValue(i + 1, gp_Pnt(q(i, 0), q(i, 1), q(i, 2)));
    const Row ro = occt([&] { return GeomAPI_PointsToBSpline(pts, 3, 8, GeomAbs_C2, tol).Curve(); }, q, 1);
    occ += ro.note.empty() && ro.signChanges == 3;
  }
  std::printf(
      "hairpin roads, %d seeds, tolerance %.3g: exactly the road's 3 sign changes: fair fit %d/%d (%.0f %%, "
      "largest deviation %.3g, mean time %.1f ms), OCCT PointsToBSpline %d/%d\n",
      seeds, tol, fair, seeds, 100.0 * fair / seeds, worstFair, 1e3 * fairSeconds / seeds, occ, seeds);
}

}  // namespace

int main(int argc, char** argv) {
  // Optional: the largest N to run (default 10^6), e.g. `bench_fair_fit 10000` for a quick look;
  // `bench_fair_fit N tight`: only the tight-tolerance table; `bench_fair_fit 0 real`: only
  // the airfoil and road table; `bench_fair_fit N fit`: the fair fit's time alone.
  const long maxN = argc > 1 ? std::atol(argv[1]) : 1000000;
  std::setvbuf(stdout, nullptr, _IOLBF, 0);  // line by line, also into a file
  const bool realOnly = argc > 2 && std::string(argv[2]) == "real";
  if (argc > 2 && std::string(argv[2]) == "fit") {  // the fair fit's time alone, 10^3 .. N samples
    std::printf("fair fit alone (best of 3), the convex data below\n  %8s %10s %10s %8s %8s\n", "N", "time [ms]",
                "no step 10", "poles", "extrema");
    for (int n : {1000, 10000, 100000, 1000000}) {
      if (n > maxN) break;
      const PointMatrix q = samples(n, 1e-4, 7);
      FairFitOptions o;
      o.tolerance = 1e-3 * (q.colwise().maxCoeff() - q.colwise().minCoeff()).norm();
      FairFitOptions plain = o;
      plain.fairing = false;
      FairFitResult r;
      const double t = bestSeconds([&] { r = fairFitReport(q, o); }, 3);
      const double t0 = bestSeconds([&] { fairFitReport(q, plain); }, 3);
      std::printf("  %8d %10.1f %10.1f %8ld %8d\n", n, 1e3 * t, 1e3 * t0, static_cast<long>(r.curve.poles.rows()),
                  r.curvatureExtrema);
    }
    return 0;
  }
  if (argc <= 2 || realOnly) {
    std::printf("real data: NACA airfoils (Selig order, blunt trailing edge) and hairpin roads (10 m, 5 cm noise)\n");
    std::printf("  %-26s %8s %12s %8s %8s %12s\n", "method", "poles", "max dev", "sign ch", "extrema", "time [ms]");
    for (double tol : {1e-3, 5e-4, 2e-4}) {
      realDataRow("NACA 0012, 61 points", naca4(0, 0, 0.12, 31), tol);
      realDataRow("NACA 0006, 61 points", naca4(0, 0, 0.06, 31), tol);
      realDataRow("NACA 6409, 61 points", naca4(0.06, 0.4, 0.09, 31), tol);
      realDataRow("NACA 2412, 399 points", naca4(0.02, 0.4, 0.12, 200), tol);
    }
    for (unsigned seed : {1u, 2u, 3u}) realDataRow("hairpin road", hairpinRoad(seed), 0.25);
    roadRate(0.25, maxN >= 100000 || realOnly ? 40 : 4);  // 4 seeds in `make bench-smoke` (bench_fair_fit 1000)
    if (realOnly) return 0;
    std::printf("\n");
  }
  std::printf("fair fit vs csr-spline vs GeomAPI_PointsToBSpline (degree 3..8, C2, Tol3D = tolerance), same data\n");
  std::printf("half circle + flat parabola (convex), uniform noise 1e-4 of the size, tolerance 1e-3 of the size\n");
  for (int n : {1000, 10000, 100000, 1000000}) {
    if (n > maxN || argc > 2) break;
    const PointMatrix q = samples(n, 1e-4, 7);
    const double size = (q.colwise().maxCoeff() - q.colwise().minCoeff()).norm();
    const double tol = 1e-3 * size;
    const int repeats = n >= 100000 ? 3 : 10, occtRepeats = n >= 10000 ? 1 : 3;
    std::printf("N = %d (tolerance %.3g)\n", n, tol);
    std::printf("  %-26s %8s %12s %8s %8s %12s\n", "method", "poles", "max dev", "sign ch", "extrema", "time [ms]");

    FairFitOptions o;
    o.tolerance = tol;
    BSplineCurve fair;
    const double tFair = bestSeconds([&] { fair = fairFit(q, o); }, repeats);
    const Row rf = measure(toOcct(fair), q, tFair);
    print("fair fit", rf);
    FairFitOptions plain = o;  // the csr-spline of the chosen subset, without step 10
    plain.fairing = false;
    BSplineCurve unpolished;
    const double tPlain = bestSeconds([&] { unpolished = fairFit(q, plain); }, repeats);
    print("  without thinning/fairing", measure(toOcct(unpolished), q, tPlain));

    BSplineCurve csr;
    const double tCsr = bestSeconds([&] { csr = csrSpline(q); }, repeats);
    if (n <= 100000) {
      print("csr-spline (eq. (6))", measure(toOcct(csr), q, tCsr, true));
    } else {  // OCCT locates a span's first pole by summing the multiplicities before it
      std::printf(
          "  %-26s %8ld %12s %8s %8s %12.2f  (not measured: OCCT evaluates a curve of %ld knots in\n"
          "  %-26s O(knots) per point)\n",
          "csr-spline (eq. (6))", static_cast<long>(csr.poles.rows()), "-", "-", "-", 1e3 * tCsr,
          static_cast<long>(csr.knots.size()), "");
    }

    TColgp_Array1OfPnt pts(1, n);
    for (int i = 0; i < n; ++i) pts.SetValue(i + 1, gp_Pnt(q(i, 0), q(i, 1), q(i, 2)));
    const Row ro = occt([&] { return GeomAPI_PointsToBSpline(pts, 3, 8, GeomAbs_C2, tol).Curve(); }, q, occtRepeats);
    print("OCCT PointsToBSpline", ro);
    const Row rs = occt([&] { return GeomAPI_PointsToBSpline(pts, 1e-3, 1e-3, 1e-3, 8, GeomAbs_C2, tol).Curve(); }, q,
                        occtRepeats);
    print("OCCT smoothing (1e-3 x3)", rs);
    std::printf("  time ratios: fair fit / csr-spline %.1f", tFair / tCsr);
    if (ro.note.empty()) std::printf(", OCCT / fair fit %.1f", ro.seconds / tFair);
    if (rs.note.empty()) std::printf(", OCCT smoothing / fair fit %.1f", rs.seconds / tFair);
    std::printf("\n");
  }

  // Tight tolerances on clean data: thousands of spans (the fit's own span polynomials keep
  // every pass O(spans + samples); OCCT's evaluation would cost O(knots) per point).
  std::printf(
      "\nnoise-free: half ellipse 2 x 1 with a sine ripple of 0.3, tolerance 1e-9 of the size; fair fit only\n");
  std::printf("  %8s %8s %24s %8s %12s %12s\n", "N", "poles", "without thinning/fairing", "extrema", "time [ms]",
              "without [ms]");
  for (int n : {8000, 32000, 128000, 1000000}) {
    if (n > maxN) break;
    PointMatrix q(n, 3);
    for (int i = 0; i < n; ++i) {
      const double t = M_PI * i / (n - 1);
      q.row(i) << 2 * std::cos(t) + 0.3 * std::sin(7 * t), std::sin(t), 0.0;
    }
    FairFitOptions o;
    o.tolerance = 1e-9 * (q.colwise().maxCoeff() - q.colwise().minCoeff()).norm();
    FairFitOptions plain = o;
    plain.fairing = false;
    FairFitResult r, r0;
    const int repeats = n >= 1000000 ? 1 : 3;
    const double t = bestSeconds([&] { r = fairFitReport(q, o); }, repeats);
    const double t0 = bestSeconds([&] { r0 = fairFitReport(q, plain); }, repeats);
    std::printf("  %8d %8ld %24ld %8d %12.1f %12.1f\n", n, static_cast<long>(r.curve.poles.rows()),
                static_cast<long>(r0.curve.poles.rows()), r.curvatureExtrema, 1e3 * t, 1e3 * t0);
  }
  return 0;
}
