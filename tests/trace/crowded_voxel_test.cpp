// The walk through crowded voxels of round spheres, which asks each voxel's
// bounding volumes for the spheres a ray may meet, against the plain walk
// that tests them all (TraceOptions::unfiltered_crowded_voxels): the same
// hits to the bit and the same operation counts, on random scenes on coarse
// grids.

#include "capsim/trace/tracer.h"
#include "support/scene_builders.h"

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <random>

using namespace capsim;
using namespace capsim::testing;

namespace {

std::uint64_t bits(double x) { return std::bit_cast<std::uint64_t>(x); }

// A cloud of overlapping spheres, some subtracted (so leaves toggle without
// the root changing), plus a lattice of unit-spaced spheres of radius 0.5,
// which axis-parallel rays along the lattice's lines graze; `boxes` mixes in
// boxes, whose voxels keep the plain walk.
Scene crowded_scene(std::mt19937_64& rng, int spheres, bool boxes) {
  std::uniform_real_distribution<double> pos(-4, 4), radius(0.05, 0.9);
  std::vector<Primitive> prims;
  for (int k = 0; k < spheres; ++k) prims.push_back(sphere({pos(rng), pos(rng), pos(rng)}, radius(rng)));
  for (int x = -2; x <= 2; ++x)
    for (int y = -2; y <= 2; ++y)
      for (int z = -2; z <= 2; ++z) prims.push_back(sphere({x, y, z}, 0.5));
  if (boxes) {
    for (int k = 0; k < 5; ++k) prims.push_back(box({pos(rng), pos(rng), pos(rng)}, {0.5, 1, 1.5}));
  }
  std::vector<CsgNode> kept, cut;
  for (std::size_t i = 0; i < prims.size(); ++i) (i % 7 == 3 ? cut : kept).push_back(leaf(static_cast<int>(i)));
  return make_scene(std::move(prims), op(CsgOp::Difference, {op(CsgOp::Union, kept), op(CsgOp::Union, cut)}));
}

glm::dvec3 random_direction(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(-1, 1);
  std::uniform_int_distribution<int> kind(0, 5);
  switch (kind(rng)) {
    case 0:  // along an axis, zero in two components
      return glm::dvec3(0, 0, unit(rng) < 0 ? -1 : 1);
    case 1:  // in a coordinate plane
      return glm::normalize(glm::dvec3(unit(rng), 0, unit(rng)) + glm::dvec3(1e-3, 0, 0));
    default: {
      glm::dvec3 d(unit(rng), unit(rng), unit(rng));
      while (glm::length(d) < 1e-3) d = {unit(rng), unit(rng), unit(rng)};
      return glm::normalize(d);
    }
  }
}

Ray random_ray(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> inside(-4.5, 4.5), outside(-40, 40), limit(0, 12);
  std::uniform_int_distribution<int> kind(0, 4), lattice(-2, 2);
  Ray r;
  switch (kind(rng)) {
    case 0: {  // along a line of the lattice, offset by about its spheres' radius: grazing, or
               // meeting them a hair's breadth inside, which a filter any tighter would miss
      const double offsets[] = {0.5, 0.5 - 1e-12, 0.5 - 1e-9, 0.5 + 1e-12};
      r.origin = glm::dvec3(lattice(rng) + offsets[kind(rng) % 4], lattice(rng), -9);
      r.dir = {0, 0, 1};
      break;
    }
    case 1:
    case 2:
      r.origin = {inside(rng), inside(rng), inside(rng)};
      r.dir = random_direction(rng);
      break;
    default: {
      r.origin = {outside(rng), outside(rng), outside(rng)};
      const glm::dvec3 aim(inside(rng), inside(rng), inside(rng));
      r.dir = glm::normalize(aim - r.origin);
    }
  }
  r.tmin = kind(rng) == 0 ? limit(rng) : 0.0;
  r.tmax = kind(rng) == 0 ? r.tmin + limit(rng) : kInfinity;
  return r;
}

}  // namespace

TEST(CrowdedVoxels, FilteredWalkEqualsThePlainWalk) {
  std::mt19937_64 rng(2024);
  int hits = 0;
  for (int trial = 0; trial < 12; ++trial) {
    PrepareOptions options;
    options.grid = 1 + trial % 3;
    options.width = options.height = 16;
    const PreparedScene scene = prepare_scene(crowded_scene(rng, 150 + 40 * trial, trial % 4 == 3), options);
    ASSERT_GT(scene.grid.largest_voxel, 32u);
    TraceOptions plain_options;
    plain_options.unfiltered_crowded_voxels = true;
    const Tracer filtered(scene, TraceOptions{}), plain(scene, plain_options);
    Tracer::Scratch filtered_scratch(scene), plain_scratch(scene);
    for (int k = 0; k < 1500; ++k) {
      const Ray r = random_ray(rng);
      OpCounts filtered_ops, plain_ops;
      Hit a, b;
      const bool met = plain.first_hit(r, plain_scratch, plain_ops, b);
      ASSERT_EQ(filtered.first_hit(r, filtered_scratch, filtered_ops, a), met) << trial << " " << k;
      ASSERT_TRUE(filtered_ops == plain_ops) << trial << " " << k;
      if (!met) continue;
      ++hits;
      EXPECT_EQ(bits(a.t), bits(b.t)) << trial << " " << k;
      EXPECT_EQ(a.primitive, b.primitive) << trial << " " << k;
      EXPECT_EQ(a.entering, b.entering) << trial << " " << k;
      for (int i = 0; i < 3; ++i) {
        EXPECT_EQ(bits(a.normal[i]), bits(b.normal[i])) << trial << " " << k;
        EXPECT_EQ(bits(a.point[i]), bits(b.point[i])) << trial << " " << k;
      }
    }
    // Whole pixels: shadow, reflection and refraction rays from the hits.
    for (int j = 0; j < 16; j += 3) {
      for (int i = 0; i < 16; i += 3) {
        OpCounts filtered_ops, plain_ops;
        const PixelSample a = filtered.trace_pixel(i, j, filtered_scratch, filtered_ops);
        const PixelSample b = plain.trace_pixel(i, j, plain_scratch, plain_ops);
        ASSERT_TRUE(filtered_ops == plain_ops) << trial << " " << i << " " << j;
        EXPECT_EQ(bits(a.depth), bits(b.depth));
        EXPECT_EQ(a.primitive, b.primitive);
        for (int c = 0; c < 3; ++c) EXPECT_EQ(bits(a.color[c]), bits(b.color[c]));
      }
    }
  }
  EXPECT_GT(hits, 1000);  // the rays do meet the spheres
}
