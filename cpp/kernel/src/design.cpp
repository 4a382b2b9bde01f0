// Design with basic curves, Sections 5 and 6 and Fig. 9 of Karčiauskas & Peters,
// "Curvature-sensitive splines and design with basic curves".
#include "fairsplines/design.hpp"
#include "finite.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "fairsplines/errors.hpp"

namespace fairsplines {

namespace {

/// Eq. (9): the blossom f^h[x, y, z] of a homogeneous cubic Bézier b_0..b_3.
Eigen::RowVector4d blossom(const HomogeneousBezier& b, double x, double y, double z) {
  const double d0 = (1 - x) * (1 - y) * (1 - z);
  const double d2 = x * y + x * z + y * z - 3 * x * y * z;
  const double d3 = x * y * z;
  const double d1 = 1 - d0 - d2 - d3;
  return d0 * b.row(0) + d1 * b.row(1) + d2 * b.row(2) + d3 * b.row(3);
}

Eigen::Vector3d affine(const Eigen::RowVector4d& h) { return h.head<3>().transpose() / h[3]; }

/// The boundary rule for a piece's polygon: every homogeneous point finite.
PiecePolygon requireFinitePolygon(PiecePolygon p) {
  const std::string what = "the piece's polygon";
  requireFinite(p.start, what, "start points");
  requireFinite(p.inner, what, "control points");
  requireFinite(p.end, what, "end points");
  return p;
}

}  // namespace

Eigen::VectorXd completeMarks(const Eigen::VectorXd& marks) {
  std::vector<double> u{0.0};
  for (Eigen::Index i = 0; i < marks.size(); ++i) {
    const double v = marks[i];
    std::ostringstream msg;
    if (!std::isfinite(v)) {
      msg << "mark " << i << " is not finite";
      throw InputError(msg.str());
    }
    if (v < -1e-12 || v > 1.0 + 1e-12) {
      msg << "mark " << i << " = " << v << " is outside [0, 1]";
      throw InputError(msg.str());
    }
    if (v <= 1e-12 || v >= 1.0 - 1e-12) continue;  // the ends are marks anyway
    if (!(v > u.back())) {
      msg << "marks must increase: mark " << i << " = " << v << " does not follow " << u.back();
      throw InputError(msg.str());
    }
    u.push_back(v);
  }
  u.push_back(1.0);
  Eigen::VectorXd complete = Eigen::Map<Eigen::VectorXd>(u.data(), static_cast<Eigen::Index>(u.size()));
  requireSeparateKnots(complete, "the marks (with 0 and 1)");  // they become knots of the design
  return complete;
}

PiecePolygon exactPolygon(const HomogeneousBezier& cubic, const Eigen::VectorXd& marks) {
  if (cubic.rows() != 4) throw InputError("the exact conversion needs a homogeneous cubic (4 Bézier points)");
  PiecePolygon p;
  p.exact = true;
  p.marks = completeMarks(marks);
  const double maxWeight = cubic.col(3).cwiseAbs().maxCoeff();
  for (int attempt = 0;; ++attempt) {
    const Eigen::VectorXd& u = p.marks;
    const Eigen::Index m = u.size() - 1;
    p.start.resize(2, 4);
    p.end.resize(2, 4);
    p.inner.resize(m - 1, 4);
    // Eq. (10): the end extension keeps the whole curve.
    p.start.row(0) = blossom(cubic, 0, 0, 0);
    p.start.row(1) = blossom(cubic, 0, 0, u[1]);
    for (Eigen::Index i = 1; i < m; ++i) p.inner.row(i - 1) = blossom(cubic, u[i - 1], u[i], u[i + 1]);  // eq. (9)
    p.end.row(0) = blossom(cubic, u[m - 1], 1, 1);
    p.end.row(1) = blossom(cubic, 1, 1, 1);
    // Every weight must be positive; else split the widest interval next to the first bad one.
    Eigen::Index split = -1;
    const double tiny = 1e-12 * maxWeight;
    if (p.start(1, 3) <= tiny) split = 0;
    for (Eigen::Index i = 1; split < 0 && i < m; ++i) {
      if (p.inner(i - 1, 3) <= tiny) split = (u[i] - u[i - 1] >= u[i + 1] - u[i]) ? i - 1 : i;
    }
    if (split < 0 && p.end(0, 3) <= tiny) split = m - 1;
    if (split < 0) return p;
    if (attempt >= 64) throw InputError("could not make every weight positive by adding marks");
    std::vector<double> more(u.data(), u.data() + u.size());
    more.insert(more.begin() + split + 1, 0.5 * (u[split] + u[split + 1]));
    p.marks = Eigen::Map<Eigen::VectorXd>(more.data(), static_cast<Eigen::Index>(more.size()));
    ++p.marksAdded;
  }
}

PiecePolygon polygonFromJets(const PointMatrix& f, const PointMatrix& df, const PointMatrix& d2f,
                             const Eigen::VectorXd& marks) {
  const Eigen::Index m = marks.size() - 1;
  if (m < 1 || f.rows() != m + 1 || df.rows() != m + 1 || d2f.rows() != m + 1) {
    throw InputError("the 2-jets must be given at every mark, the ends included");
  }
  if (f.cols() != df.cols() || f.cols() != d2f.cols() || (f.cols() != 3 && f.cols() != 4)) {
    throw InputError("the 2-jets must have 3 (or 4, homogeneous) coordinates");
  }
  if (!f.allFinite() || !df.allFinite() || !d2f.allFinite()) throw InputError("the curve's 2-jets are not finite");
  // A piece that does not move (its derivative vanishes at every mark, relative to the
  // piece's size over its parameter range) would come out as a point: refused by name. A
  // vanishing derivative at some marks only is a cusp the curve has (an involute starts so).
  PointMatrix x(m + 1, 3), dx(m + 1, 3);  // Cartesian: d(P/w) = (dP - (P/w) dw) / w
  for (Eigen::Index i = 0; i <= m; ++i) {
    const double w = f.cols() == 4 ? f(i, 3) : 1.0, dw = f.cols() == 4 ? df(i, 3) : 0.0;
    x.row(i) = f.row(i).head(3) / w;
    dx.row(i) = (df.row(i).head(3) - x.row(i) * dw) / w;
  }
  const double size = (x.colwise().maxCoeff() - x.colwise().minCoeff()).norm();
  const double scale = std::max(size, x.rowwise().norm().maxCoeff()) / (marks[m] - marks[0]);
  if (!(dx.rowwise().norm().maxCoeff() > 1e-12 * scale) && !(size > 0.0)) {
    throw InputError("the curve does not move: its derivative vanishes at every mark and its points coincide");
  }
  auto lift = [&](const Eigen::RowVectorXd& r) {
    Eigen::RowVector4d h(0, 0, 0, 1);
    h.head(r.size()) = r;
    return h;
  };
  PiecePolygon p;
  p.marks = marks;
  p.exact = false;
  p.start.resize(2, 4);
  p.end.resize(2, 4);
  p.inner.resize(m - 1, 4);
  for (Eigen::Index i = 0; i < m; ++i) {
    const double h = marks[i + 1] - marks[i];
    // Eq. (7): the first three Bézier points of the quintic over [u_i, u_{i+1}].
    const Eigen::RowVectorXd b0 = f.row(i);
    const Eigen::RowVectorXd b1 = b0 + (h / 5.0) * df.row(i);
    const Eigen::RowVectorXd b2 = b0 + (2.0 * h / 5.0) * df.row(i) + (h * h / 20.0) * d2f.row(i);
    // Eq. (8): the same 2-jet in degree 3.
    const Eigen::RowVectorXd c1 = -2.0 / 3.0 * b0 + 5.0 / 3.0 * b1;
    const Eigen::RowVectorXd c2 = b0 - 10.0 / 3.0 * b1 + 10.0 / 3.0 * b2;
    if (i == 0) {
      p.start.row(0) = lift(b0);
      p.start.row(1) = lift(c1);
    } else {
      // Eq. (3), right form: c_i = (1 + 1/beta_i) b_1^i - (1/beta_i) b_2^i.
      const double beta = h / (marks[i] - marks[i - 1]);
      p.inner.row(i - 1) = lift((1.0 + 1.0 / beta) * c1 - (1.0 / beta) * c2);
    }
  }
  // At u_m the quintic's b_4 = b_5 - h f'/5 gives the cubic's b_2 = b_5 - h f'/3.
  const double h = marks[m] - marks[m - 1];
  p.end.row(0) = lift(f.row(m) - (h / 3.0) * df.row(m));
  p.end.row(1) = lift(f.row(m));
  return p;
}

PiecePolygon piecePolygon(const BasicCurve& curve, const Eigen::VectorXd& marks) {
  if (const auto cubic = curve.homogeneousCubic()) return requireFinitePolygon(exactPolygon(*cubic, marks));
  const Eigen::VectorXd u = completeMarks(marks);
  PointMatrix f(u.size(), 3), df(u.size(), 3), d2f(u.size(), 3);
  for (Eigen::Index i = 0; i < u.size(); ++i) {
    f.row(i) = curve.value(u[i]).transpose();
    df.row(i) = curve.d1(u[i]).transpose();
    d2f.row(i) = curve.d2(u[i]).transpose();
  }
  const std::string what = "the piece's curve at the marks";
  requireFinite(f, what, "points");
  requireFinite(df, what, "first derivatives");
  requireFinite(d2f, what, "second derivatives");
  return requireFinitePolygon(polygonFromJets(f, df, d2f, u));
}

PointMatrix quinticPieces(const BasicCurve& curve, const Eigen::VectorXd& marks) {
  const Eigen::VectorXd u = completeMarks(marks);
  const Eigen::Index m = u.size() - 1;
  PointMatrix b(6 * m, 3);
  for (Eigen::Index i = 0; i < m; ++i) {
    const double h = u[i + 1] - u[i];
    const Eigen::RowVector3d f0 = curve.value(u[i]).transpose(), f1 = curve.value(u[i + 1]).transpose();
    const Eigen::RowVector3d d0 = h * curve.d1(u[i]).transpose(), d1 = h * curve.d1(u[i + 1]).transpose();
    const Eigen::RowVector3d s0 = h * h * curve.d2(u[i]).transpose(), s1 = h * h * curve.d2(u[i + 1]).transpose();
    // Eq. (7).
    b.row(6 * i + 0) = f0;
    b.row(6 * i + 1) = f0 + d0 / 5.0;
    b.row(6 * i + 2) = f0 + 2.0 * d0 / 5.0 + s0 / 20.0;
    b.row(6 * i + 3) = f1 - 2.0 * d1 / 5.0 + s1 / 20.0;
    b.row(6 * i + 4) = f1 - d1 / 5.0;
    b.row(6 * i + 5) = f1;
  }
  requireFinite(b, "the quintic pieces of the curve", "Bezier points");
  return b;
}

Design mergePieces(const std::vector<PiecePolygon>& pieces, double joinTolerance) {
  if (pieces.empty()) throw InputError("a design needs at least one piece");
  if (!(joinTolerance >= 0.0)) throw InputError("the join tolerance must not be negative");
  // The design's size, for the "end points agree" test.
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
  for (const PiecePolygon& p : pieces) {
    for (const HomogeneousPoints* rows : {&p.start, &p.inner, &p.end}) {
      for (Eigen::Index r = 0; r < rows->rows(); ++r) {
        lo = lo.cwiseMin(affine(rows->row(r)));
        hi = hi.cwiseMax(affine(rows->row(r)));
      }
    }
  }
  const double agree = 1e-12 * (hi - lo).norm();

  std::vector<Eigen::RowVector4d> poles;
  std::vector<double> knots;  // distinct knots; the first and last get multiplicity 4
  Design design;
  double lambda = 1.0 / pieces.front().start(0, 3);  // homogeneous scale: first weight 1
  double t = 0.0, scale = 1.0;
  for (size_t k = 0; k < pieces.size(); ++k) {
    const PiecePolygon& p = pieces[k];
    const Eigen::VectorXd& u = p.marks;
    const Eigen::Index m = u.size() - 1;
    if (k == 0) {
      poles.push_back(lambda * p.start.row(0));
      poles.push_back(lambda * p.start.row(1));
      knots.push_back(0.0);
    } else {
      // Fig. 9: join the previous piece's end to this piece's start.
      const PiecePolygon& a = pieces[k - 1];
      const double hPrevious = scale * (a.marks[a.marks.size() - 1] - a.marks[a.marks.size() - 2]);
      const double wJoin = lambda * a.end(1, 3);  // the weights meet at the join
      const Eigen::Vector3d aEnd = affine(a.end.row(1)), bStart = affine(p.start.row(0));
      const double gap = (aEnd - bStart).norm();
      auto point = [&](const Eigen::Vector3d& x) {
        Eigen::RowVector4d h;
        h << wJoin * x.x(), wJoin * x.y(), wJoin * x.z(), wJoin;
        return h;
      };
      // The previous piece's last knot (its u = 1) is this join's first knot.
      if (gap <= agree) {
        design.joins.push_back(JoinKind::Agree);
        poles.push_back(point(aEnd));
      } else if (gap <= joinTolerance) {
        design.joins.push_back(JoinKind::Averaged);
        poles.push_back(point(0.5 * (aEnd + bStart)));
      } else {
        design.joins.push_back(JoinKind::Edge);
        poles.push_back(point(aEnd));
        poles.push_back(point(bStart));
        t += hPrevious;  // beta := 1 at the first end point: the same interval again
        knots.push_back(t);
      }
      // beta := 1 at the (last) new point: this piece's first interval equals the previous.
      scale = hPrevious / (u[1] - u[0]);
      lambda = wJoin / p.start(0, 3);
    }
    design.ranges.push_back({t, scale});
    for (Eigen::Index i = 0; i < p.inner.rows(); ++i) poles.push_back(lambda * p.inner.row(i));
    for (Eigen::Index i = 1; i <= m; ++i) knots.push_back(t + scale * u[i]);
    t += scale * u[m];
    if (k + 1 == pieces.size()) {
      poles.push_back(lambda * p.end.row(0));
      poles.push_back(lambda * p.end.row(1));
    }
  }

  BSplineCurve& c = design.curve;
  c.degree = 3;
  const Eigen::Index n = static_cast<Eigen::Index>(poles.size());
  c.poles.resize(n, 3);
  c.weights.resize(n);
  bool rational = false;
  for (Eigen::Index i = 0; i < n; ++i) {
    const double w = poles[i][3];
    if (!(w > 0.0)) {
      std::ostringstream msg;
      msg << "control point " << i << " of the design has weight " << w << ": add marks to the piece";
      throw InputError(msg.str());
    }
    c.poles.row(i) = poles[i].head<3>() / w;
    c.weights[i] = w;
    rational = rational || std::abs(w - 1.0) > 1e-13;  // blossoms of a constant weight: 1 up to rounding
  }
  if (!rational) c.weights.resize(0);
  c.knots = Eigen::Map<Eigen::VectorXd>(knots.data(), static_cast<Eigen::Index>(knots.size()));
  c.mults = Eigen::VectorXi::Ones(c.knots.size());
  c.mults[0] = c.mults[c.knots.size() - 1] = 4;
  requireValidCurve(c, "the merged design");
  return design;
}

}  // namespace fairsplines
