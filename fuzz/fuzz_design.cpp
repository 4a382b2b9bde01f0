// Design with basic curves (design.hpp): one to four basic curves with marks, each to its
// control polygon (Section 6 exact for conics and rational Béziers, Section 5 from the
// quintics of eq. (7) otherwise), and the Fig. 9 merge into one C2 cubic NURBS, with
// pieces whose ends agree, nearly agree or are apart; then a sampled piece (the csr-spline
// of samples, the unifying spline of Fig. 1) among them, merged again.
#include <algorithm>
#include <vector>

#include "fairsplines/design.hpp"
#include "fairsplines/design_samples.hpp"
#include "fuzz_basic.hpp"

using namespace fairsplines;
using namespace fairsplines::fuzz;

namespace {

/// Marks inside (0, 1): increasing (cumulative positive steps, normalised), with the ends
/// 0 and 1 now and then, or any numbers.
Eigen::VectorXd marksOf(FuzzInput& in) {
  const int m = in.count(0, 8);
  Eigen::VectorXd marks;
  if (in.byte() < 200) {
    const Eigen::VectorXd steps = in.increasing(m + 1, in.positive());
    marks = steps.head(m) / steps[m];
    if (m > 0 && in.byte() < 32) marks[0] = 0.0;
    if (m > 0 && in.byte() < 32) marks[m - 1] = 1.0;
  } else {
    marks = in.numbers(m);
  }
  return marks;
}

void requireFinitePolygon(const char* call, const PiecePolygon& p) {
  requireFinite(call, "mark", p.marks);
  requireFinite(call, "start control point", p.start);
  requireFinite(call, "inner control point", p.inner);
  requireFinite(call, "end control point", p.end);
}

}  // namespace

int fuzzOne(FuzzInput& in) {
  const int pieces = in.count(1, 4);
  std::vector<std::unique_ptr<BasicCurve>> curves;
  std::vector<PiecePolygon> polygons;
  for (int k = 0; k < pieces; ++k) {
    std::string kind;
    std::unique_ptr<BasicCurve> curve;
    if (k > 0 && in.byte() < 96) {  // a line from where the previous piece ends (nearly)
      kind = "lineSegment(previous end, q)";
      Eigen::Vector3d from;
      if (!guarded("BasicCurve::value", [&] { from = curves.back()->value(1.0); })) return 0;
      if (in.flag()) from += in.vector3() * 1e-9;
      const Eigen::Vector3d to = from + in.vector3();
      note("line from", from);
      note("line to", to);
      if (!guarded("lineSegment", [&] { curve = lineSegment(from, to); })) return 0;
    } else if (!guarded("a basic curve's constructor", [&] { curve = basicCurve(in, kind); })) {
      return 0;
    }
    const Eigen::VectorXd marks = marksOf(in);
    note("curve", kind);
    note("marks", marks);
    PiecePolygon polygon;
    if (!guarded("piecePolygon", [&] { polygon = piecePolygon(*curve, marks); })) return 0;
    requireFinitePolygon("piecePolygon", polygon);
    if (in.byte() < 16) {
      PointMatrix quintics;
      if (guarded("quinticPieces", [&] { quintics = quinticPieces(*curve, marks); })) {
        requireFinite("quinticPieces", "Bézier point", quintics);
      }
    }
    curves.push_back(std::move(curve));
    polygons.push_back(std::move(polygon));
  }
  const double joinTolerance = in.byte() < 200 ? 1e-6 : in.number();
  note("join tolerance", joinTolerance);
  Design design;
  if (!guarded("mergePieces", [&] { design = mergePieces(polygons, joinTolerance); })) return 0;
  requireValid("mergePieces", design.curve);
  if (design.joins.size() + 1 != polygons.size() || design.ranges.size() != polygons.size()) {
    fail("mergePieces", "not one join per pair of pieces and one range per piece");
  }
  for (const PieceRange& r : design.ranges) {
    requireFinite("mergePieces", "piece range t0", r.t0);
    requireFinite("mergePieces", "piece range scale", r.scale);
  }
  // The unifying spline (design_samples.hpp): a sampled piece, the csr-spline of samples,
  // put among the basic pieces and merged with them. Read after everything above, so the
  // older seeds still take the paths they took.
  if (in.exhausted()) return 0;
  const PointMatrix q = samplePoints(in, 24);
  note("samples", q);
  PiecePolygon sampled;
  if (!guarded("samplesPolygon", [&] { sampled = samplesPolygon(q); })) return 0;
  requireFinitePolygon("samplesPolygon", sampled);
  const int at = in.count(0, static_cast<int>(polygons.size()));
  polygons.insert(polygons.begin() + at, sampled);
  Design unified;
  if (!guarded("mergePieces with samples", [&] { unified = mergePieces(polygons, joinTolerance); })) return 0;
  requireValid("mergePieces with samples", unified.curve);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) { return runOne(data, size, fuzzOne); }
