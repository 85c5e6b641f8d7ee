// Tracer::shade_primary_row works out a row of primary rays in passes (hits,
// then normals, then shading); it must give what shade_primary gives ray by
// ray, to the bit, with the same operation counts.

#include "capsim/scene/parser.h"
#include "capsim/trace/tracer.h"
#include "support/scene_builders.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

using namespace capsim;
using namespace capsim::testing;

namespace {

// kEveryKindDifference, polished, and a glass sphere, so that rows meet
// reflection and refraction, entering and leaving surfaces, and miss between
// the solids.
std::string scene_text() {
  return std::string(
             "camera(eye = [4.5, -6, 3.4], center = [-0.5, 0, -0.5], up = [0, 0, 1], fov = 60, size = [40, 30]);\n"
             "light(position = [20, -10, 25], color = [1, 1, 1]);\n"
             "light(position = [-15, -20, 10], color = [0.35, 0.35, 0.4]);\n"
             "material(reflect = 0.4, specular = 0.6, shininess = 64) ") +
         kEveryKindDifference + "material(transmit = 0.7, ior = 1.5) translate([-3, -4, 2]) sphere(r = 1.2);\n";
}

std::uint64_t bits(double v) { return std::bit_cast<std::uint64_t>(v); }

void expect_same_sample(const PixelSample& row, const PixelSample& single, int i, int j) {
  for (int c = 0; c < 3; ++c) EXPECT_EQ(bits(row.color[c]), bits(single.color[c])) << i << "," << j << " " << c;
  EXPECT_EQ(std::bit_cast<std::uint32_t>(row.alpha), std::bit_cast<std::uint32_t>(single.alpha)) << i << "," << j;
  EXPECT_EQ(bits(row.depth), bits(single.depth)) << i << "," << j;
  EXPECT_EQ(row.primitive, single.primitive) << i << "," << j;
  EXPECT_EQ(row.samples, single.samples) << i << "," << j;
}

}  // namespace

// On grids of 1 (every primitive in one crowded voxel), 4 and 9 voxels a side,
// with full shading and primary rays only; the counts summed over the row and
// kept ray by ray.
TEST(ShadePrimaryRow, IsShadePrimaryRayByRayToTheBit) {
  for (const int grid : {1, 4, 9}) {
    for (const bool primary_only : {false, true}) {
      PrepareOptions o;
      o.grid = grid;
      const PreparedScene ps = prepare_scene(parse_scene(scene_text(), "kinds.csg"), o);
      TraceOptions t;
      t.primary_only = primary_only;
      const Tracer tracer(ps, t);
      const int width = ps.camera.width;
      Tracer::Scratch row_scratch(ps), single_scratch(ps);
      OpCounts row_ops, single_ops;
      std::vector<Ray> rays(width);
      std::vector<PixelSample> out(width);
      int hits = 0, misses = 0;
      // The counts of each ray on its own add to what was there.
      OpCounts before;
      before.rays = 5;
      before.matvec = 3;
      std::vector<OpCounts> ray_ops(width);
      std::vector<PixelSample> out_each(width);
      for (int j = 0; j < ps.camera.height; ++j) {
        tracer.primary_rays(j, rays);
        tracer.shade_primary_row(rays, out, row_scratch, row_ops);
        std::fill(ray_ops.begin(), ray_ops.end(), before);
        tracer.shade_primary_row(rays, out_each, row_scratch, ray_ops);
        for (int i = 0; i < width; ++i) {
          OpCounts own;
          const PixelSample single = tracer.shade_primary(rays[i], single_scratch, own);
          single_ops += own;
          expect_same_sample(out[i], single, i, j);
          expect_same_sample(out_each[i], single, i, j);
          OpCounts expected = before;
          expected += own;
          ASSERT_EQ(ray_ops[i], expected) << "grid " << grid << " pixel " << i << "," << j;
          (single.primitive >= 0 ? hits : misses) += 1;
        }
        ASSERT_EQ(row_ops, single_ops) << "grid " << grid << " row " << j;
      }
      EXPECT_GT(hits, 400) << grid;
      EXPECT_GT(misses, 200) << grid;
    }
  }
}

// One scratch for rows of any length, into samples that hold an earlier
// row's values: every sample is written afresh.
TEST(ShadePrimaryRow, RowsOfAnyLengthShareAScratch) {
  const PreparedScene ps = prepare_scene(parse_scene(scene_text(), "kinds.csg"), PrepareOptions{});
  const Tracer tracer(ps, {});
  const int width = ps.camera.width;
  std::vector<Ray> rays(width);
  tracer.primary_rays(ps.camera.height / 2, rays);
  Tracer::Scratch row_scratch(ps), single_scratch(ps);
  std::vector<PixelSample> expected(width);
  OpCounts unused;
  for (int i = 0; i < width; ++i) expected[i] = tracer.shade_primary(rays[i], single_scratch, unused);

  PixelSample stale;
  stale.color = glm::dvec3(7);
  stale.alpha = 0.5f;
  stale.depth = 3;
  stale.primitive = 2;
  stale.samples = 9;
  std::vector<PixelSample> out(width, stale);
  for (const int first : {0, 1, width / 3, width - 1}) {
    for (const int count : {0, 1, 2, width - first}) {
      if (first + count > width) continue;
      std::fill(out.begin(), out.end(), stale);
      OpCounts row_ops, single_ops;
      tracer.shade_primary_row(std::span<const Ray>(rays).subspan(first, count),
                               std::span<PixelSample>(out).subspan(first, count), row_scratch, row_ops);
      for (int i = 0; i < width; ++i) {
        if (i < first || i >= first + count) {
          EXPECT_EQ(out[i].samples, stale.samples) << "written outside the row: " << i;
          continue;
        }
        expect_same_sample(out[i], expected[i], i, first);
        tracer.shade_primary(rays[i], single_scratch, single_ops);
      }
      EXPECT_EQ(row_ops, single_ops) << first << " " << count;
    }
  }
}
