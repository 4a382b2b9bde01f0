// The free-form side of a blend (Karčiauskas & Peters, Section 4.2): a user's ring as
// Bézier patches, matched or normalised to the interface, its knots and cuts, and the
// default ring after a profile's end; see blend_detail.hpp and blend_surface_detail.hpp.
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <algorithm>
#include <cmath>
#include <sstream>

#include "fairsplines/bspline.hpp"
#include "fairsplines/errors.hpp"
#include "blend_detail.hpp"
#include "blend_surface_detail.hpp"
#include "finite.hpp"

namespace fairsplines {
namespace detail {

// ---------------------------------------------------------------------------------------
// A user's ring: its Bézier patches, matched or normalised to the interface

Homogeneous4 bezierOf(const Handle(Geom_BSplineSurface)& s, double u0, double u1, double v0, double v1, int& du,
                      int& dv) {
  Handle(Geom_BSplineSurface) c = Handle(Geom_BSplineSurface)::DownCast(s->Copy());
  c->Segment(u0, u1, v0, v1);
  du = c->UDegree();
  dv = c->VDegree();
  if (c->NbUPoles() != du + 1 || c->NbVPoles() != dv + 1)
    throw InputError("the free-form net could not be split into Bézier patches");
  Homogeneous4 out((du + 1) * (dv + 1), 4);
  for (int a = 0; a <= du; ++a) {
    for (int b = 0; b <= dv; ++b) {
      const gp_Pnt p = c->Pole(a + 1, b + 1);
      const double w = c->Weight(a + 1, b + 1);
      out.row(a * (dv + 1) + b) << w * p.X(), w * p.Y(), w * p.Z(), w;
    }
  }
  return out;
}

Handle(Geom_BSplineSurface) matchRingStrict(const Handle(Geom_BSplineSurface)& ring, const Eigen::VectorXd& T,
                                            const Eigen::VectorXd& cuts, int degree, bool closed) {
  const int n = static_cast<int>(T.size()) - 1;
  auto mismatch = [](const std::string& why) {
    return InputError("the free-form net does not match the interface: " + why);
  };
  if (ring.IsNull()) throw mismatch("no surface");
  if (closed != ring->IsUPeriodic()) {
    throw mismatch(closed ? "it must be periodic in u (closed around the axis)"
                          : "it must be open in u, like the shape");
  }
  if (ring->UDegree() != degree || ring->VDegree() != degree) {
    throw mismatch(degree == 3 ? "it must be bicubic" : "it must be biquadratic (degree 2 in u and v)");
  }
  if (ring->NbUKnots() != n + 1) {
    std::ostringstream os;
    os << "it needs " << n << " knot intervals in u (one per arc around the axis), not " << ring->NbUKnots() - 1;
    throw mismatch(os.str());
  }
  const double period = T[n] - T[0];
  for (int i = 0; i <= n; ++i) {
    if (i > 0 && i < n && ring->UMultiplicity(i + 1) != 1) throw mismatch("its u knots must be simple");
    if (std::abs(ring->UKnot(i + 1) - T[i]) > 1e-9 * period) {
      std::ostringstream os;
      os << "u knot " << i << " is " << ring->UKnot(i + 1) << ", the interface needs " << T[i]
         << " (knot intervals in the ratios beta of the arcs)";
      throw mismatch(os.str());
    }
  }
  if (ring->VMultiplicity(1) != degree + 1)
    throw mismatch("it must be clamped in v (its first row is at the interface)");
  Handle(Geom_BSplineSurface) r = Handle(Geom_BSplineSurface)::DownCast(ring->Copy());
  for (Eigen::Index k = 0; k < cuts.size(); ++k) {
    bool existing = false;
    for (int i = 0; i <= n; ++i) existing = existing || std::abs(cuts[k] - T[i]) <= 1e-12 * period;
    if (!existing) r->InsertUKnot(cuts[k], 1, 1e-12 * period);
  }
  return r;
}

Handle(Geom_BSplineSurface) normalisedRing(const Handle(Geom_BSplineSurface)& ring, const ShapeFrame& frame,
                                           double period, int degree, double turn) {
  auto mismatch = [](const std::string& why) {
    return InputError("the free-form net does not match the interface: " + why);
  };
  const bool closed = std::abs(turn - 2 * M_PI) <= 1e-9;
  if (ring.IsNull()) throw mismatch("no surface");
  if (closed && !ring->IsUPeriodic()) throw mismatch("it must be periodic in u (closed around the axis)");
  if (!closed && (ring->IsUPeriodic() || ring->UMultiplicity(1) != degree + 1 ||
                  ring->UMultiplicity(ring->NbUKnots()) != degree + 1)) {
    throw mismatch("it must be clamped in u (open, like the shape's partial turn)");
  }
  if (ring->UDegree() != degree || ring->VDegree() != degree) {
    throw mismatch(degree == 3 ? "it must be bicubic" : "it must be biquadratic (degree 2 in u and v)");
  }
  if (ring->VMultiplicity(1) != degree + 1) throw mismatch("it must be clamped in v (its first row is the interface)");
  const double u0 = ring->UKnot(1), P = ring->UKnot(ring->NbUKnots()) - u0, v0 = ring->VKnot(1);
  // How far the first row turns about the axis (a winding number for a full turn), from 64
  // samples per knot span, against the shape's turn.
  const int samples = 64 * (ring->NbUKnots() - 1);
  double turned = 0.0, previous = 0.0;
  for (int k = 0; k <= samples; ++k) {
    const gp_Pnt q = ring->Value(u0 + P * k / samples, v0);
    const Eigen::Vector3d d = Eigen::Vector3d(q.X(), q.Y(), q.Z()) - frame.origin;
    const double angle = std::atan2(d.dot(frame.y), d.dot(frame.x));
    if (k > 0) turned += std::remainder(angle - previous, 2 * M_PI);
    previous = angle;
  }
  const double winding = turned / turn;
  if (std::abs(winding + 1) < 0.5)
    throw mismatch("its first row turns the other way around the axis (reverse its u direction)");
  if (std::abs(winding - 1) >= 0.5) {
    throw mismatch(closed ? "its first row does not go once around the shape's axis"
                          : "its first row does not run along the shape's angles around the axis");
  }
  Handle(Geom_BSplineSurface) r = Handle(Geom_BSplineSurface)::DownCast(ring->Copy());
  TColStd_Array1OfReal knots(1, r->NbUKnots());
  for (int i = 1; i <= r->NbUKnots(); ++i) knots.SetValue(i, (r->UKnot(i) - u0) * period / P);
  r->SetUKnots(knots);
  return r;
}

Handle(Geom_BSplineSurface) withKnots(const Handle(Geom_BSplineSurface)& ring, const Eigen::VectorXd& knotsU) {
  Handle(Geom_BSplineSurface) r = Handle(Geom_BSplineSurface)::DownCast(ring->Copy());
  const double period = knotsU[knotsU.size() - 1] - knotsU[0];
  for (Eigen::Index k = 0; k < knotsU.size(); ++k) {
    bool existing = false;
    for (int i = 1; i <= ring->NbUKnots(); ++i)
      existing = existing || std::abs(knotsU[k] - ring->UKnot(i)) <= 1e-12 * period;
    if (!existing) r->InsertUKnot(knotsU[k], 1, 1e-12 * period);
  }
  return r;
}

std::vector<std::vector<double>> knotCuts(const Eigen::VectorXd& values, const Eigen::VectorXd& knotsU) {
  const int P = static_cast<int>(knotsU.size()) - 1;
  const double period = knotsU[P] - knotsU[0];
  std::vector<std::vector<double>> cuts(P);
  for (Eigen::Index i = 0; i < values.size(); ++i) {
    const double u = values[i];
    for (int k = 0; k < P; ++k) {
      if (u > knotsU[k] + 1e-9 * period && u < knotsU[k + 1] - 1e-9 * period) {
        cuts[k].push_back((u - knotsU[k]) / (knotsU[k + 1] - knotsU[k]));
      }
    }
  }
  return cuts;
}

std::vector<std::vector<double>> ringCuts(const Handle(Geom_BSplineSurface)& ring, const Eigen::VectorXd& knotsU) {
  Eigen::VectorXd knots(ring->NbUKnots());
  for (int i = 1; i <= ring->NbUKnots(); ++i) knots[i - 1] = ring->UKnot(i);
  return knotCuts(knots, knotsU);
}

// ---------------------------------------------------------------------------------------
// The default ring's extent (shared with the C1 ring)

namespace {
constexpr double kAxisMargin = 0.05;       // the last row stays this share of the shape's extent off the axis
constexpr double kMinRingFraction = 0.05;  // below a twentieth of the full ring, there is no default ring
}  // namespace

double defaultRingRoom(const Eigen::Vector2d& end, const Eigen::Vector2d& tangent, double size, int rows) {
  const double margin = kAxisMargin * (std::max(std::abs(end.x()), std::abs(end.y())) + size);
  const double reach = size / 2 + (rows - 1) * size / 4;  // the last row's distance, full ring
  if (!(end.x() > margin)) return 0.0;
  if (tangent.x() >= 0.0) return 1.0;  // away from the axis, or along it
  return std::min(1.0, (end.x() - margin) / (reach * -tangent.x()));
}

RingRows defaultRingRows(const Eigen::Vector2d& end, const Eigen::Vector2d& tangent, double size, int rows,
                         const char* which) {
  const double room = defaultRingRoom(end, tangent, size, rows);
  if (!(room >= kMinRingFraction)) {
    throw InputError(
        std::string("the default ring has no room at the ") + which + ": it is " + exactNumber(end.x()) +
        " from the axis and the ring runs towards it, so less than a twentieth of the ring fits; join at the "
        "other end of the profile, end the shape farther from the axis, or give a free-form ring");
  }
  RingRows out;
  out.fraction = room;
  out.offset = room * size / 2;
  out.step = room * size / 4;
  return out;
}

// ---------------------------------------------------------------------------------------
// The default ring

Handle(Geom_BSplineSurface) defaultRing(const ShapeFrame& frame, const G2CircleSpline& lon, const RevolvedProfile& p,
                                        const Eigen::VectorXd& knotsU, const char* which) {
  const int n = lon.pieces();
  if (knotsU.size() != n + 1) throw InputError("the ring needs one knot per longitude");
  const RingRows rows = defaultRingRows(p.end, p.tangent, p.size, 4, which);
  const Eigen::Vector2d base = p.end + rows.offset * p.tangent;
  const double step = rows.step;
  // Full turn: one pole per longitude, periodic. Partial turn: clamped, the end poles on the
  // circle, the next ones along its tangent (a third of the end arc), one per inner longitude.
  const int poleCount = lon.closed ? n : n + 3;
  TColgp_Array2OfPnt poles(1, poleCount, 1, 4);
  BSplineCurve layout;
  for (int j = 0; j < 4; ++j) {
    const Eigen::Vector2d rz = base + j * step * p.tangent;
    auto at = [&](double theta, double radius) {
      const Eigen::Vector3d q =
          frame.origin + radius * (std::cos(theta) * frame.x + std::sin(theta) * frame.y) + rz.y() * frame.z;
      return Eigen::RowVector3d(q.transpose());
    };
    auto inner = [&](int i) {
      // Pushed out so that the spline passes near the circle of radius rz.x(): a uniform
      // cubic at a knot is (c_{i-1} + 4 c_i + c_{i+1}) / 6.
      const double a = (lon.alpha[(i + n - 1) % n] + lon.alpha[i % n]) / 2, f = 3.0 / (2.0 + std::cos(a));
      return at(lon.theta[i], f * rz.x());
    };
    PointMatrix row(poleCount, 3);
    if (lon.closed) {
      // periodicCubic stores row r as OCCT's pole r - 1, whose span [T_0, T_1] then lies
      // between rows 2 and 3 (evaluated by OCCT: 120-180 degrees of 6 arcs); the strip pairs
      // the ring's span k with the shape's arc k, so the pole of longitude i goes to row
      // i + 2: span k between longitudes k and k + 1 (else the strip twists by two arcs and
      // narrows to a waist, as a hyperboloid).
      for (int i = 0; i < n; ++i) row.row((i + 2) % n) = inner(i);
      layout = periodicCubic(row, knotsU);
    } else {
      const auto tangentAt = [&](double theta) {
        const Eigen::Vector3d d = -std::sin(theta) * frame.x + std::cos(theta) * frame.y;
        return Eigen::RowVector3d(d.transpose());
      };
      row.row(0) = at(lon.theta[0], rz.x());
      row.row(1) = row.row(0) + rz.x() * lon.alpha[0] / 3 * tangentAt(lon.theta[0]);
      for (int i = 1; i < n; ++i) row.row(i + 1) = inner(i);
      row.row(n + 2) = at(lon.theta[n], rz.x());
      row.row(n + 1) = row.row(n + 2) - rz.x() * lon.alpha[n - 1] / 3 * tangentAt(lon.theta[n]);
      layout = clampedCubic(row, knotsU);
    }
    for (int i = 0; i < poleCount; ++i) {
      poles.SetValue(i + 1, j + 1, gp_Pnt(layout.poles(i, 0), layout.poles(i, 1), layout.poles(i, 2)));
    }
  }
  TColStd_Array1OfReal uKnots(1, static_cast<int>(layout.knots.size())), vKnots(1, 2);
  TColStd_Array1OfInteger uMults(1, static_cast<int>(layout.mults.size())), vMults(1, 2);
  for (int k = 0; k < layout.knots.size(); ++k) {
    uKnots.SetValue(k + 1, layout.knots[k]);
    uMults.SetValue(k + 1, layout.mults[k]);
  }
  vKnots.SetValue(1, 0.0);
  vKnots.SetValue(2, 1.0);
  vMults.Init(4);
  return new Geom_BSplineSurface(poles, uKnots, vKnots, uMults, vMults, 3, 3, lon.closed, false);
}

}  // namespace detail

using detail::atInterface;
using detail::checkedLongitudes;
using detail::defaultRing;
using detail::sphereProfile;

Handle(Geom_BSplineSurface) defaultSphereRing(const ShapeFrame& frame, double radius, const Eigen::VectorXd& longitudes,
                                              const Eigen::VectorXd& latitudes, const Eigen::VectorXd& knotsU) {
  return defaultRing(frame, checkedLongitudes(frame, longitudes),
                     atInterface(sphereProfile(radius, latitudes, CircleReparam::Rho), Interface::End), knotsU);
}

}  // namespace fairsplines
