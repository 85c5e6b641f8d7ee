#include "machine/parts/cell_grid.h"

#include <fmt/core.h>

#include <stdexcept>

namespace capsim::sim {

const char* to_string(Direction d) {
  switch (d) {
    case Direction::North: return "N";
    case Direction::East: return "E";
    case Direction::South: return "S";
    case Direction::West: return "W";
  }
  return "?";
}

std::optional<CellId> CellGrid::neighbour(CellId id, Direction d) const {
  CellPosition p = position(id);
  switch (d) {
    case Direction::North: --p.row; break;
    case Direction::East: ++p.col; break;
    case Direction::South: ++p.row; break;
    case Direction::West: --p.col; break;
  }
  if (p.row < 0 || p.row >= rows || p.col < 0 || p.col >= cols) return std::nullopt;
  return this->id(p);
}

std::string to_string(const CellGrid& grid) { return fmt::format("{}x{}", grid.rows, grid.cols); }

}  // namespace capsim::sim
