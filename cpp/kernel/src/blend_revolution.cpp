// Surfaces of revolution of any designed profile (issue 32): a rational cubic spline in a
// half-plane bounded by the axis, revolved by the circle pieces of eq. (2) (Karčiauskas &
// Peters, Section 2), and the affine images under which every construction commutes.
#include <Geom_BSplineCurve.hxx>
#include <Standard_Failure.hxx>
#include <algorithm>
#include <cmath>
#include <sstream>

#include "fairsplines/blend_shapes.hpp"
#include "fairsplines/blend_surface.hpp"
#include "fairsplines/errors.hpp"
#include "fairsplines/occt.hpp"
#include "finite.hpp"

namespace fairsplines {

namespace {

std::string number(double v) {
  std::ostringstream os;
  os << v;
  return os.str();
}

/// The curve raised to degree 3 with every interior knot of multiplicity 3: its poles are
/// then the Bézier points of its pieces (knot insertion is exact in homogeneous space).
Handle(Geom_BSplineCurve) bezierForm(const BSplineCurve& curve, const Eigen::VectorXd& splits) {
  Handle(Geom_BSplineCurve) c = toOcct(curve);
  try {
    if (c->Degree() < 3) c->IncreaseDegree(3);
    c->Segment(c->FirstParameter(), c->LastParameter());  // clamped at both ends
    const double t0 = c->FirstParameter(), t1 = c->LastParameter();
    for (Eigen::Index k = 0; k < splits.size(); ++k) {
      if (!(splits[k] > t0 + 1e-9 * (t1 - t0) && splits[k] < t1 - 1e-9 * (t1 - t0))) {
        throw InputError("split " + std::to_string(k) + " (" + number(splits[k]) +
                         ") is not inside the profile's parameter range (" + number(t0) + ", " + number(t1) + ")");
      }
      c->InsertKnot(splits[k], 1);
    }
    if (c->NbKnots() > 2) c->IncreaseMultiplicity(2, c->NbKnots() - 1, 3);
  } catch (const Standard_Failure& failure) {
    throw InputError(std::string("OpenCASCADE could not split the profile into pieces: ") + failure.GetMessageString());
  }
  return c;
}

}  // namespace

RevolutionProfile revolutionProfile(const BSplineCurve& curve, const Eigen::Vector3d& origin,
                                    const Eigen::Vector3d& axis, const Eigen::VectorXd& splits) {
  requireValidCurve(curve, "the profile");
  if (curve.degree > 3) {
    throw InputError("the profile has degree " + std::to_string(curve.degree) +
                     ": a rational cubic spline needs degree <= 3 (approximate it, e.g. by fw.design_spline)");
  }
  if (curve.periodic) throw InputError("the profile is closed (periodic): give an open curve, there is no end to join");
  if (!origin.allFinite() || !axis.allFinite() || !(axis.norm() > 0)) {
    throw InputError("the axis needs a finite centre and a finite, non-zero direction");
  }
  const Handle(Geom_BSplineCurve) c = bezierForm(curve, splits);
  const int m = c->NbKnots() - 1, n = c->NbPoles();
  if (n != 3 * m + 1) throw InputError("the profile's Bézier form has an unexpected number of poles");
  RevolutionProfile out;
  out.frame.origin = origin;
  out.frame.z = axis.normalized();
  // Radial parts of the poles: the profile's half-plane is that of the farthest pole.
  Eigen::MatrixXd radial(n, 3);
  Eigen::VectorXd zeta(n);
  double reach = 0.0, far = -1.0;
  int farthest = 0;
  for (int i = 0; i < n; ++i) {
    const gp_Pnt p = c->Pole(i + 1);
    const Eigen::Vector3d d = Eigen::Vector3d(p.X(), p.Y(), p.Z()) - origin;
    zeta[i] = d.dot(out.frame.z);
    radial.row(i) = (d - zeta[i] * out.frame.z).transpose();
    reach = std::max(reach, d.norm());
    if (radial.row(i).norm() > far) {
      far = radial.row(i).norm();
      farthest = i;
    }
  }
  const double tolerance = 1e-9 * reach;
  if (!(far > tolerance)) throw InputError("the profile lies on the axis: there is nothing to revolve");
  out.frame.x = radial.row(farthest).transpose() / far;
  out.frame.y = out.frame.z.cross(out.frame.x);
  out.cubic.resize(4 * m, 3);
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d r = radial.row(i).transpose();
    if (std::abs(r.dot(out.frame.y)) > tolerance) {
      throw InputError("the profile is not in a plane through the axis: its pole " + std::to_string(i) + " is " +
                       number(std::abs(r.dot(out.frame.y))) + " off the plane of the axis and pole " +
                       std::to_string(farthest));
    }
    const double w = c->Weight(i + 1), rho = r.dot(out.frame.x);
    const Eigen::RowVector3d h(w * rho, w * zeta[i], w);
    // Bézier point k of piece j is pole 3 j + k; inner ends belong to two pieces.
    if (i < n - 1) out.cubic.row(4 * (i / 3) + i % 3) = h;
    if (i > 0 && i % 3 == 0) out.cubic.row(4 * (i / 3 - 1) + 3) = h;
  }
  out.knots.resize(m + 1);
  for (int k = 0; k <= m; ++k) out.knots[k] = c->Knot(k + 1);
  // Off the axis: a piece whose Bézier points have rho > 0 has rho > 0 throughout (convex
  // hull, positive weights); elsewhere the curve itself is sampled.
  for (int j = 0; j < m; ++j) {
    const auto piece = out.cubic.middleRows(4 * j, 4);
    bool clear = true;
    for (int k = 0; k < 4; ++k) clear = clear && piece(k, 0) / piece(k, 2) > tolerance;
    if (clear) continue;
    for (int s = 0; s <= 64; ++s) {
      const double t = s / 64.0,
                   b[4] = {(1 - t) * (1 - t) * (1 - t), 3 * t * (1 - t) * (1 - t), 3 * t * t * (1 - t), t * t * t};
      Eigen::RowVector3d h = Eigen::RowVector3d::Zero();
      for (int k = 0; k < 4; ++k) h += b[k] * piece.row(k);
      if (!(h[0] / h[2] > tolerance)) {
        throw InputError("the profile touches or crosses the axis (piece " + std::to_string(j) + ", parameter " +
                         number(out.knots[j] + t * (out.knots[j + 1] - out.knots[j])) + ", distance from the axis " +
                         number(h[0] / h[2]) + "): a surface of revolution needs its profile on one side of the axis");
      }
    }
  }
  return out;
}

G2Surface revolution(const RevolutionProfile& profile, const Eigen::VectorXd& angles) {
  const int m = profile.pieces();
  Eigen::VectorXd beta = Eigen::VectorXd::Ones(m), gamma = Eigen::VectorXd::Zero(m);
  for (int j = 1; j < m; ++j) {
    beta[j] = (profile.knots[j + 1] - profile.knots[j]) / (profile.knots[j] - profile.knots[j - 1]);
  }
  return revolveG2(profile.frame, profile.cubic, beta, gamma, false, g2Circle(angles));
}

Homogeneous4 affineImage(const Homogeneous4& rows, const Eigen::Matrix3d& A, const Eigen::Vector3d& t) {
  if (!A.allFinite() || !t.allFinite()) throw InputError("the affine map is not finite");
  const double scale = A.cwiseAbs().maxCoeff();
  if (!(std::abs(A.determinant()) > 1e-12 * scale * scale * scale)) {
    throw InputError("the affine map is degenerate (its determinant is 0): it would flatten the shape");
  }
  Eigen::Matrix4d M = Eigen::Matrix4d::Identity();
  M.topLeftCorner<3, 3>() = A;
  M.topRightCorner<3, 1>() = t;
  return projectiveImage(rows, M);
}

Homogeneous4 projectiveImage(const Homogeneous4& rows, const Eigen::Matrix4d& M) {
  if (!M.allFinite()) throw InputError("the map is not finite");
  const double scale = M.cwiseAbs().maxCoeff();
  if (!(std::abs(M.determinant()) > 1e-12 * std::pow(scale, 4))) {
    throw InputError("the map is degenerate (its determinant is 0): it would flatten the shape");
  }
  Homogeneous4 out(rows.rows(), 4);
  for (Eigen::Index k = 0; k < rows.rows(); ++k) {
    out.row(k) = (M * rows.row(k).transpose()).transpose();
    if (!(out(k, 3) > 0)) {
      throw InputError("the map sends control point " + std::to_string(k) + " to weight " + number(out(k, 3)) +
                       " (<= 0: to infinity or beyond); keep the shape where the map's weight is positive");
    }
  }
  return out;
}

ShapeOfRevolution ShapeOfRevolution::of(const RevolutionProfile& p, const Eigen::VectorXd& around) {
  ShapeOfRevolution s;
  s.kind = Kind::Revolution;
  s.frame = p.frame;
  s.around = around;
  s.profile = p.knots;
  s.curve = p.cubic;
  return s;
}

}  // namespace fairsplines
