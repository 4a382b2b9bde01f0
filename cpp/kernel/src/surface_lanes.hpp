// The frame of a face at one point and its principal curvatures (do Carmo, Differential
// Geometry of Curves and Surfaces, §3-3: the shape operator's matrix is I^-1 II), in plain
// doubles and without branches: every choice is a select between two computed values.
// One source for the scalar path (FaceSurface::frame, principalCurvatures) and the
// vectorised one (surface_curvature_batch.cpp), whose loop over points the compiler turns
// into vector code; the operations are the same, in the same order, so both give the same
// bits (no reassociation, no contraction: vectorise.hpp).
#pragma once
#include <algorithm>
#include <cmath>

namespace fairsplines::detail::lanes {

struct Vec3 {
  double x, y, z;
};

inline Vec3 operator+(const Vec3& a, const Vec3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 operator-(const Vec3& a, const Vec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3 operator*(const Vec3& a, double s) { return {a.x * s, a.y * s, a.z * s}; }
inline double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
/// a where `first`, else b, coordinate by coordinate (a select, not a branch).
inline Vec3 choose(bool first, const Vec3& a, const Vec3& b) {
  return {first ? a.x : b.x, first ? a.y : b.y, first ? a.z : b.z};
}

/// The first and second fundamental forms, the second measured against the face normal
/// n = sign (Su x Sv) / |Su x Sv| with the designer's sign: L = -Suu.n, so that convex as seen
/// from n is positive (OCCT's GeomLProp_SLProps measures against Su x Sv with the opposite
/// sign: a convex sphere reads -1/R there, whatever the face's orientation).
struct Forms {
  Vec3 n;
  double E, F, G;  ///< I = [E F; F G]
  double L, M, N;  ///< II = [L M; M N]
  /// |Su x Sv| and the larger of |Su|^2, |Sv|^2: the point is regular (not a pole, an apex or a
  /// collapsed row) where the first exceeds 1e-9 of the second; elsewhere the other fields are
  /// not to be used. (Kept as numbers, not a bool: a vectorised loop compares them in its own
  /// lanes' width.)
  double length, size;
  bool regular() const { return length > 1e-9 * size; }
};

inline Forms forms(const Vec3& su, const Vec3& sv, const Vec3& suu, const Vec3& svv, const Vec3& suv, double sign) {
  Forms f;
  f.E = dot(su, su);
  f.F = dot(su, sv);
  f.G = dot(sv, sv);
  const Vec3 normal = cross(su, sv);
  f.length = std::sqrt(dot(normal, normal));
  f.size = std::max(f.E, f.G);
  f.n = normal * (sign / f.length);
  f.L = -dot(suu, f.n);
  f.M = -dot(suv, f.n);
  f.N = -dot(svv, f.n);
  return f;
}

/// Principal curvatures k1 >= k2 and unit directions, dir1 x dir2 = n.
struct Curvatures {
  double k1, k2;
  Vec3 dir1, dir2;
  /// 1 where k1 = k2 to 1e-8 of their size (a sphere, a plane): every direction is principal,
  /// and dir1 is the unit Su (Sv where Su vanishes); else 0. (A number, as Forms' length.)
  double umbilic;
};

/// The principal curvatures of regular forms (Forms::regular). The directions are not finite
/// where rounding leaves no direction in the tangent plane; callers check.
inline Curvatures principal(const Forms& f, const Vec3& su, const Vec3& sv) {
  Curvatures k;
  const double det = f.E * f.G - f.F * f.F;  // det I > 0 at a regular point
  const double inverse = 1.0 / det;          // one division, four products
  // The shape operator's matrix W = I^-1 II = [a b; c d].
  const double a = (f.G * f.L - f.F * f.M) * inverse, b = (f.G * f.M - f.F * f.N) * inverse;
  const double c = (f.E * f.M - f.F * f.L) * inverse, d = (f.E * f.N - f.F * f.M) * inverse;
  const double H = 0.5 * (a + d);                      // mean curvature, (EN - 2FM + GL) / 2 det
  const double K = (f.L * f.N - f.M * f.M) * inverse;  // Gaussian curvature, det II / det I
  const double half = 0.5 * (a - d);
  const double r = std::sqrt(std::max(half * half + b * c, 0.0));  // k1,2 = H +- sqrt(H^2 - K)
  // The root without cancellation, H + r for H >= 0 (k1) and H - r below (k2); the other
  // from k1 k2 = K, or H -+ r where that root is 0 (then K is too).
  const bool upper = H >= 0.0;
  const double root = upper ? H + r : H - r;
  const double other = root != 0.0 ? K / root : upper ? H - r : H + r;
  k.k1 = upper ? root : other;
  k.k2 = upper ? other : root;
  const bool swap = k.k2 > k.k1;  // rounding of K / k1 at an umbilic
  const double k1 = swap ? k.k2 : k.k1, k2 = swap ? k.k1 : k.k2;
  k.k1 = k1;
  k.k2 = k2;
  // The eigenvector of W for k1: (W - k1) x = 0, from the better-conditioned row.
  const double x0a = b, x1a = k1 - a, x0b = k1 - d, x1b = c;
  const bool rowA = x0a * x0a + x1a * x1a >= x0b * x0b + x1b * x1b;
  const double x0 = rowA ? x0a : x0b, x1 = rowA ? x1a : x1b;
  Vec3 dir = su * x0 + sv * x1;
  const double scale = std::max(std::abs(k1), std::abs(k2));
  const double gap = 1e-12 * (k1 - k2);
  // Umbilic (k1 = k2 to 1e-8 of their size, a plane included): every direction is
  // principal. So is the direction of a near-umbilic that rounding hides:
  // |dir| <= 1e-12 (k1 - k2) sqrt(E + G), compared squared (no square roots).
  const double distinct = k1 - k2 > 1e-8 * scale ? 0.0 : 1.0;
  k.umbilic = dot(dir, dir) > gap * gap * (f.E + f.G) ? distinct : 1.0;
  dir = choose(k.umbilic == 0.0, dir, choose(f.E > 0.0, su, sv));
  // Orthogonal to n exactly (dir lies in the tangent plane up to rounding).
  dir = dir - f.n * dot(dir, f.n);
  k.dir1 = dir * (1.0 / std::sqrt(dot(dir, dir)));
  k.dir2 = cross(f.n, k.dir1);
  return k;
}

}  // namespace fairsplines::detail::lanes
