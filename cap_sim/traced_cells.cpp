#include "traced_cells.h"

#include "capsim/progress.h"

#include <fmt/core.h>
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <array>
#include <atomic>
#include <optional>

namespace capsim::sim {

namespace {

// A cell's pixel costs summed exactly: 128-bit counters cannot overflow for
// fewer than 2^64 pixels, so whether a cell's work fits Cycles is decided once,
// on the true sums, and does not depend on how rows were spread over threads.
struct WideBreakdown {
  std::array<unsigned __int128, kCostCategories> cycles{};

  void add(const CostBreakdown& b) {
    for (int i = 0; i < kCostCategories; ++i) cycles[i] += b.cycles[i].count();
  }
  void add(const WideBreakdown& b) {
    for (int i = 0; i < kCostCategories; ++i) cycles[i] += b.cycles[i];
  }
  unsigned __int128 total() const {
    unsigned __int128 sum = 0;
    for (unsigned __int128 c : cycles) sum += c;
    return sum;
  }
};

// The first pixel, in screen order, whose cost overflowed on one host thread.
struct PixelOverflow {
  std::uint64_t screen_index = 0;
  ScreenPixel pixel;
  CycleOverflow error;
};

std::string cell_name(const WindowLayout& layout, CellId c) {
  const CellPosition p = layout.grid().position(c);
  return fmt::format("cell[{},{}]", p.row, p.col);
}

}  // namespace

std::vector<TracedCell> trace_cells(const Tracer& tracer, const WindowLayout& layout,
                                    const CellCosts& costs, int threads, Progress* progress) {
  const int cell_count = layout.grid().cell_count();
  std::vector<TracedCell> cells(cell_count);
  for (CellId c = 0; c < cell_count; ++c) {
    const int n = layout.window(c).pixel_count();
    cells[c].samples = Framebuffer(n, 1);
    cells[c].pixel_cycles.resize(n);
  }
  // Pixels are traced in screen order, row by row as `capsim render` traces
  // them (neighbouring rays share voxels and primitives in the caches), and each
  // sample goes to the video-memory slot of the cell whose window shows it.
  // Per-cell sums are kept per host thread and added at the end: exact integer
  // sums, so the totals do not depend on how rows were spread over threads.
  struct Sums {
    std::vector<WideBreakdown> work;
    std::vector<std::uint64_t> rays;
    std::optional<PixelOverflow> overflow;
  };
  tbb::enumerable_thread_specific<Sums> sums([&] {
    return Sums{std::vector<WideBreakdown>(cell_count), std::vector<std::uint64_t>(cell_count, 0),
                std::nullopt};
  });
  tbb::enumerable_thread_specific<Tracer::Scratch> scratch(
      [&] { return Tracer::Scratch(tracer.scene()); });
  // A pixel whose cost overflows stops the work after it in screen order, never
  // before it: every pixel ahead of the first overflow is costed, so the one
  // reported is the first in screen order on any thread count.
  std::atomic<std::uint64_t> first_overflow{UINT64_MAX};
  const auto width = static_cast<std::uint64_t>(layout.width());
  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<int>(0, layout.height()), [&](const tbb::blocked_range<int>& rows) {
      Tracer::Scratch& s = scratch.local();
      Sums& sum = sums.local();
      for (int y = rows.begin(); y != rows.end(); ++y) {
        for (int x = 0; x < layout.width(); ++x) {
          const std::uint64_t index = static_cast<std::uint64_t>(y) * width + x;
          if (index > first_overflow.load(std::memory_order_relaxed)) break;
          const PixelOwner owner = layout.owner({x, y});
          OpCounts ops;
          const PixelSample px = tracer.trace_pixel(x, y, s, ops);
          TracedCell& out = cells[owner.cell];
          out.samples.set(owner.video_index, 0, px);
          try {
            const CostBreakdown cost = pixel_cost(ops, costs);
            out.pixel_cycles[owner.video_index] = cost.total().count();
            sum.work[owner.cell].add(cost);
          } catch (const CycleOverflow& e) {
            if (!sum.overflow || index < sum.overflow->screen_index)
              sum.overflow = PixelOverflow{index, {x, y}, e};
            std::uint64_t seen = first_overflow.load(std::memory_order_relaxed);
            while (index < seen && !first_overflow.compare_exchange_weak(seen, index)) {}
          }
          sum.rays[owner.cell] += ops.rays;
        }
      }
      if (progress) progress->advance(static_cast<std::uint64_t>(rows.size()) * layout.width());
    });
  });

  const PixelOverflow* first = nullptr;
  for (const Sums& sum : sums)
    if (sum.overflow && (!first || sum.overflow->screen_index < first->screen_index))
      first = &*sum.overflow;
  if (first) {
    const CellId c = layout.owner(first->pixel).cell;
    throw first->error.inside(fmt::format("pixel ({}, {}) of {}", first->pixel.x, first->pixel.y,
                                          cell_name(layout, c)));
  }

  std::vector<WideBreakdown> work(cell_count);
  for (const Sums& sum : sums)
    for (CellId c = 0; c < cell_count; ++c) {
      work[c].add(sum.work[c]);
      cells[c].rays += sum.rays[c];
    }
  for (CellId c = 0; c < cell_count; ++c) {
    // The total bounds every category: when it fits, so does each of them.
    const unsigned __int128 total = work[c].total();
    if (total > Cycles::kMax)
      throw CycleOverflow(fmt::format("{}'s work for its {} pixels adds up to {} cycles",
                                      cell_name(layout, c), layout.window(c).pixel_count(), total));
    for (int i = 0; i < kCostCategories; ++i)
      cells[c].work.cycles[i] = Cycles(static_cast<std::uint64_t>(work[c].cycles[i]));
  }
  return cells;
}

}  // namespace capsim::sim
