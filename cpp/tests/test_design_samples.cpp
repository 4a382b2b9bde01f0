// The unifying spline (csr paper, Section 1 and Fig. 1): a sampled piece (the csr-spline
// of Section 4) merged with exact pieces (Section 6) by Fig. 9, judged by OCCT evaluation.
#include <gtest/gtest.h>

#include <Geom_BSplineCurve.hxx>
#include <cmath>

#include "fairsplines/basic_curves.hpp"
#include "fairsplines/csr.hpp"
#include "fairsplines/design_samples.hpp"
#include "fairsplines/errors.hpp"
#include "fairsplines/occt.hpp"
#include "test_support.hpp"

using namespace fairsplines;

namespace {

Eigen::Vector3d at(const Handle(Geom_BSplineCurve)& c, double t) {
  const gp_Pnt p = c->Value(t);
  return {p.X(), p.Y(), p.Z()};
}

}  // namespace

/// Samples of a circle arc spaced unevenly (chordal parameters are not uniform ones).
static PointMatrix unevenArc(int n, double r, double a0, double a1) {
  PointMatrix q(n, 2);
  for (int i = 0; i < n; ++i) {
    const double a = a0 + (a1 - a0) * std::pow(i / (n - 1.0), 0.8);
    q.row(i) << r * std::cos(a), r * std::sin(a);
  }
  return q;
}

TEST(DesignSamples, PolygonIsTheCsrSplinesOwn) {
  const PointMatrix q = unevenArc(15, 2.0, 0.2, 2.6);
  const PiecePolygon p = samplesPolygon(q);
  const BSplineCurve csr = csrSpline(q);
  ASSERT_EQ(p.marks.size(), 15);
  ASSERT_EQ(p.inner.rows(), 13);
  EXPECT_FALSE(p.exact);
  EXPECT_EQ(p.marks[0], 0.0);
  EXPECT_EQ(p.marks[14], 1.0);
  // The same curve over the normalised parameters: OCCT evaluation of both.
  const Design d = mergePieces({p}, 0.0);
  const Handle(Geom_BSplineCurve) a = toOcct(d.curve), b = toOcct(csr);
  const double t0 = csr.knots[0], t1 = csr.knots[csr.knots.size() - 1];
  for (int j = 0; j <= 400; ++j) {
    const double u = j / 400.0;
    EXPECT_LT((at(a, u) - at(b, t0 + (t1 - t0) * u)).norm(), 1e-13);
  }
}

TEST(DesignSamples, JoinedToAnExactArcTheArcStaysExactAndTheCsrPartStaysTheCsrSpline) {
  // Samples of a circle of radius 2 about the origin, then an exact circle arc of radius 1
  // from the last sample on (agree).
  const PointMatrix q = unevenArc(21, 2.0, 0.0, 1.5);
  const double a = 1.5;
  const Frame frame{{2.0 * std::cos(a) - std::cos(a), 2.0 * std::sin(a) - std::sin(a), 0.0},
                    Eigen::Vector3d::UnitX(),
                    Eigen::Vector3d::UnitY()};
  const CircleArc arc(frame, 1.0, a, 1.4);
  Eigen::VectorXd marks(5);
  marks << 0.15, 0.3, 0.5, 0.7, 0.85;
  const std::vector<PiecePolygon> pieces{samplesPolygon(q), piecePolygon(arc, marks)};
  const Design d = mergePieces(pieces, 1e-9);
  ASSERT_EQ(d.joins.size(), 1u);
  EXPECT_EQ(d.joins[0], JoinKind::Agree);
  const Handle(Geom_BSplineCurve) c = toOcct(d.curve), csr = toOcct(csrSpline(q));
  // The arc from its second mark to its free end.
  const Eigen::VectorXd& u = pieces[1].marks;
  for (int j = 0; j <= 200; ++j) {
    const double v = u[2] + (1.0 - u[2]) * j / 200.0;
    EXPECT_LT((at(c, d.ranges[1].t0 + d.ranges[1].scale * v) - arc.value(v)).norm(), 1e-12);
  }
  // The sampled piece equals its csr-spline up to its second last mark.
  const Eigen::VectorXd& s = pieces[0].marks;
  const double t0 = csr->FirstParameter(), t1 = csr->LastParameter();
  for (int j = 0; j <= 200; ++j) {
    const double v = s[s.size() - 3] * j / 200.0;
    EXPECT_LT((at(c, d.ranges[0].t0 + d.ranges[0].scale * v) - at(csr, t0 + (t1 - t0) * v)).norm(), 1e-12);
  }
  EXPECT_EQ(test::signChanges(c), 0);
}

TEST(DesignSamples, BadSamplesAreRefusedByName) {
  PointMatrix two(2, 2);
  two << 0, 0, 1, 1;
  EXPECT_THROW(samplesPolygon(two), InputError);
  PointMatrix repeated(4, 2);
  repeated << 0, 0, 1, 1, 1, 1, 2, 0;
  EXPECT_THROW(samplesPolygon(repeated), InputError);
  PointMatrix nan(3, 2);
  nan << 0, 0, std::nan(""), 1, 2, 0;
  EXPECT_THROW(samplesPolygon(nan), InputError);
  CsrOptions closed;
  closed.closed = true;
  EXPECT_THROW(samplesPolygon(test::circleSamples(8, 1.0, 0.0, 2.0), closed), InputError);
}
