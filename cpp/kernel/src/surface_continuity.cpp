// Continuity across the edges of a shape (issue 27): gap, angle between the normals and
// the jump of normal curvature, per edge, with a verdict "gap" / G0 / G1 / G2.
//
// G1 makes the normal curvature along the edge equal on both sides (they share the edge's
// curve and normal); G2 then needs the whole second fundamental form equal, which holds when
// the normal curvatures in two more tangent directions agree: across the edge (n x T) and at
// 45 degrees to it (catching the mixed term). The jump is judged against the largest normal
// curvature along the edge (not point by point: where the curvature passes through zero a
// pointwise ratio reads a C2 joint as a jump). docs/SURFACE_ANALYSIS.md.
//
// Sampling: the edge's parameter range is split at the knots of its curve, of its pcurves,
// and where the pcurves cross the knot lines of B-spline faces, and by turning; each span
// gets interior samples; then the worst sample of each measure is refined by golden-section
// search between its neighbours, so a defect narrower than the sample spacing is still found.
#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Curve2d.hxx>
#include <BRepBndLib.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopTools_ListIteratorOfListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <algorithm>
#include <cmath>
#include <memory>

#include "fairsplines/errors.hpp"
#include "fairsplines/surface_analysis.hpp"
#include "finite.hpp"
#include "surface_analysis_detail.hpp"

namespace fairsplines {

namespace {

using detail::FaceSurface;
using detail::SurfaceFrame;

constexpr double kPi = 3.14159265358979323846;
constexpr int kMaxBreaks = 4096;  // bounds the work on one edge

/// One side of the edge: a face, the edge as oriented in it, and its pcurve.
struct Side {
  Side(const TopoDS_Face& face, const TopoDS_Edge& edge) : surface(face), pcurve(edge, face) {
    Handle(Geom_Surface) s = BRep_Tool::Surface(face);
    if (auto b = Handle(Geom_BSplineSurface)::DownCast(s); !b.IsNull()) {
      for (int i = 1; i <= b->NbUKnots(); ++i) uKnots.push_back(b->UKnot(i));
      for (int i = 1; i <= b->NbVKnots(); ++i) vKnots.push_back(b->VKnot(i));
    }
  }
  FaceSurface surface;
  BRepAdaptor_Curve2d pcurve;
  std::vector<double> uKnots, vKnots;
  gp_Pnt2d uv(double s) const {
    return pcurve.Value(pcurve.FirstParameter() + s * (pcurve.LastParameter() - pcurve.FirstParameter()));
  }
};

/// The measures at one parameter s in [0, 1] of the edge.
struct Sample {
  bool valid = false;  // both sides regular there
  double gap = 0, angle = 0, jump = 0, scale = 0;
  gp_Pnt p;
};

/// The edge with its two sides (the same face twice for a seam).
class EdgePair {
public:
  EdgePair(const TopoDS_Edge& edge, const TopoDS_Face& f1, const TopoDS_Edge& e1, const TopoDS_Face& f2,
           const TopoDS_Edge& e2)
      : curve_(edge), a_(f1, e1), b_(f2, e2) {
    // In a consistently oriented shell each face holds the shared edge the other way round
    // (a seam too, in its one face): the normals then agree on a smooth joint. Faces holding
    // it the same way are oriented against each other; side b's normal is turned round.
    flip_ = e1.Orientation() == e2.Orientation() ? -1.0 : 1.0;
    t0_ = curve_.FirstParameter();
    t1_ = curve_.LastParameter();
  }
  double parameter(double s) const { return t0_ + s * (t1_ - t0_); }

  Sample at(double s) const {
    Sample out;
    gp_Pnt c;
    gp_Vec t;
    SurfaceFrame fa, fb;
    bool regular = false;
    try {
      curve_.D1(parameter(s), c, t);
      const gp_Pnt2d ua = a_.uv(s), ub = b_.uv(s);
      const bool ra = a_.surface.frame(ua.X(), ua.Y(), fa), rb = b_.surface.frame(ub.X(), ub.Y(), fb);
      regular = ra && rb;
      if (!regular) {  // still measure the gap where a side is degenerate (a pole on the edge)
        out.gap = std::max({fa.p.Distance(fb.p), fa.p.Distance(c), fb.p.Distance(c)});
        out.p = c;
        return out;
      }
    } catch (const Standard_Failure&) {
      return out;  // an offset surface undefined here: no sample
    }
    out.p = c;
    out.gap = std::max({fa.p.Distance(fb.p), fa.p.Distance(c), fb.p.Distance(c)});
    const gp_Vec nb = fb.n * flip_;
    out.angle = std::atan2(fa.n.Crossed(nb).Magnitude(), fa.n.Dot(nb)) * 180.0 / kPi;
    const double tLength = t.Magnitude();
    if (!(tLength > 0.0)) return out;
    const gp_Vec along = t / tLength;
    gp_Vec across = fa.n.Crossed(along);
    if (!(across.Magnitude() > 0.5)) return out;
    across.Normalize();
    const gp_Vec oblique = (along + across) / std::sqrt(2.0);
    // Side b's curvatures against side a's normal (flip_) in the same 3D directions.
    double jump = 0.0, scale = 0.0;
    const gp_Vec directions[3] = {along, across, oblique};
    for (int i = 0; i < 3; ++i) {
      const double ka = detail::normalCurvature(fa, directions[i]),
                   kb = flip_ * detail::normalCurvature(fb, directions[i]);
      scale = std::max({scale, std::abs(ka), std::abs(kb)});
      if (i > 0) jump = std::max(jump, std::abs(ka - kb));
    }
    out.jump = jump;
    out.scale = scale;
    out.valid = true;
    return out;
  }

  /// Where the edge splits: its curve's and pcurves' knots, where the pcurves cross the
  /// faces' knot lines, and every 22.5 degrees of turning. Sorted, in [0, 1].
  std::vector<double> breaks() const {
    std::vector<double> s = {0.0, 1.0};
    auto addKnots = [&](const auto& curve, double first, double last) {
      for (int i = 1; i <= curve->NbKnots() && static_cast<int>(s.size()) < kMaxBreaks; ++i) {
        const double x = (curve->Knot(i) - first) / (last - first);
        if (x > 0.0 && x < 1.0) s.push_back(x);
      }
    };
    if (curve_.GetType() == GeomAbs_BSplineCurve) addKnots(curve_.BSpline(), t0_, t1_);
    for (const Side* side : {&a_, &b_}) {
      if (side->pcurve.GetType() == GeomAbs_BSplineCurve) {
        addKnots(side->pcurve.BSpline(), side->pcurve.FirstParameter(), side->pcurve.LastParameter());
      }
    }
    // Turning of the edge, from 17 tangents.
    double turning = 0.0;
    gp_Vec previous;
    for (int i = 0; i <= 16; ++i) {
      gp_Pnt p;
      gp_Vec t;
      curve_.D1(parameter(i / 16.0), p, t);
      if (i > 0 && t.Magnitude() > 0.0 && previous.Magnitude() > 0.0) turning += t.Angle(previous);
      previous = t;
    }
    const int pieces = std::min(64, std::max(1, static_cast<int>(std::ceil(turning / (kPi / 8.0)))));
    for (int i = 1; i < pieces; ++i) s.push_back(static_cast<double>(i) / pieces);
    std::sort(s.begin(), s.end());
    // Knot lines of B-spline faces crossed by a pcurve between two breaks (bisection).
    std::vector<double> crossings;
    for (const Side* side : {&a_, &b_}) {
      for (int coordinate = 0; coordinate < 2; ++coordinate) {
        const std::vector<double>& knots = coordinate == 0 ? side->uKnots : side->vKnots;
        if (knots.size() <= 2) continue;
        auto value = [&](double x) { return coordinate == 0 ? side->uv(x).X() : side->uv(x).Y(); };
        for (std::size_t i = 0; i + 1 < s.size(); ++i) {
          // Four sub-steps per span, so that a pcurve going back and forth is still followed.
          for (int j = 0; j < 4; ++j) {
            const double xa = s[i] + (s[i + 1] - s[i]) * j / 4.0, xb = s[i] + (s[i + 1] - s[i]) * (j + 1) / 4.0;
            const double ya = value(xa), yb = value(xb);
            const double lo = std::min(ya, yb), hi = std::max(ya, yb);
            for (auto k = std::upper_bound(knots.begin(), knots.end(), lo); k != knots.end() && *k < hi; ++k) {
              double l = xa, r = xb;
              const bool increasing = yb > ya;
              for (int it = 0; it < 50; ++it) {
                const double m = 0.5 * (l + r);
                ((value(m) < *k) == increasing ? l : r) = m;
              }
              if (static_cast<int>(crossings.size() + s.size()) < kMaxBreaks) crossings.push_back(0.5 * (l + r));
            }
          }
        }
      }
    }
    s.insert(s.end(), crossings.begin(), crossings.end());
    std::sort(s.begin(), s.end());
    s.erase(std::unique(s.begin(), s.end(), [](double x, double y) { return y - x < 1e-12; }), s.end());
    return s;
  }

private:
  BRepAdaptor_Curve curve_;
  Side a_, b_;
  double flip_ = 1.0, t0_ = 0.0, t1_ = 1.0;
};

/// The largest of measure(s) near s = x[i], between x[i - 1] and x[i + 1], by golden-section
/// search (25 steps: the bracket shrinks to 1e-5 of itself), the samples it takes counted.
template <class Measure>
std::pair<double, double> refine(const std::vector<double>& x, std::size_t i, Measure measure, double best,
                                 int& count) {
  double a = x[i > 0 ? i - 1 : 0], b = x[std::min(i + 1, x.size() - 1)];
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double c = b - g * (b - a), d = a + g * (b - a);
  double fc = measure(c), fd = measure(d);
  count += 2;
  double bestS = x[i];
  for (int it = 0; it < 25; ++it) {
    if (fc > fd) {
      b = d, d = c, fd = fc;
      c = b - g * (b - a);
      fc = measure(c);
    } else {
      a = c, c = d, fc = fd;
      d = a + g * (b - a);
      fd = measure(d);
    }
    ++count;
    if (fc > best) best = fc, bestS = c;
    if (fd > best) best = fd, bestS = d;
  }
  return {best, bestS};
}

/// The oriented occurrences of the edge in the face (two for a seam).
std::vector<TopoDS_Edge> occurrences(const TopoDS_Face& face, const TopoDS_Shape& edge) {
  std::vector<TopoDS_Edge> found;
  for (TopExp_Explorer ex(face, TopAbs_EDGE); ex.More(); ex.Next()) {
    if (ex.Current().IsSame(edge)) found.push_back(TopoDS::Edge(ex.Current()));
  }
  return found;
}

void measurePair(const EdgePair& pair, const ContinuityOptions& options, double minScale, EdgeContinuity& record) {
  std::vector<double> breaks = pair.breaks();
  const int inner = options.samplesPerSpan > 0 ? options.samplesPerSpan : 4;
  std::vector<double> x;
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
    for (int j = 0; j <= inner; ++j) x.push_back(breaks[i] + (breaks[i + 1] - breaks[i]) * j / (inner + 1.0));
  }
  x.push_back(1.0);
  if (options.samplesPerSpan <= 0 && x.size() < 17) {  // at least 16 intervals on an edge
    x.clear();
    for (int i = 0; i <= 16; ++i) x.push_back(i / 16.0);
  }
  std::vector<Sample> samples(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) samples[i] = pair.at(x[i]);
  int count = static_cast<int>(x.size());
  double scale = minScale;
  for (const Sample& s : samples) scale = std::max(scale, s.scale);
  // Each measure: the worst sample, refined between its neighbours.
  auto worst = [&](auto get, bool needValid) {
    std::size_t iBest = 0;
    double best = -1.0;
    for (std::size_t i = 0; i < samples.size(); ++i) {
      if (needValid && !samples[i].valid) continue;
      if (get(samples[i]) > best) best = get(samples[i]), iBest = i;
    }
    if (best < 0.0) return std::pair<double, double>{0.0, 0.0};
    return refine(
        x, iBest,
        [&](double s) {
          const Sample t = pair.at(s);
          return needValid && !t.valid ? -1.0 : get(t);
        },
        best, count);
  };
  const auto [gap, gapS] = worst([](const Sample& s) { return s.gap; }, false);
  const auto [angle, angleS] = worst([](const Sample& s) { return s.angle; }, true);
  const auto [jump, jumpS] = worst([](const Sample& s) { return s.jump; }, true);
  // The scale may grow at refined points (a sharp feature): take the largest seen.
  scale = std::max(scale, pair.at(jumpS).scale);
  auto point = [&](double s) {
    const gp_Pnt p = pair.at(s).p;
    return Eigen::Vector3d(p.X(), p.Y(), p.Z());
  };
  if (gap > record.gap || record.samples == 0)
    record.gap = gap, record.gapPoint = point(gapS), record.gapParameter = pair.parameter(gapS);
  if (angle > record.angle || record.samples == 0)
    record.angle = angle, record.anglePoint = point(angleS), record.angleParameter = pair.parameter(angleS);
  if (jump / scale > record.curvatureJump || record.samples == 0) {
    record.curvatureJump = jump / scale;
    record.curvatureJumpAbs = jump;
    record.curvatureScale = scale;
    record.curvaturePoint = point(jumpS);
    record.curvatureParameter = pair.parameter(jumpS);
  }
  record.samples += count;
}

}  // namespace

std::vector<EdgeContinuity> edgeContinuity(const TopoDS_Shape& shape, const ContinuityOptions& options) {
  if (shape.IsNull()) throw InputError("the shape is null");
  if (!(options.angleTolerance >= 0.0) || !(options.curvatureTolerance >= 0.0) || std::isnan(options.gapTolerance) ||
      options.samplesPerSpan < 0 || options.samplesPerSpan > 1000) {
    throw InputError("the tolerances must be numbers >= 0 and the samples per span from 0 to 1000");
  }
  TopTools_IndexedMapOfShape edges, faces;
  TopExp::MapShapes(shape, TopAbs_EDGE, edges);
  TopExp::MapShapes(shape, TopAbs_FACE, faces);
  if (edges.Extent() == 0) throw InputError("the shape has no edges");
  TopTools_IndexedDataMapOfShapeListOfShape ancestors;
  TopExp::MapShapesAndAncestors(shape, TopAbs_EDGE, TopAbs_FACE, ancestors);
  Bnd_Box box;
  BRepBndLib::Add(shape, box);
  const double size = box.IsVoid() ? 1.0 : std::sqrt(box.SquareExtent());
  const double minScale = size > 0.0 ? 1.0 / size : 1.0;

  std::vector<EdgeContinuity> out;
  out.reserve(edges.Extent());
  for (int i = 1; i <= edges.Extent(); ++i) {
    const TopoDS_Edge edge = TopoDS::Edge(edges(i));
    EdgeContinuity record;
    record.edge = i;
    std::vector<TopoDS_Face> around;
    if (const int k = ancestors.FindIndex(edge); k > 0) {
      for (TopTools_ListIteratorOfListOfShape it(ancestors(k)); it.More(); it.Next()) {
        const TopoDS_Face f = TopoDS::Face(it.Value());
        if (std::none_of(around.begin(), around.end(), [&](const TopoDS_Face& g) { return g.IsSame(f); })) {
          around.push_back(f);
          record.faces.push_back(faces.FindIndex(f));
        }
      }
    }
    if (BRep_Tool::Degenerated(edge)) {
      record.kind = record.continuity = "degenerate";
      out.push_back(record);
      continue;
    }
    // Pairs to compare: the seam's two sides in one face, or each pair of faces.
    std::vector<std::unique_ptr<EdgePair>> pairs;
    try {
      if (around.size() == 1) {
        const std::vector<TopoDS_Edge> in = occurrences(around[0], edge);
        if (in.size() == 2 && BRep_Tool::IsClosed(edge, around[0])) {
          record.kind = "seam";
          pairs.push_back(std::make_unique<EdgePair>(edge, around[0], in[0], around[0], in[1]));
        }
      } else if (around.size() >= 2) {
        record.kind = around.size() == 2 ? "shared" : "non-manifold";
        for (std::size_t a = 0; a < around.size(); ++a) {
          for (std::size_t b = a + 1; b < around.size(); ++b) {
            pairs.push_back(std::make_unique<EdgePair>(edge, around[a], occurrences(around[a], edge).front(), around[b],
                                                       occurrences(around[b], edge).front()));
          }
        }
      }
    } catch (const Standard_Failure& e) {
      throw InputError("edge " + std::to_string(i) + " has no curve on its faces (" + e.GetMessageString() + ")");
    }
    if (pairs.empty()) {
      record.kind = record.continuity = around.empty() ? "free" : "boundary";
      out.push_back(record);
      continue;
    }
    for (const auto& pair : pairs) measurePair(*pair, options, minScale, record);
    // The boundary rule (finite.hpp): no number that is not finite leaves the kernel.
    if (!std::isfinite(record.gap) || !std::isfinite(record.angle) || !std::isfinite(record.curvatureJump) ||
        !std::isfinite(record.curvatureScale) || firstNonFinite(record.gapPoint) >= 0) {
      throw InputError("edge " + std::to_string(i) +
                       ": its faces give values that are not finite (the geometry is beyond double precision)");
    }
    const double gapTolerance =
        options.gapTolerance >= 0.0 ? options.gapTolerance : std::max(2.0 * BRep_Tool::Tolerance(edge), 1e-6 * size);
    record.continuity = record.gap > gapTolerance                           ? "gap"
                        : record.angle > options.angleTolerance             ? "G0"
                        : record.curvatureJump > options.curvatureTolerance ? "G1"
                                                                            : "G2";
    out.push_back(record);
  }
  return out;
}

}  // namespace fairsplines
