#include "fairsplines/surfaces.hpp"

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRep_Builder.hxx>
#include <Eigen/Geometry>
#include <Precision.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColStd_Array2OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <algorithm>
#include <cmath>
#include <sstream>

#include "fairsplines/errors.hpp"
#include "finite.hpp"

namespace fairsplines {

PointMatrix tensorControlNet(const PointMatrix& bezier, int nI, int nJ, const Eigen::VectorXd& betaU,
                             const Eigen::VectorXd& betaV) {
  if (nI < 1 || nJ < 1 || bezier.rows() != 16 * nI * nJ) throw InputError("eq. (11) needs 16 Bézier points per patch");
  if (betaU.size() != nI + 1 || betaV.size() != nJ + 1) throw InputError("eq. (11) needs one beta per control row");
  PointMatrix c(nI * nJ, bezier.cols());
  for (int i = 1; i <= nI; ++i) {
    for (int j = 1; j <= nJ; ++j) {
      const Eigen::Index base = static_cast<Eigen::Index>((i - 1) * nJ + (j - 1)) * 16;
      auto b = [&](int r, int s) { return bezier.row(base + 4 * r + s); };
      const double bu = betaU[i], bv = betaV[j];
      // Eq. (11): the left form of eq. (3) in each variable.
      c.row((i - 1) * nJ + (j - 1)) =
          bu * bv * b(1, 1) - bu * (1 + bv) * b(1, 2) - (1 + bu) * bv * b(2, 1) + (1 + bu) * (1 + bv) * b(2, 2);
    }
  }
  return c;
}

BSplineSurface revolve(const BSplineCurve& profile, const Eigen::Vector3d& axisPoint,
                       const Eigen::Vector3d& axisDirection) {
  if (!axisPoint.allFinite() || !axisDirection.allFinite() || axisDirection.norm() <= 1e-300) {
    throw InputError("the axis of revolution needs a point and a non-zero direction");
  }
  if (profile.periodic) throw InputError("revolve a profile that is not periodic");
  const Eigen::Vector3d axis = axisDirection.normalized();
  const Eigen::Index nu = profile.poles.rows();
  // Radial frame of every pole; the profile must stay on one side of the axis.
  auto pole = [&](Eigen::Index i) {
    Eigen::Vector3d p = Eigen::Vector3d::Zero();
    p.head(profile.poles.cols()) = profile.poles.row(i).transpose();
    return p;
  };
  // Rotation is linear, so each pole turns with its own radial vector d_i: the tensor
  // product is exact for any profile, planar or not.
  bool offAxis = false;
  for (Eigen::Index i = 0; i < nu && !offAxis; ++i) {
    const Eigen::Vector3d d = pole(i) - axisPoint;
    offAxis = (d - d.dot(axis) * axis).norm() > 1e-12 * (1.0 + d.norm());
  }
  if (!offAxis) throw InputError("the profile lies on the axis of revolution");
  // Unit circle as four rational quadratic quarter arcs: 9 poles, corners weighted 1/sqrt(2).
  const double s = std::sqrt(0.5);
  const double cx[9] = {1, 1, 0, -1, -1, -1, 0, 1, 1};
  const double cy[9] = {0, 1, 1, 1, 0, -1, -1, -1, 0};
  const double cw[9] = {1, s, 1, s, 1, s, 1, s, 1};
  BSplineSurface surface;
  surface.degreeU = profile.degree;
  surface.degreeV = 2;
  surface.nu = static_cast<int>(nu);
  surface.nv = 9;
  surface.poles.resize(nu * 9, 3);
  surface.weights.resize(nu * 9);
  for (Eigen::Index i = 0; i < nu; ++i) {
    const Eigen::Vector3d d = pole(i) - axisPoint;
    const Eigen::Vector3d radial = d - d.dot(axis) * axis, turned = axis.cross(radial);
    const double w = profile.isRational() ? profile.weights[i] : 1.0;
    for (int j = 0; j < 9; ++j) {
      surface.poles.row(i * 9 + j) = (axisPoint + d.dot(axis) * axis + cx[j] * radial + cy[j] * turned).transpose();
      surface.weights[i * 9 + j] = w * cw[j];
    }
  }
  surface.knotsU = profile.knots;
  surface.multsU = profile.mults;
  surface.knotsV.resize(5);
  surface.knotsV << 0.0, 0.25, 0.5, 0.75, 1.0;
  surface.knotsV *= 2.0 * std::acos(-1.0);  // v is the angle at the quarter points
  surface.multsV.resize(5);
  surface.multsV << 3, 2, 2, 2, 3;
  return surface;
}

Handle(Geom_BSplineSurface) toOcct(const BSplineSurface& surface) {
  if (surface.poles.rows() != static_cast<Eigen::Index>(surface.nu) * surface.nv || surface.poles.cols() != 3) {
    throw InputError("a B-spline surface needs nu * nv poles of 3 coordinates");
  }
  requireFinite(surface.poles, "the B-spline surface", "poles");
  requireFinite(surface.weights, "the B-spline surface", "weights");
  requireFinite(surface.knotsU, "the B-spline surface", "u knots");
  requireFinite(surface.knotsV, "the B-spline surface", "v knots");
  TColgp_Array2OfPnt poles(1, surface.nu, 1, surface.nv);
  TColStd_Array2OfReal weights(1, surface.nu, 1, surface.nv);
  for (int i = 0; i < surface.nu; ++i) {
    for (int j = 0; j < surface.nv; ++j) {
      const auto row = surface.poles.row(i * surface.nv + j);
      poles.SetValue(i + 1, j + 1, gp_Pnt(row[0], row[1], row[2]));
      weights.SetValue(i + 1, j + 1, surface.weights.size() ? surface.weights[i * surface.nv + j] : 1.0);
    }
  }
  auto array = [](const Eigen::VectorXd& v) {
    TColStd_Array1OfReal a(1, static_cast<int>(v.size()));
    for (int i = 0; i < v.size(); ++i) a.SetValue(i + 1, v[i]);
    return a;
  };
  auto intArray = [](const Eigen::VectorXi& v) {
    TColStd_Array1OfInteger a(1, static_cast<int>(v.size()));
    for (int i = 0; i < v.size(); ++i) a.SetValue(i + 1, v[i]);
    return a;
  };
  try {
    if (surface.weights.size()) {
      return new Geom_BSplineSurface(poles, weights, array(surface.knotsU), array(surface.knotsV),
                                     intArray(surface.multsU), intArray(surface.multsV), surface.degreeU,
                                     surface.degreeV, surface.periodicU, surface.periodicV);
    }
    return new Geom_BSplineSurface(poles, array(surface.knotsU), array(surface.knotsV), intArray(surface.multsU),
                                   intArray(surface.multsV), surface.degreeU, surface.degreeV, surface.periodicU,
                                   surface.periodicV);
  } catch (const Standard_Failure& failure) {
    throw InputError(std::string("OpenCASCADE rejected the B-spline surface: ") + failure.GetMessageString());
  }
}

BSplineSurface fromOcct(const Handle(Geom_BSplineSurface)& s) {
  BSplineSurface out;
  out.degreeU = s->UDegree();
  out.degreeV = s->VDegree();
  out.nu = s->NbUPoles();
  out.nv = s->NbVPoles();
  out.periodicU = s->IsUPeriodic();
  out.periodicV = s->IsVPeriodic();
  out.poles.resize(static_cast<Eigen::Index>(out.nu) * out.nv, 3);
  out.weights.resize(static_cast<Eigen::Index>(out.nu) * out.nv);
  for (int i = 0; i < out.nu; ++i) {
    for (int j = 0; j < out.nv; ++j) {
      const gp_Pnt p = s->Pole(i + 1, j + 1);
      out.poles.row(i * out.nv + j) << p.X(), p.Y(), p.Z();
      out.weights[i * out.nv + j] = s->Weight(i + 1, j + 1);
    }
  }
  out.knotsU.resize(s->NbUKnots());
  out.multsU.resize(s->NbUKnots());
  for (int k = 0; k < s->NbUKnots(); ++k) {
    out.knotsU[k] = s->UKnot(k + 1);
    out.multsU[k] = s->UMultiplicity(k + 1);
  }
  out.knotsV.resize(s->NbVKnots());
  out.multsV.resize(s->NbVKnots());
  for (int k = 0; k < s->NbVKnots(); ++k) {
    out.knotsV[k] = s->VKnot(k + 1);
    out.multsV[k] = s->VMultiplicity(k + 1);
  }
  return out;
}

TopoDS_Face validFace(const Handle(Geom_BSplineSurface)& surface, const std::string& what) {
  TopoDS_Face face;
  try {
    // The tolerance of its edges: Precision::Confusion(), or about 100 rounding units of its
    // largest coordinate far from the origin (as blendShell's edges), where 1e-7 is below
    // what the coordinates can tell apart.
    double magnitude = 0.0;
    for (int i = 1; i <= surface->NbUPoles(); ++i) {
      for (int j = 1; j <= surface->NbVPoles(); ++j) {
        const gp_Pnt& p = surface->Pole(i, j);
        magnitude = std::max({magnitude, std::abs(p.X()), std::abs(p.Y()), std::abs(p.Z())});
      }
    }
    face = BRepBuilderAPI_MakeFace(surface, Precision::Confusion()).Face();
    const double tolerance = 1e-14 * magnitude;
    if (tolerance > Precision::Confusion()) {  // face <= edges <= vertices, as BRepCheck wants them
      BRep_Builder builder;
      builder.UpdateFace(face, tolerance);
      for (TopExp_Explorer e(face, TopAbs_EDGE); e.More(); e.Next())
        builder.UpdateEdge(TopoDS::Edge(e.Current()), tolerance);
      for (TopExp_Explorer v(face, TopAbs_VERTEX); v.More(); v.Next()) {
        builder.UpdateVertex(TopoDS::Vertex(v.Current()), tolerance);
      }
    }
  } catch (const Standard_Failure& failure) {
    throw InputError(what + ": OpenCASCADE made no face of it (" + failure.GetMessageString() + ")");
  }
  requireValidShape(face, what);  // the boundary rule (finite.hpp)
  return face;
}

}  // namespace fairsplines
