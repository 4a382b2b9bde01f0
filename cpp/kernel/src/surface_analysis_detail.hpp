// Shared by surface_analysis.cpp, surface_continuity.cpp and surface_curvature_map.cpp:
// the frame of a face at a parameter, in the face's sign convention, and the principal
// curvatures from its fundamental forms.
#pragma once
#include <BRepAdaptor_Surface.hxx>
#include <TopoDS_Face.hxx>
#include <cstddef>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>
#include <memory>
#include <vector>

#include "fairsplines/surface_analysis.hpp"
#include "surface_curvature_batch.hpp"
#include "surface_patches.hpp"

namespace fairsplines::detail {

/// The first and second fundamental forms at a point, the second measured against the face
/// normal n and with the designer's sign (convex positive as seen from n).
struct SurfaceFrame {
  gp_Pnt p;
  gp_Vec su, sv, n;
  double E = 0, F = 0, G = 0;  ///< I = [E F; F G]
  double L = 0, M = 0, N = 0;  ///< II = [L M; M N]
};

/// Principal curvatures k1 >= k2 and unit directions (dir1 x dir2 = n).
struct Principal {
  double k1 = 0, k2 = 0;
  gp_Vec dir1, dir2;
  PointState state = PointState::Regular;
};

/// A face's surface with its location, orientation and parameter bounds.
class FaceSurface {
public:
  explicit FaceSurface(const TopoDS_Face& face);
  /// The frame at (u, v); false where Su x Sv vanishes (a degenerate point), frame unset.
  /// May throw Standard_Failure (an offset surface where it is undefined).
  bool frame(double u, double v, SurfaceFrame& f) const;
  /// The frame and principal curvatures at (u, v), at a degenerate point the limit from
  /// inside the face; false where that limit does not exist (curvature growing without
  /// bound towards the point: a cone's apex), with the values just inside the face.
  bool curvature(double u, double v, SurfaceFrame& f, Principal& k) const;
  /// The points and derivatives at m parameters (the rows (u, v) of uv, `stride` doubles
  /// apart) into the batch, each the same bits as frame's. May throw Standard_Failure.
  void jets(const double* uv, std::ptrdiff_t stride, int m, CurvatureBatch& batch) const;
  /// Whether threads may evaluate it at once: its own patches are read-only, where OCCT's
  /// adaptor keeps a cache it rewrites.
  bool threadSafe() const { return patches_ != nullptr; }
  double u0, u1, v0, v1;  ///< the face's parameter bounds (BRepTools::UVBounds)
  double sign;            ///< +1 for a forward face, -1 for a reversed one

private:
  BRepAdaptor_Surface surface_;
  /// B-spline and Bezier faces: their spans in power form (surface_patches.hpp), evaluated
  /// in place of surface_ (2-3 times faster on scattered points); null for other faces.
  std::unique_ptr<PowerPatches> patches_;
};

/// Principal curvatures from the fundamental forms (do Carmo, Differential Geometry of
/// Curves and Surfaces, §3-3: the shape operator's matrix is I^-1 II).
Principal principalCurvatures(const SurfaceFrame& f);

/// The normal curvature II(a, a) / I(a, a) in the 3D tangent direction d (projected into the
/// tangent plane and written a = (du, dv) in the basis Su, Sv); 0 if d is normal to it.
double normalCurvature(const SurfaceFrame& f, const gp_Vec& d);

}  // namespace fairsplines::detail
