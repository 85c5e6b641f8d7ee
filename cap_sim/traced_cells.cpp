#include "traced_cells.h"

#include "capsim/progress.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <array>
#include <atomic>

namespace capsim::sim {

std::vector<TracedCell> trace_cells(const Tracer& tracer, const WindowLayout& layout,
                                    const CellCosts& costs, int threads, Progress* progress) {
  const int cell_count = layout.grid().cell_count();
  std::vector<TracedCell> cells(cell_count);
  for (CellId c = 0; c < cell_count; ++c) {
    const int n = layout.window(c).pixel_count();
    cells[c].samples = Framebuffer(n, 1);
    cells[c].pixel_cycles.resize(n);
  }
  // Per-cell sums, added to from several threads: integer sums, so the totals do
  // not depend on the order of the additions.
  struct Sums {
    std::array<std::atomic<std::uint64_t>, kCostCategories> work{};
    std::atomic<std::uint64_t> rays{0};
  };
  std::vector<Sums> sums(cell_count);
  tbb::enumerable_thread_specific<Tracer::Scratch> scratch(
      [&] { return Tracer::Scratch(tracer.scene()); });
  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
  arena.execute([&] {
    tbb::parallel_for(0, cell_count, [&](CellId c) {
      const CellWindow& window = layout.window(c);
      TracedCell& out = cells[c];
      tbb::parallel_for(tbb::blocked_range<int>(0, window.pixel_count(), 256),
                        [&](const tbb::blocked_range<int>& ks) {
                          Tracer::Scratch& s = scratch.local();
                          CostBreakdown work;
                          std::uint64_t rays = 0;
                          for (int k = ks.begin(); k != ks.end(); ++k) {
                            const ScreenPixel p = window.screen_pixel(k);
                            const PixelSample px = tracer.trace_pixel(p.x, p.y, s);
                            out.samples.set(k, 0, px);
                            const CostBreakdown cost = pixel_cost(px.ops, costs);
                            out.pixel_cycles[k] = cost.total().count();
                            work += cost;
                            rays += px.ops.rays;
                          }
                          for (int i = 0; i < kCostCategories; ++i)
                            sums[c].work[i].fetch_add(work.cycles[i].count(), std::memory_order_relaxed);
                          sums[c].rays.fetch_add(rays, std::memory_order_relaxed);
                          if (progress) progress->advance(static_cast<std::uint64_t>(ks.size()));
                        });
    });
  });
  for (CellId c = 0; c < cell_count; ++c) {
    for (int i = 0; i < kCostCategories; ++i) cells[c].work.cycles[i] = Cycles(sums[c].work[i].load());
    cells[c].rays = sums[c].rays.load();
  }
  return cells;
}

}  // namespace capsim::sim
