#include "capsim/trace/render.h"

#include "capsim/image/srgb.h"
#include "capsim/system/host_threads.h"

#include <tbb/blocked_range.h>

namespace capsim {

void set_pixel(Framebuffer& fb, int i, int j, const PixelSample& s) {
  const std::size_t k = static_cast<std::size_t>(j) * fb.width + i;
  fb.rgba[4 * k + 0] = static_cast<float>(s.color.x);
  fb.rgba[4 * k + 1] = static_cast<float>(s.color.y);
  fb.rgba[4 * k + 2] = static_cast<float>(s.color.z);
  fb.rgba[4 * k + 3] = s.alpha;
  fb.depth[k] = static_cast<float>(s.depth);
  fb.id[k] = static_cast<float>(s.primitive);
}

void encode_srgb8_row(std::span<const PixelSample> row, unsigned char* rgb) {
  const Srgb8Encoder& encode = srgb8_encoder();
  for (const PixelSample& px : row) {
    *rgb++ = encode(static_cast<float>(px.color.x));
    *rgb++ = encode(static_cast<float>(px.color.y));
    *rgb++ = encode(static_cast<float>(px.color.z));
  }
}

namespace {

// A row's samples, beside the rays they are traced from.
struct PixelRowWorkspace : RowWorkspace {
  PixelRowWorkspace(const Tracer& tracer, int width) : RowWorkspace(tracer, width), row(width) {}
  std::vector<PixelSample> row;
};


}  // namespace

std::uint64_t render_work(int width, int height, const AntialiasOptions& aa) {
  const std::uint64_t pixels = static_cast<std::uint64_t>(width) * height;
  return aa.depth > 0 ? pixels + static_cast<std::uint64_t>(width + 1) * (height + 1) : pixels;
}

CornerSamples trace_corners(const Tracer& tracer, int threads, const CornerCostSink& cost,
                            Progress* progress) {
  const Camera& cam = tracer.scene().camera;
  CornerSamples corners;
  corners.width = cam.width;
  corners.height = cam.height;
  corners.samples.resize(static_cast<std::size_t>(cam.width + 1) * (cam.height + 1));
  parallel_rows_with(
      threads, cam.height + 1, [&] { return ShadedRowWorkspace(tracer, cam.width + 1); },
      [&](const tbb::blocked_range<int>& rows, ShadedRowWorkspace& w) {
    for (int y = rows.begin(); y != rows.end(); ++y) {
      // trace_screen_sample(tracer, x, y, scratch, ops) for the row's corners,
      // from the rays made already
      tracer.corner_rays(y, w.rays);
      w.shade(tracer, w.samples);
      for (int x = 0; x <= cam.width; ++x)
        corners.samples[corners.index(x, y)] = ScreenSample::from(w.samples[static_cast<std::size_t>(x)]);
      cost(y, w.ops);
    }
    if (progress) progress->advance(static_cast<std::uint64_t>(rows.size()) * (cam.width + 1));
  });
  return corners;
}

void render_rows(const Tracer& tracer, int threads, const RowSink& store, RenderStats* stats,
                 Progress* progress, const AntialiasOptions& aa) {
  const Camera& cam = tracer.scene().camera;
  // Per-row counts, summed in row order afterwards: the totals never depend on
  // how rows were spread over threads.
  std::vector<OpCounts> row_ops(cam.height);
  CornerSamples corners;
  std::vector<OpCounts> corner_row_ops;
  if (aa.depth > 0) {
    corner_row_ops.resize(cam.height + 1);
    corners = trace_corners(
        tracer, threads,
        [&](int y, std::span<const OpCounts> row) {
          for (const OpCounts& ops : row) corner_row_ops[y] += ops;
        },
        progress);
  }
  parallel_rows_with(
      threads, cam.height, [&] { return PixelRowWorkspace(tracer, cam.width); },
      [&](const tbb::blocked_range<int>& rows, PixelRowWorkspace& w) {
    for (int j = rows.begin(); j != rows.end(); ++j) {
      OpCounts& ops = row_ops[j];
      if (aa.depth == 0) {
        tracer.primary_rays(j, w.rays);
        tracer.shade_primary_row(w.rays, w.row, w.scratch, ops);
      } else {
        for (int i = 0; i < cam.width; ++i) {
          const ScreenSample c[4] = {corners.at(i, j), corners.at(i + 1, j), corners.at(i, j + 1),
                                     corners.at(i + 1, j + 1)};
          const AntialiasedPixel p = resolve_pixel(tracer, i, j, c, aa, w.scratch, ops);
          w.row[i] = p.value;
          w.row[i].samples = owned_corner_count(i, j, cam.width, cam.height) + p.subdivision_samples;
        }
      }
      store(j, w.row);
    }
    if (progress) progress->advance(static_cast<std::uint64_t>(rows.size()) * cam.width);
  });
  if (stats) {
    stats->ops = {};
    for (const OpCounts& o : corner_row_ops) stats->ops += o;
    for (const OpCounts& o : row_ops) stats->ops += o;
  }
}

Framebuffer render(const Tracer& tracer, int threads, RenderStats* stats, Progress* progress,
                   const AntialiasOptions& aa) {
  const Camera& cam = tracer.scene().camera;
  Framebuffer fb(cam.width, cam.height);
  render_rows(
      tracer, threads,
      [&](int j, std::span<const PixelSample> row) {
        for (int i = 0; i < cam.width; ++i) set_pixel(fb, i, j, row[i]);
      },
      stats, progress, aa);
  return fb;
}

}  // namespace capsim
