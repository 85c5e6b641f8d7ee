// Algorithm-2 of the paper: the parametric 3DDDA.

#include "capsim/trace/dda.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace capsim {

namespace {

// A direction component below the least normal double moves the ray by less
// than 1e-278 over any distance the scene's range allows (docs/scene-format.md),
// and its reciprocal would overflow: the walk takes it as zero.
double walked(double d) { return std::abs(d) >= std::numeric_limits<double>::min() ? d : 0.0; }

// One axis of the set-up. Written with selects rather than branches: secondary
// rays point every way, and a branch on a direction's sign is then a coin toss
// for the predictor. Every value is the one the branching form gives, bit for
// bit: the selects choose between the same operations' results.
struct Axis {
  double origin, dir, inv;

  Axis(double o, double d) : origin(o), dir(walked(d)), inv(1.0 / (dir != 0 ? dir : 1.0)) {}

  // Clips [t0, t1] to the slab lo <= origin + t dir <= hi; a zero component
  // leaves it as it is, and says whether the origin lies in the slab.
  bool clip(double lo, double hi, double& t0, double& t1) const {
    const double a = (lo - origin) * inv, b = (hi - origin) * inv;
    const double near = dir == 0 ? -kInfinity : (a > b ? b : a);
    const double far = dir == 0 ? kInfinity : (a > b ? a : b);
    t0 = std::max(t0, near);
    t1 = std::min(t1, far);
    return dir != 0 || (origin >= lo && origin <= hi);
  }
};

}  // namespace

bool Dda3::setup(const VoxelGrid& grid, const Ray& ray) {
  const Aabb& u = grid.universe;
  // The only divisions of the walk: one per axis, here in the set-up.
  const Axis x(ray.origin.x, ray.dir.x), y(ray.origin.y, ray.dir.y), z(ray.origin.z, ray.dir.z);
  double t0 = ray.tmin, t1 = ray.tmax;
  // Each clip only raises t0 and lowers t1, so one test at the end finds an
  // empty interval as the test after each clip would.
  const bool in_x = x.clip(u.lo.x, u.hi.x, t0, t1);
  const bool in_y = y.clip(u.lo.y, u.hi.y, t0, t1);
  const bool in_z = z.clip(u.lo.z, u.hi.z, t0, t1);
  // A ray that moves along no axis clips nothing: it stays in its first voxel
  // over [tmin, tmax] as given.
  const bool moves = x.dir != 0 || y.dir != 0 || z.dir != 0;
  if (!(in_x && in_y && in_z) || (moves && !(t0 <= t1))) return false;

  n_ = grid.n;
  t_in_ = t0;
  t_end_ = t1;
  // A ray that starts inside the universe (a shadow ray, a reflection) keeps
  // t0 = tmin, bit for bit (a clip only ever raises t0 strictly). Its entry
  // point is then worked out from tmin, which does not wait for the clip's
  // divisions; the test is a branch the predictor learns, so the first
  // voxel's index need not wait either.
  const glm::dvec3 dir(x.dir, y.dir, z.dir);
  glm::dvec3 entry = ray.origin + ray.tmin * dir;
  if (t0 != ray.tmin) entry = ray.origin + t0 * dir;
  start_axis(entry.x, x.origin, x.dir, x.inv, u.lo.x, grid.voxel_size.x, grid.inv_voxel_size.x, vx_,
             incre_x_, tx_, dtx_);
  start_axis(entry.y, y.origin, y.dir, y.inv, u.lo.y, grid.voxel_size.y, grid.inv_voxel_size.y, vy_,
             incre_y_, ty_, dty_);
  start_axis(entry.z, z.origin, z.dir, z.inv, u.lo.z, grid.voxel_size.z, grid.inv_voxel_size.z, vz_,
             incre_z_, tz_, dtz_);
  return true;
}

void Dda3::start_axis(double entry, double origin, double dir, double inv, double lo, double size,
                      double inv_size, int& v, int& incre, double& t_next, double& dt) const {
  // entry lies in the universe (up to rounding), so the offset is >= 0 or a
  // hair below, and truncation is the floor there (it is a plain conversion,
  // where std::floor is a library call on baseline x86-64).
  v = clamped_voxel_index((entry - lo) * inv_size, n_);
  // A zero component never crosses a plane of its axis: no increment, and the
  // next crossing at +inf.
  const bool forward = dir > 0;
  incre = dir == 0 ? 0 : (forward ? 1 : -1);
  const double plane = lo + (v + (forward ? 1 : 0)) * size;
  t_next = dir == 0 ? kInfinity : (plane - origin) * inv;
  dt = dir == 0 ? kInfinity : size * std::abs(inv);
}

}  // namespace capsim
