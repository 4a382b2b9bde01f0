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
#include <exception>
#include <memory>
#include <numeric>
#include <sstream>
#include <thread>
#include <vector>

#include "fairsplines/errors.hpp"
#include "fairsplines/surface_analysis.hpp"
#include "finite.hpp"
#include "surface_analysis_detail.hpp"
#include "surface_lanes.hpp"

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

namespace {

lanes::Vec3 vec3(const gp_Vec& x) { return {x.X(), x.Y(), x.Z()}; }
gp_Vec vec(const lanes::Vec3& x) { return gp_Vec(x.x, x.y, x.z); }

}  // namespace

bool FaceSurface::frame(double u, double v, SurfaceFrame& f) const {
  gp_Vec suu, svv, suv;
  if (patches_) {
    patches_->d2(u, v, f.p, f.su, f.sv, suu, svv, suv);
  } else {
    surface_.D2(u, v, f.p, f.su, f.sv, suu, svv, suv);
  }
  const lanes::Forms forms = lanes::forms(vec3(f.su), vec3(f.sv), vec3(suu), vec3(svv), vec3(suv), sign);
  if (!forms.regular()) return false;
  f.E = forms.E;
  f.F = forms.F;
  f.G = forms.G;
  f.n = vec(forms.n);
  f.L = forms.L;
  f.M = forms.M;
  f.N = forms.N;
  return true;
}

void FaceSurface::jets(const double* uv, std::ptrdiff_t stride, int m, CurvatureBatch& b) const {
  if (patches_) {
    patches_->jets(uv, stride, m, b);
    return;
  }
  gp_Pnt p;
  gp_Vec su, sv, suu, svv, suv;
  for (int i = 0; i < m; ++i) {
    surface_.D2(uv[i * stride], uv[i * stride + 1], p, su, sv, suu, svv, suv);
    for (int c = 0; c < 3; ++c) {
      b.p[c][i] = p.Coord(c + 1);
      b.su[c][i] = su.Coord(c + 1);
      b.sv[c][i] = sv.Coord(c + 1);
      b.suu[c][i] = suu.Coord(c + 1);
      b.svv[c][i] = svv.Coord(c + 1);
      b.suv[c][i] = suv.Coord(c + 1);
    }
  }
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
  lanes::Forms forms{};  // (length and size, the regularity test, stay 0: principal reads neither)
  forms.n = vec3(f.n);
  forms.E = f.E;
  forms.F = f.F;
  forms.G = f.G;
  forms.L = f.L;
  forms.M = f.M;
  forms.N = f.N;
  const lanes::Curvatures c = lanes::principal(forms, vec3(f.su), vec3(f.sv));
  Principal k;
  k.k1 = c.k1;
  k.k2 = c.k2;
  k.dir1 = vec(c.dir1);
  k.dir2 = vec(c.dir2);
  k.state = c.umbilic != 0.0 ? PointState::Umbilic : PointState::Regular;
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

/// A thread evaluates at least this many points (about 0.8 ms of work: starting a thread
/// costs some 50 us).
constexpr Eigen::Index kPointsPerThread = 16384;

/// The threads a call may use: `threads`, or where it is 0 the processor's cores (at most 8).
Eigen::Index threadCount(int threads) {
  if (threads > 0) return std::min(threads, 64);
  return std::clamp<Eigen::Index>(std::thread::hardware_concurrency(), 1, 8);
}

std::string pointName(Eigen::Index i, double u, double v) {
  return "point " + std::to_string(i) + " (u = " + exactNumber(u) + ", v = " + exactNumber(v) + ")";
}

}  // namespace

void surfaceCurvature(const TopoDS_Face& face, const PointsRef& uv, Eigen::Ref<CurvatureBlock> values,
                      Eigen::Ref<PointStates> state, int threads) {
  if (face.IsNull()) throw InputError("the face is null");
  if (threads < 0) throw InputError("threads must be 0 (one a core) or more, got " + std::to_string(threads));
  if (uv.cols() != 2) throw InputError("uv must have 2 columns (u, v), got " + std::to_string(uv.cols()));
  const Eigen::Index n = uv.rows();
  if (n == 0) throw InputError("uv is empty: no points to evaluate");
  if (values.rows() != n || state.rows() != n) {
    throw InputError("the results need " + std::to_string(n) + " rows, one per uv point, got " +
                     std::to_string(values.rows()) + " and " + std::to_string(state.rows()));
  }
  // The columns are written through pointers that alias nothing (surface_curvature_batch.hpp).
  if (values.outerStride() < n) {
    throw InputError("the results' columns overlap: their stride " + std::to_string(values.outerStride()) +
                     " is less than their " + std::to_string(n) + " rows");
  }
  const detail::FaceSurface surface(face);
  const double wu = surface.u1 - surface.u0, wv = surface.v1 - surface.v0;
  if (!(std::isfinite(wu) && std::isfinite(wv))) throw InputError("the face is unbounded: trim it first");
  const double uLow = surface.u0 - 0.1 * wu, uHigh = surface.u1 + 0.1 * wu;
  const double vLow = surface.v0 - 0.1 * wv, vHigh = surface.v1 + 0.1 * wv;
  // One vectorised pass; where it finds a point out, a second names it.
  const bool inside = detail::allInside(uv.data(), n, uv.outerStride(), uLow, uHigh, vLow, vHigh);
  for (Eigen::Index i = 0; !inside && i < n; ++i) {
    const double u = uv(i, 0), v = uv(i, 1);
    if (!(std::isfinite(u) && std::isfinite(v))) throw InputError("uv point " + std::to_string(i) + " is not finite");
    if (u < uLow || u > uHigh || v < vLow || v > vHigh) {
      throw InputError(pointName(i, u, v) + " is outside the face's parameter range u in [" + exactNumber(surface.u0) +
                       ", " + exactNumber(surface.u1) + "], v in [" + exactNumber(surface.v0) + ", " +
                       exactNumber(surface.v1) + "] by more than 10%");
    }
  }
  namespace column = curvature_column;
  // OCCT throws where a surface cannot be evaluated (an offset surface past its validity).
  const auto guarded = [&uv](Eigen::Index i, auto&& evaluate) {
    try {
      return evaluate();
    } catch (const Standard_Failure& e) {
      throw InputError("the surface cannot be evaluated at " + pointName(i, uv(i, 0), uv(i, 1)) + " (" +
                       e.GetMessageString() + ")");
    }
  };
  // The scalar path, for the points the batch leaves to it: a degenerate point's limit, and
  // the refusals, each naming its point.
  const auto scalar = [&](Eigen::Index i) {
    const double u = uv(i, 0), v = uv(i, 1);
    detail::SurfaceFrame f;
    detail::Principal k;
    if (guarded(i, [&] { return surface.frame(u, v, f); })) {
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
    const auto put = [&values, i](int c, const gp_XYZ& x) {
      values(i, c) = x.X();
      values(i, c + 1) = x.Y();
      values(i, c + 2) = x.Z();
    };
    values(i, column::k1) = k.k1;
    values(i, column::k2) = k.k2;
    values(i, column::gaussian) = K;
    values(i, column::mean) = 0.5 * (k.k1 + k.k2);
    put(column::dir1, k.dir1.XYZ());
    put(column::dir2, k.dir2.XYZ());
    put(column::normal, f.n.XYZ());
    put(column::point, f.p.XYZ());
    state[i] = static_cast<std::int8_t>(k.state);
  };
  // A batch at a time (surface_curvature_batch.hpp): the derivatives of its points, their
  // curvatures in one vectorised loop, written straight into the caller's columns.
  const std::ptrdiff_t stride = uv.outerStride();
  const auto evaluate = [&](Eigen::Index from, Eigen::Index to) {
    const auto batch = std::make_unique<detail::CurvatureBatch>();
    detail::CurvatureBatch& b = *batch;
    for (Eigen::Index i0 = from; i0 < to; i0 += detail::CurvatureBatch::kSize) {
      const int m = static_cast<int>(std::min<Eigen::Index>(detail::CurvatureBatch::kSize, to - i0));
      try {
        surface.jets(uv.data() + i0 * stride, stride, m, b);
      } catch (const Standard_Failure& e) {
        for (int j = 0; j < m; ++j) scalar(i0 + j);  // names the point that fails (the same evaluations)
        throw InputError(std::string("the surface cannot be evaluated (") + e.GetMessageString() + ")");
      }
      const auto at = [&values, i0](int c) { return values.col(c).data() + i0; };
      detail::CurvatureColumns out{
          at(column::k1), at(column::k2), at(column::gaussian), at(column::mean), {}, {}, {}, {}};
      for (int c = 0; c < 3; ++c) {
        out.dir1[c] = at(column::dir1 + c);
        out.dir2[c] = at(column::dir2 + c);
        out.normal[c] = at(column::normal + c);
        out.point[c] = at(column::point + c);
      }
      detail::curvaturesOfBatch(b, m, surface.sign, out);
      for (int j = 0; j < m; ++j) {
        if (b.verdict[j] == detail::CurvatureBatch::kScalar) {
          scalar(i0 + j);
        } else {
          state[i0 + j] = static_cast<std::int8_t>(b.verdict[j]);
        }
      }
    }
  };
  // Large calls on surfaces that threads may share (FaceSurface::threadSafe) are split into
  // consecutive ranges, one a thread; each range writes only its own rows. A refusal names
  // the first point that fails: the ranges' errors are rethrown in their order.
  const Eigen::Index ranges =
      surface.threadSafe() ? std::min<Eigen::Index>(threadCount(threads), n / kPointsPerThread) : 1;
  if (ranges <= 1) {
    evaluate(0, n);
    return;
  }
  const auto start = [n, ranges](Eigen::Index r) {
    return std::min(n, (n * r / ranges + detail::CurvatureBatch::kSize - 1) / detail::CurvatureBatch::kSize *
                           detail::CurvatureBatch::kSize);
  };
  std::vector<std::exception_ptr> errors(ranges);
  const auto guardedRange = [&](Eigen::Index r) {
    try {
      evaluate(start(r), start(r + 1));
    } catch (...) {
      errors[r] = std::current_exception();
    }
  };
  // Where a thread cannot start (a limit on threads, no memory), this one takes its range:
  // the threads started are joined whatever happens.
  std::vector<std::thread> workers;
  workers.reserve(ranges - 1);
  Eigen::Index started = 1;
  try {
    for (; started < ranges; ++started) workers.emplace_back(guardedRange, started);
  } catch (const std::exception&) {
  }
  guardedRange(0);
  for (Eigen::Index r = started; r < ranges; ++r) guardedRange(r);
  for (std::thread& w : workers) w.join();
  for (const std::exception_ptr& e : errors) {
    if (e) std::rethrow_exception(e);
  }
}

SurfaceCurvature surfaceCurvature(const TopoDS_Face& face, const PointsRef& uv, int threads) {
  SurfaceCurvature out;
  out.values.resize(uv.rows(), Eigen::NoChange);
  out.state.resize(uv.rows());
  surfaceCurvature(face, uv, out.values, out.state, threads);
  return out;
}

}  // namespace fairsplines
