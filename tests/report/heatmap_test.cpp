// The heat maps' colour scale.

#include "report/heatmap.h"

#include <gtest/gtest.h>

#include <array>
#include <limits>

namespace capsim::sim {
namespace {

TEST(Heatmap, ViridisClampsItsArgumentAndTakesNaNAsZero) {
  using Rgb = std::array<unsigned char, 3>;
  EXPECT_EQ(viridis(0.0), (Rgb{68, 1, 84}));
  EXPECT_EQ(viridis(1.0), (Rgb{253, 231, 37}));
  EXPECT_EQ(viridis(0.5), (Rgb{33, 145, 140}));
  EXPECT_EQ(viridis(-1e300), viridis(0.0));
  EXPECT_EQ(viridis(1e300), viridis(1.0));
  EXPECT_EQ(viridis(std::numeric_limits<double>::infinity()), viridis(1.0));
  // A cell grid whose cells all did nothing divides 0 by 0.
  EXPECT_EQ(viridis(std::numeric_limits<double>::quiet_NaN()), viridis(0.0));
}

}  // namespace
}  // namespace capsim::sim
