#pragma once
// The parametric 3DDDA (Algorithm-2): walks the voxels a ray passes through, in
// order, with two additions and a comparison per step and no division.

#include "capsim/trace/voxel_grid.h"

#include <algorithm>

namespace capsim {

class Dda3 {
 public:
  // Set-up: clips the ray to the universe and finds the first voxel, the
  // increments and the t of the next x, y, z plane crossings. A zero direction
  // component never crosses its planes (t = +inf). Returns false if the ray's
  // [tmin, tmax] misses the universe. A ray that moves along no axis (every
  // component zero, subnormal or NaN) is not clipped: it stays in the voxel
  // of its origin, if the universe holds that, whatever its [tmin, tmax].
  bool setup(const VoxelGrid& grid, const Ray& ray);

  // The current voxel and the t range [t_in(), t_out()] the ray spends in it.
  int voxel() const { return (vz_ * n_ + vy_) * n_ + vx_; }
  double t_in() const { return t_in_; }
  double t_out() const { return std::min(std::min(tx_, ty_), std::min(tz_, t_end_)); }

  // Moves to the next voxel along the ray; false when the ray leaves the grid or
  // passes its tmax. Inline: it is the inner loop of every ray.
  bool step() {
    // argmin(tx, ty, tz); only one index changes per step: two additions and the
    // comparisons, no division.
    if (tx_ <= ty_ && tx_ <= tz_) return advance(tx_, dtx_, vx_, incre_x_);
    if (ty_ <= tz_) return advance(ty_, dty_, vy_, incre_y_);
    return advance(tz_, dtz_, vz_, incre_z_);
  }

  int vx() const { return vx_; }
  int vy() const { return vy_; }
  int vz() const { return vz_; }

 private:
  bool advance(double& t_next, double dt, int& v, int incre) {
    if (t_next >= t_end_) return false;
    v += incre;
    if (v < 0 || v >= n_) return false;
    t_in_ = t_next;
    t_next += dt;
    return true;
  }

  // The first voxel index along one axis, its increment, and the t of the next
  // plane crossing and between crossings.
  void start_axis(double entry, double origin, double dir, double inv, double lo, double size,
                  double inv_size, int& v, int& incre, double& t_next, double& dt) const;

  int n_ = 1;
  int vx_ = 0, vy_ = 0, vz_ = 0;
  int incre_x_ = 1, incre_y_ = 1, incre_z_ = 1;
  double tx_ = kInfinity, ty_ = kInfinity, tz_ = kInfinity;
  double dtx_ = kInfinity, dty_ = kInfinity, dtz_ = kInfinity;
  double t_in_ = 0;
  double t_end_ = 0;  // where the ray leaves the universe or reaches tmax
};

}  // namespace capsim
