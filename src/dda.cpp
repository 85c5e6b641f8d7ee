// Algorithm-2 of the paper: the parametric 3DDDA.

#include "capsim/dda.h"

#include <algorithm>
#include <cmath>

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

}  // namespace

bool Dda3::setup(const VoxelGrid& grid, const Ray& ray) {
  const Aabb& u = grid.universe;
  // The only divisions of the walk: one per axis, here in the set-up.
  const glm::dvec3 inv(ray.dir.x != 0 ? 1.0 / ray.dir.x : 0.0, ray.dir.y != 0 ? 1.0 / ray.dir.y : 0.0,
                       ray.dir.z != 0 ? 1.0 / ray.dir.z : 0.0);
  double t0 = ray.tmin, t1 = ray.tmax;
  for (int a = 0; a < 3; ++a)
    if (!clip_slab(ray.origin[a], ray.dir[a], inv[a], u.lo[a], u.hi[a], t0, t1)) return false;

  n_ = grid.n;
  t_in_ = t0;
  t_end_ = t1;
  const glm::dvec3 entry = ray.at(t0);
  int* v[3] = {&vx_, &vy_, &vz_};
  int* incre[3] = {&incre_x_, &incre_y_, &incre_z_};
  double* t_next[3] = {&tx_, &ty_, &tz_};
  double* dt[3] = {&dtx_, &dty_, &dtz_};
  for (int a = 0; a < 3; ++a) {
    const double size = grid.voxel_size[a];
    *v[a] = std::clamp(static_cast<int>(std::floor((entry[a] - u.lo[a]) * grid.inv_voxel_size[a])), 0,
                       n_ - 1);
    const double d = ray.dir[a];
    if (d == 0) {
      // Never crosses a plane of this axis.
      *incre[a] = 0;
      *t_next[a] = kInfinity;
      *dt[a] = kInfinity;
    } else {
      *incre[a] = d > 0 ? 1 : -1;
      const double plane = u.lo[a] + (*v[a] + (d > 0 ? 1 : 0)) * size;
      *t_next[a] = (plane - ray.origin[a]) * inv[a];
      *dt[a] = size * std::abs(inv[a]);
    }
  }
  return true;
}

double Dda3::t_out() const { return std::min({tx_, ty_, tz_, t_end_}); }

bool Dda3::step() {
  // argmin(tx, ty, tz); only one index changes per step: two additions and the
  // comparisons, no division.
  if (tx_ <= ty_ && tx_ <= tz_) {
    if (tx_ >= t_end_) return false;
    vx_ += incre_x_;
    if (vx_ < 0 || vx_ >= n_) return false;
    t_in_ = tx_;
    tx_ += dtx_;
  } else if (ty_ <= tz_) {
    if (ty_ >= t_end_) return false;
    vy_ += incre_y_;
    if (vy_ < 0 || vy_ >= n_) return false;
    t_in_ = ty_;
    ty_ += dty_;
  } else {
    if (tz_ >= t_end_) return false;
    vz_ += incre_z_;
    if (vz_ < 0 || vz_ >= n_) return false;
    t_in_ = tz_;
    tz_ += dtz_;
  }
  return true;
}

}  // namespace capsim
