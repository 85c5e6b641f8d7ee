#pragma once
// The window controller of each cell: where on the screen, and in which pattern,
// the cell's video memory appears (paper §3.1). Every pattern is a strided
// rectangle: video-memory pixel k of a cell appears at
//   x = origin_x + (k % columns) * stride_x,   y = origin_y + (k / columns) * stride_y.
// Modes on an R x C cell grid and a W x H screen, for cell (row r, col c), k = r*C + c:
//   block: the rectangle [floor(c*W/C), floor((c+1)*W/C)) x [floor(r*H/R), floor((r+1)*H/R)):
//          rows and columns split as evenly as possible;
//   line:  every (R*C)-th screen row, starting at row k, full width;
//   dot:   in every R x C square of the screen (R rows, C columns) the pixel at the
//          cell's own (col, row) position (the paper's 8x8 dot mode); shifted by
//          (rows, cols) = (a, b), cell (r, c) takes position ((r + a) mod R,
//          (c + b) mod C) instead (frame-averaged distribution, dot_shift_for_frame).
// Screens that are not multiples of the grid are covered the same way; cells may
// then own different pixel counts, or none at all.

#include "machine/parts/cell_grid.h"

#include <optional>
#include <string>
#include <vector>

namespace capsim::sim {

enum class PixelMode { Block, Line, Dot };
const char* to_string(PixelMode mode);
std::optional<PixelMode> parse_pixel_mode(const std::string& text);

struct ScreenPixel {
  int x = 0;  // column, from the left
  int y = 0;  // row, from the top
  bool operator==(const ScreenPixel&) const = default;
};

class CellWindow {
 public:
  CellWindow() = default;
  CellWindow(int origin_x, int origin_y, int columns, int rows, int stride_x, int stride_y);

  int pixel_count() const { return columns_ * rows_; }
  int columns() const { return columns_; }
  int rows() const { return rows_; }
  int origin_x() const { return origin_x_; }
  int origin_y() const { return origin_y_; }
  int stride_x() const { return stride_x_; }
  int stride_y() const { return stride_y_; }
  // Precondition: 0 <= k < pixel_count().
  ScreenPixel screen_pixel(int k) const {
    return {origin_x_ + (k % columns_) * stride_x_, origin_y_ + (k / columns_) * stride_y_};
  }

 private:
  int origin_x_ = 0, origin_y_ = 0;
  int columns_ = 0, rows_ = 0;
  int stride_x_ = 1, stride_y_ = 1;
};

// Which cell shows a screen pixel, and from which video-memory pixel.
struct PixelOwner {
  CellId cell = 0;
  int video_index = 0;
  bool operator==(const PixelOwner&) const = default;
};

// How far the dot pattern is turned: rows down, columns right, on the grid's torus.
struct DotShift {
  int rows = 0;
  int cols = 0;
  bool operator==(const DotShift&) const = default;
};

// The shift of frame k of a unit under frame-averaged distribution: diagonal,
// rows by k mod R and columns by (k mod R + k div R) mod C (k taken mod R x C).
// Every R consecutive frames from k = 0, R, 2R, ... move a cell over R
// different rows and R different columns of the square, so a unit of a few
// multiples of R frames, fewer than R x C, still spreads each pixel over
// different cells; R x C frames take every shift once, so every cell owns
// every position of the square exactly once.
DotShift dot_shift_for_frame(const CellGrid& grid, int frame);

// The window set-up of the whole machine for one mode, grid and screen size.
class WindowLayout {
 public:
  // Precondition: width, height >= 1; grid sides >= 1; shift only in dot mode,
  // each part in 0 .. side-1.
  WindowLayout(PixelMode mode, CellGrid grid, int width, int height, DotShift shift = {});

  const CellWindow& window(CellId cell) const { return windows_[cell]; }
  // The inverse of the windows, computed directly from the mode's rule.
  PixelOwner owner(ScreenPixel p) const;

  PixelMode mode() const { return mode_; }
  DotShift shift() const { return shift_; }
  const CellGrid& grid() const { return grid_; }
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  friend class OwnerTable;
  PixelMode mode_;
  CellGrid grid_;
  DotShift shift_;
  int width_, height_;
  std::vector<CellWindow> windows_;
};

// WindowLayout::owner for every pixel of the screen at a few operations each,
// for the loops that visit every pixel. In every mode the owner splits into a
// part of the row and a part of the column:
//   cell = row_cell[y] + col_cell[x],  video index = row_step[y] * col_step[x] + col_index[x].
// The parts never collide: row parts are multiples of C and column parts
// below C (block, dot), or column parts are all 0 (line). So two pixels have
// one owner exactly when their row parts agree and their column parts agree.
class OwnerTable {
 public:
  explicit OwnerTable(const WindowLayout& layout);
  PixelOwner owner(int x, int y) const {
    return {row_cell_[y] + col_cell_[x], row_step_[y] * col_step_[x] + col_index_[x]};
  }
  int row_cell(int y) const { return row_cell_[y]; }
  int col_cell(int x) const { return col_cell_[x]; }

 private:
  std::vector<int> row_cell_, row_step_;
  std::vector<int> col_cell_, col_step_, col_index_;
};

}  // namespace capsim::sim
