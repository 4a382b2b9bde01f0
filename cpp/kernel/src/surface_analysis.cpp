// Principal curvatures on any face (issue 27), vectorised over points: the shape operator
// from the first and second fundamental forms (do Carmo, Differential Geometry of Curves
// and Surfaces, §3-3, Prop. 3 and the expressions of K and H in the local coordinates).
// OCCT evaluates the surface (BRepAdaptor_Surface::D2, the face's location applied), or for
// B-spline and Bezier faces their spans in power form (surface_patches.cpp).
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <sstream>
#include <vector>

#include "fairsplines/errors.hpp"
#include "fairsplines/surface_analysis.hpp"
#include "finite.hpp"
#include "surface_analysis_detail.hpp"

namespace fairsplines {

// ---- reading shapes

TopoDS_Shape readBrepShape(const std::string& text) {
  if (text.empty()) throw InputError("the shape is empty (no BRep text)");
  std::istringstream in(text);
  TopoDS_Shape shape;
  BRep_Builder builder;
  try {
    BRepTools::Read(shape, in, builder);
  } catch (const Standard_Failure& e) {
    throw InputError(std::string("the shape's BRep text could not be read (") + e.GetMessageString() + ")");
  }
  if (shape.IsNull()) throw InputError("the shape's BRep text holds no shape");
  return shape;
}

TopoDS_Face singleFace(const TopoDS_Shape& shape) {
  if (shape.IsNull()) throw InputError("the shape is null");
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(shape, TopAbs_FACE, faces);
  if (faces.Extent() != 1) {
    throw InputError("expected one face, got a shape with " + std::to_string(faces.Extent()) + " faces");
  }
  return TopoDS::Face(faces(1));
}

namespace detail {

// ---- the frame in the face's sign convention

FaceSurface::FaceSurface(const TopoDS_Face& face) : surface_(face, false) {
  BRepTools::UVBounds(face, u0, u1, v0, v1);
  // The conversion from OCCT's convention: OCCT measures II against Su x Sv and a convex
  // sphere reads -1/R (GeomLProp_SLProps, Face.curvatureAt, whatever the orientation);
  // here II is measured against the face normal n = sign (Su x Sv) (Face.normalAt's) with
  // the opposite sign, L = -Suu.n, so convex as seen from n is positive.
  sign = face.Orientation() == TopAbs_REVERSED ? -1.0 : 1.0;
  if (surface_.GetType() == GeomAbs_BSplineSurface || surface_.GetType() == GeomAbs_BezierSurface) {
    patches_ = PowerPatches::of(face);
  }
}

bool FaceSurface::frame(double u, double v, SurfaceFrame& f) const {
  gp_Vec suu, svv, suv;
  if (patches_) {
    patches_->d2(u, v, f.p, f.su, f.sv, suu, svv, suv);
  } else {
    surface_.D2(u, v, f.p, f.su, f.sv, suu, svv, suv);
  }
  f.E = f.su.Dot(f.su);
  f.F = f.su.Dot(f.sv);
  f.G = f.sv.Dot(f.sv);
  const gp_Vec cross = f.su.Crossed(f.sv);
  const double length = cross.Magnitude();
  // Su x Sv vanishing against the larger of |Su|^2, |Sv|^2: a pole, an apex, a collapsed row.
  if (!(length > 1e-9 * std::max(f.E, f.G))) return false;
  f.n = cross * (sign / length);
  f.L = -suu.Dot(f.n);
  f.M = -suv.Dot(f.n);
  f.N = -svv.Dot(f.n);
  return true;
}

namespace {

double largest(const Principal& k) { return std::max(std::abs(k.k1), std::abs(k.k2)); }

}  // namespace

bool FaceSurface::curvature(double u, double v, SurfaceFrame& f, Principal& k) const {
  if (frame(u, v, f)) {
    k = principalCurvatures(f);
    return true;
  }
  // A degenerate point: the limit along a path into the face, towards the centre of its
  // parameter box, at two distances (1e-5 and 1e-7 of the box). Where the curvature is
  // continuous (a sphere's pole) both agree; where it grows like 1/distance (a cone's apex)
  // the nearer one is 100 times larger and there is no limit.
  double du = 0.5 * (u0 + u1) - u, dv = 0.5 * (v0 + v1) - v;
  const double wu = std::max(u1 - u0, 1e-300), wv = std::max(v1 - v0, 1e-300);
  const double norm = std::hypot(du / wu, dv / wv);
  if (!(norm > 0.0)) {
    du = wu;
    dv = 0.0;
  } else {
    du /= norm;
    dv /= norm;
  }
  SurfaceFrame far;
  if (!frame(u + 1e-5 * du, v + 1e-5 * dv, far) || !frame(u + 1e-7 * du, v + 1e-7 * dv, f)) {
    k = Principal{};
    k.dir1 = gp_Vec(1, 0, 0);
    k.dir2 = gp_Vec(0, 1, 0);
    f.n = gp_Vec(0, 0, 1);
    return false;
  }
  const Principal kFar = principalCurvatures(far);
  k = principalCurvatures(f);
  k.state = PointState::Degenerate;
  return largest(k) <= 10.0 * largest(kFar) + 1e-300;
}

// ---- principal curvatures (do Carmo §3-3)

Principal principalCurvatures(const SurfaceFrame& f) {
  Principal k;
  const double det = f.E * f.G - f.F * f.F;  // det I > 0 away from degenerate points
  const double inverse = 1.0 / det;          // one division, four products
  // The shape operator's matrix W = I^-1 II = [a b; c d].
  const double a = (f.G * f.L - f.F * f.M) * inverse, b = (f.G * f.M - f.F * f.N) * inverse;
  const double c = (f.E * f.M - f.F * f.L) * inverse, d = (f.E * f.N - f.F * f.M) * inverse;
  const double H = 0.5 * (a + d);                      // mean curvature, (EN - 2FM + GL) / 2 det
  const double K = (f.L * f.N - f.M * f.M) * inverse;  // Gaussian curvature, det II / det I
  const double half = 0.5 * (a - d);
  const double r = std::sqrt(std::max(half * half + b * c, 0.0));  // k1,2 = H +- sqrt(H^2 - K)
  // The root without cancellation first, the other from k1 k2 = K.
  if (H >= 0.0) {
    k.k1 = H + r;
    k.k2 = k.k1 != 0.0 ? K / k.k1 : H - r;
  } else {
    k.k2 = H - r;
    k.k1 = K / k.k2;
  }
  if (k.k2 > k.k1) std::swap(k.k1, k.k2);  // rounding of K / k1 at an umbilic
  // The eigenvector of W for k1: (W - k1) x = 0, from the better-conditioned row.
  const double x0a = b, x1a = k.k1 - a, x0b = k.k1 - d, x1b = c;
  const bool rowA = x0a * x0a + x1a * x1a >= x0b * x0b + x1b * x1b;
  const double x0 = rowA ? x0a : x0b, x1 = rowA ? x1a : x1b;
  gp_Vec dir = f.su * x0 + f.sv * x1;
  const double scale = std::max(std::abs(k.k1), std::abs(k.k2));
  const double gap = 1e-12 * (k.k1 - k.k2);
  // Umbilic (k1 = k2 to 1e-8 of their size, a plane included): every direction is
  // principal; dir1 is Su. So is the direction of a near-umbilic that rounding hides:
  // |dir| <= 1e-12 (k1 - k2) sqrt(E + G), compared squared (no square roots).
  if (!(k.k1 - k.k2 > 1e-8 * scale) || !(dir.SquareMagnitude() > gap * gap * (f.E + f.G))) {
    k.state = PointState::Umbilic;
    dir = f.su.Magnitude() > 0.0 ? f.su : f.sv;
  }
  // Orthogonal to n exactly (dir lies in the tangent plane up to rounding).
  dir -= f.n * dir.Dot(f.n);
  k.dir1 = dir.Normalized();
  k.dir2 = f.n.Crossed(k.dir1);
  return k;
}

double normalCurvature(const SurfaceFrame& f, const gp_Vec& d) {
  // a = I^-1 (Su.d, Sv.d): the tangent vector in the basis Su, Sv (least squares for a d
  // that leaves the tangent plane); kappa_n = II(a, a) / I(a, a).
  const double det = f.E * f.G - f.F * f.F;
  const double p = f.su.Dot(d), q = f.sv.Dot(d);
  const double a0 = (f.G * p - f.F * q) / det, a1 = (f.E * q - f.F * p) / det;
  const double I = f.E * a0 * a0 + 2.0 * f.F * a0 * a1 + f.G * a1 * a1;
  const double II = f.L * a0 * a0 + 2.0 * f.M * a0 * a1 + f.N * a1 * a1;
  return I > 0.0 ? II / I : 0.0;
}

}  // namespace detail

// ---- the vectorised entry point

namespace {

std::string pointName(Eigen::Index i, double u, double v) {
  return "point " + std::to_string(i) + " (u = " + exactNumber(u) + ", v = " + exactNumber(v) + ")";
}

}  // namespace

void surfaceCurvature(const TopoDS_Face& face, const PointsRef& uv, Eigen::Ref<CurvatureBlock> values,
                      Eigen::Ref<PointStates> state) {
  if (face.IsNull()) throw InputError("the face is null");
  if (uv.cols() != 2) throw InputError("uv must have 2 columns (u, v), got " + std::to_string(uv.cols()));
  const Eigen::Index n = uv.rows();
  if (n == 0) throw InputError("uv is empty: no points to evaluate");
  if (values.rows() != n || state.rows() != n) {
    throw InputError("the results need " + std::to_string(n) + " rows, one per uv point, got " +
                     std::to_string(values.rows()) + " and " + std::to_string(state.rows()));
  }
  const detail::FaceSurface surface(face);
  const double wu = surface.u1 - surface.u0, wv = surface.v1 - surface.v0;
  if (!(std::isfinite(wu) && std::isfinite(wv))) throw InputError("the face is unbounded: trim it first");
  for (Eigen::Index i = 0; i < n; ++i) {
    const double u = uv(i, 0), v = uv(i, 1);
    if (!(std::isfinite(u) && std::isfinite(v))) throw InputError("uv point " + std::to_string(i) + " is not finite");
    if (u < surface.u0 - 0.1 * wu || u > surface.u1 + 0.1 * wu || v < surface.v0 - 0.1 * wv ||
        v > surface.v1 + 0.1 * wv) {
      throw InputError(pointName(i, u, v) + " is outside the face's parameter range u in [" + exactNumber(surface.u0) +
                       ", " + exactNumber(surface.u1) + "], v in [" + exactNumber(surface.v0) + ", " +
                       exactNumber(surface.v1) + "] by more than 10%");
    }
  }
  namespace column = curvature_column;
  detail::Principal k;
  // Each point's 16 values go straight into the caller's block, one column each.
  const auto put = [&values](Eigen::Index i, int c, const gp_XYZ& x) {
    values(i, c) = x.X();
    values(i, c + 1) = x.Y();
    values(i, c + 2) = x.Z();
  };
  // OCCT throws where a surface cannot be evaluated (an offset surface past its validity).
  const auto guarded = [&uv](Eigen::Index i, auto&& evaluate) {
    try {
      return evaluate();
    } catch (const Standard_Failure& e) {
      throw InputError("the surface cannot be evaluated at " + pointName(i, uv(i, 0), uv(i, 1)) + " (" +
                       e.GetMessageString() + ")");
    }
  };
  // In batches: the frames of a few points, then their curvatures. Both are chains of square
  // roots and divisions; the points of a batch are independent, and in these shorter loops the
  // processor overlaps their chains (one point's whole evaluation is too long for it to reach
  // the next point's).
  constexpr Eigen::Index kBatch = 8;
  detail::SurfaceFrame frames[kBatch];
  bool regular[kBatch];
  for (Eigen::Index i0 = 0; i0 < n; i0 += kBatch) {
    const Eigen::Index m = std::min(kBatch, n - i0);
    for (Eigen::Index j = 0; j < m; ++j) {
      const Eigen::Index i = i0 + j;
      regular[j] = guarded(i, [&] { return surface.frame(uv(i, 0), uv(i, 1), frames[j]); });
    }
    for (Eigen::Index j = 0; j < m; ++j) {
      const Eigen::Index i = i0 + j;
      const double u = uv(i, 0), v = uv(i, 1);
      detail::SurfaceFrame& f = frames[j];
      if (regular[j]) {
        k = detail::principalCurvatures(f);
      } else if (!guarded(i, [&] { return surface.curvature(u, v, f, k); })) {  // the limit at a degenerate point
        throw InputError("the curvature is not defined at " + pointName(i, u, v) +
                         ": the surface is singular there (an apex or a collapsed edge) and the curvature grows "
                         "without bound towards it");
      }
      const double K = k.k1 * k.k2;
      if (!(std::isfinite(k.k1) && std::isfinite(k.k2) && std::isfinite(K))) {
        throw InputError("the curvature at " + pointName(i, u, v) + " is beyond double precision");
      }
      // Unit vectors: their sum is finite exactly when each coordinate is.
      if (!std::isfinite(k.dir1.X() + k.dir1.Y() + k.dir1.Z() + f.n.X() + f.n.Y() + f.n.Z())) {
        throw InputError("the principal directions or the normal at " + pointName(i, u, v) +
                         " are not finite: the surface is too large, too small or too close to singular there for "
                         "double precision");
      }
      values(i, column::k1) = k.k1;
      values(i, column::k2) = k.k2;
      values(i, column::gaussian) = K;
      values(i, column::mean) = 0.5 * (k.k1 + k.k2);
      put(i, column::dir1, k.dir1.XYZ());
      put(i, column::dir2, k.dir2.XYZ());
      put(i, column::normal, f.n.XYZ());
      put(i, column::point, f.p.XYZ());
      state[i] = static_cast<std::int8_t>(k.state);
    }
  }
}

SurfaceCurvature surfaceCurvature(const TopoDS_Face& face, const PointsRef& uv) {
  SurfaceCurvature out;
  out.values.resize(uv.rows(), Eigen::NoChange);
  out.state.resize(uv.rows());
  surfaceCurvature(face, uv, out.values, out.state);
  return out;
}

}  // namespace fairsplines
