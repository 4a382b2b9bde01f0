// Shape to shape (Karčiauskas & Peters, Figs. 11 and 12, and the Fig. 2a baseline between
// two G2 complexes) and edited control structures of a shape (Section 4.1 on every layer,
// then Section 4.2), on the assembly of blend_surface.cpp.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "fairsplines/errors.hpp"
#include "blend_detail.hpp"
#include "blend_surface_detail.hpp"

namespace fairsplines {

using detail::assembleBlend;
using detail::BasicLayers;
using detail::checkedLongitudes;
using detail::lineProfile;
using detail::reversedProfile;
using detail::RevolvedProfile;
using detail::revolveRows;
using detail::sphereProfile;
using detail::stripPatch;
using detail::torusProfile;

namespace detail {

// ---------------------------------------------------------------------------------------
// The shapes of a join

JoinSide joinSide(const ShapeOfRevolution& shape, CircleReparam method) {
  JoinSide side;
  side.frame = shape.frame;
  side.lon = checkedLongitudes(shape.frame, shape.around);
  switch (shape.kind) {
    case ShapeOfRevolution::Kind::SphereZone:
      side.profile = sphereProfile(shape.size0, shape.profile, method);
      break;
    case ShapeOfRevolution::Kind::Cone:
      if (!std::isfinite(shape.size0) || !std::isfinite(shape.size1))
        throw InputError("a cone needs a finite radius and slope");
      side.profile = lineProfile(shape.size0, shape.size1, shape.profile);
      break;
    case ShapeOfRevolution::Kind::Torus:
      side.profile = torusProfile(shape.size0, shape.size1, shape.profile, method);
      break;
    case ShapeOfRevolution::Kind::Revolution:
      side.profile = detail::curveProfile(shape.curve, shape.profile);
      break;
  }
  return side;
}

void checkJoinOffAxis(const JoinSide& side, Interface at, const std::string& name) {
  const RevolvedProfile interface = at == Interface::End ? side.profile : reversedProfile(side.profile);
  if (!(interface.end.x() > 1e-9 * (std::abs(interface.end.y()) + interface.size))) {
    throw InputError("the " + name + " shape's profile meets the axis (a pole) at the join");
  }
}

// ---------------------------------------------------------------------------------------
// An edited control structure, layer by layer

BasicLayers editedLayers(const JoinSide& side, const G2Surface& edited, CircleReparam method,
                         const Eigen::VectorXd& betaT) {
  const int n = side.lon.pieces(), rows = static_cast<int>(side.profile.cubic.size());
  if (edited.nu != n || edited.nv != rows || edited.bezier.rows() != 16 * n * rows) {
    std::ostringstream os;
    os << "the edited control structure has " << edited.nu << " x " << edited.nv << " patches; the shape has " << n
       << " x " << rows;
    throw InputError(os.str());
  }
  for (Eigen::Index k = 0; k < edited.bezier.rows(); ++k) {
    if (!edited.bezier.row(k).allFinite() || !(edited.bezier(k, 3) > 0)) {
      throw InputError("the edited control structure has a non-finite point or a non-positive weight");
    }
  }
  // Section 4.1 on every control layer of the structure: the circle partition's maps (rho,
  // sigma or mixed) compose the Hermite quadratics of each layer's cubic pieces (eqs. (9),
  // (10)); eq. (11) then makes every arc-to-arc join C2 (it changes nothing where the join
  // is already C2, i.e. away from the edits).
  const CircleMaps maps = circleMaps(side.lon, method, betaT);
  BasicLayers basic;
  basic.rows = rows;
  basic.dv = 3;
  basic.knotsV = Eigen::VectorXd::LinSpaced(rows + 1, 0.0, rows);
  for (int J = 0; J < rows; ++J) {
    for (int sv = 0; sv <= 3; ++sv) {
      PointMatrix cubic(4 * n, 4);
      for (int I = 0; I < n; ++I) {
        for (int r = 0; r < 4; ++r) cubic.row(4 * I + r) = edited.point(I, J, r, sv);
      }
      C2SexticSpline layer = g2ToC2(cubic, maps.maps, maps.betaPieces, side.lon.closed);
      const int P = layer.pieces();
      for (int i = side.lon.closed ? 0 : 1; i < n; ++i) {
        const int k = layer.firstPiece[i], left = (k + P - 1) % P;
        PointMatrix a = layer.bezier.middleRows(7 * left, 7), b = layer.bezier.middleRows(7 * k, 7);
        adjustC2(a, b, layer.beta[k]);
        layer.bezier.middleRows(7 * left, 7) = a;
        layer.bezier.middleRows(7 * k, 7) = b;
      }
      basic.layers.push_back(std::move(layer));
    }
  }
  return basic;
}

}  // namespace detail

namespace {

using detail::JoinSide;

// ---------------------------------------------------------------------------------------
// Fig. 2a between two G2 complexes

/// The Fig. 2a baseline between two G2 complexes: cubic circle pieces as they are, a (3,5)
/// Hermite strip without reparameterization.
BlendComplex joinNaive(const JoinSide& a, const JoinSide& b) {
  BlendComplex out;
  out.knotsU = arcKnots(circleToC2(a.lon, CircleReparam::Sigma));
  out.piecesU = a.lon.pieces();
  out.closedU = a.lon.closed;
  out.rowsBasic = static_cast<int>(a.profile.cubic.size());
  out.rowsFreeForm = static_cast<int>(b.profile.cubic.size());
  out.knotsV =
      Eigen::VectorXd::LinSpaced(out.rowsBasic + out.rowsFreeForm + 2, 0.0, out.rowsBasic + out.rowsFreeForm + 1);
  for (int k = 0; k < out.piecesU; ++k) {
    Homogeneous4 top, bottom;
    for (int j = 0; j < out.rowsBasic; ++j) {
      TaggedPatch p;
      p.uPiece = k;
      p.vPiece = j;
      p.bezier = revolveRows(a.frame, a.lon.cubic.middleRows(4 * k, 4), a.profile.cubic[j]);
      if (j + 1 == out.rowsBasic) top = p.bezier;
      out.patches.push_back(std::move(p));
    }
    for (int j = 0; j < out.rowsFreeForm; ++j) {
      TaggedPatch p;
      p.uPiece = k;
      p.vPiece = out.rowsBasic + 1 + j;
      p.bezier = revolveRows(b.frame, b.lon.cubic.middleRows(4 * k, 4), b.profile.cubic[j]);
      if (j == 0) bottom = p.bezier;
      out.patches.push_back(std::move(p));
    }
    out.patches.push_back(stripPatch(k, out.rowsBasic, 3, top, 3, bottom, 3));
  }
  return out;
}

}  // namespace

// ---------------------------------------------------------------------------------------
// An edited control structure of a shape

BlendComplex blendEdited(const ShapeOfRevolution& shape, const G2Surface& edited, CircleReparam method,
                         Handle(Geom_BSplineSurface) ring) {
  const JoinSide side = detail::joinSide(shape, method);
  detail::checkJoinOffAxis(side, Interface::End, "edited");
  return assembleBlend(side.frame, side.lon, side.profile, detail::editedLayers(side, edited, method), ring);
}

// ---------------------------------------------------------------------------------------
// Figs. 11 and 12: shape to shape

BlendComplex joinShapes(const ShapeOfRevolution& shapeA, const ShapeOfRevolution& shapeB, CircleReparam method,
                        bool sexticInV, bool naive) {
  if (!naive) {
    BlendComplex out = blendChain({ChainShape{shapeA, std::nullopt}, ChainShape{shapeB, std::nullopt}},
                                  ChainEnd::open(), ChainEnd::open(), method, sexticInV);
    // As declared: rowsBasic counts a's rows (before the strip), rowsFreeForm b's (after it).
    const auto strip = std::find_if(out.patches.begin(), out.patches.end(),
                                    [](const TaggedPatch& p) { return p.role == TaggedPatch::Role::Transition; });
    out.rowsFreeForm = out.rowsBasic - strip->vPiece;
    out.rowsBasic = strip->vPiece;
    return out;
  }
  const JoinSide a = detail::joinSide(shapeA, method), b = detail::joinSide(shapeB, method);
  detail::checkJoinOffAxis(a, Interface::End, "first");
  detail::checkJoinOffAxis(b, Interface::Start, "second");
  if (b.lon.pieces() != a.lon.pieces()) {
    std::ostringstream os;
    os << "the two shapes need the same number of arcs around the axis (" << a.lon.pieces() << " and " << b.lon.pieces()
       << ")";
    throw InputError(os.str());
  }
  if (a.lon.closed != b.lon.closed)
    throw InputError("both shapes need a full turn around the axis, or both a partial one");
  return joinNaive(a, b);
}

}  // namespace fairsplines
