// The shell of a blend complex from the grid the kernel built (issue 13): no sewing. The
// complex knows which patch sides meet, so every vertex and edge is made once and shared
// by the faces around it; the only numerics are the measured gaps between neighbours.
#include <BRep_Builder.hxx>
#include <Geom2d_Line.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Precision.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS_Wire.hxx>
#include <algorithm>
#include <array>
#include <cmath>
#include <gp_Dir2d.hxx>
#include <gp_Pnt2d.hxx>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

#include "fairsplines/blend_surface.hpp"
#include "fairsplines/errors.hpp"
#include "bernstein.hpp"
#include "finite.hpp"

namespace fairsplines {

namespace {

/// The four sides of a patch over [0,1]^2; each runs the way its parameter increases
/// (u for Bottom and Top, v for Left and Right).
enum Side { Bottom = 0, Right = 1, Top = 2, Left = 3 };
constexpr const char* kSideNames[] = {"bottom (v = 0)", "right (u = 1)", "top (v = 1)", "left (u = 0)"};
constexpr int kSamples = 24;  ///< intervals at which two patches' shared side is compared

/// The homogeneous Bézier points of one side of a patch, in the side's direction.
Homogeneous4 sidePoints(const TaggedPatch& p, Side side) {
  const int du = p.degreeU, dv = p.degreeV;
  const bool alongU = side == Bottom || side == Top;
  const int n = alongU ? du : dv;
  Homogeneous4 out(n + 1, 4);
  for (int k = 0; k <= n; ++k) {
    const int a = alongU ? k : (side == Right ? du : 0);
    const int b = alongU ? (side == Top ? dv : 0) : k;
    out.row(k) = p.bezier.row(a * (dv + 1) + b);
  }
  return out;
}

/// The side's points at t = s / kSamples (de Casteljau on the homogeneous points, projected).
std::vector<Eigen::Vector3d> sampled(const Homogeneous4& h) {
  std::vector<Eigen::Vector3d> out(kSamples + 1);
  for (int s = 0; s <= kSamples; ++s) {
    const Eigen::RowVector4d p = bernstein::value(h, static_cast<double>(s) / kSamples);
    out[s] = p.head<3>().transpose() / p[3];
  }
  return out;
}

const char* roleName(TaggedPatch::Role r) {
  return r == TaggedPatch::Role::Basic ? "basic" : r == TaggedPatch::Role::Transition ? "transition" : "freeform";
}

std::string patchName(const BlendComplex& c, int index) {
  const TaggedPatch& p = c.patches[index];
  std::ostringstream os;
  os << "patch " << index << " (" << roleName(p.role) << ", u piece " << p.uPiece << ", row " << p.vPiece << ")";
  return os.str();
}

/// Exact rational Bézier curve of a side (poles h / w, as patchToOcct makes them).
Handle(Geom_BSplineCurve) curveOf(const Homogeneous4& h) {
  const int n = static_cast<int>(h.rows()) - 1;
  TColgp_Array1OfPnt poles(1, n + 1);
  TColStd_Array1OfReal weights(1, n + 1), knots(1, 2);
  TColStd_Array1OfInteger mults(1, 2);
  for (int k = 0; k <= n; ++k) {
    poles.SetValue(k + 1, gp_Pnt(h(k, 0) / h(k, 3), h(k, 1) / h(k, 3), h(k, 2) / h(k, 3)));
    weights.SetValue(k + 1, h(k, 3));
  }
  knots.SetValue(1, 0.0);
  knots.SetValue(2, 1.0);
  mults.Init(n + 1);
  return new Geom_BSplineCurve(poles, weights, knots, mults, n);
}

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(int n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int i) { return parent[i] == i ? i : parent[i] = find(parent[i]); }
  void join(int a, int b) { parent[find(a)] = find(b); }
};

/// One patch side on an edge of the grid.
struct SideRef {
  int patch = -1;
  Side side = Bottom;
};

struct GridEdge {
  std::array<SideRef, 2> sides;  ///< the first owns the 3D curve; the second is absent (patch -1) on a free edge
  int from = 0, to = 0;          ///< grid corners at t = 0 and t = 1
  bool degenerated = false;
  double tolerance = 0.0;
};

}  // namespace

BlendShell blendShell(const BlendComplex& complex) {
  const int K = complex.piecesU;
  const int R = complex.rowsBasic + complex.rowsTransition + complex.rowsFreeForm;
  const int P = static_cast<int>(complex.patches.size());
  if (K < 1 || R < 1) throw InputError("the complex has no patches to make a shell of");

  // Every number finite, every weight positive, and the complex's size: extent (bounding box
  // diagonal) and magnitude (largest coordinate, which sets the rounding of the points).
  Eigen::Vector3d low = Eigen::Vector3d::Constant(HUGE_VAL), high = -low;
  double magnitude = 0.0;
  for (int i = 0; i < P; ++i) {
    const TaggedPatch& p = complex.patches[i];
    if (p.bezier.rows() != (p.degreeU + 1) * (p.degreeV + 1)) {
      throw InputError(patchName(complex, i) + " needs (degreeU + 1) (degreeV + 1) control points");
    }
    for (Eigen::Index k = 0; k < p.bezier.rows(); ++k) {
      const auto h = p.bezier.row(k);
      if (!h.allFinite()) throw InputError(patchName(complex, i) + " has a control point that is not finite");
      if (!(h[3] > 0)) throw InputError(patchName(complex, i) + " has a weight that is not positive");
      const Eigen::Vector3d q = h.head<3>().transpose() / h[3];
      if (!q.allFinite()) throw InputError(patchName(complex, i) + " has a control point that is not finite");
      low = low.cwiseMin(q);
      high = high.cwiseMax(q);
      magnitude = std::max(magnitude, q.cwiseAbs().maxCoeff());
    }
  }
  const double extent = (high - low).norm();
  if (!std::isfinite(extent)) throw InputError("the complex is too large for double precision (its extent overflows)");
  BlendShell out;
  // 1e-9 of the size, plus about 500 rounding units of the coordinates (far from the origin).
  out.allowedGap = 1e-9 * extent + 1e-13 * magnitude;
  out.tolerance = std::max(Precision::Confusion(), 1e-14 * magnitude);

  // The grid: cell (k, j) holds the patch over u piece k in row j.
  std::vector<int> cell(static_cast<size_t>(K) * R, -1);
  for (int i = 0; i < P; ++i) {
    const TaggedPatch& p = complex.patches[i];
    if (p.uPiece < 0 || p.uPiece >= K || p.vPiece < 0 || p.vPiece >= R) {
      std::ostringstream os;
      os << patchName(complex, i) << " lies outside the complex's grid of " << K << " u pieces and " << R << " rows";
      throw InputError(os.str());
    }
    int& c = cell[static_cast<size_t>(p.vPiece) * K + p.uPiece];
    if (c >= 0) throw InputError(patchName(complex, c) + " and " + patchName(complex, i) + " cover the same cell");
    c = i;
  }
  for (int j = 0; j < R; ++j) {
    for (int k = 0; k < K; ++k) {
      if (cell[static_cast<size_t>(j) * K + k] < 0) {
        std::ostringstream os;
        os << "no patch covers u piece " << k << " of row " << j << ": the complex is not a grid of patches";
        throw InputError(os.str());
      }
    }
  }
  auto at = [&](int k, int j) { return cell[static_cast<size_t>(j) * K + k]; };

  // Corners and edges of the grid; around a full turn column K is column 0.
  const bool closed = complex.closedU;
  const int columns = closed ? K : K + 1;
  auto corner = [&](int i, int j) { return j * columns + (closed ? i % K : i); };
  const int horizontal = K * (R + 1);  // along u: edge (k, j) at row line j
  std::vector<GridEdge> edges(static_cast<size_t>(horizontal) + static_cast<size_t>(columns) * R);
  std::vector<std::array<int, 4>> edgeOf(P);  // the edge of each patch side
  for (int j = 0; j <= R; ++j) {
    for (int k = 0; k < K; ++k) {
      GridEdge& e = edges[static_cast<size_t>(j) * K + k];
      int n = 0;
      if (j > 0) e.sides[n++] = {at(k, j - 1), Top};
      if (j < R) e.sides[n++] = {at(k, j), Bottom};
      e.from = corner(k, j);
      e.to = corner(k + 1, j);
    }
  }
  for (int j = 0; j < R; ++j) {
    for (int i = 0; i < columns; ++i) {
      GridEdge& e = edges[horizontal + static_cast<size_t>(j) * columns + i];
      int n = 0;
      if (i > 0 || closed) e.sides[n++] = {at(i > 0 ? i - 1 : K - 1, j), Right};
      if (i < K) e.sides[n++] = {at(i, j), Left};
      e.from = corner(i, j);
      e.to = corner(i, j + 1);
    }
  }
  for (size_t id = 0; id < edges.size(); ++id) {
    for (const SideRef& s : edges[id].sides) {
      if (s.patch >= 0) edgeOf[s.patch][s.side] = static_cast<int>(id);
    }
  }

  // Measure every edge: collapsed to a point (a pole), or the gap between its two patches.
  std::vector<std::array<Homogeneous4, 4>> sides(P);
  for (int i = 0; i < P; ++i) {
    for (int s = 0; s < 4; ++s) sides[i][s] = sidePoints(complex.patches[i], static_cast<Side>(s));
  }
  auto spread = [](const Homogeneous4& h) {
    double d = 0.0;
    const Eigen::Vector3d first = h.row(0).head<3>().transpose() / h(0, 3);
    for (Eigen::Index k = 1; k < h.rows(); ++k)
      d = std::max(d, (h.row(k).head<3>().transpose() / h(k, 3) - first).norm());
    return d;
  };
  UnionFind corners(columns * (R + 1));
  for (size_t id = 0; id < edges.size(); ++id) {
    GridEdge& e = edges[id];
    const SideRef a = e.sides[0], b = e.sides[1];
    const Homogeneous4& ha = sides[a.patch][a.side];
    const double length = spread(ha);
    e.degenerated = length <= out.tolerance;  // a pole: the side's control points coincide
    if (e.degenerated && static_cast<int>(id) >= horizontal) {
      // A side along the profile never collapses on a shape of revolution (only rows do, at a pole).
      std::ostringstream os;
      os.precision(3);
      os << "the " << kSideNames[a.side] << " side of " << patchName(complex, a.patch) << " collapses to a point ("
         << length << " long, below the tolerance " << out.tolerance << " of a complex " << extent
         << " in size): the shape is too thin along its profile for its size";
      throw InputError(os.str());
    }
    double gap = 0.0;
    if (b.patch >= 0) {
      const Homogeneous4& hb = sides[b.patch][b.side];
      if (ha.rows() != hb.rows() || ha != hb) {  // the same points are the same curve: no gap
        const std::vector<Eigen::Vector3d> pa = sampled(ha), pb = sampled(hb);
        for (int s = 0; s <= kSamples; ++s) gap = std::max(gap, (pa[s] - pb[s]).norm());
      }
      if (gap > out.allowedGap) {
        std::ostringstream os;
        os.precision(3);
        os << "the patches do not meet: " << patchName(complex, a.patch) << " and " << patchName(complex, b.patch)
           << " are " << gap << " apart along their shared side (the " << kSideNames[a.side] << " of the first, the "
           << kSideNames[b.side] << " of the second";
        if (a.side == Right && a.patch == at(K - 1, complex.patches[a.patch].vPiece) && closed)
          os << ", where the turn closes";
        os << "), more than the " << out.allowedGap << " allowed (1e-9 of the complex's size " << extent
           << " plus 1e-13 of its largest coordinate " << magnitude << ")";
        throw InputError(os.str());
      }
    }
    out.maxGap = std::max(out.maxGap, gap);
    e.tolerance = std::max(out.tolerance, 2 * gap);  // twice the measured gap: BRepCheck samples elsewhere
    if (e.degenerated) {
      corners.join(e.from, e.to);
      ++out.degenerated;
    } else if (b.patch < 0) {
      ++out.freeEdges;
    }
  }

  // Vertices: the first patch corner at each (merged) grid corner; the tolerance covers
  // every patch corner there and the edges that end there.
  const int count = columns * (R + 1);
  std::vector<Eigen::Vector3d> point(count);
  std::vector<double> vertexTolerance(count, -1.0);
  for (int i = 0; i < P; ++i) {
    const TaggedPatch& p = complex.patches[i];
    const int k = p.uPiece, j = p.vPiece;
    const std::array<int, 4> ids = {corner(k, j), corner(k + 1, j), corner(k + 1, j + 1), corner(k, j + 1)};
    const std::array<int, 4> rows = {0, p.degreeU * (p.degreeV + 1), p.degreeU * (p.degreeV + 1) + p.degreeV,
                                     p.degreeV};
    for (int c = 0; c < 4; ++c) {
      const int root = corners.find(ids[c]);
      const Eigen::Vector3d q = p.bezier.row(rows[c]).head<3>().transpose() / p.bezier(rows[c], 3);
      if (vertexTolerance[root] < 0) {
        point[root] = q;
        vertexTolerance[root] = out.tolerance;
      }
      const double d = (q - point[root]).norm();
      if (d > out.allowedGap) {
        std::ostringstream os;
        os.precision(3);
        os << "the patches do not meet: a corner of " << patchName(complex, i) << " is " << d
           << " from the other patches' corner there, more than the " << out.allowedGap
           << " allowed (1e-9 of the complex's size " << extent << " plus 1e-13 of its largest coordinate " << magnitude
           << ")";
        throw InputError(os.str());
      }
      out.maxGap = std::max(out.maxGap, d);
      vertexTolerance[root] = std::max(vertexTolerance[root], 2 * d);
    }
  }
  for (const GridEdge& e : edges) {
    for (int c : {e.from, e.to})
      vertexTolerance[corners.find(c)] = std::max(vertexTolerance[corners.find(c)], e.tolerance);
  }

  try {
    BRep_Builder builder;
    std::vector<TopoDS_Vertex> vertices(count);
    for (int c = 0; c < count; ++c) {
      if (corners.find(c) != c) continue;
      builder.MakeVertex(vertices[c], gp_Pnt(point[c][0], point[c][1], point[c][2]), vertexTolerance[c]);
    }
    std::vector<TopoDS_Face> faces(P);
    for (int i = 0; i < P; ++i) builder.MakeFace(faces[i], patchToOcct(complex.patches[i]), out.tolerance);
    std::vector<TopoDS_Edge> shared(edges.size());
    for (size_t id = 0; id < edges.size(); ++id) {
      const GridEdge& e = edges[id];
      TopoDS_Edge& edge = shared[id];
      if (e.degenerated) {
        builder.MakeEdge(edge);
        builder.Degenerated(edge, Standard_True);
      } else {
        builder.MakeEdge(edge, curveOf(sides[e.sides[0].patch][e.sides[0].side]), e.tolerance);
      }
      builder.Add(edge, vertices[corners.find(e.from)].Oriented(TopAbs_FORWARD));
      builder.Add(edge, vertices[corners.find(e.to)].Oriented(TopAbs_REVERSED));
    }
    // The pcurves: each side is a straight line in its face's [0,1]^2.
    static const std::array<gp_Pnt2d, 4> origin = {gp_Pnt2d(0, 0), gp_Pnt2d(1, 0), gp_Pnt2d(0, 1), gp_Pnt2d(0, 0)};
    static const std::array<gp_Dir2d, 4> direction = {gp_Dir2d(1, 0), gp_Dir2d(0, 1), gp_Dir2d(1, 0), gp_Dir2d(0, 1)};
    for (int i = 0; i < P; ++i) {
      for (int s = 0; s < 4; ++s) {
        const int id = edgeOf[i][s];
        builder.UpdateEdge(shared[id], new Geom2d_Line(origin[s], direction[s]), faces[i], edges[id].tolerance);
      }
    }
    for (TopoDS_Edge& edge : shared) builder.Range(edge, 0.0, 1.0);
    // Wires counter-clockwise in (u, v): bottom and right forward, top and left reversed, so
    // a side shared by two faces runs opposite ways in them (an oriented shell).
    builder.MakeShell(out.shell);
    for (int i = 0; i < P; ++i) {
      TopoDS_Wire wire;
      builder.MakeWire(wire);
      builder.Add(wire, shared[edgeOf[i][Bottom]].Oriented(TopAbs_FORWARD));
      builder.Add(wire, shared[edgeOf[i][Right]].Oriented(TopAbs_FORWARD));
      builder.Add(wire, shared[edgeOf[i][Top]].Oriented(TopAbs_REVERSED));
      builder.Add(wire, shared[edgeOf[i][Left]].Oriented(TopAbs_REVERSED));
      wire.Closed(Standard_True);
      builder.Add(faces[i], wire);
      builder.Add(out.shell, faces[i]);
    }
    out.shell.Closed(out.freeEdges == 0);
  } catch (const Standard_Failure& failure) {
    throw InputError(std::string("OpenCASCADE rejected the shell of the complex: ") + failure.GetMessageString());
  }
  // The boundary rule (finite.hpp) where the shell is at risk: far from the origin (its edges'
  // tolerance raised above Precision::Confusion() to the rounding of its coordinates) or
  // within a thousand Precision::Confusion() across. Elsewhere the construction keeps it valid
  // (tolerances from the measured gaps, the tests' BRepCheck), and OCCT's check would cost
  // 0.2 ms a face, ten times the shell (2 s at 400 arcs by 20 latitudes).
  if (out.tolerance > Precision::Confusion() || extent < 1e3 * Precision::Confusion()) {
    requireValidShape(out.shell, "the shell of the complex");
  }
  return out;
}

}  // namespace fairsplines
