// Voxel generation places primitives on several threads: the grid, its counts
// and its order must be exactly the one-thread result for every thread count.

#include "capsim/trace/voxel_grid.h"
#include "support/scene_builders.h"

#include <gtest/gtest.h>

#include <random>

using namespace capsim;
using namespace capsim::testing;

namespace {

// count random spheres, boxes and cones, turned and stretched, spread over a
// box of side `spread` (small: they overlap and share voxels), about one in
// seven left unplaced as a dropped object would be.
struct RandomPrimitives {
  std::vector<PreparedPrimitive> prims;
  std::vector<bool> placed;
};

RandomPrimitives random_primitives(std::uint64_t seed, int count, double spread) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> at(-spread, spread), size(0.1, 2.0), ang(0, 6.283185307179586);
  RandomPrimitives r;
  for (int i = 0; i < count; ++i) {
    Primitive p = i % 3 == 0   ? sphere({at(rng), at(rng), at(rng)}, size(rng))
                  : i % 3 == 1 ? box({at(rng), at(rng), at(rng)}, {size(rng), size(rng), size(rng)})
                               : cone({at(rng), at(rng), at(rng)}, size(rng), size(rng), i % 2 ? 0.0 : size(rng));
    p.to_world = glm::rotate(glm::dmat4(1.0), ang(rng), glm::normalize(glm::dvec3(at(rng), at(rng), 1))) *
                 glm::scale(glm::dmat4(1.0), glm::dvec3(1, 0.5 + size(rng), 1)) * p.to_world;
    r.prims.push_back(prepare_primitive(p));
    r.placed.push_back(rng() % 7 != 0);
  }
  return r;
}

void expect_same_grid(const VoxelGrid& a, const VoxelGrid& b) {
  EXPECT_EQ(a.n, b.n);
  EXPECT_EQ(a.universe.lo, b.universe.lo);
  EXPECT_EQ(a.universe.hi, b.universe.hi);
  EXPECT_EQ(a.voxel_size, b.voxel_size);
  EXPECT_EQ(a.offsets, b.offsets);
  EXPECT_EQ(a.items, b.items);
  EXPECT_EQ(a.largest_voxel, b.largest_voxel);
}

}  // namespace

TEST(ParallelVoxelGeneration, EqualsOneThreadExactly) {
  // Counts below, at and above the range size, so that ranges end inside and
  // at the end of the primitives.
  std::uint64_t seed = 1;
  for (const int count : {1, 7, 31, 32, 33, 65, 300, 1000}) {
    for (const double spread : {2.0, 20.0}) {
      const RandomPrimitives r = random_primitives(seed++, count, spread);
      const Aabb universe = universe_of(r.prims, r.placed);
      if (universe.empty()) continue;  // nothing placed
      for (const int n : {1, 7, 24}) {
        SCOPED_TRACE(::testing::Message() << count << " primitives over " << spread << ", N = " << n);
        VoxelGenCounts serial_counts;
        const VoxelGrid serial = generate_voxels(r.prims, r.placed, universe, n, &serial_counts, 1);
        for (const int threads : {2, 3, 8}) {
          VoxelGenCounts counts;
          const VoxelGrid parallel = generate_voxels(r.prims, r.placed, universe, n, &counts, threads);
          expect_same_grid(serial, parallel);
          EXPECT_EQ(serial_counts, counts) << threads << " threads";
        }
      }
    }
  }
}

TEST(ParallelVoxelGeneration, PreparedSceneDoesNotDependOnThreads) {
  std::vector<Primitive> prims;
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> at(-10, 10);
  for (int i = 0; i < 200; ++i) prims.push_back(sphere({at(rng), at(rng), at(rng)}, 0.7));
  const Scene sc = make_scene(prims);
  PrepareOptions o;
  o.width = o.height = 8;
  o.threads = 1;
  const PreparedScene one = prepare_scene(sc, o);
  for (const int threads : {0, 2, 3, 8}) {
    o.threads = threads;
    const PreparedScene many = prepare_scene(sc, o);
    expect_same_grid(one.grid, many.grid);
    EXPECT_EQ(one.voxel_counts, many.voxel_counts);
  }
}

// Over the limit, the grid is refused on many threads as on one (the
// bounding boxes might pass it, so the primitives go in one range, in order;
// tracer_test checks the refusal's message).
TEST(ParallelVoxelGeneration, RefusalDoesNotDependOnThreads) {
  const std::vector<PreparedPrimitive> prims(3, prepare_primitive(box({0, 0, 0}, {1, 1, 1})));
  const std::vector<bool> placed(3, true);
  const Aabb universe = universe_of(prims, placed);
  EXPECT_THROW(generate_voxels(prims, placed, universe, 256, nullptr, 8), VoxelGridTooLarge);
}
