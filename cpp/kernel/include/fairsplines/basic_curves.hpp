// Basic curves of "design with basic curves" (Karčiauskas & Peters, "Curvature-sensitive
// splines and design with basic curves", Sections 3.2, 5 and 6): each is parameterised
// over u in [0, 1], with point, first and second derivative and the parameter of a point.
#pragma once
#include <Eigen/Core>
#include <functional>
#include <memory>
#include <optional>

namespace fairsplines {

/// A rational Bézier curve of degree <= 3 in homogeneous form: row j is (w_j x_j, w_j y_j,
/// w_j z_j, w_j), degree + 1 rows.
using HomogeneousBezier = Eigen::Matrix<double, Eigen::Dynamic, 4, Eigen::RowMajor>;

/// A planar frame in space: origin and two orthonormal directions.
struct Frame {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d x = Eigen::Vector3d::UnitX();
  Eigen::Vector3d y = Eigen::Vector3d::UnitY();
  Eigen::Vector3d at(double a, double b) const { return origin + a * x + b * y; }
  Eigen::Vector3d dir(double a, double b) const { return a * x + b * y; }
  /// Throws InputError unless x and y are unit and orthogonal (relative 1e-9).
  void check() const;
};

class BasicCurve {
public:
  virtual ~BasicCurve() = default;
  /// value, d1, d2 (and homogeneousCubic, size) throw nothing: the constructors and factories
  /// below refuse every curve they could not evaluate.
  virtual Eigen::Vector3d value(double u) const = 0;
  virtual Eigen::Vector3d d1(double u) const = 0;
  virtual Eigen::Vector3d d2(double u) const = 0;
  /// Parameter of a point on the curve: eq. (5), a safeguarded 1-D Newton iteration on
  /// d/du |f(u) - q|^2 = 0 from the best of a coarse sampling. Throws InputError when the
  /// point is farther than `tolerance` (relative to the curve's size) from the curve.
  virtual double parameterOf(const Eigen::Vector3d& q, double tolerance = 1e-9) const;
  /// The homogeneous cubic Bézier form when the curve is rational of degree <= 3
  /// (Section 6 applies), empty otherwise (Section 5 applies).
  virtual std::optional<HomogeneousBezier> homogeneousCubic() const { return std::nullopt; }
  /// Diagonal of the bounding box of 65 samples: the size tolerances refer to.
  double size() const;
};

/// Rational curve of degree <= 3 given by its homogeneous Bézier points; evaluation by
/// de Casteljau in homogeneous space and the quotient rule.
class RationalBezierCurve : public BasicCurve {
public:
  /// Throws InputError for a degree above 3, non-finite data, a weight function that
  /// vanishes on [0, 1], or points and derivatives that overflow or do not move in double
  /// precision; the messages call the curve `what` ("line segment", "circle arc", ...).
  explicit RationalBezierCurve(HomogeneousBezier homogeneous, const char* what = "rational curve");
  Eigen::Vector3d value(double u) const override;
  Eigen::Vector3d d1(double u) const override;
  Eigen::Vector3d d2(double u) const override;
  std::optional<HomogeneousBezier> homogeneousCubic() const override;
  const HomogeneousBezier& homogeneous() const { return h_; }
  /// Homogeneous point and its first two derivatives.
  void jets(double u, Eigen::Vector4d& f, Eigen::Vector4d& df, Eigen::Vector4d& d2f) const;

private:
  HomogeneousBezier h_;
};

/// Line segment from p0 to p1 (degree 1, weights 1). Throws InputError if p0 == p1.
std::unique_ptr<RationalBezierCurve> lineSegment(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1);

/// Circle arc in the classic symmetric rational quadratic form (Section 3.2): f(0) at
/// angle `start`, f(1) at `start + sweep`, middle weight cos(sweep / 2). Parameter of a
/// point by eq. (4). A sweep of pi or more has a negative middle weight: the B-spline
/// built from marks then needs enough marks to keep every weight positive (see design.hpp).
class CircleArc : public RationalBezierCurve {
public:
  /// Throws InputError for radius <= 0 or |sweep| not in (0, 2 pi).
  CircleArc(const Frame& frame, double radius, double start, double sweep);
  double parameterOf(const Eigen::Vector3d& q, double tolerance = 1e-9) const override;
  double radius() const { return radius_; }
  double sweep() const { return sweep_; }

private:
  Frame frame_;
  double radius_, start_, sweep_;
};

/// Ellipse arc x = a cos t, y = b sin t, t from `start` over `sweep`; rational quadratic,
/// middle weight cos(sweep / 2). Throws InputError for a, b <= 0 or |sweep| not in (0, 2 pi).
std::unique_ptr<RationalBezierCurve> ellipseArc(const Frame& frame, double a, double b, double start, double sweep);

/// Parabola arc x = t^2 / (4 focal), y = t (OCCT's convention), t in [t0, t1]; polynomial
/// quadratic. Throws InputError for focal <= 0 or t0 >= t1.
std::unique_ptr<RationalBezierCurve> parabolaArc(const Frame& frame, double focal, double t0, double t1);

/// Hyperbola arc x = a cosh t, y = b sinh t, t in [t0, t1]; rational quadratic, middle
/// weight cosh((t1 - t0) / 2). Throws InputError for a, b <= 0 or t0 >= t1.
std::unique_ptr<RationalBezierCurve> hyperbolaArc(const Frame& frame, double a, double b, double t0, double t1);

/// A curve given by a function of its own parameter s in [s0, s1] returning point, first
/// and second derivative (in s); u in [0, 1] maps linearly to s.
class ParametricCurve : public BasicCurve {
public:
  using Jet = std::function<void(double s, Eigen::Vector3d& f, Eigen::Vector3d& df, Eigen::Vector3d& d2f)>;
  /// Throws InputError unless s0 < s1, both finite, and s1 - s0 is finite.
  ParametricCurve(Jet jet, double s0, double s1);
  Eigen::Vector3d value(double u) const override;
  Eigen::Vector3d d1(double u) const override;
  Eigen::Vector3d d2(double u) const override;

protected:
  Jet jet_;
  double s0_, s1_;
};

/// Archimedean spiral r = a + b theta, theta in [theta0, theta1]. Throws InputError for
/// theta0 >= theta1 or a spiral through its centre inside the range (r = 0).
std::unique_ptr<ParametricCurve> archimedeanSpiral(const Frame& frame, double a, double b, double theta0,
                                                   double theta1);

/// Involute of the circle of radius r: r (cos t + t sin t, sin t - t cos t), t in [t0, t1].
/// Throws InputError for r <= 0, t0 >= t1 or t0 < 0 (t = 0 is the cusp on the circle).
std::unique_ptr<ParametricCurve> circleInvolute(const Frame& frame, double r, double t0, double t1);

}  // namespace fairsplines
