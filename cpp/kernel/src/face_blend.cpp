// G1 and G2 blends between two faces (issue 29; docs/FACE_BLENDS.md).
//
// Method: an edge that is an isoparametric boundary v = v0 of its face is taken exactly (below);
// any other edge (trimmed, a seam, an isoline inside the face, a surface without an exact B-spline
// form) is fitted: face_blend_fitted.cpp samples the face along it and fits its boundary rows
// until the tolerances hold, and returns them as a surface of v-degree 2 that enters here as an
// exact side would. The face's surface is
// converted exactly to a (rational) B-spline (GeomConvert), cut to the face's side with the full
// multiplicity of v0, so the first three rows of homogeneous poles Q_0, Q_1, Q_2 give the
// position, first and second cross-boundary derivative exactly (Piegl & Tiller, The NURBS Book,
// eq. (3.17), derivative poles of a B-spline). Both edges are mapped to u in [0, 1] (linear maps,
// the flip reverses one), degree-elevated to a common u-degree and their knot vectors merged by
// knot insertion, so both sides' rows share one u-basis. The blend is a Bezier in s of degree
// kA + kB + 1 (kA, kB each side's continuity: 5 for G2 both, 4 for G2 and G1, 3 for G1 both)
// whose first kA + 1 rows are those of side A under the reparametrisation
// v(s) = v0 - alpha s + beta s^2 / 2, likewise the last kB + 1 rows from side B: C2 (C1) in
// homogeneous coordinates after a reparametrisation, hence G2 (G1), exact to rounding along the
// whole edge (section 2 of the doc has the formulas). alpha, beta are constants per side (a
// polynomial in u would raise the u-degree) chosen for fairness of the cross sections: fewest
// curvature extrema, then least curvature variation L^3 int kappa_s^2 ds (section 3; the sections
// and the search are in face_blend_fairness.cpp, shared through face_blend_detail.hpp).
#include "fairsplines/face_blend.hpp"

#include <BRepAdaptor_Curve.hxx>
#include <BRepClass_FaceClassifier.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <BSplCLib.hxx>
#include <Eigen/Geometry>
#include <GCPnts_AbscissaPoint.hxx>
#include <Geom2d_Curve.hxx>
#include <GeomConvert.hxx>
#include <Geom_Plane.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <math_Matrix.hxx>
#include <optional>

#include "fairsplines/errors.hpp"
#include "fairsplines/monotone.hpp"
#include "face_blend_detail.hpp"
#include "monotone_common.hpp"

namespace fairsplines {

namespace {

using detail::num;
using namespace face_blend_detail;

// ---------------------------------------------------------------------------------------
// One side: the face's surface as a B-spline, u along the edge, the face at v >= v0

struct Side {
  Handle(Geom_BSplineSurface) surface;  // made after both sides are read when `fitted` is set
  FaceBlendSide report;
  std::optional<FittedEdge> fitted;  // the edge is fitted (face_blend_fitted.cpp), not taken exactly
  std::vector<Vec3> rim;             // 17 points of the edge's covered part (the fit's size)
};

std::string surfaceName(const Handle(Geom_Surface)& s) {
  std::string name = s->DynamicType()->Name();
  return name.rfind("Geom_", 0) == 0 ? name.substr(5) : name;
}

bool exactlyConverted(const std::string& type) {
  static const char* kinds[] = {
      "Plane",          "CylindricalSurface", "ConicalSurface",      "SphericalSurface",        "ToroidalSurface",
      "BSplineSurface", "BezierSurface",      "SurfaceOfRevolution", "SurfaceOfLinearExtrusion"};
  return std::any_of(std::begin(kinds), std::end(kinds), [&](const char* k) { return type == k; });
}

/// The face's extent across a straight edge of a plane: the signed distances of its boundary
/// samples from the edge's line, along y (in the plane, normal to the edge).
std::pair<double, double> extentAcross(const TopoDS_Face& face, const gp_Pnt& origin, const gp_Dir& y) {
  double lo = 0.0, hi = 0.0;
  for (TopExp_Explorer e(face, TopAbs_EDGE); e.More(); e.Next()) {
    BRepAdaptor_Curve c(TopoDS::Edge(e.Current()));
    for (int i = 0; i <= 8; ++i) {
      const gp_Pnt p = c.Value(c.FirstParameter() + (c.LastParameter() - c.FirstParameter()) * i / 8.0);
      const double d = gp_Vec(origin, p).Dot(gp_Vec(y));
      lo = std::min(lo, d);
      hi = std::max(hi, d);
    }
  }
  return {lo, hi};
}

/// The fitted route for an edge that is not an isoparametric boundary (`reason` says why): the
/// face's surface and the edge's pcurve with the orientation it has in the face, so the face
/// lies left of it in the parameter plane (right for a reversed edge), checked by OCCT's
/// classifier beside the edge's middle.
Side fittedSide(const TopoDS_Face& face, const TopoDS_Edge& edge, const std::string& name, const std::string& reason,
                const FaceBlendOptions& o) {
  const TopoDS_Face forward = TopoDS::Face(face.Oriented(TopAbs_FORWARD));
  TopoDS_Edge oriented = edge;
  for (TopExp_Explorer x(forward, TopAbs_EDGE); x.More(); x.Next())
    if (x.Current().IsSame(edge)) {
      oriented = TopoDS::Edge(x.Current());
      break;
    }
  Side side;
  FittedEdge& e = side.fitted.emplace();
  e.edgeName = "edge_" + name;
  e.faceName = "face_" + name;
  double f = 0.0, l = 0.0;
  e.pcurve = BRep_Tool::CurveOnSurface(oriented, forward, f, l);
  e.surface = BRep_Tool::Surface(forward);
  if (e.pcurve.IsNull() || e.surface.IsNull())
    throw InputError(e.edgeName + " is not an edge of " + e.faceName + " (no curve on its surface)");
  e.from = f + o.start * (l - f);
  e.to = f + o.end * (l - f);
  e.inward = oriented.Orientation() == TopAbs_REVERSED ? -1.0 : 1.0;
  double umin, umax, vmin, vmax;
  BRepTools::UVBounds(forward, umin, umax, vmin, vmax);
  gp_Pnt2d mid;
  gp_Vec2d d;
  e.pcurve->D1(0.5 * (f + l), mid, d);
  if (d.Magnitude() > 0) {
    const gp_Vec2d left = gp_Vec2d(-d.Y(), d.X()).Normalized() * (1e-3 * std::hypot(umax - umin, vmax - vmin));
    const double tol = BRep_Tool::Tolerance(edge);
    const TopAbs_State inside = BRepClass_FaceClassifier(forward, mid.Translated(e.inward * left), tol).State();
    const TopAbs_State outside = BRepClass_FaceClassifier(forward, mid.Translated(-e.inward * left), tol).State();
    if (inside == TopAbs_OUT && outside == TopAbs_IN) e.inward = -e.inward;
  }
  Handle(Geom_Surface) basis = e.surface;
  const Handle(Geom_RectangularTrimmedSurface) trimmed = Handle(Geom_RectangularTrimmedSurface)::DownCast(basis);
  if (!trimmed.IsNull()) basis = trimmed->BasisSurface();
  side.report.method = "fitted";
  side.report.reason = reason;
  side.report.surfaceType = surfaceName(basis);
  side.report.isoparametric = "none";
  BRepAdaptor_Curve c(edge);
  const double length = GCPnts_AbscissaPoint::Length(c);
  side.report.closed = o.start == 0.0 && o.end == 1.0 &&
                       c.Value(c.FirstParameter()).Distance(c.Value(c.LastParameter())) <= 1e-9 * length;
  return side;
}

/// Side of `face` along its edge number `index`: the exact B-spline of the face near the edge,
/// u along the edge (its parameter's direction) over [start, end] of it, v into the face.
Side readSide(const TopoDS_Face& face, int index, const std::string& name, const FaceBlendOptions& o) {
  const std::string faceName = "face_" + name, edgeName = "edge_" + name;
  TopTools_IndexedMapOfShape edges;
  TopExp::MapShapes(face, TopAbs_EDGE, edges);
  if (index < 1 || index > edges.Extent())
    throw InputError(edgeName + " is edge " + std::to_string(index) + " of " + faceName + ", which has " +
                     std::to_string(edges.Extent()) + " edges");
  const TopoDS_Edge edge = TopoDS::Edge(edges(index));
  if (BRep_Tool::Degenerated(edge)) throw InputError(edgeName + " is degenerate (a point of " + faceName + ")");
  BRepAdaptor_Curve curve3d(edge);
  const double length = GCPnts_AbscissaPoint::Length(curve3d);
  Handle(Geom_Surface) base = BRep_Tool::Surface(face);
  if (base.IsNull()) throw InputError(faceName + " has no surface");
  double umin, umax, vmin, vmax;
  BRepTools::UVBounds(face, umin, umax, vmin, vmax);
  const double extent = std::max(umax - umin, vmax - vmin);
  if (!(length > 1e-12 * std::max(1.0, extent)))
    throw InputError(edgeName + " is degenerate (length " + num(length) + ")");
  if (BRep_Tool::IsClosed(edge, face))
    return fittedSide(face, edge, name, "a seam of " + faceName + " (the face lies on both sides of it)", o);
  Side side;
  Handle(Geom_Surface) basis = base;
  const Handle(Geom_RectangularTrimmedSurface) trimmedBase = Handle(Geom_RectangularTrimmedSurface)::DownCast(basis);
  // Trim the basis itself below, not the face's trimmed surface: OCCT 7.8+ gives the face's
  // bounds normalised into the basis' period, which can lie outside a trimmed surface's range.
  if (!trimmedBase.IsNull()) basis = trimmedBase->BasisSurface(), base = basis;
  side.report.surfaceType = surfaceName(basis);
  if (!exactlyConverted(side.report.surfaceType))
    return fittedSide(face, edge, name, faceName + " is a " + side.report.surfaceType + " (no exact B-spline form)", o);

  double f = 0.0, l = 0.0;
  Handle(Geom2d_Curve) pcurve = BRep_Tool::CurveOnSurface(edge, face, f, l);
  if (pcurve.IsNull()) throw InputError(edgeName + " is not an edge of " + faceName + " (no curve on its surface)");
  bool alongU = true, alongV = true;
  const gp_Pnt2d a = pcurve->Value(f), b = pcurve->Value(l);
  const double tolUV = 1e-9 * std::max(1.0, extent);
  for (int i = 0; i <= 16; ++i) {
    const gp_Pnt2d p = pcurve->Value(f + (l - f) * i / 16.0);
    alongU = alongU && std::abs(p.Y() - a.Y()) <= tolUV;
    alongV = alongV && std::abs(p.X() - a.X()) <= tolUV;
  }
  double first, last, v0, vOther;
  if (alongU || alongV) {
    side.report.isoparametric = alongU ? "v" : "u";
    const double fixed = alongU ? a.Y() : a.X();
    const double lo = alongU ? vmin : umin, hi = alongU ? vmax : umax;
    if (std::abs(fixed - lo) <= tolUV) {
      v0 = lo;
      vOther = hi;
    } else if (std::abs(fixed - hi) <= tolUV) {
      v0 = hi;
      vOther = lo;
    } else {
      return fittedSide(face, edge, name, "an isoparametric line inside " + faceName + ", not its boundary", o);
    }
    first = alongU ? a.X() : a.Y();
    last = alongU ? b.X() : b.Y();
  } else if (!Handle(Geom_Plane)::DownCast(basis).IsNull()) {
    const Handle(Geom_Plane) plane = Handle(Geom_Plane)::DownCast(basis);
    // A straight edge of a plane: the plane again, parametrised with x along the edge (exact).
    const gp_Pnt p0 = curve3d.Value(curve3d.FirstParameter()), p1 = curve3d.Value(curve3d.LastParameter());
    const gp_Pnt pm = curve3d.Value(0.5 * (curve3d.FirstParameter() + curve3d.LastParameter()));
    const gp_Vec chord(p0, p1);
    if (chord.Magnitude() < 1e-12 || gp_Vec(p0, pm).Crossed(chord).Magnitude() > 1e-9 * chord.SquareMagnitude())
      return fittedSide(face, edge, name, "a curved edge of the plane " + faceName, o);
    const gp_Dir z = plane->Position().Direction(), x(chord);
    const gp_Dir y = z.Crossed(x);
    base = new Geom_Plane(gp_Ax3(p0, z, x));
    side.report.isoparametric = "line";
    alongU = true;
    const auto [lo, hi] = extentAcross(face, p0, y);
    if (std::abs(lo) <= 1e-9 * (hi - lo)) {
      v0 = 0.0;
      vOther = hi;
    } else if (std::abs(hi) <= 1e-9 * (hi - lo)) {
      v0 = 0.0;
      vOther = lo;
    } else {
      throw InputError(edgeName + " is a straight line through the inside of " + faceName + ", not its boundary");
    }
    first = 0.0;
    last = chord.Magnitude();
  } else {
    return fittedSide(face, edge, name, "not an isoparametric line of " + faceName + " (a trimmed edge)", o);
  }
  const double from = first + o.start * (last - first), to = first + o.end * (last - first);
  if (!(std::abs(vOther - v0) > tolUV)) throw InputError(faceName + " has no width across " + edgeName);

  // The face's side of the edge as an exact B-spline.
  Handle(Geom_Surface) trimmed;
  double a0 = std::min(from, to), a1 = std::max(from, to);
  const double b0 = std::min(v0, vOther), b1 = std::max(v0, vOther);
  // A periodic direction may be trimmed one period lower or higher: only the order of v0 and
  // vOther and of from and to is used below. OCCT 7.8+ gives a face's bounds normalised into
  // the period (a torus zone's v in [3 pi/2, 5 pi/2] for [-pi/2, pi/2]) and its conversions
  // refuse some such ranges, so the shifted ranges are tried in turn.
  const double periodA =
      alongU ? (base->IsUPeriodic() ? base->UPeriod() : 0.0) : (base->IsVPeriodic() ? base->VPeriod() : 0.0);
  const double periodB =
      alongU ? (base->IsVPeriodic() ? base->VPeriod() : 0.0) : (base->IsUPeriodic() ? base->UPeriod() : 0.0);
  // A closed rim read from its pcurve may span the period plus a rounding error (2 pi + 4e-15
  // on OCCT 7.9), which OCCT's conversions refuse: at most one period.
  if (periodA > 0.0 && a1 - a0 > periodA && a1 - a0 <= periodA * (1.0 + 1e-12)) {
    a1 = a0 + periodA;
    while (a1 - a0 > periodA) a1 = std::nextafter(a1, a0);
  }
  std::string failure;
  for (const auto& [ka, kb] : {std::pair{0, 0}, {0, -1}, {0, 1}, {-1, 0}, {1, 0}, {-1, -1}, {1, 1}}) {
    if ((ka != 0 && periodA == 0.0) || (kb != 0 && periodB == 0.0)) continue;
    const double sa = ka * periodA, sb = kb * periodB;
    try {
      trimmed = alongU ? new Geom_RectangularTrimmedSurface(base, a0 + sa, a1 + sa, b0 + sb, b1 + sb)
                       : new Geom_RectangularTrimmedSurface(base, b0 + sb, b1 + sb, a0 + sa, a1 + sa);
      side.surface = GeomConvert::SurfaceToBSplineSurface(trimmed);
      break;
    } catch (const Standard_Failure& e) {
      if (failure.empty()) failure = e.GetMessageString();
    }
  }
  if (side.surface.IsNull())
    return fittedSide(face, edge, name, faceName + " could not be converted to a B-spline: " + failure, o);
  Handle(Geom_BSplineSurface)& s = side.surface;
  if (s->IsUPeriodic()) s->SetUNotPeriodic();
  if (s->IsVPeriodic()) s->SetVNotPeriodic();
  // Clamped knots at all four ends (a converted full circle may come unclamped): the first rows
  // of poles are then the boundary's.
  double u1, u2, v1, v2;
  s->Bounds(u1, u2, v1, v2);
  s->Segment(u1, u2, v1, v2);
  if (!alongU) s->ExchangeUV();
  if (vOther < v0) s->VReverse();
  if (to < from) s->UReverse();
  if (s->VDegree() < 2) s->IncreaseDegree(s->UDegree(), 2);
  // u in [0, 1] (a linear map of the edge's parameter).
  const int nk = s->NbUKnots();
  const double k0 = s->UKnot(1), k1 = s->UKnot(nk);
  TColStd_Array1OfReal knots(1, nk);
  for (int k = 1; k <= nk; ++k) knots(k) = k == nk ? 1.0 : (s->UKnot(k) - k0) / (k1 - k0);
  s->SetUKnots(knots);
  side.report.method = "exact";
  side.report.rational = s->IsURational() || s->IsVRational();
  const gp_Pnt e0 = s->Pole(1, 1), e1 = s->Pole(s->NbUPoles(), 1);
  side.report.closed = e0.Distance(e1) <= 1e-12 * std::max(1.0, length);
  return side;
}

/// readSide, and 17 points of the edge's covered part.
Side prepareSide(const TopoDS_Face& face, int index, const std::string& name, const FaceBlendOptions& o) {
  Side side = readSide(face, index, name, o);
  TopTools_IndexedMapOfShape edges;
  TopExp::MapShapes(face, TopAbs_EDGE, edges);
  BRepAdaptor_Curve c(TopoDS::Edge(edges(index)));
  const double f = c.FirstParameter(), l = c.LastParameter();
  for (int i = 0; i <= 16; ++i) {
    const gp_Pnt p = c.Value(f + (o.start + (o.end - o.start) * i / 16.0) * (l - f));
    side.rim.emplace_back(p.X(), p.Y(), p.Z());
  }
  return side;
}

/// The fitted sides' boundary data (face_blend_fitted.cpp), judged against the size of the box of
/// both edges: the blend's pole box holds both boundary curves, so its size is at least this.
/// kA, kB: each side's continuity (G1 fits position and normal, G2 the normal curvature too).
void fitSides(Side& a, Side& b, int kA, int kB) {
  Eigen::AlignedBox3d box;
  for (const Side* s : {&a, &b})
    for (const Vec3& p : s->rim) box.extend(p);
  const double size = box.diagonal().norm();
  for (Side* s : {&a, &b}) {
    if (!s->fitted) continue;
    if (!(size > 0) || !std::isfinite(size)) throw InputError("the two edges have no extent");
    const FittedSide fit = fitSide(*s->fitted, s == &a ? kA : kB, size);
    s->surface = fit.surface;
    s->report.spans = fit.spans;
    s->report.refinements = fit.refinements;
    s->report.samples = fit.samples;
    s->report.fitGap = fit.gap;
    s->report.fitAngle = fit.angle;
    s->report.fitCurvature = fit.curvature;
  }
}

/// Both sides on one u-basis: common degree, merged knots (knot insertion, Boehm).
void commonBasis(Side& a, Side& b) {
  const int p = std::max(a.surface->UDegree(), b.surface->UDegree());
  for (Side* s : {&a, &b}) {
    if (s->surface->UDegree() < p) s->surface->IncreaseDegree(p, s->surface->VDegree());
  }
  auto insertFrom = [](const Handle(Geom_BSplineSurface)& into, const Handle(Geom_BSplineSurface)& from) {
    const int n = from->NbUKnots() - 2;  // the interior knots (both ends are clamped at 0 and 1)
    if (n < 1) return;
    TColStd_Array1OfReal knots(1, n);
    TColStd_Array1OfInteger mults(1, n);
    for (int k = 1; k <= n; ++k) {
      knots(k) = from->UKnot(k + 1);
      mults(k) = from->UMultiplicity(k + 1);
    }
    into->InsertUKnots(knots, mults, 1e-10, Standard_False);
  };
  insertFrom(a.surface, b.surface);
  insertFrom(b.surface, a.surface);
  if (a.surface->NbUPoles() != b.surface->NbUPoles() || a.surface->NbUKnots() != b.surface->NbUKnots())
    throw InputError("the two edges' knot vectors could not be merged");
}

// ---------------------------------------------------------------------------------------
// Homogeneous boundary rows: position, first and second cross-boundary derivative

Vec4 homogeneous(const Handle(Geom_BSplineSurface)& s, int i, int j) {
  const gp_Pnt p = s->Pole(i, j);
  const double w = s->Weight(i, j);
  return Vec4(w * p.X(), w * p.Y(), w * p.Z(), w);
}

/// NURBS Book eq. (3.17) at a clamped start: Q^(1)_0 = q (Q_1 - Q_0) / (t_{q+1} - t_1),
/// Q^(2)_0 = (q - 1) (Q^(1)_1 - Q^(1)_0) / (t_{q+1} - t_2), with flat knots t_0 = ... = t_q = v0.
Boundary boundaryRows(const Handle(Geom_BSplineSurface)& s) {
  const int q = s->VDegree(), nu = s->NbUPoles();
  std::vector<double> t;
  for (int k = 1; k <= s->NbVKnots(); ++k)
    for (int m = 0; m < s->VMultiplicity(k); ++m) t.push_back(s->VKnot(k));
  Boundary out;
  out.r0.resize(nu, 4);
  out.d1.resize(nu, 4);
  out.d2.resize(nu, 4);
  for (int i = 0; i < nu; ++i) {
    const Vec4 Q0 = homogeneous(s, i + 1, 1), Q1 = homogeneous(s, i + 1, 2), Q2 = homogeneous(s, i + 1, 3);
    const Vec4 D0 = q * (Q1 - Q0) / (t[q + 1] - t[1]), D1 = q * (Q2 - Q1) / (t[q + 2] - t[2]);
    out.r0.row(i) = Q0;
    out.d1.row(i) = D0;
    out.d2.row(i) = (q - 1) * (D1 - D0) / (t[q + 1] - t[2]);
  }
  return out;
}

// ---------------------------------------------------------------------------------------
// Evaluation of the boundary rows at a section

std::vector<double> flatKnots(const Handle(Geom_BSplineSurface)& s) {
  std::vector<double> t;
  for (int k = 1; k <= s->NbUKnots(); ++k)
    for (int m = 0; m < s->UMultiplicity(k); ++m) t.push_back(s->UKnot(k));
  return t;
}

/// sum_i N_i(u) rows_i for the u-basis of `s` (BSplCLib's basis values).
Vec4 atU(const Rows& rows, const TColStd_Array1OfReal& flat, int p, double u) {
  math_Matrix basis(1, 1, 1, p + 1);
  int first = 0;
  BSplCLib::EvalBsplineBasis(0, p + 1, flat, u, first, basis);
  Vec4 out = Vec4::Zero();
  for (int k = 0; k <= p; ++k) out += basis(1, k + 1) * rows.row(first - 1 + k).transpose();
  return out;
}

Vec3 euclid(const Vec4& h) { return h.head<3>() / h[3]; }
Vec3 euclidDerivative(const Vec4& h, const Vec4& d) { return (d.head<3>() - d[3] * euclid(h)) / h[3]; }

// ---------------------------------------------------------------------------------------
// Checks of the result

/// The surface's normal field must not vanish or turn over between neighbouring samples.
void requireNoFold(const Handle(Geom_BSplineSurface)& s, double size) {
  const int nu = 48, ns = 16;
  std::vector<gp_Vec> previousRow(nu + 1);
  for (int j = 0; j <= ns; ++j) {
    gp_Vec left;
    for (int i = 0; i <= nu; ++i) {
      gp_Pnt p;
      gp_Vec du, ds;
      s->D1(static_cast<double>(i) / nu, static_cast<double>(j) / ns, p, du, ds);
      const gp_Vec normal = du.Crossed(ds);
      if (normal.Magnitude() <= 1e-12 * size * size)
        throw InputError("the blend would cross itself: its surface degenerates at u = " + num(double(i) / nu) +
                         ", s = " + num(double(j) / ns));
      const gp_Vec unit = normal.Normalized();
      if ((i > 0 && unit.Dot(left) < 0) || (j > 0 && unit.Dot(previousRow[i]) < 0))
        throw InputError("the blend would cross itself: its surface folds over near u = " + num(double(i) / nu) +
                         ", s = " + num(double(j) / ns));
      left = unit;
      previousRow[i] = unit;
    }
  }
}

}  // namespace

FaceBlend blendFaces(const TopoDS_Face& faceA, int edgeA, const TopoDS_Face& faceB, int edgeB,
                     const FaceBlendOptions& o) {
  if (o.continuity != 1 && o.continuity != 2) throw InputError("continuity must be G1 or G2");
  if (o.continuityB != 0 && o.continuityB != 1 && o.continuityB != 2)
    throw InputError("edge b's continuity must be G1 or G2");
  const int kA = o.continuity, kB = o.continuityB != 0 ? o.continuityB : o.continuity;
  if (!(o.start >= 0.0 && o.end <= 1.0 && o.end - o.start > 1e-9))
    throw InputError("start and end must satisfy 0 <= start < end <= 1, got " + num(o.start) + ", " + num(o.end));
  if (o.sections < 2 || o.sections > 1000) throw InputError("sections must lie in [2, 1000]");
  if (!(o.scaleA >= 0.0 && o.scaleB >= 0.0 && std::isfinite(o.scaleA) && std::isfinite(o.scaleB)))
    throw InputError("the derivative scales must be finite and >= 0 (0: chosen for fairness)");
  Side a = prepareSide(faceA, edgeA, "a", o);
  Side b = prepareSide(faceB, edgeB, "b", o);
  fitSides(a, b, kA, kB);
  if (o.flip) b.surface->UReverse();
  commonBasis(a, b);
  const Boundary A = boundaryRows(a.surface);
  Boundary B = boundaryRows(b.surface);
  // Gauge: side B's homogeneous rows times one constant (the same geometry) so that the two
  // boundaries' mean weights agree.
  const double gauge = A.r0.col(3).mean() / B.r0.col(3).mean();
  B.r0 *= gauge;
  B.d1 *= gauge;
  B.d2 *= gauge;

  const int p = a.surface->UDegree(), nu = a.surface->NbUPoles();
  const std::vector<double> flatStd = flatKnots(a.surface);
  TColStd_Array1OfReal flat(1, static_cast<int>(flatStd.size()));
  for (size_t k = 0; k < flatStd.size(); ++k) flat(static_cast<int>(k) + 1) = flatStd[k];

  // Sections, and the default magnitude: mean chord over mean cross-boundary speed.
  std::vector<SectionData> sections(o.sections);
  double chord = 0.0, speedA = 0.0, speedB = 0.0, size = 0.0;
  for (int j = 0; j < o.sections; ++j) {
    SectionData& d = sections[j];
    d.u = static_cast<double>(j) / (o.sections - 1);
    d.a0 = atU(A.r0, flat, p, d.u);
    d.a1 = atU(A.d1, flat, p, d.u);
    d.a2 = atU(A.d2, flat, p, d.u);
    d.b0 = atU(B.r0, flat, p, d.u);
    d.b1 = atU(B.d1, flat, p, d.u);
    d.b2 = atU(B.d2, flat, p, d.u);
    const double c = (euclid(d.a0) - euclid(d.b0)).norm();
    chord += c;
    speedA += euclidDerivative(d.a0, d.a1).norm();
    speedB += euclidDerivative(d.b0, d.b1).norm();
  }
  for (int i = 0; i < nu; ++i) {
    size = std::max(size, (euclid(A.r0.row(i).transpose()) - euclid(A.r0.row(0).transpose())).norm());
    size = std::max(size, (euclid(B.r0.row(i).transpose()) - euclid(A.r0.row(0).transpose())).norm());
  }
  // Faces that touch: a section of (nearly) no length.
  for (int j = 0; j <= 100; ++j) {
    const double u = j / 100.0;
    const double c = (euclid(atU(A.r0, flat, p, u)) - euclid(atU(B.r0, flat, p, u))).norm();
    if (c <= 1e-7 * std::max(size, chord / o.sections))
      throw InputError("the faces touch: edge_a and edge_b meet at u = " + num(u) + " of the edges");
  }
  if (!(speedA > 0 && speedB > 0)) throw InputError("a face's cross-boundary derivative vanishes along its edge");
  const int n = kA + kB + 1;  // the degree across: each side sets rows 0 .. k of its end
  Search search{sections, A, B, chord / speedA, chord / speedB, kA, kB};
  const std::array<double, 4> x = searchMagnitudes(search, o);
  const Magnitudes ma = search.magnitudes(x[0], x[1], search.alpha0A);
  const Magnitudes mb = search.magnitudes(x[2], x[3], search.alpha0B);

  // The blend's poles: rows of side A, then side B's in reverse (s runs from A to B).
  TColgp_Array2OfPnt poles(1, nu, 1, n + 1);
  TColStd_Array2OfReal weights(1, nu, 1, n + 1);
  const auto rowsA = sideRows<Rows>(A.r0, A.d1, A.d2, ma, n), rowsB = sideRows<Rows>(B.r0, B.d1, B.d2, mb, n);
  for (int i = 0; i < nu; ++i)
    for (int side = 0; side < 2; ++side)
      for (int r = 0; r <= (side == 0 ? kA : kB); ++r) {
        const Vec4 h = (side == 0 ? rowsA[r] : rowsB[r]).row(i).transpose();
        const int col = side == 0 ? r : n - r;
        if (!(h[3] > 0) || !h.allFinite())
          throw InputError("the blend's weights would not be positive (a rational face with a steep weight)");
        poles(i + 1, col + 1) = gp_Pnt(h[0] / h[3], h[1] / h[3], h[2] / h[3]);
        weights(i + 1, col + 1) = h[3];
      }
  TColStd_Array1OfReal knotsU(1, a.surface->NbUKnots()), knotsS(1, 2);
  TColStd_Array1OfInteger multsU(1, a.surface->NbUKnots()), multsS(1, 2);
  for (int j = 1; j <= a.surface->NbUKnots(); ++j) {
    knotsU(j) = a.surface->UKnot(j);
    multsU(j) = a.surface->UMultiplicity(j);
  }
  knotsS(1) = 0.0;
  knotsS(2) = 1.0;
  multsS(1) = multsS(2) = n + 1;
  FaceBlend out;
  try {
    out.surface = new Geom_BSplineSurface(poles, weights, knotsU, knotsS, multsU, multsS, p, n);
  } catch (const Standard_Failure& e) {
    throw InputError(std::string("the blend surface could not be built: ") + e.GetMessageString());
  }
  double lo[3] = {1e308, 1e308, 1e308}, hi[3] = {-1e308, -1e308, -1e308};
  for (int i = 1; i <= nu; ++i)
    for (int j = 1; j <= n + 1; ++j) {
      const gp_Pnt q = poles(i, j);
      for (int c = 0; c < 3; ++c) {
        lo[c] = std::min(lo[c], q.Coord(c + 1));
        hi[c] = std::max(hi[c], q.Coord(c + 1));
      }
    }
  out.size = std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                       (hi[2] - lo[2]) * (hi[2] - lo[2]));
  requireNoFold(out.surface, out.size);

  out.evaluations = search.evaluations;
  a.report.alpha = ma.alpha;
  a.report.beta = ma.beta;
  a.report.scale = x[0];
  a.report.bend = x[1];
  b.report.alpha = mb.alpha;
  b.report.beta = mb.beta;
  b.report.scale = x[2];
  b.report.bend = x[3];
  a.report.continuity = kA;
  b.report.continuity = kB;
  out.sides[0] = a.report;
  out.sides[1] = b.report;
  for (const SectionData& d : sections) {
    const Net net = sectionNet(d, ma, mb, kA, kB);
    const Sampled sampled = sampleSection(net, kSamples, true);
    if (sampled.folded) throw InputError("the blend would cross itself: its section at u = " + num(d.u) + " folds");
    FaceBlendSection section;
    section.u = d.u;
    section.sampledExtrema = sampled.extrema;
    section.variation = sampled.variation;
    section.kappaMin = sampled.kappaMin;
    section.kappaMax = sampled.kappaMax;
    BSplineCurve c;
    c.degree = n;
    c.poles.resize(n + 1, 3);
    c.weights.resize(n + 1);
    for (int i = 0; i <= n; ++i) {
      c.poles.row(i) = euclid(net.row(i).transpose()).transpose();
      c.weights[i] = net(i, 3);
    }
    c.knots.resize(2);
    c.knots << 0.0, 1.0;
    c.mults.resize(2);
    c.mults << n + 1, n + 1;
    try {
      const SpaceCurvatureCertificate certificate = certifySpaceCurvature(c);
      section.monotone = certificate.monotone;
      section.curvatureExtrema = static_cast<int>(certificate.extrema.size());
      section.reason = certificate.reason;
    } catch (const InputError& e) {
      section.curvatureExtrema = sampled.extrema;
      section.reason = std::string("not certified: ") + e.what();
    }
    out.sections.push_back(section);
  }
  return out;
}

}  // namespace fairsplines
