#pragma once
// Phase 2 of an antialiased frame (paper §3.3, fig. 3-4): before a cell can
// subdivide its pixels it needs the corner samples of its right, lower and
// lower-right neighbouring pixels, which other cells traced in phase 1.
//
// Corner (x, y) of the (W+1) x (H+1) screen corners belongs to the cell that
// shows pixel (min(x, W-1), min(y, H-1)): its own pixel's top-left corner, and
// for the cells of the last column and row also the screen's extra corners.
//
// Routes, the paper's "up, then left" made general: a corner owned by cell O and
// needed by cell N first goes vertically, from O to the cell M in N's row and
// O's column, then horizontally from M to N; either step is skipped where it
// would stay in one cell. So every cell runs two steps: it sends the vertical
// messages (its own corners), takes in the ones for it, then sends the
// horizontal ones (its own corners with those it relays), and takes in those.
// In dot mode that is the paper's scheme: the lower neighbour's corners come up
// one hop, the right neighbour's come one hop left, and the lower-right ones
// come up to the right neighbour and on to the left with its own. The cells of
// the last grid row and column need corners from the opposite edge (the next
// R x C square); how far those travel depends on the links' topology (mesh:
// across the grid; torus: one hop over the wrap-around link).
//
// One exchange can serve several frames at once (a group of frame-averaged
// frames, each with its own dot shift): the corners of all of them travel in
// the same messages, one per pair of cells and step.

#include "machine/parts/cell_grid.h"
#include "machine/parts/frame_protocol.h"
#include "machine/parts/window_controller.h"

#include <cstdint>
#include <vector>

namespace capsim::sim {

// Corners are numbered frame by frame, then row by row:
// frame * (W + 1) * (H + 1) + y * (W + 1) + x.
using CornerIndex = std::uint32_t;

struct CornerMessage {
  CellId from = 0;
  CellId to = 0;
  std::vector<CornerIndex> corners;  // ascending
};

class CornerExchange {
 public:
  // One layout per frame, all of one screen size and cell grid, for the run's
  // frames first_frame, first_frame + 1, ...; they must outlive the exchange.
  explicit CornerExchange(std::vector<const WindowLayout*> frames, int first_frame = 0);
  explicit CornerExchange(const WindowLayout& layout) : CornerExchange(std::vector{&layout}) {}

  // The cell whose video memory holds a corner.
  CellId owner(CornerIndex corner) const;
  // Corner (x, y) of the run's frame `frame`.
  CornerIndex index(int frame, int x, int y) const {
    return static_cast<CornerIndex>(frame) * corners_per_frame_ +
           static_cast<CornerIndex>(y) * static_cast<CornerIndex>(width_ + 1) + x;
  }
  int width() const { return width_; }
  int height() const { return height_; }

  // The messages a cell sends in a step, in order of destination.
  const std::vector<CornerMessage>& sends(CellId cell, ExchangeStep step) const {
    return (step == ExchangeStep::Vertical ? vertical_ : horizontal_)[cell];
  }
  // How many messages a cell receives in a step.
  int receives(CellId cell, ExchangeStep step) const {
    return (step == ExchangeStep::Vertical ? vertical_in_ : horizontal_in_)[cell];
  }
  // The corners a cell needs from other cells (ascending).
  const std::vector<CornerIndex>& needs(CellId cell) const { return needs_[cell]; }

 private:
  std::vector<const WindowLayout*> frames_;
  int first_frame_;
  int width_, height_;
  CornerIndex corners_per_frame_;
  std::vector<std::vector<CornerIndex>> needs_;
  std::vector<std::vector<CornerMessage>> vertical_, horizontal_;
  std::vector<int> vertical_in_, horizontal_in_;
};

// Per cell, how many corners of one frame it needs from other cells: the size
// of CornerExchange(layout).needs(cell), counted without planning messages,
// from the rows and the columns apart (O(W + H + cells), not O(W x H)).
std::vector<std::uint64_t> corners_needed(const WindowLayout& layout);

}  // namespace capsim::sim
