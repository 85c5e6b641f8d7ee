#include "machine/parts/window_controller.h"

#include <stdexcept>

namespace capsim::sim {

const char* to_string(PixelMode mode) {
  switch (mode) {
    case PixelMode::Block: return "block";
    case PixelMode::Line: return "line";
    case PixelMode::Dot: return "dot";
  }
  return "?";
}

std::optional<PixelMode> parse_pixel_mode(const std::string& text) {
  if (text == "block") return PixelMode::Block;
  if (text == "line") return PixelMode::Line;
  if (text == "dot") return PixelMode::Dot;
  return std::nullopt;
}

CellWindow::CellWindow(int origin_x, int origin_y, int columns, int rows, int stride_x,
                       int stride_y)
    : origin_x_(origin_x),
      origin_y_(origin_y),
      columns_(rows > 0 ? columns : 0),
      rows_(columns > 0 ? rows : 0),
      stride_x_(stride_x),
      stride_y_(stride_y) {}

namespace {

// Start of part `k` when `length` is split into `parts` as evenly as possible.
int split_start(int k, int length, int parts) {
  return static_cast<int>(static_cast<long long>(k) * length / parts);
}

// The part of an even split that holds position p: the largest k with
// split_start(k) <= p, i.e. floor(((p + 1) * parts - 1) / length).
int split_part(int p, int length, int parts) {
  return static_cast<int>((static_cast<long long>(p + 1) * parts - 1) / length);
}

// How many of 0 .. length-1 are congruent to `first` modulo `stride`.
int strided_count(int length, int first, int stride) {
  return first < length ? (length - first + stride - 1) / stride : 0;
}

}  // namespace

DotShift dot_shift_for_frame(const CellGrid& grid, int frame) {
  const int k = frame % grid.cell_count();
  const int row = k % grid.rows;
  return {row, (row + k / grid.rows) % grid.cols};
}

WindowLayout::WindowLayout(PixelMode mode, CellGrid grid, int width, int height, DotShift shift)
    : mode_(mode), grid_(grid), shift_(shift), width_(width), height_(height) {
  if (width < 1 || height < 1 || grid.rows < 1 || grid.cols < 1)
    throw std::invalid_argument("window layout needs a non-empty screen and cell grid");
  if (shift.rows < 0 || shift.rows >= grid.rows || shift.cols < 0 || shift.cols >= grid.cols ||
      (mode != PixelMode::Dot && shift != DotShift{}))
    throw std::invalid_argument("a dot shift must lie inside the grid, and only in dot mode");
  const int cells = grid.cell_count();
  windows_.reserve(cells);
  for (CellId id = 0; id < cells; ++id) {
    const CellPosition p = grid.position(id);
    switch (mode) {
      case PixelMode::Block: {
        const int x0 = split_start(p.col, width, grid.cols);
        const int x1 = split_start(p.col + 1, width, grid.cols);
        const int y0 = split_start(p.row, height, grid.rows);
        const int y1 = split_start(p.row + 1, height, grid.rows);
        windows_.emplace_back(x0, y0, x1 - x0, y1 - y0, 1, 1);
        break;
      }
      case PixelMode::Line:
        windows_.emplace_back(0, id, width, strided_count(height, id, cells), 1, cells);
        break;
      case PixelMode::Dot: {
        const int x0 = (p.col + shift.cols) % grid.cols, y0 = (p.row + shift.rows) % grid.rows;
        windows_.emplace_back(x0, y0, strided_count(width, x0, grid.cols),
                              strided_count(height, y0, grid.rows), grid.cols, grid.rows);
        break;
      }
    }
  }
}

PixelOwner WindowLayout::owner(ScreenPixel s) const {
  switch (mode_) {
    case PixelMode::Block: {
      const int row = split_part(s.y, height_, grid_.rows);
      const int col = split_part(s.x, width_, grid_.cols);
      const int x0 = split_start(col, width_, grid_.cols);
      const int x1 = split_start(col + 1, width_, grid_.cols);
      const int y0 = split_start(row, height_, grid_.rows);
      return {grid_.id({row, col}), (s.y - y0) * (x1 - x0) + (s.x - x0)};
    }
    case PixelMode::Line: {
      const int cells = grid_.cell_count();
      return {s.y % cells, (s.y / cells) * width_ + s.x};
    }
    case PixelMode::Dot: {
      // The position in the square, and the cell the shift puts there.
      const int py = s.y % grid_.rows, px = s.x % grid_.cols;
      const CellPosition cell{(py - shift_.rows + grid_.rows) % grid_.rows,
                              (px - shift_.cols + grid_.cols) % grid_.cols};
      return {grid_.id(cell), (s.y / grid_.rows) * strided_count(width_, px, grid_.cols) +
                                  s.x / grid_.cols};
    }
  }
  throw std::logic_error("unknown pixel mode");
}

OwnerTable::OwnerTable(const WindowLayout& layout)
    : row_cell_(layout.height()),
      row_step_(layout.height()),
      col_cell_(layout.width()),
      col_step_(layout.width()),
      col_index_(layout.width()) {
  const CellGrid& g = layout.grid();
  const int w = layout.width(), h = layout.height();
  switch (layout.mode()) {
    case PixelMode::Block:
      // index = (y - y0) * (x1 - x0) + (x - x0)
      for (int y = 0; y < h; ++y) {
        const int row = split_part(y, h, g.rows);
        row_cell_[y] = row * g.cols;
        row_step_[y] = y - split_start(row, h, g.rows);
      }
      for (int x = 0; x < w; ++x) {
        const int col = split_part(x, w, g.cols);
        const int x0 = split_start(col, w, g.cols);
        col_cell_[x] = col;
        col_step_[x] = split_start(col + 1, w, g.cols) - x0;
        col_index_[x] = x - x0;
      }
      break;
    case PixelMode::Line:
      // cell = y mod RC, index = (y / RC) * W + x
      for (int y = 0; y < h; ++y) {
        row_cell_[y] = y % g.cell_count();
        row_step_[y] = y / g.cell_count();
      }
      for (int x = 0; x < w; ++x) {
        col_cell_[x] = 0;
        col_step_[x] = w;
        col_index_[x] = x;
      }
      break;
    case PixelMode::Dot:
      // index = (y / R) * (pixels of the window's row) + x / C
      for (int y = 0; y < h; ++y) {
        row_cell_[y] = (y % g.rows - layout.shift().rows + g.rows) % g.rows * g.cols;
        row_step_[y] = y / g.rows;
      }
      for (int x = 0; x < w; ++x) {
        col_cell_[x] = (x % g.cols - layout.shift().cols + g.cols) % g.cols;
        col_step_[x] = strided_count(w, x % g.cols, g.cols);
        col_index_[x] = x / g.cols;
      }
      break;
  }
}

}  // namespace capsim::sim
