// The window controller: every screen pixel has exactly one owner, for every mode,
// screen size and cell grid (exhaustive on small sizes), and the modes follow the
// issue's rules.

#include "machine/parts/video_bus.h"
#include "machine/parts/window_controller.h"

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <vector>

namespace capsim::sim {
namespace {

// Walks every cell's video memory through its window and checks the screen is
// covered exactly once and agrees with the inverse mapping.
void expect_exact_cover(PixelMode mode, CellGrid grid, int w, int h) {
  const WindowLayout layout(mode, grid, w, h);
  std::vector<int> writes(static_cast<std::size_t>(w) * h, 0);
  int total = 0;
  for (CellId c = 0; c < grid.cell_count(); ++c) {
    const CellWindow& win = layout.window(c);
    for (int k = 0; k < win.pixel_count(); ++k) {
      const ScreenPixel p = win.screen_pixel(k);
      ASSERT_TRUE(p.x >= 0 && p.x < w && p.y >= 0 && p.y < h)
          << to_string(mode) << " " << to_string(grid) << " " << w << "x" << h;
      ++writes[static_cast<std::size_t>(p.y) * w + p.x];
      ASSERT_EQ(layout.owner(p), (PixelOwner{c, k}))
          << to_string(mode) << " " << to_string(grid) << " " << w << "x" << h << " at "
          << p.x << "," << p.y;
      ++total;
    }
  }
  ASSERT_EQ(total, w * h);
  for (int n : writes) ASSERT_EQ(n, 1);
}

TEST(WindowController, EveryPixelHasExactlyOneOwnerExhaustively) {
  for (PixelMode mode : {PixelMode::Block, PixelMode::Line, PixelMode::Dot})
    for (int rows = 1; rows <= 5; ++rows)
      for (int cols = 1; cols <= 5; ++cols)
        for (int w = 1; w <= 13; ++w)
          for (int h = 1; h <= 13; ++h) expect_exact_cover(mode, {rows, cols}, w, h);
}

TEST(WindowController, EveryPixelHasExactlyOneOwnerOnLargerGrids) {
  for (PixelMode mode : {PixelMode::Block, PixelMode::Line, PixelMode::Dot})
    for (CellGrid grid : {CellGrid{8, 8}, CellGrid{3, 7}, CellGrid{32, 32}, CellGrid{1, 32}})
      for (int w : {1, 7, 8, 9, 31, 33, 64, 100})
        for (int h : {1, 5, 8, 17, 64, 65}) expect_exact_cover(mode, grid, w, h);
}

TEST(WindowController, DotModeGivesEachCellItsPlaceInEverySquare) {
  const WindowLayout layout(PixelMode::Dot, {8, 8}, 512, 512);
  // Cell 0 owns the pixel at (0, 0) of every 8x8 square (the paper's figure 3-3).
  const CellWindow& w0 = layout.window(0);
  EXPECT_EQ(w0.pixel_count(), 64 * 64);
  EXPECT_EQ(w0.screen_pixel(0), (ScreenPixel{0, 0}));
  EXPECT_EQ(w0.screen_pixel(1), (ScreenPixel{8, 0}));
  EXPECT_EQ(w0.screen_pixel(64), (ScreenPixel{0, 8}));
  // Cell (row 2, col 5) owns (5, 2) of every square.
  const CellWindow& w = layout.window(2 * 8 + 5);
  EXPECT_EQ(w.screen_pixel(0), (ScreenPixel{5, 2}));
  EXPECT_EQ(w.screen_pixel(65), (ScreenPixel{13, 10}));
}

TEST(WindowController, LineModeGivesCellKEveryNthRowFromK) {
  const WindowLayout layout(PixelMode::Line, {2, 3}, 10, 20);
  const CellWindow& w = layout.window(4);  // row 1, col 1: k = 1 * 3 + 1
  EXPECT_EQ(w.rows(), 3);                  // rows 4, 10, 16
  EXPECT_EQ(w.screen_pixel(0), (ScreenPixel{0, 4}));
  EXPECT_EQ(w.screen_pixel(10), (ScreenPixel{0, 10}));
  EXPECT_EQ(w.screen_pixel(29), (ScreenPixel{9, 16}));
}

TEST(WindowController, BlockModeSplitsAsEvenlyAsPossible) {
  // 10 columns over 3 cells: floor(k * 10 / 3) = 0, 3, 6, 10.
  const WindowLayout layout(PixelMode::Block, {1, 3}, 10, 4);
  EXPECT_EQ(layout.window(0).columns(), 3);
  EXPECT_EQ(layout.window(1).columns(), 3);
  EXPECT_EQ(layout.window(2).columns(), 4);
  EXPECT_EQ(layout.window(2).screen_pixel(0), (ScreenPixel{6, 0}));
}

TEST(WindowController, CellsBeyondTheScreenOwnNothing) {
  const WindowLayout dot(PixelMode::Dot, {4, 4}, 2, 3);
  EXPECT_EQ(dot.window(3).pixel_count(), 0);   // column 3 of a 2-pixel-wide screen
  EXPECT_EQ(dot.window(12).pixel_count(), 0);  // row 3 of a 3-pixel-high screen
  const WindowLayout line(PixelMode::Line, {2, 2}, 5, 3);
  EXPECT_EQ(line.window(3).pixel_count(), 0);
}

TEST(WindowController, ParsesModeNames) {
  EXPECT_EQ(parse_pixel_mode("dot"), PixelMode::Dot);
  EXPECT_EQ(parse_pixel_mode("line"), PixelMode::Line);
  EXPECT_EQ(parse_pixel_mode("block"), PixelMode::Block);
  EXPECT_EQ(parse_pixel_mode("Dot"), std::nullopt);
}

}  // namespace
}  // namespace capsim::sim

namespace capsim::sim {
namespace {

// The scatter that the video bus and the cycles screen share visits every
// screen pixel once, naming the cell and video-memory pixel that own it.
TEST(VideoBus, EveryWindowPixelIsVisitedOnceWithItsOwner) {
  for (PixelMode mode : {PixelMode::Block, PixelMode::Line, PixelMode::Dot}) {
    const WindowLayout layout(mode, CellGrid{3, 4}, 29, 17);
    std::vector<std::atomic<int>> visits(29 * 17);
    std::vector<PixelOwner> owner(29 * 17);
    for_each_window_pixel(layout, [&](CellId c, int k, std::size_t s) {
      ++visits[s];
      owner[s] = {c, k};
    });
    for (int y = 0; y < 17; ++y)
      for (int x = 0; x < 29; ++x) {
        const std::size_t s = static_cast<std::size_t>(y) * 29 + x;
        ASSERT_EQ(visits[s], 1) << to_string(mode) << " at " << x << "," << y;
        ASSERT_EQ(owner[s], layout.owner({x, y})) << to_string(mode) << " at " << x << "," << y;
      }
  }
}

// A video memory whose size is not its window's is refused, naming the cell.
TEST(VideoBus, RefusesAVideoMemoryOfTheWrongSize) {
  const WindowLayout layout(PixelMode::Dot, CellGrid{2, 2}, 8, 8);
  std::vector<Framebuffer> memories;
  for (CellId c = 0; c < 4; ++c) memories.emplace_back(layout.window(c).pixel_count() - (c == 2), 1);
  std::vector<const Framebuffer*> video;
  for (const Framebuffer& m : memories) video.push_back(&m);
  try {
    compose_screen(layout, video);
    FAIL() << "a short video memory was accepted";
  } catch (const std::logic_error& e) {
    EXPECT_STREQ(e.what(), "cell 2 video memory holds 15 pixels, its window 16");
  }
}

TEST(WindowController, OwnerTableAgreesWithOwnerEverywhere) {
  for (PixelMode mode : {PixelMode::Block, PixelMode::Line, PixelMode::Dot})
    for (int rows = 1; rows <= 4; ++rows)
      for (int cols = 1; cols <= 5; ++cols)
        for (const auto& [w, h] : {std::pair{1, 1}, std::pair{13, 7}, std::pair{20, 24}}) {
          const CellGrid grid{rows, cols};
          for (int shift = 0; shift < (mode == PixelMode::Dot ? grid.cell_count() : 1); ++shift) {
            const WindowLayout layout(mode, grid, w, h, mode == PixelMode::Dot ? dot_shift_for_frame(grid, shift) : DotShift{});
            const OwnerTable table(layout);
            for (int y = 0; y < h; ++y)
              for (int x = 0; x < w; ++x)
                ASSERT_EQ(table.owner(x, y), layout.owner({x, y}))
                    << to_string(mode) << " " << to_string(grid) << " shift " << shift << " at " << x << "," << y;
          }
        }
}

}  // namespace
}  // namespace capsim::sim
