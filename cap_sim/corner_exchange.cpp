#include "corner_exchange.h"

#include <algorithm>
#include <tuple>

namespace capsim::sim {

namespace {

// One corner on its way: from the cell that has it to the cell that takes it in.
struct Leg {
  CellId from, to;
  CornerIndex corner;
  auto operator<=>(const Leg&) const = default;
};

// Sorted, unique legs -> one message per (from, to), per sending cell.
std::vector<std::vector<CornerMessage>> group(std::vector<Leg>& legs, int cell_count,
                                              std::vector<int>& receives) {
  std::sort(legs.begin(), legs.end());
  legs.erase(std::unique(legs.begin(), legs.end()), legs.end());
  std::vector<std::vector<CornerMessage>> sends(cell_count);
  receives.assign(cell_count, 0);
  for (const Leg& l : legs) {
    auto& out = sends[l.from];
    if (out.empty() || out.back().to != l.to) {
      out.push_back({l.from, l.to, {}});
      ++receives[l.to];
    }
    out.back().corners.push_back(l.corner);
  }
  return sends;
}

}  // namespace

CornerExchange::CornerExchange(const WindowLayout& layout)
    : layout_(layout), width_(layout.width()), height_(layout.height()) {
  const CellGrid& grid = layout.grid();
  const int cells = grid.cell_count();
  std::vector<Leg> vertical, horizontal;
  std::vector<std::pair<CellId, CornerIndex>> needs;
  for (int y = 0; y < height_; ++y)
    for (int x = 0; x < width_; ++x) {
      const CellId n = layout.owner({x, y}).cell;
      const int corner_xy[3][2] = {{x + 1, y}, {x, y + 1}, {x + 1, y + 1}};
      for (const auto& [cx, cy] : corner_xy) {
        const CellId o = owner(cx, cy);
        if (o == n) continue;
        const CornerIndex c = index(cx, cy);
        needs.emplace_back(n, c);
        const CellId m = grid.id({grid.position(n).row, grid.position(o).col});
        if (m != o) vertical.push_back({o, m, c});
        if (m != n) horizontal.push_back({m, n, c});
      }
    }
  std::sort(needs.begin(), needs.end());
  needs.erase(std::unique(needs.begin(), needs.end()), needs.end());
  needs_.resize(cells);
  for (const auto& [n, c] : needs) needs_[n].push_back(c);
  vertical_ = group(vertical, cells, vertical_in_);
  horizontal_ = group(horizontal, cells, horizontal_in_);
}

CellId CornerExchange::owner(int x, int y) const {
  return layout_.owner({std::min(x, width_ - 1), std::min(y, height_ - 1)}).cell;
}

std::vector<CornerIndex> CornerExchange::owned_corners(CellId cell) const {
  const CellWindow& w = layout_.window(cell);
  std::vector<CornerIndex> out;
  out.reserve(w.pixel_count());
  for (int k = 0; k < w.pixel_count(); ++k) {
    const ScreenPixel p = w.screen_pixel(k);
    const bool last_x = p.x == width_ - 1, last_y = p.y == height_ - 1;
    out.push_back(index(p.x, p.y));
    if (last_x) out.push_back(index(p.x + 1, p.y));
    if (last_y) out.push_back(index(p.x, p.y + 1));
    if (last_x && last_y) out.push_back(index(p.x + 1, p.y + 1));
  }
  return out;
}

}  // namespace capsim::sim
