// The batch's curvatures (surface_curvature_batch.hpp): do Carmo §3-3 on each point, from the
// shared arithmetic of surface_lanes.hpp, in a loop without branches over the batch's arrays
// that the compiler vectorises.
#include "surface_curvature_batch.hpp"

#include <cmath>
#include <limits>

#include "surface_lanes.hpp"
#include "vectorise.hpp"

namespace fairsplines::detail {

namespace {

/// Finite, as a comparison that vectorises (NaN compares false).
inline bool finite(double x) { return std::abs(x) <= std::numeric_limits<double>::max(); }

/// The loop, its outputs each a pointer of its own that aliases nothing (__restrict), so that
/// the compiler vectorises it without checks of overlap between them.
FAIRSPLINES_VECTORISE void curvatures(CurvatureBatch& b, int m, double sign, double* __restrict k1,
                                      double* __restrict k2, double* __restrict gaussian, double* __restrict mean,
                                      double* __restrict d1x, double* __restrict d1y, double* __restrict d1z,
                                      double* __restrict d2x, double* __restrict d2y, double* __restrict d2z,
                                      double* __restrict nx, double* __restrict ny, double* __restrict nz,
                                      double* __restrict px, double* __restrict py, double* __restrict pz) {
  using lanes::Vec3;
  for (int i = 0; i < m; ++i) {
    const Vec3 su{b.su[0][i], b.su[1][i], b.su[2][i]}, sv{b.sv[0][i], b.sv[1][i], b.sv[2][i]};
    const Vec3 suu{b.suu[0][i], b.suu[1][i], b.suu[2][i]}, svv{b.svv[0][i], b.svv[1][i], b.svv[2][i]};
    const Vec3 suv{b.suv[0][i], b.suv[1][i], b.suv[2][i]};
    const lanes::Forms f = lanes::forms(su, sv, suu, svv, suv, sign);
    const lanes::Curvatures k = lanes::principal(f, su, sv);
    const double K = k.k1 * k.k2;
    k1[i] = k.k1;
    k2[i] = k.k2;
    gaussian[i] = K;
    mean[i] = 0.5 * (k.k1 + k.k2);
    d1x[i] = k.dir1.x;
    d1y[i] = k.dir1.y;
    d1z[i] = k.dir1.z;
    d2x[i] = k.dir2.x;
    d2y[i] = k.dir2.y;
    d2z[i] = k.dir2.z;
    nx[i] = f.n.x;
    ny[i] = f.n.y;
    nz[i] = f.n.z;
    px[i] = b.p[0][i];
    py[i] = b.p[1][i];
    pz[i] = b.p[2][i];
    // The scalar path where the point is not regular or a value is not finite (unit vectors:
    // their sum is finite exactly when each coordinate is); selects, one condition each.
    constexpr double scalar = CurvatureBatch::kScalar;
    double verdict = f.regular() ? k.umbilic : scalar;
    verdict = finite(k.k1) ? verdict : scalar;
    verdict = finite(k.k2) ? verdict : scalar;
    verdict = finite(K) ? verdict : scalar;
    b.verdict[i] = finite(k.dir1.x + k.dir1.y + k.dir1.z + f.n.x + f.n.y + f.n.z) ? verdict : scalar;
  }
}

/// allInside's loop: a product of comparisons, no early exit, so that it vectorises.
FAIRSPLINES_VECTORISE bool inside(const double* __restrict uv, std::ptrdiff_t n, std::ptrdiff_t stride, double u0,
                                  double u1, double v0, double v1) {
  int all = 1;
  for (std::ptrdiff_t i = 0; i < n; ++i) {
    const double u = uv[i * stride], v = uv[i * stride + 1];
    // Finite too (the bounds may be infinite on a face near the largest double).
    all &= (u >= u0) & (u <= u1) & (v >= v0) & (v <= v1) & finite(u) & finite(v);
  }
  return all != 0;
}

}  // namespace

bool allInside(const double* uv, std::ptrdiff_t n, std::ptrdiff_t stride, double u0, double u1, double v0, double v1) {
  return stride == 2 ? inside(uv, n, 2, u0, u1, v0, v1) : inside(uv, n, stride, u0, u1, v0, v1);
}

void curvaturesOfBatch(CurvatureBatch& batch, int m, double sign, const CurvatureColumns& out) {
  curvatures(batch, m, sign, out.k1, out.k2, out.gaussian, out.mean, out.dir1[0], out.dir1[1], out.dir1[2], out.dir2[0],
             out.dir2[1], out.dir2[2], out.normal[0], out.normal[1], out.normal[2], out.point[0], out.point[1],
             out.point[2]);
}

}  // namespace fairsplines::detail
