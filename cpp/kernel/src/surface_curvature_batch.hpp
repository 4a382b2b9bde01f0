// Principal curvatures of many points of one face, a batch at a time (issue 27, the speed of
// surfaceCurvature): the surface's points and derivatives in one array per coordinate, then
// one loop over the batch that the compiler vectorises (four points per AVX instruction), on
// the same arithmetic as the scalar path (surface_lanes.hpp): the same bits.
#pragma once
#include <cstddef>

namespace fairsplines::detail {

/// A batch of points: their surface points and first and second derivatives in (u, v), one
/// array per coordinate, and a verdict per point.
struct CurvatureBatch {
  static constexpr int kSize = 128;  ///< 128 points: the batch's 19 arrays take 19 KB, within L1
  alignas(64) double p[3][kSize];
  alignas(64) double su[3][kSize], sv[3][kSize], suu[3][kSize], svv[3][kSize], suv[3][kSize];
  /// Per point: 0 regular, 1 umbilic (PointState); kScalar where the batch's arithmetic has
  /// no answer (a degenerate point, values not finite): the scalar path decides there.
  alignas(64) double verdict[kSize];
  static constexpr double kScalar = 2.0;
};

/// Where curvaturesOfBatch writes: the caller's columns (surfaceCurvature's block), each at
/// the batch's first point. They must not overlap the batch or each other.
struct CurvatureColumns {
  double *k1, *k2, *gaussian, *mean;
  double *dir1[3], *dir2[3], *normal[3], *point[3];
};

/// The forms, principal curvatures, directions and normals of the batch's first m points from
/// their derivatives, and their points, into `out`; sign: +1 for a forward face, -1 for a
/// reversed one. Sets the batch's verdicts.
void curvaturesOfBatch(CurvatureBatch& batch, int m, double sign, const CurvatureColumns& out);

/// Whether every row (u, v) of the n x 2 row-major uv (`stride` doubles a row) lies in
/// [u0, u1] x [v0, v1]; false at a NaN. One vectorised pass; the caller names a point that
/// fails with a second, scalar one.
bool allInside(const double* uv, std::ptrdiff_t n, std::ptrdiff_t stride, double u0, double u1, double v0, double v1);

}  // namespace fairsplines::detail
