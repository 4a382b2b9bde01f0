// A curvature map of a shape's faces (issue 27): OCCT's mesh (BRepMesh), the quantity at
// every vertex from the exact surface (surface_analysis.cpp's frame, at the vertex's
// (u, v)), and edges split where the quantity changes fast, so that colours do not alias on
// small fillets. The split is conforming inside a face: each marked edge gets one midpoint
// (in (u, v), evaluated on the surface), shared by the triangles on both sides, and a
// triangle with 1, 2 or 3 marked edges becomes 2, 3 or 4 triangles (red-green refinement).
#include <BRepBndLib.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <Poly_Triangulation.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopLoc_Location.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <vector>

#include "fairsplines/errors.hpp"
#include "fairsplines/surface_analysis.hpp"
#include "finite.hpp"
#include "surface_analysis_detail.hpp"

namespace fairsplines {

MapQuantity parseMapQuantity(const std::string& name) {
  if (name == "gaussian") return MapQuantity::Gaussian;
  if (name == "mean") return MapQuantity::Mean;
  if (name == "max_abs") return MapQuantity::MaxAbs;
  if (name == "min") return MapQuantity::Min;
  if (name == "max") return MapQuantity::Max;
  if (name == "radius") return MapQuantity::Radius;
  throw InputError("unknown quantity '" + name + "': one of gaussian, mean, max_abs, min, max, radius");
}

namespace {

constexpr Eigen::Index kMaxTriangles = 4'000'000;  // bounds the refinement's work

/// One face's mesh in (u, v) with points and values.
struct FaceMesh {
  std::vector<double> u, v, value;
  std::vector<gp_Pnt> p;
  std::vector<gp_Vec> n;       ///< the face's unit normal (orientation included; zero where singular)
  std::vector<char> singular;  ///< no curvature there (a cone's apex): the value is its neighbours' mean
  std::vector<std::array<int, 3>> triangles;
};

double quantityOf(MapQuantity q, const detail::Principal& k, double flatRadius) {
  switch (q) {
    case MapQuantity::Gaussian:
      return k.k1 * k.k2;
    case MapQuantity::Mean:
      return 0.5 * (k.k1 + k.k2);
    case MapQuantity::MaxAbs:
      return std::max(std::abs(k.k1), std::abs(k.k2));
    case MapQuantity::Min:
      return k.k2;
    case MapQuantity::Max:
      return k.k1;
    case MapQuantity::Radius: {
      const double m = std::max(std::abs(k.k1), std::abs(k.k2));
      return m * flatRadius > 1.0 ? 1.0 / m : flatRadius;
    }
  }
  return 0.0;
}

/// The quantity at (u, v); a singular point (a cone's apex, or where the surface cannot be
/// evaluated) is marked, and smoothSingular gives it its neighbours' mean.
void addVertex(FaceMesh& mesh, const detail::FaceSurface& surface, MapQuantity q, double flatRadius, double u, double v,
               const gp_Pnt* meshPoint) {
  detail::SurfaceFrame f;
  detail::Principal k;
  double value = 0.0;
  gp_Pnt p = meshPoint ? *meshPoint : gp_Pnt();
  bool defined = false;
  try {
    defined = surface.curvature(u, v, f, k);
    value = quantityOf(q, k, flatRadius);
    if (!meshPoint) p = f.p;
  } catch (const Standard_Failure&) {
    defined = false;
  }
  if (!std::isfinite(value)) defined = false;
  if (!defined) value = 0.0;
  mesh.singular.push_back(!defined);
  mesh.u.push_back(u);
  mesh.v.push_back(v);
  mesh.p.push_back(p);
  mesh.n.push_back(defined ? f.n : gp_Vec(0.0, 0.0, 0.0));
  mesh.value.push_back(value);
}

/// Singular vertices take the mean of their regular neighbours' values (0 without any) and
/// the normalised mean of their normals (zero without any).
void smoothSingular(FaceMesh& mesh) {
  std::vector<double> sum(mesh.value.size(), 0.0);
  std::vector<gp_Vec> normals(mesh.value.size(), gp_Vec(0.0, 0.0, 0.0));
  std::vector<int> count(mesh.value.size(), 0);
  for (const auto& t : mesh.triangles) {
    for (int a = 0; a < 3; ++a) {
      for (int b = 0; b < 3; ++b) {
        if (mesh.singular[t[a]] && !mesh.singular[t[b]]) {
          sum[t[a]] += mesh.value[t[b]];
          normals[t[a]] += mesh.n[t[b]];
          ++count[t[a]];
        }
      }
    }
  }
  for (std::size_t i = 0; i < sum.size(); ++i) {
    if (!mesh.singular[i]) continue;
    mesh.value[i] = count[i] > 0 ? sum[i] / count[i] : 0.0;
    const double length = normals[i].Magnitude();
    mesh.n[i] = length > 0.0 ? normals[i] / length : gp_Vec(0.0, 0.0, 0.0);
  }
}

/// One pass of red-green refinement: edges whose values differ by more than `threshold`
/// get a midpoint. Returns whether anything was split.
bool refinePass(FaceMesh& mesh, const detail::FaceSurface& surface, MapQuantity q, double flatRadius, double threshold,
                Eigen::Index budget) {
  std::map<std::pair<int, int>, int> midpoint;
  auto key = [](int a, int b) { return std::make_pair(std::min(a, b), std::max(a, b)); };
  for (const auto& t : mesh.triangles) {
    for (int e = 0; e < 3; ++e) {
      const int a = t[e], b = t[(e + 1) % 3];
      if (std::abs(mesh.value[a] - mesh.value[b]) > threshold) midpoint.emplace(key(a, b), -1);
    }
  }
  if (midpoint.empty() || static_cast<Eigen::Index>(mesh.triangles.size() + 3 * midpoint.size()) > budget) {
    return false;
  }
  for (auto& [edge, index] : midpoint) {
    index = static_cast<int>(mesh.u.size());
    addVertex(mesh, surface, q, flatRadius, 0.5 * (mesh.u[edge.first] + mesh.u[edge.second]),
              0.5 * (mesh.v[edge.first] + mesh.v[edge.second]), nullptr);
  }
  std::vector<std::array<int, 3>> next;
  next.reserve(mesh.triangles.size() * 2);
  for (const auto& t : mesh.triangles) {
    std::array<int, 3> m;
    int marked = 0;
    for (int e = 0; e < 3; ++e) {
      const auto it = midpoint.find(key(t[e], t[(e + 1) % 3]));
      m[e] = it == midpoint.end() ? -1 : it->second;
      marked += m[e] >= 0;
    }
    if (marked == 0) {
      next.push_back(t);
    } else if (marked == 3) {
      next.push_back({t[0], m[0], m[2]});
      next.push_back({m[0], t[1], m[1]});
      next.push_back({m[2], m[1], t[2]});
      next.push_back({m[0], m[1], m[2]});
    } else {
      // Rotate so that edge 0 (t0, t1) is marked; with two marked, edge 1 or 2 is the other.
      int r = 0;
      while (m[r] < 0) ++r;
      if (marked == 2 && m[(r + 2) % 3] >= 0) r = (r + 2) % 3;
      const int a = t[r], b = t[(r + 1) % 3], c = t[(r + 2) % 3];
      const int mab = m[r], mbc = m[(r + 1) % 3];
      if (marked == 1) {
        next.push_back({a, mab, c});
        next.push_back({mab, b, c});
      } else {  // edges ab and bc marked
        next.push_back({a, mab, c});
        next.push_back({mab, b, mbc});
        next.push_back({mab, mbc, c});
      }
    }
  }
  mesh.triangles.swap(next);
  smoothSingular(mesh);
  return true;
}

}  // namespace

CurvatureMap curvatureMap(const TopoDS_Shape& shape, MapQuantity quantity, double deflection, double fraction,
                          int levels) {
  if (shape.IsNull()) throw InputError("the shape is null");
  if (!(deflection >= 0.0) || !std::isfinite(deflection)) throw InputError("the deflection must be >= 0");
  if (!(fraction > 0.0 && fraction <= 1.0)) throw InputError("the refinement fraction must be in (0, 1]");
  if (levels < 0 || levels > 8) throw InputError("the refinement levels must be from 0 to 8");
  TopTools_IndexedMapOfShape faces;
  TopExp::MapShapes(shape, TopAbs_FACE, faces);
  if (faces.Extent() == 0) throw InputError("the shape has no faces");
  Bnd_Box box;
  BRepBndLib::Add(shape, box);
  const double size = box.IsVoid() ? 1.0 : std::sqrt(box.SquareExtent());
  if (!(size > 0.0) || !std::isfinite(size)) throw InputError("the shape has no extent");
  if (deflection > 0.0 && deflection < 1e-6 * size) {
    throw InputError("the deflection " + std::to_string(deflection) + " is below 1e-6 of the shape's size (" +
                     std::to_string(size) + "): the mesh would have billions of triangles");
  }
  const double flatRadius = 1e3 * size;
  try {
    BRepMesh_IncrementalMesh mesher(shape, deflection > 0.0 ? deflection : 1e-3 * size, false, 0.35, false);
  } catch (const Standard_Failure& e) {
    throw InputError(std::string("the shape could not be meshed (") + e.GetMessageString() + ")");
  }

  std::vector<FaceMesh> meshes(faces.Extent());
  std::vector<std::unique_ptr<detail::FaceSurface>> surfaces;
  surfaces.reserve(faces.Extent());
  double lo = HUGE_VAL, hi = -HUGE_VAL;
  for (int i = 1; i <= faces.Extent(); ++i) {
    const TopoDS_Face face = TopoDS::Face(faces(i));
    surfaces.push_back(std::make_unique<detail::FaceSurface>(face));
    TopLoc_Location location;
    const Handle(Poly_Triangulation) mesh = BRep_Tool::Triangulation(face, location);
    if (mesh.IsNull() || !mesh->HasUVNodes()) continue;  // a face BRepMesh could not mesh: left out
    FaceMesh& m = meshes[i - 1];
    for (int j = 1; j <= mesh->NbNodes(); ++j) {
      const gp_Pnt p = mesh->Node(j).Transformed(location.Transformation());
      const gp_Pnt2d uv = mesh->UVNode(j);
      addVertex(m, *surfaces.back(), quantity, flatRadius, uv.X(), uv.Y(), &p);
    }
    const bool reversed = face.Orientation() == TopAbs_REVERSED;
    for (int j = 1; j <= mesh->NbTriangles(); ++j) {
      int a, b, c;
      mesh->Triangle(j).Get(a, b, c);
      m.triangles.push_back(reversed ? std::array<int, 3>{a - 1, c - 1, b - 1}
                                     : std::array<int, 3>{a - 1, b - 1, c - 1});
    }
    smoothSingular(m);
    for (double x : m.value) lo = std::min(lo, x), hi = std::max(hi, x);
  }
  // Refinement against the range over the whole shape (not a range of rounding errors).
  if (hi - lo > 1e-9 * std::max(std::abs(hi), std::abs(lo))) {
    const double threshold = fraction * (hi - lo);
    for (int level = 0; level < levels; ++level) {
      Eigen::Index total = 0;
      for (const FaceMesh& m : meshes) total += static_cast<Eigen::Index>(m.triangles.size());
      bool any = false;
      for (std::size_t i = 0; i < meshes.size(); ++i) {
        const Eigen::Index own = static_cast<Eigen::Index>(meshes[i].triangles.size());
        if (refinePass(meshes[i], *surfaces[i], quantity, flatRadius, threshold, kMaxTriangles - total + own)) {
          any = true;
          total += static_cast<Eigen::Index>(meshes[i].triangles.size()) - own;
        }
      }
      if (!any) break;
    }
  }
  // Gather.
  Eigen::Index nPoints = 0, nTriangles = 0;
  for (const FaceMesh& m : meshes) {
    nPoints += static_cast<Eigen::Index>(m.p.size());
    nTriangles += static_cast<Eigen::Index>(m.triangles.size());
  }
  if (nTriangles == 0) throw InputError("the shape could not be meshed: no face has triangles");
  CurvatureMap out;
  out.points.resize(nPoints, 3);
  out.normals.resize(nPoints, 3);
  out.values.resize(nPoints);
  out.triangles.resize(nTriangles, 3);
  out.face.resize(nTriangles);
  out.faceRanges.setZero(faces.Extent(), 2);
  Eigen::Index p0 = 0, t0 = 0;
  for (std::size_t i = 0; i < meshes.size(); ++i) {
    const FaceMesh& m = meshes[i];
    for (std::size_t j = 0; j < m.p.size(); ++j) {
      out.points.row(p0 + j) << m.p[j].X(), m.p[j].Y(), m.p[j].Z();
      out.normals.row(p0 + j) << m.n[j].X(), m.n[j].Y(), m.n[j].Z();
      out.values[p0 + j] = m.value[j];
    }
    for (std::size_t j = 0; j < m.triangles.size(); ++j) {
      out.triangles.row(t0 + j) << m.triangles[j][0] + p0, m.triangles[j][1] + p0, m.triangles[j][2] + p0;
      out.face[t0 + j] = static_cast<int>(i) + 1;
    }
    if (!m.value.empty()) {
      out.faceRanges(i, 0) = *std::min_element(m.value.begin(), m.value.end());
      out.faceRanges(i, 1) = *std::max_element(m.value.begin(), m.value.end());
    }
    p0 += static_cast<Eigen::Index>(m.p.size());
    t0 += static_cast<Eigen::Index>(m.triangles.size());
  }
  requireFinite(out.points, "the curvature map", "points");
  return out;
}

}  // namespace fairsplines
