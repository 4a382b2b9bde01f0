// Basic shapes of the blending paper (blend_shapes.hpp, g2_to_c2.hpp, g1_to_c1.hpp): the G2
// circle of eq. (2) on any partition, the sphere zone, cylinder, cone and torus as G2
// bicubic splines (with edits through setControl and patches converted to OCCT), the C2
// sextic conversion of Section 4.1 (rho, sigma, mixed; the circle's or any scalars betaT;
// g2ToC2 of the circle's maps) and the G1 to C1 quartics of eq. (12).
#include "fairsplines/g1_to_c1.hpp"
#include "fairsplines/g2_to_c2.hpp"
#include "fuzz_shapes.hpp"

using namespace fairsplines;
using namespace fairsplines::fuzz;

namespace {

void requireFiniteSurface(const char* call, const G2Surface& s) {
  requireFinite(call, "Bézier point", s.bezier);
  requireFinite(call, "u scalar beta", s.betaU);
  requireFinite(call, "u scalar gamma", s.gammaU);
  requireFinite(call, "v scalar beta", s.betaV);
  requireFinite(call, "v scalar gamma", s.gammaV);
  if (s.bezier.rows() != 16 * s.nu * s.nv) fail(call, "not 16 rows per patch");
}

void requireFiniteSextics(const char* call, const C2SexticSpline& c2) {
  requireFinite(call, "sextic Bézier point", c2.bezier);
  requireFinite(call, "sextic scalar", c2.beta);
  Eigen::VectorXd knots;
  if (guarded("C2SexticSpline::knots", [&] { knots = c2.knots(); })) requireFinite(call, "sextic knot", knots);
}

Eigen::VectorXd scalars(FuzzInput& in, const Eigen::VectorXd& natural) {
  switch (in.choice(4)) {
    case 0:
      return in.numbers(natural.size() + (in.byte() == 255 ? 1 : 0));
    case 1: {  // the natural ones, scaled (their product around a turn changes)
      Eigen::VectorXd b = natural;
      if (b.size() > 0) b[in.count(0, 255) % b.size()] *= in.positive();
      return b;
    }
    default:
      return Eigen::VectorXd();  // the default: the circle's own
  }
}

void circles(FuzzInput& in) {
  const Eigen::VectorXd theta = turnAngles(in, 12);
  note("theta", theta);
  G2CircleSpline circle;
  if (!guarded("g2Circle", [&] { circle = g2Circle(theta); })) return;
  const char* call = "g2Circle";
  requireFinite(call, "alpha", circle.alpha);
  requireFinite(call, "w", circle.w);
  requireFinite(call, "beta", circle.beta);
  requireFinite(call, "gamma", circle.gamma);
  requireFinite(call, "cubic Bézier point", circle.cubic);
  const CircleReparam method = reparam(in);
  const Eigen::VectorXd betaT = scalars(in, circle.beta);
  note("method (0 rho, 1 sigma, 2 mixed)", static_cast<int>(method));
  note("betaT", betaT);
  C2SexticSpline c2;
  if (guarded("circleToC2", [&] { c2 = circleToC2(circle, method, betaT); })) requireFiniteSextics("circleToC2", c2);
  if (in.flag()) {
    CircleMaps maps;
    if (!guarded("circleMaps", [&] { maps = circleMaps(circle, method, betaT); })) return;
    for (const auto& arc : maps.maps)
      for (const Reparam& r : arc) requireFinite("circleMaps", "map coefficient", r);
    requireFinite("circleMaps", "piece scalar", maps.betaPieces);
    PointMatrix pieces = circle.cubic;
    if (in.flag() && pieces.rows() > 0) {  // an edited control point (Fig. 4a)
      const Eigen::Index row = in.count(0, 255) % pieces.rows();
      const Eigen::Vector2d move = in.vector2();
      pieces.row(row) += Eigen::RowVector3d(move.x(), move.y(), 0.0) * pieces(row, 2);
      note("edited row", static_cast<int>(row));
      note("edited pieces", pieces);
    }
    C2SexticSpline g;
    if (guarded("g2ToC2", [&] { g = g2ToC2(pieces, maps.maps, maps.betaPieces, circle.closed); })) {
      requireFiniteSextics("g2ToC2", g);
    }
  }
}

void shapes(FuzzInput& in) {
  const ShapeFrame frame = shapeFrame(in);
  note("frame origin", frame.origin);
  note("frame x", frame.x);
  note("frame y", frame.y);
  note("frame z", frame.z);
  if (!guarded("ShapeFrame::check", [&] { frame.check(); })) return;
  const Eigen::VectorXd around = turnAngles(in, 12);
  note("angles around", around);
  G2Surface s;
  const char* call = "";
  switch (in.choice(4)) {
    case 0: {
      call = "sphereZone";
      const double radius = in.positive();
      const Eigen::VectorXd lat = latitudes(in, 5);
      note("radius", radius);
      note("latitudes", lat);
      if (!guarded(call, [&] { s = sphereZone(frame, radius, around, lat); })) return;
      break;
    }
    case 1: {
      call = "cylinder";
      const double radius = in.positive();
      const Eigen::VectorXd heights = profileValues(in, 5);
      note("radius", radius);
      note("heights", heights);
      if (!guarded(call, [&] { s = cylinder(frame, radius, around, heights); })) return;
      break;
    }
    case 2: {
      call = "cone";
      const double radius0 = in.positive(), slope = in.number();
      const Eigen::VectorXd heights = profileValues(in, 5);
      note("radius0", radius0);
      note("slope", slope);
      note("heights", heights);
      if (!guarded(call, [&] { s = cone(frame, radius0, slope, around, heights); })) return;
      break;
    }
    default: {
      call = "torus";
      const double R = in.positive(), r = in.byte() < 192 ? R * in.unit() : in.number();
      const Eigen::VectorXd anglesV = in.byte() < 64 ? turnAngles(in, 6) : profileValues(in, 5);
      note("R", R);
      note("r", r);
      note("angles v", anglesV);
      if (!guarded(call, [&] { s = torus(frame, R, r, around, anglesV); })) return;
      break;
    }
  }
  requireFiniteSurface(call, s);
  const int edits = in.count(0, 2);
  for (int k = 0; k < edits; ++k) {  // documented: InputError for a bad index or weight
    const int I = in.count(-1, 12), J = in.count(-1, 5), r = in.count(-1, 4), c = in.count(-1, 4);
    const Eigen::Vector3d p = in.vector3();
    const double weight = in.byte() < 128 ? 1.0 : in.number();
    note("setControl I, J, r, s", Eigen::Vector4d(I, J, r, c));
    note("setControl point", p);
    note("setControl weight", weight);
    if (guarded("G2Surface::setControl", [&] { s.setControl(I, J, r, c, p, weight); })) {
      requireFiniteSurface("G2Surface::setControl", s);
    }
  }
  if (s.nu > 0 && s.nv > 0) {
    const int I = in.count(0, 255) % s.nu, J = in.count(0, 255) % s.nv;
    Handle(Geom_BSplineSurface) patch;
    if (guarded("patchToOcct(G2Surface)", [&] { patch = patchToOcct(s, I, J); })) {
      requireValid("patchToOcct(G2Surface)", patch);
    }
  }
}

void g1(FuzzInput& in) {
  const Eigen::VectorXd theta = turnAngles(in, 12);
  note("theta", theta);
  PointMatrix quadratics;
  Eigen::VectorXd beta;
  bool closed = false;
  if (!guarded("g1Circle", [&] { g1Circle(theta, quadratics, beta, closed); })) return;
  requireFinite("g1Circle", "quadratic Bézier point", quadratics);
  requireFinite("g1Circle", "beta", beta);
  Eigen::VectorXd betaT = scalars(in, beta);
  if (betaT.size() == 0) betaT = beta;
  if (in.byte() < 32) closed = !closed;
  note("betaT", betaT);
  note("closed", closed);
  C1QuarticSpline c1;
  if (guarded("g1ToC1", [&] { c1 = g1ToC1(quadratics, beta, betaT, closed); })) {
    requireFinite("g1ToC1", "quartic Bézier point", c1.bezier);
    requireFinite("g1ToC1", "quartic scalar", c1.beta);
  }
}

}  // namespace

int fuzzOne(FuzzInput& in) {
  switch (in.choice(3)) {
    case 0:
      circles(in);
      break;
    case 1:
      shapes(in);
      break;
    default:
      g1(in);
      break;
  }
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) { return runOne(data, size, fuzzOne); }
