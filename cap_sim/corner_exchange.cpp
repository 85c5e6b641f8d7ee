#include "corner_exchange.h"

#include <algorithm>
#include <stdexcept>
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

CornerExchange::CornerExchange(std::vector<const WindowLayout*> frames, int first_frame)
    : frames_(std::move(frames)),
      first_frame_(first_frame),
      width_(frames_.at(0)->width()),
      height_(frames_.at(0)->height()),
      corners_per_frame_(static_cast<CornerIndex>(width_ + 1) * static_cast<CornerIndex>(height_ + 1)) {
  const CellGrid& grid = frames_[0]->grid();
  const int cells = grid.cell_count();
  std::vector<Leg> vertical, horizontal;
  std::vector<std::pair<CellId, CornerIndex>> needs;
  for (std::size_t f = 0; f < frames_.size(); ++f) {
    const WindowLayout& layout = *frames_[f];
    if (layout.width() != width_ || layout.height() != height_ || !(layout.grid() == grid))
      throw std::logic_error("the frames of one exchange need one screen size and cell grid");
    const OwnerTable owners(layout);
    for (int y = 0; y < height_; ++y)
      for (int x = 0; x < width_; ++x) {
        const CellId n = owners.owner(x, y).cell;
        const int corner_xy[3][2] = {{x + 1, y}, {x, y + 1}, {x + 1, y + 1}};
        for (const auto& [cx, cy] : corner_xy) {
          const CornerIndex c = index(first_frame_ + static_cast<int>(f), cx, cy);
          const CellId o = owner(c);
          if (o == n) continue;
          needs.emplace_back(n, c);
          const CellId m = grid.id({grid.position(n).row, grid.position(o).col});
          if (m != o) vertical.push_back({o, m, c});
          if (m != n) horizontal.push_back({m, n, c});
        }
      }
  }
  std::sort(needs.begin(), needs.end());
  needs.erase(std::unique(needs.begin(), needs.end()), needs.end());
  needs_.resize(cells);
  for (const auto& [n, c] : needs) needs_[n].push_back(c);
  vertical_ = group(vertical, cells, vertical_in_);
  horizontal_ = group(horizontal, cells, horizontal_in_);
}

CellId CornerExchange::owner(CornerIndex corner) const {
  const CornerIndex f = corner / corners_per_frame_ - static_cast<CornerIndex>(first_frame_);
  const CornerIndex k = corner % corners_per_frame_;
  const int x = static_cast<int>(k % static_cast<CornerIndex>(width_ + 1));
  const int y = static_cast<int>(k / static_cast<CornerIndex>(width_ + 1));
  return frames_[f]->owner({std::min(x, width_ - 1), std::min(y, height_ - 1)}).cell;
}

}  // namespace capsim::sim
