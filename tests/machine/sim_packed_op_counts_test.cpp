// Packed operation counts read back exactly what was set, whether each count
// fits 32 bits or the item is kept whole, and add into a sum as OpCounts does.

#include "machine/packed_op_counts.h"

#include <gtest/gtest.h>

#include <tbb/parallel_for.h>

#include <cstdint>

namespace capsim::sim {
namespace {

OpCounts counts(std::uint64_t base) {
  OpCounts ops;
  ops.sphere_tests = base;
  ops.triangle_tests = base + 1;
  ops.dda_steps = 3 * base;
  ops.tree_visits = base / 2;
  ops.rays = 1;
  ops.aa_squares = base % 7;
  return ops;
}

TEST(PackedOpCounts, ReadsBackWhatWasSet) {
  PackedOpCounts packed(4);
  EXPECT_EQ(packed.size(), 4u);
  EXPECT_EQ(packed.at(2), OpCounts());
  packed.set(0, counts(5));
  packed.set(3, counts(UINT32_MAX - 2));  // 3 * base does not fit: kept whole
  EXPECT_EQ(packed.at(0), counts(5));
  EXPECT_EQ(packed.at(3), counts(UINT32_MAX - 2));
  EXPECT_EQ(packed.at(1), OpCounts());
  EXPECT_EQ(packed.kept_whole(), 1u);
}

TEST(PackedOpCounts, KeepsWholeEveryCountFrom2To32Less1) {
  // The first count of a packed item marks one kept whole, so that count's
  // largest value must be kept whole too.
  OpCounts marker;
  marker.sphere_tests = UINT32_MAX;
  OpCounts last;
  last.aa_squares = std::uint64_t{1} << 40;
  OpCounts fits;
  fits.sphere_tests = UINT32_MAX - 1;
  fits.aa_squares = UINT32_MAX - 1;
  PackedOpCounts packed(3);
  packed.set(0, marker);
  packed.set(1, last);
  packed.set(2, fits);
  EXPECT_EQ(packed.at(0), marker);
  EXPECT_EQ(packed.at(1), last);
  EXPECT_EQ(packed.at(2), fits);
  EXPECT_EQ(packed.kept_whole(), 2u);
}

TEST(PackedOpCounts, AddsIntoASumAsOpCountsDo) {
  PackedOpCounts packed(3);
  packed.set(0, counts(11));
  packed.set(1, counts(std::uint64_t{1} << 35));
  packed.set(2, counts(UINT32_MAX / 3));
  OpCounts sum = counts(2), expected = counts(2);
  for (std::size_t i = 0; i < packed.size(); ++i) {
    packed.add_to(i, sum);
    expected += packed.at(i);
  }
  EXPECT_EQ(sum, expected);
  EXPECT_EQ(sum, counts(2) + counts(11) + counts(std::uint64_t{1} << 35) + counts(UINT32_MAX / 3));
}

TEST(PackedOpCounts, SetFromManyThreadsAtOnce) {
  constexpr std::size_t kItems = 20000;
  auto value = [](std::size_t i) { return counts(i % 97 == 0 ? (std::uint64_t{1} << 33) + i : i); };
  PackedOpCounts packed(kItems);
  tbb::parallel_for(std::size_t{0}, kItems, [&](std::size_t i) { packed.set(i, value(i)); });
  for (std::size_t i = 0; i < kItems; ++i) ASSERT_EQ(packed.at(i), value(i)) << i;
  EXPECT_EQ(packed.kept_whole(), (kItems + 96) / 97);
}

}  // namespace
}  // namespace capsim::sim
