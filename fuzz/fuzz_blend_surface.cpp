// Blends of basic shapes (blend_surface.hpp, blend_c1.hpp): a sphere zone, cone (cylinder)
// or torus zone joined to its default free-form ring by the (6,5) strip of Section 4.2
// (rho, sigma or mixed circles; sextic in v or not; at the profile's end or start; the
// naive Fig. 2a baseline), shape to shape (joinShapes), an edited control structure
// (blendEdited), and the C1 constructions of Section 5 (blendC1, joinShapesC1); then the
// complex as one surface, a patch in OCCT and now and then the shell (blendShell, no sewing).
#include <TopoDS_Shell.hxx>

#include "fairsplines/blend_c1.hpp"
#include "fuzz_shapes.hpp"

using namespace fairsplines;
using namespace fairsplines::fuzz;

namespace {

G2Surface g2SurfaceOf(const ShapeOfRevolution& s) {
  switch (s.kind) {
    case ShapeOfRevolution::Kind::SphereZone:
      return sphereZone(s.frame, s.size0, s.around, s.profile);
    case ShapeOfRevolution::Kind::Cone:
      return cone(s.frame, s.size0, s.size1, s.around, s.profile);
    case ShapeOfRevolution::Kind::Torus:
      break;
  }
  return torus(s.frame, s.size0, s.size1, s.around, s.profile);
}

}  // namespace

int fuzzOne(FuzzInput& in) {
  const int which = in.choice(9);
  const ShapeOfRevolution a = shapeOfRevolution(in, 10);
  noteShape("shape", a);
  if (!guarded("ShapeFrame::check", [&] { a.frame.check(); })) return 0;
  const CircleReparam method = reparam(in);
  const bool both = in.flag(), naive = in.byte() < 48;
  const Interface at = in.byte() < 64 ? Interface::Start : Interface::End;
  note("which", which);
  note("method (0 rho, 1 sigma, 2 mixed)", static_cast<int>(method));
  note("sexticInV / quarticInV", both);
  note("naive / withoutEta", naive);
  note("interface (0 end, 1 start)", static_cast<int>(at));

  BlendComplex complex;
  const char* call = "";
  bool built = false;
  switch (which) {
    case 0:
    case 1: {  // the shape's own blend
      switch (a.kind) {
        case ShapeOfRevolution::Kind::SphereZone:
          call = naive ? "blendSphereZoneNaive" : "blendSphereZone";
          built = guarded(call, [&] {
            complex = naive ? blendSphereZoneNaive(a.frame, a.size0, a.around, a.profile, nullptr, at)
                            : blendSphereZone(a.frame, a.size0, a.around, a.profile, method, nullptr, both, at);
          });
          break;
        case ShapeOfRevolution::Kind::Cone:
          call = "blendCone";
          built = guarded(call, [&] {
            complex = blendCone(a.frame, a.size0, a.size1, a.around, a.profile, method, nullptr, both, naive, at);
          });
          break;
        case ShapeOfRevolution::Kind::Torus:
          call = "blendTorus";
          built = guarded(call, [&] {
            complex = blendTorus(a.frame, a.size0, a.size1, a.around, a.profile, method, nullptr, both, naive, at);
          });
          break;
      }
      break;
    }
    case 2:
    case 3: {  // shape to shape, mostly with the same angles around
      const ShapeOfRevolution b = shapeOfRevolution(in, 10, &a.around);
      noteShape("second shape", b);
      call = "joinShapes";
      built = guarded(call, [&] { complex = joinShapes(a, b, method, both, naive); });
      break;
    }
    case 4: {  // an edited control structure
      G2Surface edited;
      if (!guarded("the shape's G2Surface", [&] { edited = g2SurfaceOf(a); })) return 0;
      const int edits = in.count(0, 3);
      for (int k = 0; k < edits && edited.nu > 0 && edited.nv > 0; ++k) {
        const int I = in.count(0, 255) % edited.nu, J = in.count(0, 255) % edited.nv;
        const int r = in.count(0, 3), s = in.count(0, 3);
        const Eigen::Vector3d p =
            Eigen::Vector3d(edited.point(I, J, r, s).head<3>().transpose()) / edited.point(I, J, r, s)[3] +
            in.vector3() * 0.1;
        const double weight = in.byte() < 128 ? edited.point(I, J, r, s)[3] : in.positive();
        note("edit I, J, r, s", Eigen::Vector4d(I, J, r, s));
        note("edit point", p);
        note("edit weight", weight);
        guarded("G2Surface::setControl", [&] { edited.setControl(I, J, r, s, p, weight); });
      }
      call = "blendEdited";
      built = guarded(call, [&] { complex = blendEdited(a, edited, method); });
      break;
    }
    case 5:
    case 6: {  // Section 5: the shape as a G1 biquadratic spline to a C1 ring
      G1RevolvedShape g1;
      if (!guarded("g1Shape", [&] { g1 = g1Shape(a); })) return 0;
      if (at == Interface::Start && !guarded("reversedProfile", [&] { g1 = reversedProfile(g1); })) return 0;
      C1BlendOptions options;
      options.quarticInV = both;
      options.withoutEta = naive;
      if (in.byte() < 64) {
        options.betaT = in.numbers(g1.beta.size());
        if (in.flag()) options.betaT = g1.beta.cwiseAbs().cwiseMax(1e-3).cwiseMin(1e3);
      }
      note("betaT", options.betaT);
      call = "blendC1";
      built = guarded(call, [&] { complex = blendC1(g1, nullptr, options); });
      break;
    }
    case 7: {  // Section 5, shape to shape
      const ShapeOfRevolution b = shapeOfRevolution(in, 10, &a.around);
      noteShape("second shape", b);
      G1RevolvedShape ga, gb;
      if (!guarded("g1Shape", [&] { ga = g1Shape(a), gb = g1Shape(b); })) return 0;
      call = "joinShapesC1";
      built = guarded(call, [&] { complex = joinShapesC1(ga, gb, both); });
      break;
    }
    default: {  // the ring knots alone
      Eigen::VectorXd knots;
      if (guarded("ringKnots", [&] { knots = ringKnots(a.around, method); })) requireFinite("ringKnots", "knot", knots);
      if (guarded("ringKnotsC1", [&] { knots = ringKnotsC1(a.around); })) requireFinite("ringKnotsC1", "knot", knots);
      return 0;
    }
  }
  if (!built) return 0;
  requireFiniteComplex(call, complex);

  if (!complex.patches.empty()) {
    const TaggedPatch& patch = complex.patches[in.count(0, 255) % complex.patches.size()];
    Handle(Geom_BSplineSurface) occt;
    if (guarded("patchToOcct(TaggedPatch)", [&] { occt = patchToOcct(patch); })) requireValid("patchToOcct", occt);
  }
  if (in.byte() < 64) {
    Handle(Geom_BSplineSurface) single;
    if (guarded("singleSurface", [&] { single = singleSurface(complex, 1e-9, complex.smoothness); })) {
      requireValid("singleSurface", single);
    }
  }
  if (in.byte() < 8 && complex.patches.size() <= 64) {
    BlendShell shell;  // the product's route: the shell built from the patches, no sewing
    if (guarded("blendShell", [&] { shell = blendShell(complex); }) && shell.shell.IsNull()) {
      fail("blendShell", "a null shape");
    }
  }
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) { return runOne(data, size, fuzzOne); }
