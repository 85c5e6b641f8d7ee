#pragma once
// The cells of CAP on an R x C grid. Cell k sits at row k / C, column k % C;
// row 0 is the top row, column 0 the left column (as on the screen).

#include <optional>
#include <string>

namespace capsim::sim {

using CellId = int;

inline constexpr int kMaxGridSide = 32;

struct CellPosition {
  int row = 0;
  int col = 0;
};

enum class Direction { North, East, South, West };
const char* to_string(Direction d);

struct CellGrid {
  int rows = 8;
  int cols = 8;

  int cell_count() const { return rows * cols; }
  CellId id(CellPosition p) const { return p.row * cols + p.col; }
  CellPosition position(CellId id) const { return {id / cols, id % cols}; }
  // The neighbour in direction d, if the grid has one there (no wrap-around).
  std::optional<CellId> neighbour(CellId id, Direction d) const;
  bool operator==(const CellGrid&) const = default;
};

std::string to_string(const CellGrid& grid);  // "RxC"

}  // namespace capsim::sim
