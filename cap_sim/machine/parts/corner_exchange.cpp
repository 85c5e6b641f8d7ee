#include "machine/parts/corner_exchange.h"

#include "capsim/trace/antialias.h"

#include <algorithm>
#include <stdexcept>
#include <tuple>

namespace capsim::sim {

namespace {

// The messages each cell sends in one step while they are planned. Corner c
// goes to the message from `from` to `to` unless it was the last corner added
// there (a corner reaches a relaying cell once, for every cell it relays it
// to). A sender's consecutive corners mostly go to the destination of its last
// one, so that message is tried before the search of its few others.
class StepPlan {
 public:
  explicit StepPlan(std::vector<std::vector<CornerMessage>>& sends) : sends_(sends), last_(sends.size(), 0) {}
  void add(CellId from, CellId to, CornerIndex c) {
    std::vector<CornerMessage>& out = sends_[from];
    std::size_t& k = last_[from];
    if (k >= out.size() || out[k].to != to) {
      k = static_cast<std::size_t>(
          std::find_if(out.begin(), out.end(), [to](const CornerMessage& x) { return x.to == to; }) - out.begin());
      if (k == out.size()) out.push_back({from, to, {}});
    }
    std::vector<CornerIndex>& corners = out[k].corners;
    if (corners.empty() || corners.back() != c) corners.push_back(c);
  }

 private:
  std::vector<std::vector<CornerMessage>>& sends_;
  std::vector<std::size_t> last_;
};

// Each cell's messages in order of destination; counts what each cell receives.
void finish(std::vector<std::vector<CornerMessage>>& sends, std::vector<int>& receives) {
  receives.assign(sends.size(), 0);
  for (auto& out : sends) {
    std::sort(out.begin(), out.end(), [](const CornerMessage& a, const CornerMessage& b) { return a.to < b.to; });
    for (const CornerMessage& m : out) ++receives[m.to];
  }
}

// Calls need(x, y, owner, needer) for every corner (x, y) of a frame and every
// cell other than the corner's owner that needs it: the cells of the pixels
// whose right, lower or lower-right corner it is. Corner by corner, in
// ascending order, and for each corner its needers in ascending order, each
// once, so that lists built from the calls come out ascending with no sort.
template <class Need>
void for_each_need(const WindowLayout& layout, Need need) {
  const int width = layout.width(), height = layout.height();
  const OwnerTable owners(layout);
  auto pixel_owner = [&](int x, int y) { return owners.owner(x, y).cell; };
  for (int y = 0; y <= height; ++y)
    for (int x = 0; x <= width; ++x) {
      const CornerPixel p = corner_pixel(x, y, width, height);
      const CellId o = pixel_owner(p.x, p.y);
      CellId needers[3];
      int count = 0;
      auto add_needer = [&](int px, int py) {
        if (px < 0 || py < 0 || px >= width || py >= height) return;
        const CellId n = pixel_owner(px, py);
        if (n == o || std::find(needers, needers + count, n) != needers + count) return;
        needers[count++] = n;
      };
      add_needer(x - 1, y - 1);
      add_needer(x, y - 1);
      add_needer(x - 1, y);
      // In ascending order, by insertion: at most three. (std::sort here makes
      // GCC 12 warn of subscripts past the array it cannot bound.)
      for (int i = 1; i < count; ++i)
        for (int j = i; j > 0 && needers[j] < needers[j - 1]; --j) std::swap(needers[j], needers[j - 1]);
      for (int i = 0; i < count; ++i) need(x, y, o, needers[i]);
    }
}

}  // namespace

// Counts the needs for_each_need would name, by the owners' split into a row
// part R[y] and a column part K[x] (OwnerTable): pixels share an owner
// exactly when both parts agree. Call a row y "split" when R[y - 1] != R[y],
// a column x when K[x - 1] != K[x]. An inner corner (0 < x < W, 0 < y < H),
// owned by (x, y), is needed by the owners of (x - 1, y - 1), (x, y - 1) and
// (x - 1, y) that are not its own:
//   row and column split: all three, each a different cell;
//   only the row split:   (x, y - 1);
//   only the column:      (x - 1, y);
//   neither:              none.
// So the owner of (x, y - 1) needs it where the row splits, whatever the
// column, the owner of (x - 1, y) where the column splits, and that of
// (x - 1, y - 1) where both do: each a product of a count over the rows and
// one over the columns. On the screen's edge only one pixel besides the
// owner touches a corner: (x - 1, 0) on the top row, (0, y - 1) on the left
// column, (W - 1, y - 1) on the right column (owned by (W - 1, y)) and
// (x - 1, H - 1) on the bottom row (owned by (x, H - 1)), each needing it
// where its row or column splits. The four screen corners touch only their
// owner's pixel.
std::vector<std::uint64_t> corners_needed(const WindowLayout& layout) {
  const int width = layout.width(), height = layout.height();
  const int cells = layout.grid().cell_count();
  const OwnerTable owners(layout);
  const auto R = [&](int y) { return owners.row_cell(y); };
  const auto K = [&](int x) { return owners.col_cell(x); };
  const auto row_split = [&](int y) { return R(y - 1) != R(y); };
  const auto col_split = [&](int x) { return K(x - 1) != K(x); };
  std::vector<std::uint64_t> out(static_cast<std::size_t>(cells), 0);

  // Counts by part over the inner rows and columns: all of them, and the
  // split ones by the part before the split.
  std::vector<std::uint64_t> rows_all(static_cast<std::size_t>(cells), 0), rows_split(rows_all.size(), 0);
  std::vector<std::uint64_t> cols_all(static_cast<std::size_t>(cells), 0), cols_split(cols_all.size(), 0);
  for (int y = 1; y < height; ++y) {
    ++rows_all[R(y)];
    if (row_split(y)) ++rows_split[R(y - 1)];
  }
  for (int x = 1; x < width; ++x) {
    ++cols_all[K(x)];
    if (col_split(x)) ++cols_split[K(x - 1)];
  }
  // The parts that occur, for the products.
  std::vector<int> row_parts, col_parts;
  for (int r = 0; r < cells; ++r)
    if (rows_all[r] || rows_split[r]) row_parts.push_back(r);
  for (int k = 0; k < cells; ++k)
    if (cols_all[k] || cols_split[k]) col_parts.push_back(k);
  for (const int r : row_parts)
    for (const int k : col_parts) {
      std::uint64_t& n = out[static_cast<std::size_t>(r + k)];
      n += rows_split[r] * cols_all[k];    // (x, y - 1), where the row splits
      n += rows_all[r] * cols_split[k];    // (x - 1, y), where the column splits
      n += rows_split[r] * cols_split[k];  // (x - 1, y - 1), where both do
    }
  // The edges.
  for (int x = 1; x < width; ++x)
    if (col_split(x)) {
      ++out[R(0) + K(x - 1)];           // top row
      ++out[R(height - 1) + K(x - 1)];  // bottom row
    }
  for (int y = 1; y < height; ++y)
    if (row_split(y)) {
      ++out[R(y - 1) + K(0)];          // left column
      ++out[R(y - 1) + K(width - 1)];  // right column
    }
  return out;
}

CornerExchange::CornerExchange(std::vector<const WindowLayout*> frames, int first_frame)
    : frames_(std::move(frames)),
      first_frame_(first_frame),
      width_(frames_.at(0)->width()),
      height_(frames_.at(0)->height()),
      corners_per_frame_(static_cast<CornerIndex>(width_ + 1) * static_cast<CornerIndex>(height_ + 1)) {
  const CellGrid& grid = frames_[0]->grid();
  const int cells = grid.cell_count();
  needs_.resize(cells);
  vertical_.resize(cells);
  horizontal_.resize(cells);
  // Each cell's row and column, looked up rather than divided out per corner.
  std::vector<int> row_start(static_cast<std::size_t>(cells)), col(row_start.size());
  for (CellId c = 0; c < cells; ++c) {
    row_start[c] = grid.id({grid.position(c).row, 0});
    col[c] = grid.position(c).col;
  }
  // Each cell's needed corners over all the frames, so that its list is
  // allocated once.
  std::vector<std::uint64_t> needed(row_start.size(), 0);
  for (const WindowLayout* layout : frames_) {
    if (layout->width() != width_ || layout->height() != height_ || !(layout->grid() == grid))
      throw std::logic_error("the frames of one exchange need one screen size and cell grid");
    const std::vector<std::uint64_t> in_frame = corners_needed(*layout);
    for (CellId c = 0; c < cells; ++c) needed[c] += in_frame[c];
  }
  for (CellId c = 0; c < cells; ++c) needs_[c].reserve(needed[c]);
  StepPlan vertical(vertical_), horizontal(horizontal_);
  for (std::size_t f = 0; f < frames_.size(); ++f) {
    for_each_need(*frames_[f], [&](int x, int y, CellId o, CellId n) {
      const CornerIndex c = index(first_frame_ + static_cast<int>(f), x, y);
      needs_[n].push_back(c);
      const CellId m = row_start[n] + col[o];
      if (m != o) vertical.add(o, m, c);
      if (m != n) horizontal.add(m, n, c);
    });
  }
  finish(vertical_, vertical_in_);
  finish(horizontal_, horizontal_in_);
}

CellId CornerExchange::owner(CornerIndex corner) const {
  const CornerIndex f = corner / corners_per_frame_ - static_cast<CornerIndex>(first_frame_);
  const CornerIndex k = corner % corners_per_frame_;
  const int x = static_cast<int>(k % static_cast<CornerIndex>(width_ + 1));
  const int y = static_cast<int>(k / static_cast<CornerIndex>(width_ + 1));
  const CornerPixel p = corner_pixel(x, y, width_, height_);
  return frames_[f]->owner({p.x, p.y}).cell;
}

}  // namespace capsim::sim
