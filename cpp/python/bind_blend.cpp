// Bindings for basic shapes blended into NURBS (blending paper): G2 circles and shapes,
// the C2 sextic conversion, and the sphere-zone blend with its naive baseline.
#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRep_Builder.hxx>
#include <Precision.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Shape.hxx>
#include <cstdint>

#include "fairsplines/blend_shapes.hpp"
#include "fairsplines/blend_surface.hpp"
#include "fairsplines/errors.hpp"
#include "fairsplines/g2_to_c2.hpp"
#include "fairsplines/surfaces.hpp"
#include "bindings.hpp"
#include "shape_capsule.hpp"

namespace py = pybind11;
using namespace pybind11::literals;

namespace fairsplines::python {

namespace {

ShapeFrame frameOf(const Eigen::Vector3d& origin, const Eigen::Vector3d& x, const Eigen::Vector3d& y) {
  ShapeFrame f;
  f.origin = origin;
  f.x = x;
  f.y = y;
  f.z = x.cross(y);
  f.check();
  return f;
}

CircleReparam methodOf(const std::string& name) {
  if (name == "rho") return CircleReparam::Rho;
  if (name == "sigma") return CircleReparam::Sigma;
  if (name == "mixed") return CircleReparam::Mixed;
  throw InputError("method must be 'rho', 'sigma' or 'mixed', not '" + name + "'");
}

const char* roleOf(TaggedPatch::Role r) {
  return r == TaggedPatch::Role::Basic ? "basic" : r == TaggedPatch::Role::Transition ? "transition" : "freeform";
}

Interface interfaceOf(const std::string& at) {
  if (at == "end") return Interface::End;
  if (at == "start") return Interface::Start;
  if (at == "auto") return Interface::Auto;
  throw InputError("the interface must be at the profile's 'end', 'start' or 'auto', not '" + at + "'");
}

ShapeOfRevolution::Kind kindOf(const std::string& kind) {
  if (kind == "sphere") return ShapeOfRevolution::Kind::SphereZone;
  if (kind == "cone") return ShapeOfRevolution::Kind::Cone;
  if (kind == "torus") return ShapeOfRevolution::Kind::Torus;
  throw InputError("a shape of revolution is a 'sphere', 'cone' or 'torus', not '" + kind + "'");
}

Handle(Geom_BSplineSurface) ringOf(const std::optional<BSplineSurface>& ring) {
  return ring ? toOcct(*ring) : Handle(Geom_BSplineSurface)();
}

}  // namespace

void bindBlend(py::module_& m) {
  py::class_<G2CircleSpline>(m, "G2CircleSpline", "The circle pieces of eq. (2) with the scalars of eqs. (3)-(4).")
      .def_readonly("theta", &G2CircleSpline::theta)
      .def_readonly("alpha", &G2CircleSpline::alpha)
      .def_readonly("w", &G2CircleSpline::w)
      .def_readonly("beta", &G2CircleSpline::beta)
      .def_readonly("gamma", &G2CircleSpline::gamma)
      .def_readonly("closed", &G2CircleSpline::closed)
      .def_readonly("cubic", &G2CircleSpline::cubic);
  m.def("g2_circle", &g2Circle, "theta"_a,
        "Eq. (2): the G2 rational cubic pieces of the unit circle at the angles theta (closed when they span 2 pi).");

  py::class_<G2Surface>(m, "G2Surface", "Rational bicubic G2 patches of a basic shape (homogeneous Bézier rows).")
      .def_readonly("nu", &G2Surface::nu)
      .def_readonly("nv", &G2Surface::nv)
      .def_readonly("bezier", &G2Surface::bezier)
      .def_readonly("beta_u", &G2Surface::betaU)
      .def_readonly("gamma_u", &G2Surface::gammaU)
      .def_readonly("beta_v", &G2Surface::betaV)
      .def_readonly("gamma_v", &G2Surface::gammaV)
      .def_readonly("closed_u", &G2Surface::closedU)
      .def_readonly("closed_v", &G2Surface::closedV)
      .def("set_control", &G2Surface::setControl, "i"_a, "j"_a, "r"_a, "s"_a, "point"_a, "weight"_a)
      .def(
          "patch", [](const G2Surface& s, int i, int j) { return fromOcct(patchToOcct(s, i, j)); }, "i"_a, "j"_a);
  m.def(
      "sphere_zone",
      [](const Eigen::Vector3d& o, const Eigen::Vector3d& x, const Eigen::Vector3d& y, double radius,
         const Eigen::VectorXd& longitudes,
         const Eigen::VectorXd& latitudes) { return sphereZone(frameOf(o, x, y), radius, longitudes, latitudes); },
      "origin"_a, "x"_a, "y"_a, "radius"_a, "longitudes"_a, "latitudes"_a,
      "A sphere zone or dome as a G2 rational bicubic surface (eq. (2) both ways): longitudes around the frame's z, "
      "latitudes in [-pi/2, pi/2], increasing.");
  m.def(
      "cylinder",
      [](const Eigen::Vector3d& o, const Eigen::Vector3d& x, const Eigen::Vector3d& y, double radius,
         const Eigen::VectorXd& angles,
         const Eigen::VectorXd& heights) { return cylinder(frameOf(o, x, y), radius, angles, heights); },
      "origin"_a, "x"_a, "y"_a, "radius"_a, "angles"_a, "heights"_a,
      "A circular cylinder as a G2 rational bicubic surface: angles around the frame's z, increasing heights.");
  m.def(
      "cone",
      [](const Eigen::Vector3d& o, const Eigen::Vector3d& x, const Eigen::Vector3d& y, double radius0, double slope,
         const Eigen::VectorXd& angles,
         const Eigen::VectorXd& heights) { return cone(frameOf(o, x, y), radius0, slope, angles, heights); },
      "origin"_a, "x"_a, "y"_a, "radius0"_a, "slope"_a, "angles"_a, "heights"_a,
      "A cone of radius radius0 + slope z as a G2 rational bicubic surface: angles around the frame's z, increasing "
      "heights.");
  m.def(
      "torus",
      [](const Eigen::Vector3d& o, const Eigen::Vector3d& x, const Eigen::Vector3d& y, double R, double r,
         const Eigen::VectorXd& anglesU,
         const Eigen::VectorXd& anglesV) { return torus(frameOf(o, x, y), R, r, anglesU, anglesV); },
      "origin"_a, "x"_a, "y"_a, "major_radius"_a, "minor_radius"_a, "angles_u"_a, "angles_v"_a,
      "A torus (0 < r < R) as a G2 rational bicubic surface: angles_u around the frame's z, angles_v around the "
      "tube (0 = outer equator).");

  m.def(
      "dupin_cyclide",
      [](const Eigen::Vector3d& o, const Eigen::Vector3d& x, const Eigen::Vector3d& y, double a, double c, double mu,
         const Eigen::VectorXd& anglesU,
         const Eigen::VectorXd& anglesV) { return dupinCyclide(frameOf(o, x, y), a, c, mu, anglesU, anglesV); },
      "origin"_a, "x"_a, "y"_a, "a"_a, "c"_a, "mu"_a, "angles_u"_a, "angles_v"_a,
      "A Dupin ring cyclide (c < mu < a) as a G2 rational bicubic surface: both families of curvature lines are "
      "circles, angles_u and angles_v their partitions.");

  m.def(
      "blend_cyclide",
      [](const Eigen::Vector3d& o, const Eigen::Vector3d& x, const Eigen::Vector3d& y, double a, double c, double mu,
         const Eigen::VectorXd& anglesU, const Eigen::VectorXd& anglesV, const std::string& method) {
        return blendCyclide(frameOf(o, x, y), a, c, mu, anglesU, anglesV, methodOf(method));
      },
      "origin"_a, "x"_a, "y"_a, "a"_a, "c"_a, "mu"_a, "angles_u"_a, "angles_v"_a, "method"_a = "rho",
      "Section 4.2 for a Dupin ring cyclide: C2 into its default (rational) ring at the last v angle.");

  m.def(
      "blend_cyclide_naive",
      [](const Eigen::Vector3d& o, const Eigen::Vector3d& x, const Eigen::Vector3d& y, double a, double c, double mu,
         const Eigen::VectorXd& anglesU,
         const Eigen::VectorXd& anglesV) { return blendCyclideNaive(frameOf(o, x, y), a, c, mu, anglesU, anglesV); },
      "origin"_a, "x"_a, "y"_a, "a"_a, "c"_a, "mu"_a, "angles_u"_a, "angles_v"_a,
      "The naive baseline of Fig. 2a for a Dupin ring cyclide: a (3,5) Hermite strip to its default ring.");

  py::class_<C2SexticSpline>(m, "C2SexticSpline", "Sextic pieces, C2 in homogeneous space (Section 4.1).")
      .def_readonly("bezier", &C2SexticSpline::bezier)
      .def_readonly("beta", &C2SexticSpline::beta)
      .def_readonly("closed", &C2SexticSpline::closed)
      .def_readonly("first_piece", &C2SexticSpline::firstPiece)
      .def("knots", &C2SexticSpline::knots);
  m.def(
      "circle_to_c2",
      [](const G2CircleSpline& c, const std::string& method, const Eigen::VectorXd& betaT) {
        return circleToC2(c, methodOf(method), betaT);
      },
      "circle"_a, "method"_a = "rho", "beta_t"_a = Eigen::VectorXd(),
      "Section 4.1: the G2 circle partition as C2 sextic pieces (method 'rho', 'sigma' or 'mixed'; beta_t empty: "
      "the circle's beta).");

  py::class_<BlendComplex>(m, "BlendComplex", "Tagged patches of a blend (Section 4.2).")
      .def_readonly("knots_u", &BlendComplex::knotsU)
      .def_readonly("knots_v", &BlendComplex::knotsV)
      .def_readonly("pieces_u", &BlendComplex::piecesU)
      .def_readonly("rows_basic", &BlendComplex::rowsBasic)
      .def_readonly("rows_freeform", &BlendComplex::rowsFreeForm)
      .def_readonly("smoothness", &BlendComplex::smoothness)
      .def(
          "patches",
          [](const BlendComplex& c) {
            py::list out;
            for (const TaggedPatch& p : c.patches) {
              out.append(py::make_tuple(roleOf(p.role), p.uPiece, p.vPiece, fromOcct(patchToOcct(p))));
            }
            return out;
          },
          "[(role, u_piece, v_piece, BSplineSurface)] for every patch.")
      .def(
          "single_surface",
          [](const BlendComplex& c, double tolerance) -> std::optional<BSplineSurface> {
            try {
              return fromOcct(singleSurface(c, tolerance, c.smoothness));
            } catch (const InputError&) {
              return std::nullopt;  // not a C2 (C1) tensor grid (e.g. the naive baseline)
            }
          },
          "tolerance"_a = 1e-9,
          "One Geom_BSplineSurface of the complex, C2 (C1 for the Section 5 complexes), or None where it is not.")
      .def(
          "roles",
          [](const BlendComplex& c) {
            py::list out;
            for (const TaggedPatch& p : c.patches) out.append(roleOf(p.role));
            return out;
          },
          "The role of every patch ('basic', 'transition', 'freeform'), in the order of patches().")
      .def(
          "shell_capsule",
          [](const BlendComplex& c) {
            return py::reinterpret_steal<py::object>(newShapeCapsule(new TopoDS_Shape(blendShell(c).shell)));
          },
          "A capsule owning the complex's shell (blendShell: the grid's own topology, no sewing), for kernel.adopt.")
      .def(
          "result_capsule",
          [](const BlendComplex& c, bool single, double tolerance) {
            // One hand-over for the whole result: a compound of the shell and, where the
            // complex is C2 (C1) and asked for, a face on its single surface.
            BRep_Builder builder;
            TopoDS_Compound compound;
            builder.MakeCompound(compound);
            builder.Add(compound, blendShell(c).shell);
            if (single) {
              Handle(Geom_BSplineSurface) surface;
              try {
                surface = singleSurface(c, tolerance, c.smoothness);
              } catch (const InputError&) {
                // not a C2 (C1) tensor grid (e.g. the naive baseline): no single surface
              }
              if (!surface.IsNull()) builder.Add(compound, validFace(surface, "the single surface of the complex"));
            }
            return py::reinterpret_steal<py::object>(newShapeCapsule(new TopoDS_Shape(compound)));
          },
          "single"_a = true, "tolerance"_a = 1e-9,
          "A capsule owning a compound of the shell (its faces the patches, in order) and, if single and the complex "
          "has one, a face on the single C2 (C1) surface.")
      .def(
          "shell_report",
          [](const BlendComplex& c) {
            const BlendShell s = blendShell(c);
            return py::dict("max_gap"_a = s.maxGap, "tolerance"_a = s.tolerance, "allowed_gap"_a = s.allowedGap,
                            "free_edges"_a = s.freeEdges, "degenerated"_a = s.degenerated);
          },
          "What building the shell measured: max_gap (between patches sharing a side or corner), tolerance (the "
          "edges' least), allowed_gap, free_edges (on one face only), degenerated (sides collapsed to a point).");
  m.def(
      "blend_sphere_zone",
      [](const Eigen::Vector3d& o, const Eigen::Vector3d& x, const Eigen::Vector3d& y, double radius,
         const Eigen::VectorXd& longitudes, const Eigen::VectorXd& latitudes, const std::string& method,
         const std::optional<BSplineSurface>& ring, bool bothDirections, const std::string& at) {
        return blendSphereZone(frameOf(o, x, y), radius, longitudes, latitudes, methodOf(method), ringOf(ring),
                               bothDirections, interfaceOf(at));
      },
      "origin"_a, "x"_a, "y"_a, "radius"_a, "longitudes"_a, "latitudes"_a, "method"_a = "rho", "ring"_a = py::none(),
      "both_directions"_a = true, "at"_a = "end",
      "Section 4.2: a sphere zone joined to a free-form ring (none: the default ring) by a C2 transition row of "
      "degree (6,5).");
  m.def(
      "blend_sphere_zone_naive",
      [](const Eigen::Vector3d& o, const Eigen::Vector3d& x, const Eigen::Vector3d& y, double radius,
         const Eigen::VectorXd& longitudes, const Eigen::VectorXd& latitudes, const std::optional<BSplineSurface>& ring,
         const std::string& at) {
        return blendSphereZoneNaive(frameOf(o, x, y), radius, longitudes, latitudes, ringOf(ring), interfaceOf(at));
      },
      "origin"_a, "x"_a, "y"_a, "radius"_a, "longitudes"_a, "latitudes"_a, "ring"_a = py::none(), "at"_a = "end",
      "The naive baseline of Fig. 2a for a sphere zone: a (3,5) Hermite transition row without reparameterization.");
  m.def(
      "make_bspline_surface",
      [](const PointMatrix& poles, const Eigen::VectorXd& weights, const Eigen::VectorXd& knotsU,
         const Eigen::VectorXd& knotsV, const Eigen::VectorXi& multsU, const Eigen::VectorXi& multsV, int degreeU,
         int degreeV, bool periodicU, bool periodicV, int nu, int nv) {
        BSplineSurface s;
        s.poles = poles;
        s.weights = weights;
        s.knotsU = knotsU;
        s.knotsV = knotsV;
        s.multsU = multsU;
        s.multsV = multsV;
        s.degreeU = degreeU;
        s.degreeV = degreeV;
        s.periodicU = periodicU;
        s.periodicV = periodicV;
        s.nu = nu;
        s.nv = nv;
        toOcct(s);  // InputError now if OCCT rejects it
        return s;
      },
      "poles"_a, "weights"_a, "knots_u"_a, "knots_v"_a, "mults_u"_a, "mults_v"_a, "degree_u"_a, "degree_v"_a,
      "periodic_u"_a, "periodic_v"_a, "nu"_a, "nv"_a,
      "A kernel BSplineSurface from arrays (poles nu*nv x 3, row i*nv+j).");
  m.def(
      "blend_cone",
      [](const Eigen::Vector3d& o, const Eigen::Vector3d& x, const Eigen::Vector3d& y, double radius0, double slope,
         const Eigen::VectorXd& angles, const Eigen::VectorXd& heights, const std::string& method,
         const std::optional<BSplineSurface>& ring, bool bothDirections, bool naive, const std::string& at) {
        return blendCone(frameOf(o, x, y), radius0, slope, angles, heights, methodOf(method), ringOf(ring),
                         bothDirections, naive, interfaceOf(at));
      },
      "origin"_a, "x"_a, "y"_a, "radius0"_a, "slope"_a, "angles"_a, "heights"_a, "method"_a = "rho",
      "ring"_a = py::none(), "both_directions"_a = true, "naive"_a = false, "at"_a = "end",
      "Section 4.2 for a cone (a cylinder for slope 0) joined at its top height to a free-form ring; naive: the "
      "Fig. 2a baseline.");
  m.def(
      "blend_torus",
      [](const Eigen::Vector3d& o, const Eigen::Vector3d& x, const Eigen::Vector3d& y, double R, double r,
         const Eigen::VectorXd& anglesU, const Eigen::VectorXd& anglesV, const std::string& method,
         const std::optional<BSplineSurface>& ring, bool bothDirections, bool naive, const std::string& at) {
        return blendTorus(frameOf(o, x, y), R, r, anglesU, anglesV, methodOf(method), ringOf(ring), bothDirections,
                          naive, interfaceOf(at));
      },
      "origin"_a, "x"_a, "y"_a, "major_radius"_a, "minor_radius"_a, "angles_u"_a, "angles_v"_a, "method"_a = "rho",
      "ring"_a = py::none(), "both_directions"_a = true, "naive"_a = false, "at"_a = "end",
      "Section 4.2 for a torus zone joined at its last v angle to a free-form ring; naive: the Fig. 2a baseline.");
  py::class_<ShapeOfRevolution>(m, "ShapeOfRevolution", "A basic shape of revolution for join_shapes.")
      .def(py::init([](const std::string& kind, const Eigen::Vector3d& o, const Eigen::Vector3d& x,
                       const Eigen::Vector3d& y, double size0, double size1, const Eigen::VectorXd& around,
                       const Eigen::VectorXd& profile) {
             ShapeOfRevolution s;
             s.kind = kindOf(kind);
             s.frame = frameOf(o, x, y);
             s.size0 = size0;
             s.size1 = size1;
             s.around = around;
             s.profile = profile;
             return s;
           }),
           "kind"_a, "origin"_a, "x"_a, "y"_a, "size0"_a, "size1"_a, "around"_a, "profile"_a);
  py::class_<RevolutionProfile>(m, "RevolutionProfile",
                                "A rational cubic profile in a half-plane bounded by the axis (issue 32).")
      .def_property_readonly("origin", [](const RevolutionProfile& p) { return p.frame.origin; })
      .def_property_readonly("x", [](const RevolutionProfile& p) { return p.frame.x; })
      .def_property_readonly("y", [](const RevolutionProfile& p) { return p.frame.y; })
      .def_property_readonly("z", [](const RevolutionProfile& p) { return p.frame.z; })
      .def_readonly("cubic", &RevolutionProfile::cubic)
      .def_readonly("knots", &RevolutionProfile::knots);
  m.def("revolution_profile", &revolutionProfile, "curve"_a, "origin"_a, "axis"_a, "splits"_a = Eigen::VectorXd(),
        "The profile of a B-spline curve of degree <= 3 about an axis (the parameters splits inserted as knots): "
        "its Bézier pieces as (w rho, w z, w).");
  m.def("revolution", &revolution, "profile"_a, "angles"_a,
        "The profile revolved by the circle pieces of eq. (2): a G2 rational bicubic surface.");
  m.def(
      "shape_of_revolution",
      [](const RevolutionProfile& p, const Eigen::VectorXd& around) { return ShapeOfRevolution::of(p, around); },
      "profile"_a, "around"_a, "A Revolution of the profile over the angles, for the blends and joins.");
  m.def(
      "blend_shape",
      [](const ShapeOfRevolution& shape, const std::string& method, const std::optional<BSplineSurface>& ring,
         bool bothDirections, bool naive, const std::string& at) {
        return blendShape(shape, methodOf(method), ringOf(ring), bothDirections, naive, interfaceOf(at));
      },
      "shape"_a, "method"_a = "rho", "ring"_a = py::none(), "both_directions"_a = true, "naive"_a = false,
      "at"_a = "end", "Section 4.2 for any shape of revolution (a Revolution too); naive: the Fig. 2a baseline.");
  m.def(
      "image_g2",
      [](const G2Surface& g2, const Eigen::Matrix4d& M) {
        G2Surface out = g2;
        out.bezier = projectiveImage(g2.bezier, M);
        return out;
      },
      "g2"_a, "matrix"_a, "The G2 structure under (w p, w) -> M (w p, w): affine or projective, exact.");
  m.def(
      "image_complex",
      [](const BlendComplex& c, const Eigen::Matrix4d& M) {
        BlendComplex out = c;
        for (TaggedPatch& p : out.patches) p.bezier = projectiveImage(p.bezier, M);
        return out;
      },
      "complex"_a, "matrix"_a,
      "The blend complex under (w p, w) -> M (w p, w): the blend of the image (the construction commutes with it).");
  m.def(
      "join_shapes",
      [](const ShapeOfRevolution& a, const ShapeOfRevolution& b, const std::string& method, bool bothDirections,
         bool naive) { return joinShapes(a, b, methodOf(method), bothDirections, naive); },
      "a"_a, "b"_a, "method"_a = "rho", "both_directions"_a = true, "naive"_a = false,
      "The end of a's profile joined to the start of b's (Figs. 9, 11, 12).");
  m.def(
      "blend_chain",
      [](const std::vector<ShapeOfRevolution>& shapes, const std::vector<std::optional<G2Surface>>& edited,
         bool startRing, bool endRing, const std::optional<BSplineSurface>& startNet,
         const std::optional<BSplineSurface>& endNet, const std::string& method, bool bothDirections) {
        if (edited.size() != shapes.size()) throw InputError("blend_chain: one edited entry (or None) per shape");
        std::vector<ChainShape> chain;
        for (std::size_t s = 0; s < shapes.size(); ++s) chain.push_back(ChainShape{shapes[s], edited[s]});
        const ChainEnd start = startRing ? ChainEnd::freeForm(ringOf(startNet)) : ChainEnd::open();
        const ChainEnd end = endRing ? ChainEnd::freeForm(ringOf(endNet)) : ChainEnd::open();
        return blendChain(chain, start, end, methodOf(method), bothDirections);
      },
      "shapes"_a, "edited"_a, "start_ring"_a, "end_ring"_a, "start_net"_a = py::none(), "end_net"_a = py::none(),
      "method"_a = "rho", "both_directions"_a = true,
      "Several interfaces on one complex (issue 15): shapes joined end to start (Figs. 9, 11, 12), a free-form ring "
      "(None: the default one) at the chain's start and/or end (Section 4.2).");
  m.def(
      "blend_edited",
      [](const ShapeOfRevolution& shape, const G2Surface& edited, const std::string& method,
         const std::optional<BSplineSurface>& ring) {
        return blendEdited(shape, edited, methodOf(method), ringOf(ring));
      },
      "shape"_a, "edited"_a, "method"_a = "rho", "ring"_a = py::none(),
      "An edited G2 control structure of the shape blended into a ring (Figs. 1c/d).");
  m.def(
      "ring_knots",
      [](const Eigen::VectorXd& angles, const std::string& method) { return ringKnots(angles, methodOf(method)); },
      "angles"_a, "method"_a = "rho", "The u knots (one period) a free-form ring must have to join a shape.");
}

}  // namespace fairsplines::python
