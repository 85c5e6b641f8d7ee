#include "traced_cells.h"

#include "capsim/host_threads.h"
#include "capsim/progress.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

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
  // Pixels are traced in screen order, row by row as `capsim render` traces
  // them (neighbouring rays share voxels and primitives in the caches), and each
  // sample goes to the video-memory slot of the cell whose window shows it.
  // Per-cell sums are kept per host thread and added at the end: integer sums,
  // so the totals do not depend on how rows were spread over threads.
  struct Sums {
    std::vector<CostBreakdown> work;
    std::vector<std::uint64_t> rays;
  };
  tbb::enumerable_thread_specific<Sums> sums([&] {
    return Sums{std::vector<CostBreakdown>(cell_count), std::vector<std::uint64_t>(cell_count, 0)};
  });
  tbb::enumerable_thread_specific<Tracer::Scratch> scratch(
      [&] { return Tracer::Scratch(tracer.scene()); });
  tbb::task_arena arena(host_arena_concurrency(threads));
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<int>(0, layout.height()), [&](const tbb::blocked_range<int>& rows) {
      Tracer::Scratch& s = scratch.local();
      Sums& sum = sums.local();
      for (int y = rows.begin(); y != rows.end(); ++y) {
        for (int x = 0; x < layout.width(); ++x) {
          const PixelOwner owner = layout.owner({x, y});
          OpCounts ops;
          const PixelSample px = tracer.trace_pixel(x, y, s, ops);
          TracedCell& out = cells[owner.cell];
          out.samples.set(owner.video_index, 0, px);
          const CostBreakdown cost = pixel_cost(ops, costs);
          out.pixel_cycles[owner.video_index] = cost.total().count();
          sum.work[owner.cell] += cost;
          sum.rays[owner.cell] += ops.rays;
        }
      }
      if (progress) progress->advance(static_cast<std::uint64_t>(rows.size()) * layout.width());
    });
  });
  for (const Sums& sum : sums)
    for (CellId c = 0; c < cell_count; ++c) {
      cells[c].work += sum.work[c];
      cells[c].rays += sum.rays[c];
    }
  return cells;
}

}  // namespace capsim::sim
