#include "traced_screen.h"

#include "progress.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

namespace capsim::sim {

TracedScreen trace_screen(const Tracer& tracer, const CellCosts& costs, int threads,
                          Progress* progress) {
  const Camera& cam = tracer.scene().camera;
  TracedScreen screen{Framebuffer(cam.width, cam.height),
                      std::vector<PixelWork>(static_cast<std::size_t>(cam.width) * cam.height)};
  tbb::enumerable_thread_specific<Tracer::Scratch> scratch(
      [&] { return Tracer::Scratch(tracer.scene()); });
  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<int>(0, cam.height), [&](const tbb::blocked_range<int>& rows) {
      Tracer::Scratch& s = scratch.local();
      for (int j = rows.begin(); j != rows.end(); ++j) {
        for (int i = 0; i < cam.width; ++i) {
          const PixelSample px = tracer.trace_pixel(i, j, s);
          screen.image.set(i, j, px);
          PixelWork& w = screen.work[static_cast<std::size_t>(j) * cam.width + i];
          w.cost = pixel_cost(px.ops, costs);
          w.rays = px.ops.rays;
        }
        if (progress) progress->advance(static_cast<std::uint64_t>(cam.width));
      }
    });
  });
  return screen;
}

}  // namespace capsim::sim
