// Several interfaces on one complex (issue 15): shapes of revolution joined end to start
// (Karčiauskas & Peters, Figs. 9, 11, 12), with free-form rings (Section 4.2) at either or
// both ends of the chain, all in one C2 complex. The strip, the layers of a shape and the
// rings are those of blend_surface.cpp, blend_join.cpp and blend_ring.cpp.
#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "fairsplines/errors.hpp"
#include "blend_detail.hpp"
#include "blend_surface_detail.hpp"

namespace fairsplines {

using detail::BasicLayers;
using detail::JoinSide;

namespace {

// ---------------------------------------------------------------------------------------
// The shapes of the chain and their layers

/// "shape 2" for messages (numbers from 1), or "the shape" when there is only one.
std::string shapeName(int s, int count) {
  return count == 1 ? std::string("the") : "shape " + std::to_string(s + 1) + "'s";
}

/// Throws InputError where an interface of shape s lies on the axis.
void checkInterface(const JoinSide& side, Interface at, int s, int count) {
  const detail::RevolvedProfile p = at == Interface::End ? side.profile : detail::reversedProfile(side.profile);
  if (!(p.end.x() > 1e-9 * (std::abs(p.end.y()) + p.size))) {
    throw InputError(shapeName(s, count) + " profile meets the axis (a pole) at its " +
                     (at == Interface::End ? "end" : "start") + ", where the chain joins it: nothing can join there");
  }
}

/// Fig. 11 for any number of shapes: betaT_i = (prod_s beta_i^s)^(1/S), the geometric mean,
/// which keeps the product around a closed turn at 1 as every beta^s does.
Eigen::VectorXd meanScalars(const std::vector<JoinSide>& sides) {
  Eigen::ArrayXd logBeta = Eigen::ArrayXd::Zero(sides.front().lon.beta.size());
  for (const JoinSide& side : sides) logBeta += side.lon.beta.array().log();
  return (logBeta / static_cast<double>(sides.size())).exp().matrix();
}

/// Fig. 12: arc i of every layer split into the least common multiple of the pieces the
/// shapes give it, so that all share their pieces without knot insertion.
void commonPieces(std::vector<BasicLayers>& layers, int arcs) {
  std::vector<int> parts(arcs, 1);
  for (const BasicLayers& l : layers) {
    const C2SexticSpline& c = l.layers.front();
    for (int i = 0; i < arcs; ++i) parts[i] = std::lcm(parts[i], c.firstPiece[i + 1] - c.firstPiece[i]);
  }
  for (BasicLayers& l : layers) {
    for (C2SexticSpline& layer : l.layers) layer = refineArcs(layer, parts);
  }
}

/// The u knots of the layers, scaled to `period` (period <= 0: the first arc of length 1,
/// as arcKnots).
Eigen::VectorXd knotsOf(const C2SexticSpline& c, double period) {
  const Eigen::VectorXd t = c.knots();
  return period > 0 ? Eigen::VectorXd(t * (period / t[t.size() - 1])) : Eigen::VectorXd(t / t[c.firstPiece[1]]);
}

// ---------------------------------------------------------------------------------------
// The rows of the complex along v

/// One row of patches across the complex: a shape's row, a strip or a ring span.
struct VRow {
  TaggedPatch::Role role = TaggedPatch::Role::Basic;
  int link = 0, row = 0;  ///< shape and its row (Basic), or ring 0 (start) / 1 (end) and span (FreeForm)
  double length = 0.0;    ///< v interval
};

/// The Bézier patch of ring span sp over u piece [u0, u1], its v reversed where `flip`.
TaggedPatch ringPatch(const Handle(Geom_BSplineSurface)& r, double u0, double u1, int sp, bool flip) {
  int du = 0, dv = 0;
  TaggedPatch p;
  p.role = TaggedPatch::Role::FreeForm;
  const Homogeneous4 b = detail::bezierOf(r, u0, u1, r->VKnot(sp + 1), r->VKnot(sp + 2), du, dv);
  p.degreeU = du;
  p.degreeV = dv;
  p.bezier = b;
  if (flip) {
    for (int a = 0; a <= du; ++a) {
      for (int c = 0; c <= dv; ++c) p.bezier.row(a * (dv + 1) + c) = b.row(a * (dv + 1) + dv - c);
    }
  }
  return p;
}

}  // namespace

// ---------------------------------------------------------------------------------------
// The chain

BlendComplex blendChain(const std::vector<ChainShape>& shapes, const ChainEnd& start, const ChainEnd& end,
                        CircleReparam method, bool sexticInV) {
  const int S = static_cast<int>(shapes.size());
  if (S == 0) throw InputError("a chain needs at least one shape");
  if (S == 1 && !start.ring && !end.ring)
    throw InputError("one shape with no free-form at either end has nothing to join: ask for a ring at an end");
  std::vector<JoinSide> sides;
  for (int s = 0; s < S; ++s) sides.push_back(detail::joinSide(shapes[s].shape, method));
  const int n = sides.front().lon.pieces();
  for (int s = 1; s < S; ++s) {
    if (sides[s].lon.pieces() != n) {
      std::ostringstream os;
      if (S == 2) {
        os << "the two shapes need the same number of arcs around the axis (" << n << " and " << sides[s].lon.pieces()
           << ")";
      } else {
        os << "the shapes need the same number of arcs around the axis: shape 1 has " << n << ", shape " << s + 1
           << " has " << sides[s].lon.pieces();
      }
      throw InputError(os.str());
    }
    if (sides[s].lon.closed != sides.front().lon.closed) {
      throw InputError(S == 2 ? "both shapes need a full turn around the axis, or both a partial one"
                              : "the shapes need a full turn around the axis, or all a partial one");
    }
  }
  for (int s = 0; s < S; ++s) {
    if (s > 0 || start.ring) checkInterface(sides[s], Interface::Start, s, S);
    if (s + 1 < S || end.ring) checkInterface(sides[s], Interface::End, s, S);
  }

  // Section 4.1 for every shape with the chain's scalars (Fig. 11), on common pieces (Fig. 12).
  const Eigen::VectorXd betaT = meanScalars(sides);
  std::vector<BasicLayers> layers;
  bool anyEdited = false;
  for (int s = 0; s < S; ++s) {
    if (shapes[s].edited) {
      anyEdited = true;
      layers.push_back(detail::editedLayers(sides[s], *shapes[s].edited, method, betaT));
    } else {
      layers.push_back(
          detail::revolvedLayers(sides[s].frame, circleToC2(sides[s].lon, method, betaT), sides[s].profile, sexticInV));
    }
  }
  commonPieces(layers, n);
  Eigen::VectorXd knotsU = knotsOf(layers.front().layers.front(), 0.0);
  for (int s = 1; s < S; ++s) {
    const Eigen::VectorXd t = knotsOf(layers[s].layers.front(), 0.0);
    if (t.size() != knotsU.size() || !((t - knotsU).cwiseAbs().maxCoeff() <= 1e-9 * knotsU[knotsU.size() - 1])) {
      throw std::logic_error("blendChain: the shapes' u knots differ after refinement");
    }
  }
  const double period = knotsU[knotsU.size() - 1];

  // User rings: the period mapped onto the circle's; the pieces of every shape split at
  // their u knots, so that all sides share one C2 parameterization (as assembleBlend).
  const G2CircleSpline& lon = sides.front().lon;
  const double turn = lon.theta[lon.pieces()] - lon.theta[0];
  Handle(Geom_BSplineSurface) rings[2];
  const ChainEnd* ends[2] = {&start, &end};
  const JoinSide* ringSide[2] = {&sides.front(), &sides.back()};
  for (int e = 0; e < 2; ++e) {
    if (!ends[e]->ring || ends[e]->net.IsNull()) continue;
    rings[e] = detail::normalisedRing(ends[e]->net, ringSide[e]->frame, period, 3, turn);
    const std::vector<std::vector<double>> cuts = detail::ringCuts(rings[e], knotsU);
    if (std::none_of(cuts.begin(), cuts.end(), [](const std::vector<double>& c) { return !c.empty(); })) continue;
    for (BasicLayers& l : layers) {
      for (C2SexticSpline& layer : l.layers) layer = splitPieces(layer, cuts);
    }
    knotsU = knotsOf(layers.front().layers.front(), period);
  }
  // Default rings on the arc knots of the conversion (one pole per longitude).
  const std::vector<int>& firstPiece = layers.front().layers.front().firstPiece;
  Eigen::VectorXd T(n + 1);
  for (int i = 0; i <= n; ++i) T[i] = knotsU[firstPiece[i]];
  for (int e = 0; e < 2; ++e) {
    if (!ends[e]->ring) continue;
    if (rings[e].IsNull()) {
      const detail::RevolvedProfile p = e == 0 ? detail::reversedProfile(ringSide[e]->profile) : ringSide[e]->profile;
      const std::string which =
          e == 0 ? "start of " + shapeName(0, S) + " profile" : "end of " + shapeName(S - 1, S) + " profile";
      rings[e] = detail::defaultRing(ringSide[e]->frame, ringSide[e]->lon, p, T, which.c_str());
    }
    rings[e] = detail::withKnots(rings[e], knotsU);
  }

  // The rows along v, with their lengths: scalar 1 across both seams of every strip.
  std::vector<VRow> rows;
  auto ringSpanLengths = [&](int e, double first) {
    const Handle(Geom_BSplineSurface)& r = rings[e];
    std::vector<double> out;
    for (int sp = 0; sp + 1 < r->NbVKnots(); ++sp) {
      out.push_back(first * (r->VKnot(sp + 2) - r->VKnot(sp + 1)) / (r->VKnot(2) - r->VKnot(1)));
    }
    return out;
  };
  double previous = 0.0;  // length of the last row added
  if (start.ring) {
    const Eigen::VectorXd& k0 = layers.front().knotsV;
    const double first = k0[1] - k0[0];
    const std::vector<double> spans = ringSpanLengths(0, first);
    for (int sp = static_cast<int>(spans.size()) - 1; sp >= 0; --sp) {
      rows.push_back({TaggedPatch::Role::FreeForm, 0, sp, spans[sp]});
    }
    rows.push_back({TaggedPatch::Role::Transition, 0, 0, first});
  }
  for (int s = 0; s < S; ++s) {
    const Eigen::VectorXd& k = layers[s].knotsV;
    double scale = 1.0;
    if (s > 0) {
      rows.push_back({TaggedPatch::Role::Transition, s, 0, previous});
      scale = previous / (k[1] - k[0]);
    }
    for (int j = 0; j < layers[s].rows; ++j)
      rows.push_back({TaggedPatch::Role::Basic, s, j, scale * (k[j + 1] - k[j])});
    previous = rows.back().length;
  }
  if (end.ring) {
    rows.push_back({TaggedPatch::Role::Transition, S, 0, previous});
    const std::vector<double> spans = ringSpanLengths(1, previous);
    for (int sp = 0; sp < static_cast<int>(spans.size()); ++sp) {
      rows.push_back({TaggedPatch::Role::FreeForm, 1, sp, spans[sp]});
    }
  }

  BlendComplex out;
  out.knotsU = knotsU;
  out.piecesU = layers.front().layers.front().pieces();
  out.closedU = lon.closed;
  out.basicC2InV = sexticInV && !anyEdited;
  out.smoothness = 2;
  out.rowsBasic = out.rowsTransition = out.rowsFreeForm = 0;
  out.knotsV.resize(static_cast<Eigen::Index>(rows.size()) + 1);
  out.knotsV[0] = layers.front().knotsV[0];
  for (std::size_t v = 0; v < rows.size(); ++v) {
    out.knotsV[v + 1] = out.knotsV[v] + rows[v].length;
    (rows[v].role == TaggedPatch::Role::Basic        ? out.rowsBasic
     : rows[v].role == TaggedPatch::Role::Transition ? out.rowsTransition
                                                     : out.rowsFreeForm) += 1;
  }
  const int V = static_cast<int>(rows.size());
  for (int k = 0; k < out.piecesU; ++k) {
    std::vector<TaggedPatch> column(V);
    for (int v = 0; v < V; ++v) {
      const VRow& row = rows[v];
      TaggedPatch& p = column[v];
      if (row.role == TaggedPatch::Role::Basic) {
        const BasicLayers& l = layers[row.link];
        p.degreeU = 6;
        p.degreeV = l.dv;
        p.bezier.resize(7 * (l.dv + 1), 4);
        for (int a = 0; a <= 6; ++a) {
          for (int sv = 0; sv <= l.dv; ++sv) {
            p.bezier.row(a * (l.dv + 1) + sv) = l.layers[row.row * (l.dv + 1) + sv].bezier.row(7 * k + a);
          }
        }
      } else if (row.role == TaggedPatch::Role::FreeForm) {
        p = ringPatch(rings[row.link], knotsU[k], knotsU[k + 1], row.row, row.link == 0);
      }
      p.uPiece = k;
      p.vPiece = v;
    }
    // Section 4.2, steps 2-3: every strip from three layers of the rows on either side,
    // degree-raised to (6,5).
    for (int v = 0; v < V; ++v) {
      if (rows[v].role != TaggedPatch::Role::Transition) continue;
      const TaggedPatch lower = raisePatch(column[v - 1], 6, column[v - 1].degreeV);
      const TaggedPatch upper = raisePatch(column[v + 1], 6, column[v + 1].degreeV);
      column[v] = detail::stripPatch(k, v, 6, lower.bezier, lower.degreeV, upper.bezier, upper.degreeV);
    }
    for (TaggedPatch& p : column) out.patches.push_back(std::move(p));
  }
  return out;
}

}  // namespace fairsplines
