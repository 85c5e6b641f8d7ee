// Algorithm-2 of the paper: the parametric 3DDDA.

#include "capsim/dda.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace capsim {

namespace {

// Clips [t0, t1] to the slab lo <= o + t d <= hi (inv = 1 / d); false if it
// becomes empty.
bool clip_slab(double o, double d, double inv, double lo, double hi, double& t0, double& t1) {
  if (d == 0) return o >= lo && o <= hi;
  double a = (lo - o) * inv, b = (hi - o) * inv;
  if (a > b) std::swap(a, b);
  t0 = std::max(t0, a);
  t1 = std::min(t1, b);
  return t0 <= t1;
}

// A direction component below the least normal double moves the ray by less
// than 1e-278 over any distance the scene's range allows (docs/scene-format.md),
// and its reciprocal would overflow: the walk takes it as zero.
double walked(double d) { return std::abs(d) >= std::numeric_limits<double>::min() ? d : 0.0; }

}  // namespace

bool Dda3::setup(const VoxelGrid& grid, const Ray& ray) {
  const Aabb& u = grid.universe;
  const glm::dvec3 dir(walked(ray.dir.x), walked(ray.dir.y), walked(ray.dir.z));
  // The only divisions of the walk: one per axis, here in the set-up.
  const glm::dvec3 inv(dir.x != 0 ? 1.0 / dir.x : 0.0, dir.y != 0 ? 1.0 / dir.y : 0.0,
                       dir.z != 0 ? 1.0 / dir.z : 0.0);
  double t0 = ray.tmin, t1 = ray.tmax;
  if (!clip_slab(ray.origin.x, dir.x, inv.x, u.lo.x, u.hi.x, t0, t1) ||
      !clip_slab(ray.origin.y, dir.y, inv.y, u.lo.y, u.hi.y, t0, t1) ||
      !clip_slab(ray.origin.z, dir.z, inv.z, u.lo.z, u.hi.z, t0, t1))
    return false;

  n_ = grid.n;
  t_in_ = t0;
  t_end_ = t1;
  const glm::dvec3 entry = ray.origin + t0 * dir;
  start_axis(entry.x, ray.origin.x, dir.x, inv.x, u.lo.x, grid.voxel_size.x, grid.inv_voxel_size.x, vx_,
             incre_x_, tx_, dtx_);
  start_axis(entry.y, ray.origin.y, dir.y, inv.y, u.lo.y, grid.voxel_size.y, grid.inv_voxel_size.y, vy_,
             incre_y_, ty_, dty_);
  start_axis(entry.z, ray.origin.z, dir.z, inv.z, u.lo.z, grid.voxel_size.z, grid.inv_voxel_size.z, vz_,
             incre_z_, tz_, dtz_);
  return true;
}

void Dda3::start_axis(double entry, double origin, double dir, double inv, double lo, double size,
                      double inv_size, int& v, int& incre, double& t_next, double& dt) const {
  // entry lies in the universe (up to rounding), so the offset is >= 0 or a
  // hair below, and truncation is the floor there (it is a plain conversion,
  // where std::floor is a library call on baseline x86-64).
  v = clamped_voxel_index((entry - lo) * inv_size, n_);
  if (dir == 0) {
    // Never crosses a plane of this axis.
    incre = 0;
    t_next = kInfinity;
    dt = kInfinity;
    return;
  }
  incre = dir > 0 ? 1 : -1;
  const double plane = lo + (v + (dir > 0 ? 1 : 0)) * size;
  t_next = (plane - origin) * inv;
  dt = size * std::abs(inv);
}

}  // namespace capsim
