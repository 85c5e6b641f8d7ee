#include "cell_grid.h"

#include <fmt/core.h>

#include <charconv>
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

namespace {

bool parse_side(std::string_view s, int& out) {
  if (s.empty()) return false;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return ec == std::errc() && end == s.data() + s.size();
}

}  // namespace

CellGrid parse_cell_grid(const std::string& text) {
  const auto x = text.find_first_of("xX");
  CellGrid g;
  if (x == std::string::npos || !parse_side(std::string_view(text).substr(0, x), g.rows) ||
      !parse_side(std::string_view(text).substr(x + 1), g.cols))
    throw std::invalid_argument(fmt::format("cell grid '{}' is not of the form RxC (e.g. 8x8)", text));
  if (g.rows < 1 || g.rows > kMaxGridSide || g.cols < 1 || g.cols > kMaxGridSide)
    throw std::invalid_argument(fmt::format(
        "cell grid '{}' is out of range: rows and columns must be 1 to {}", text, kMaxGridSide));
  return g;
}

std::string to_string(const CellGrid& grid) { return fmt::format("{}x{}", grid.rows, grid.cols); }

}  // namespace capsim::sim
