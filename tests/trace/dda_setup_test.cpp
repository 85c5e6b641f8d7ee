// Dda3::setup computes with selects where the plain form of Algorithm-2's
// set-up branches. This test keeps the plain form, clip by clip with an early
// return, and walks both over rays chosen to reach every case (zero, subnormal
// and NaN direction components, origins outside the universe and on its faces,
// empty and reversed [tmin, tmax]): the voxels and t values must agree to the bit.

#include "capsim/trace/dda.h"
#include "support/scene_builders.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <random>
#include <vector>

namespace capsim {
namespace {

using testing::unit_voxel_grid;

// One visited voxel: its indices and its [t_in, t_out], t's as bit patterns
// (NaN compares unequal to itself).
struct Visit {
  int x, y, z;
  std::uint64_t t_in, t_out;
  bool operator==(const Visit&) const = default;
};

std::uint64_t bits(double t) { return std::bit_cast<std::uint64_t>(t); }

// The plain set-up and walk, as Algorithm-2 states them.
class PlainDda {
 public:
  bool setup(const VoxelGrid& g, const Ray& ray) {
    glm::dvec3 dir;
    for (int a = 0; a < 3; ++a) dir[a] = std::abs(ray.dir[a]) >= std::numeric_limits<double>::min() ? ray.dir[a] : 0.0;
    double t0 = ray.tmin, t1 = ray.tmax;
    for (int a = 0; a < 3; ++a) {
      if (dir[a] == 0) {
        if (!(ray.origin[a] >= g.universe.lo[a] && ray.origin[a] <= g.universe.hi[a])) return false;
        continue;
      }
      const double inv = 1.0 / dir[a];
      double near = (g.universe.lo[a] - ray.origin[a]) * inv, far = (g.universe.hi[a] - ray.origin[a]) * inv;
      if (near > far) std::swap(near, far);
      t0 = std::max(t0, near);
      t1 = std::min(t1, far);
      if (!(t0 <= t1)) return false;
    }
    n_ = g.n;
    t_in_ = t0;
    t_end_ = t1;
    for (int a = 0; a < 3; ++a) {
      const double entry = ray.origin[a] + t0 * dir[a];
      v_[a] = clamped_voxel_index((entry - g.universe.lo[a]) * g.inv_voxel_size[a], n_);
      if (dir[a] == 0) {
        incre_[a] = 0;
        next_[a] = kInfinity;
        dt_[a] = kInfinity;
        continue;
      }
      const double inv = 1.0 / dir[a];
      incre_[a] = dir[a] > 0 ? 1 : -1;
      const double plane = g.universe.lo[a] + (v_[a] + (dir[a] > 0 ? 1 : 0)) * g.voxel_size[a];
      next_[a] = (plane - ray.origin[a]) * inv;
      dt_[a] = g.voxel_size[a] * std::abs(inv);
    }
    return true;
  }

  Visit visit() const {
    const double out = std::min(std::min(next_[0], next_[1]), std::min(next_[2], t_end_));
    return {v_[0], v_[1], v_[2], bits(t_in_), bits(out)};
  }

  bool step() {
    const int a = next_[0] <= next_[1] && next_[0] <= next_[2] ? 0 : (next_[1] <= next_[2] ? 1 : 2);
    if (next_[a] >= t_end_) return false;
    v_[a] += incre_[a];
    if (v_[a] < 0 || v_[a] >= n_) return false;
    t_in_ = next_[a];
    next_[a] += dt_[a];
    return true;
  }

 private:
  int n_ = 1;
  int v_[3] = {}, incre_[3] = {};
  double next_[3] = {}, dt_[3] = {};
  double t_in_ = 0, t_end_ = 0;
};

// The voxels a walk visits (at most 64), or nothing if its set-up fails.
template <class Walk, class VisitOf>
std::optional<std::vector<Visit>> walk(Walk& w, const VoxelGrid& g, const Ray& r, VisitOf visit_of) {
  if (!w.setup(g, r)) return std::nullopt;
  std::vector<Visit> v{visit_of(w)};
  while (v.size() < 64 && w.step()) v.push_back(visit_of(w));
  return v;
}

TEST(Dda3Setup, AgreesToTheBitWithThePlainSetUp) {
  VoxelGrid g;
  g.universe = {glm::dvec3(-2, -1, 0.5), glm::dvec3(2, 3, 1.5)};
  g.n = 5;
  g.voxel_size = (g.universe.hi - g.universe.lo) / 5.0;
  g.inv_voxel_size = 1.0 / g.voxel_size;

  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double special[] = {0.0, -0.0, 1e-310, -1e-310, nan, 1.0, -1.0, 1e-300};
  const double starts[] = {-2.0, 2.0, 0.5, 1.5, -3.0, 0.0, nan};
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> coord(-4.0, 4.0), unit(-1.0, 1.0);
  const auto pick = [&](const auto& values) {
    return values[std::uniform_int_distribution<std::size_t>(0, std::size(values) - 1)(rng)];
  };
  int compared = 0, walked = 0, zero_components = 0, still = 0, refused = 0;
  for (int k = 0; k < 200000; ++k) {
    const auto one_in = [&](int m) { return std::uniform_int_distribution<int>(0, m - 1)(rng) == 0; };
    const int origin_kind = std::uniform_int_distribution<int>(0, 2)(rng);
    const bool special_dir = one_in(4);
    Ray r;
    for (int a = 0; a < 3; ++a) {
      const double inside = std::uniform_real_distribution<double>(g.universe.lo[a], g.universe.hi[a])(rng);
      r.origin[a] = origin_kind == 0 ? pick(starts) : origin_kind == 1 ? inside : coord(rng);
      r.dir[a] = special_dir ? pick(special) : unit(rng);
    }
    r.tmin = one_in(5) ? 2.0 : 0.0;
    r.tmax = one_in(7) ? (one_in(2) ? 1.0 : nan) : kInfinity;
    PlainDda plain;
    Dda3 dda;
    const auto expected = walk(plain, g, r, [](const PlainDda& w) { return w.visit(); });
    const auto got = walk(dda, g, r, [](const Dda3& w) {
      return Visit{w.vx(), w.vy(), w.vz(), bits(w.t_in()), bits(w.t_out())};
    });
    ASSERT_EQ(got.has_value(), expected.has_value()) << k;
    ++compared;
    if (!got) {
      ++refused;
      continue;
    }
    ASSERT_EQ(*got, *expected) << k;
    ++walked;
    zero_components += r.dir.x == 0 || r.dir.y == 0 || r.dir.z == 0;
    still += got->size() == 1 && !(r.tmin <= r.tmax);
  }
  // The rays reached the cases they were chosen for.
  EXPECT_EQ(compared, 200000);
  EXPECT_GT(walked, 20000);
  EXPECT_GT(refused, 50000);
  EXPECT_GT(zero_components, 1000);
  EXPECT_GT(still, 10);  // not moving, over a reversed or NaN [tmin, tmax]
}

// A ray that moves along no axis clips nothing, so even a reversed [tmin,
// tmax] leaves it in its first voxel, as the plain set-up does.
TEST(Dda3Setup, ARayMovingAlongNoAxisStaysInItsFirstVoxel) {
  const VoxelGrid g = unit_voxel_grid(4);
  Dda3 dda;
  ASSERT_TRUE(dda.setup(g, Ray{{1.5, 2.5, 3.5}, {0, 0, 0}, 2.0, 1.0}));
  EXPECT_EQ(dda.voxel(), (3 * 4 + 2) * 4 + 1);
  EXPECT_EQ(dda.t_in(), 2.0);
  EXPECT_FALSE(dda.step());
  EXPECT_FALSE(dda.setup(g, Ray{{4.5, 2.5, 3.5}, {0, 0, 0}, 0.0, 1.0}));  // outside the universe
}

}  // namespace
}  // namespace capsim
