// The tensor grid of a blend complex: its u pieces split at cuts or refined arc by arc,
// its knots, its patches raised to one degree, and the complex as OpenCASCADE surfaces
// (one patch, or the single surface of the whole grid).
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <algorithm>
#include <sstream>

#include "fairsplines/blend_surface.hpp"
#include "fairsplines/errors.hpp"
#include "bernstein.hpp"
#include "blend_detail.hpp"
#include "finite.hpp"
#include "knot_removal.hpp"

namespace fairsplines {

// ---------------------------------------------------------------------------------------
// Pieces: split at cuts (de Casteljau, exact), arcs refined

namespace detail {

SplitPieces splitBezierPieces(const PointMatrix& bezier, int order, const Eigen::VectorXd& knots,
                              const std::vector<std::vector<double>>& cuts) {
  const int P = static_cast<int>(bezier.rows()) / order;
  if (static_cast<int>(cuts.size()) != P || knots.size() != P + 1) {
    throw InputError("splitting needs one list of cuts per piece and one knot more than pieces");
  }
  std::vector<PointMatrix> pieces;
  std::vector<double> t{knots[0]};
  SplitPieces out;
  out.first.assign(P + 1, 0);
  for (int k = 0; k < P; ++k) {
    out.first[k] = static_cast<int>(pieces.size());
    PointMatrix rest = bezier.middleRows(order * k, order);
    double done = 0.0;  // the part of piece k already cut off
    for (double x : cuts[k]) {
      if (!(x > done && x < 1.0)) throw InputError("cuts must increase strictly inside (0, 1)");
      PointMatrix left, right;
      bernstein::split(rest, (x - done) / (1.0 - done), left, right);
      pieces.push_back(left);
      t.push_back(knots[k] + x * (knots[k + 1] - knots[k]));
      rest = right;
      done = x;
    }
    pieces.push_back(rest);
    t.push_back(knots[k + 1]);
  }
  out.first[P] = static_cast<int>(pieces.size());
  out.bezier.resize(order * static_cast<Eigen::Index>(pieces.size()), bezier.cols());
  for (size_t k = 0; k < pieces.size(); ++k)
    out.bezier.middleRows(order * static_cast<Eigen::Index>(k), order) = pieces[k];
  out.knots = Eigen::Map<const Eigen::VectorXd>(t.data(), static_cast<Eigen::Index>(t.size()));
  return out;
}

}  // namespace detail

C2SexticSpline splitPieces(const C2SexticSpline& c2, const std::vector<std::vector<double>>& cuts) {
  if (static_cast<int>(cuts.size()) != c2.pieces()) throw InputError("splitPieces needs one list of cuts per piece");
  const Eigen::VectorXd t = c2.knots();
  const detail::SplitPieces split = detail::splitBezierPieces(c2.bezier, 7, t, cuts);
  C2SexticSpline out;
  out.closed = c2.closed;
  out.bezier = split.bezier;
  for (int first : c2.firstPiece) out.firstPiece.push_back(split.first[first]);
  const int P = out.pieces();
  out.beta.resize(P);
  for (int k = 0; k < P; ++k) {
    out.beta[k] = k > 0 ? (split.knots[k + 1] - split.knots[k]) / (split.knots[k] - split.knots[k - 1]) : 1.0;
  }
  // The closing join keeps its scalar, rescaled by the new lengths of the first and last pieces.
  const int last = c2.pieces() - 1;
  out.beta[0] = c2.closed ? c2.beta[0] * ((split.knots[1] - split.knots[0]) / (t[1] - t[0])) /
                                ((split.knots[P] - split.knots[P - 1]) / (t[last + 1] - t[last]))
                          : c2.beta[0];
  return out;
}

C2SexticSpline refineArcs(const C2SexticSpline& c2, const std::vector<int>& parts) {
  const int n = static_cast<int>(c2.firstPiece.size()) - 1;
  if (static_cast<int>(parts.size()) != n) throw InputError("refineArcs needs one piece count per arc");
  std::vector<std::vector<double>> cuts(c2.pieces());
  for (int i = 0; i < n; ++i) {
    const int have = c2.firstPiece[i + 1] - c2.firstPiece[i];
    if (parts[i] < have || parts[i] % have != 0) {
      std::ostringstream os;
      os << "arc " << i << " has " << have << " pieces; it cannot be split into " << parts[i];
      throw InputError(os.str());
    }
    const int m = parts[i] / have;  // every piece of the arc into m equal parts
    for (int k = c2.firstPiece[i]; k < c2.firstPiece[i + 1]; ++k) {
      for (int j = 1; j < m; ++j) cuts[k].push_back(static_cast<double>(j) / m);
    }
  }
  return splitPieces(c2, cuts);
}

// ---------------------------------------------------------------------------------------
// Knots

Eigen::VectorXd arcKnots(const C2SexticSpline& c2) {
  const Eigen::VectorXd t = c2.knots();
  const int n = static_cast<int>(c2.firstPiece.size()) - 1;
  const double firstArc = t[c2.firstPiece[1]] - t[0];  // normalise: the first arc has length 1
  Eigen::VectorXd T(n + 1);
  for (int i = 0; i <= n; ++i) T[i] = t[c2.firstPiece[i]] / firstArc;
  return T;
}

Eigen::VectorXd ringKnots(const Eigen::VectorXd& longitudes, CircleReparam method) {
  return arcKnots(circleToC2(g2Circle(longitudes), method));
}

// ---------------------------------------------------------------------------------------
// OpenCASCADE surfaces: one patch, the single surface

Handle(Geom_BSplineSurface) patchToOcct(const TaggedPatch& patch) {
  const int nu = patch.degreeU + 1, nv = patch.degreeV + 1;
  if (patch.bezier.rows() != nu * nv) throw InputError("a patch needs (degreeU + 1) (degreeV + 1) points");
  return detail::bezierPatchToOcct(patch.bezier, patch.degreeU, patch.degreeV, "a patch of the blend");
}

TaggedPatch raisePatch(const TaggedPatch& patch, int du, int dv) {
  // Row a (degreeV + 1) + b of a patch is b_ab: each column (fixed b) is a Bézier curve in
  // u, each row (fixed a) one in v; both are raised by bernstein::raise.
  TaggedPatch out = patch;
  if (out.degreeU < du) {
    const int ev = out.degreeV + 1;
    Homogeneous4 raised((du + 1) * ev, 4), column(out.degreeU + 1, 4);
    for (int b = 0; b < ev; ++b) {
      for (int a = 0; a <= out.degreeU; ++a) column.row(a) = out.bezier.row(a * ev + b);
      const Homogeneous4 c = bernstein::raise(column, du);
      for (int a = 0; a <= du; ++a) raised.row(a * ev + b) = c.row(a);
    }
    out.bezier = std::move(raised);
    out.degreeU = du;
  }
  if (out.degreeV < dv) {
    const int ev = out.degreeV + 1;
    Homogeneous4 raised((out.degreeU + 1) * (dv + 1), 4);
    for (int a = 0; a <= out.degreeU; ++a) {
      raised.middleRows(a * (dv + 1), dv + 1) = bernstein::raise(out.bezier.middleRows(a * ev, ev), dv);
    }
    out.bezier = std::move(raised);
    out.degreeV = dv;
  }
  return out;
}

Handle(Geom_BSplineSurface) singleSurface(const BlendComplex& complex, double tolerance, int smoothness) {
  if (smoothness < 0) throw InputError("smoothness must be 0 or more");
  const int rows = complex.rowsBasic + complex.rowsTransition + complex.rowsFreeForm, K = complex.piecesU;
  if (complex.knotsV.size() != rows + 1 || complex.knotsU.size() != K + 1)
    throw InputError("the complex has no shared knots");
  // Knots OpenCASCADE would call "too close" (arcs or heights a few ulps apart) are refused by name.
  requireSeparateKnots(complex.knotsU, "the complex's u knots (around the axis)");
  requireSeparateKnots(complex.knotsV, "the complex's v knots (along the profile)");
  int d = 0, e = 0;
  for (const TaggedPatch& p : complex.patches) {
    d = std::max(d, p.degreeU);
    e = std::max(e, p.degreeV);
  }
  // The homogeneous poles of the grid in Bezier form, one row per u index: row a holds
  // (w x, w y, w z, w) of every v index b at columns 4 b .. 4 b + 3.
  const Eigen::Index nu = d * K + 1, nv = e * rows + 1;
  detail::PointRows grid = detail::PointRows::Zero(nu, 4 * nv);
  double size = 0.0;
  int seen = 0;
  for (const TaggedPatch& patch : complex.patches) {
    const TaggedPatch p = raisePatch(patch, d, e);
    ++seen;
    for (int a = 0; a <= d; ++a) {
      for (int b = 0; b <= e; ++b) {
        const auto h = p.bezier.row(a * (e + 1) + b);
        if (!(h[3] > 0)) throw InputError("a patch has a non-positive weight");
        const Eigen::Vector3d point = h.head<3>().transpose() / h[3];
        requireFinite(point, "the single surface of the complex", "poles");
        grid.block<1, 4>(d * p.uPiece + a, 4 * (e * p.vPiece + b)) = h;
        size = std::max(size, h.cwiseAbs().maxCoeff());
      }
    }
  }
  if (seen != K * rows) throw InputError("the complex is not a tensor grid of patches");
  // C^smoothness where the multiplicities allow it: each interior knot down to degree -
  // smoothness, by knot removal in one pass per direction (knot_removal.hpp: linear in the
  // knots), first along u on whole rows of v poles, then along v on whole rows of u poles.
  const int qu = std::max(d - smoothness, 0), qv = std::max(e - smoothness, 0);
  const detail::KnotRemoval alongU = detail::removeKnotsBezier(grid, complex.knotsU, d, qu, tolerance * size);
  if (alongU.failedKnot > 0) {
    std::ostringstream os;
    os << "the complex is not C" << smoothness << " across u knot " << alongU.failedKnot;
    throw InputError(os.str());
  }
  const Eigen::Index NU = alongU.poles.rows();
  detail::PointRows byV(nv, 4 * NU);
  for (Eigen::Index a = 0; a < NU; ++a) {
    for (Eigen::Index b = 0; b < nv; ++b) byV.block<1, 4>(b, 4 * a) = alongU.poles.block<1, 4>(a, 4 * b);
  }
  const detail::KnotRemoval alongV = detail::removeKnotsBezier(byV, complex.knotsV, e, qv, tolerance * size);
  if (alongV.failedKnot > 0) {
    std::ostringstream os;
    os << "the complex is not C" << smoothness << " across v knot " << alongV.failedKnot
       << " (basic rows only G2? use sexticInV)";
    throw InputError(os.str());
  }
  const Eigen::Index NV = alongV.poles.rows();
  TColgp_Array2OfPnt poles(1, static_cast<int>(NU), 1, static_cast<int>(NV));
  TColStd_Array2OfReal weights(1, static_cast<int>(NU), 1, static_cast<int>(NV));
  for (Eigen::Index a = 0; a < NU; ++a) {
    for (Eigen::Index b = 0; b < NV; ++b) {
      const Eigen::Vector4d h = alongV.poles.block<1, 4>(b, 4 * a).transpose();
      const Eigen::Vector3d point = h.head<3>() / h[3];
      requireFinite(Eigen::Vector4d(point.x(), point.y(), point.z(), h[3]), "the single surface of the complex",
                    "poles after the knot removal");
      if (!(h[3] > 0))
        throw InputError("the single surface of the complex: a weight after the knot removal is not positive");
      poles.SetValue(static_cast<int>(a) + 1, static_cast<int>(b) + 1, gp_Pnt(point.x(), point.y(), point.z()));
      weights.SetValue(static_cast<int>(a) + 1, static_cast<int>(b) + 1, h[3]);
    }
  }
  // Distinct knots with multiplicities degree + 1 at the ends and degree - smoothness inside
  // (none inside when that is 0).
  auto knots = [](const Eigen::VectorXd& t, int degree, int inner, TColStd_Array1OfReal& k,
                  TColStd_Array1OfInteger& m) {
    int n = 0;
    for (Eigen::Index i = 0; i < t.size(); ++i) {
      const bool end = i == 0 || i + 1 == t.size();
      if (!end && inner == 0) continue;
      ++n;
      k.SetValue(n, t[i]);
      m.SetValue(n, end ? degree + 1 : inner);
    }
  };
  const int ku_count = qu > 0 ? K + 1 : 2, kv_count = qv > 0 ? rows + 1 : 2;
  TColStd_Array1OfReal ku(1, ku_count), kv(1, kv_count);
  TColStd_Array1OfInteger mu(1, ku_count), mv(1, kv_count);
  knots(complex.knotsU, d, qu, ku, mu);
  knots(complex.knotsV, e, qv, kv, mv);
  Handle(Geom_BSplineSurface) s;
  try {
    s = new Geom_BSplineSurface(poles, weights, ku, kv, mu, mv, d, e);
  } catch (const Standard_Failure& failure) {
    throw InputError(std::string("OpenCASCADE rejected the single surface of the complex: ") +
                     failure.GetMessageString());
  }
  return s;
}

}  // namespace fairsplines
