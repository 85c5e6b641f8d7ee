#include "capsim/render.h"

#include "capsim/host_threads.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

namespace capsim {

Framebuffer::Framebuffer(int w, int h)
    : width(w),
      height(h),
      rgba(static_cast<std::size_t>(w) * h * 4, 0.0f),
      depth(static_cast<std::size_t>(w) * h, std::numeric_limits<float>::infinity()),
      id(static_cast<std::size_t>(w) * h, -1.0f) {}

std::uint64_t Framebuffer::bytes(int w, int h) {
  return static_cast<std::uint64_t>(w) * static_cast<std::uint64_t>(h) * (4 + 1 + 1) * sizeof(float);
}

void Framebuffer::set(int i, int j, const PixelSample& s) {
  const std::size_t k = static_cast<std::size_t>(j) * width + i;
  rgba[4 * k + 0] = static_cast<float>(s.color.x);
  rgba[4 * k + 1] = static_cast<float>(s.color.y);
  rgba[4 * k + 2] = static_cast<float>(s.color.z);
  rgba[4 * k + 3] = s.alpha;
  depth[k] = static_cast<float>(s.depth);
  id[k] = static_cast<float>(s.primitive);
}

void render_rows(const Tracer& tracer, int threads, const RowSink& store, RenderStats* stats,
                 Progress* progress) {
  const Camera& cam = tracer.scene().camera;
  // Per-row counts, summed in row order afterwards: the totals never depend on
  // how rows were spread over threads.
  std::vector<OpCounts> row_ops(cam.height);
  struct Worker {
    Tracer::Scratch scratch;
    std::vector<PixelSample> row;
  };
  tbb::enumerable_thread_specific<Worker> workers(
      [&] { return Worker{Tracer::Scratch(tracer.scene()), std::vector<PixelSample>(cam.width)}; });
  tbb::task_arena arena(host_arena_concurrency(threads));
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<int>(0, cam.height), [&](const tbb::blocked_range<int>& rows) {
      Worker& w = workers.local();
      for (int j = rows.begin(); j != rows.end(); ++j) {
        OpCounts& ops = row_ops[j];
        for (int i = 0; i < cam.width; ++i) w.row[i] = tracer.trace_pixel(i, j, w.scratch, ops);
        store(j, w.row);
      }
      if (progress) progress->advance(static_cast<std::uint64_t>(rows.size()) * cam.width);
    });
  });
  if (stats) {
    stats->ops = {};
    for (const OpCounts& o : row_ops) stats->ops += o;
  }
}

Framebuffer render(const Tracer& tracer, int threads, RenderStats* stats, Progress* progress) {
  const Camera& cam = tracer.scene().camera;
  Framebuffer fb(cam.width, cam.height);
  render_rows(
      tracer, threads,
      [&](int j, std::span<const PixelSample> row) {
        for (int i = 0; i < cam.width; ++i) fb.set(i, j, row[i]);
      },
      stats, progress);
  return fb;
}

}  // namespace capsim
