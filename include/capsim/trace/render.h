#pragma once
// Renders every pixel of a prepared scene with the tracer (host threads via TBB;
// the result does not depend on the thread count).

#include "capsim/image/framebuffer.h"
#include "capsim/system/progress.h"
#include "capsim/trace/antialias.h"
#include "capsim/trace/tracer.h"

#include <algorithm>
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace capsim {

// Stores a traced sample as pixel (i, j) of fb.
void set_pixel(Framebuffer& fb, int i, int j, const PixelSample& s);

// One row of samples' colours as 8-bit sRGB, 3 bytes per sample, as the PNG
// output encodes them; rgb holds 3 * row.size() bytes.
void encode_srgb8_row(std::span<const PixelSample> row, unsigned char* rgb);

// What a host thread keeps from one row to the next while tracing rows: the
// tracer's scratch and room for a row of rays, made together
// (Tracer::primary_rays, Tracer::corner_rays).
struct RowWorkspace {
  RowWorkspace(const Tracer& tracer, int rays) : scratch(tracer.scene()), rays(static_cast<std::size_t>(rays)) {}
  Tracer::Scratch scratch;
  std::vector<Ray> rays;
};

// A RowWorkspace whose rays are shaded as one row (Tracer::shade_primary_row),
// each ray's operation counts kept on their own: room for the row's samples
// and counts.
struct ShadedRowWorkspace : RowWorkspace {
  ShadedRowWorkspace(const Tracer& tracer, int rays)
      : RowWorkspace(tracer, rays), samples(static_cast<std::size_t>(rays)), ops(static_cast<std::size_t>(rays)) {}
  // Shades the rays made last into out (samples, or a row of the caller's),
  // ops[i] counting ray i's operations from zero.
  // Precondition: out.size() == rays.size().
  void shade(const Tracer& tracer, std::span<PixelSample> out) {
    std::fill(ops.begin(), ops.end(), OpCounts{});
    tracer.shade_primary_row(rays, out, scratch, ops);
  }
  std::vector<PixelSample> samples;
  std::vector<OpCounts> ops;
};

struct RenderStats {
  OpCounts ops;  // summed over every pixel
};

// Receives each finished row j of the image, its samples in column order. Called
// from several host threads at once, for different rows, in no set order.
using RowSink = std::function<void(int j, std::span<const PixelSample> row)>;

// Traces every pixel of the camera's image and hands the rows to store. Callers
// that need only part of a sample (an 8-bit image, say) keep only that part,
// rather than a whole Framebuffer. threads: 0 = all hardware threads. stats, if
// given, receives the summed counts (equal for any thread count); progress, if
// given, advances by render_work(...) in all. With aa.depth >= 1 every pixel is
// antialiased from the screen's corner samples (capsim/trace/antialias.h).
void render_rows(const Tracer& tracer, int threads, const RowSink& store,
                 RenderStats* stats = nullptr, Progress* progress = nullptr,
                 const AntialiasOptions& aa = {});

// render_rows into a Framebuffer.
Framebuffer render(const Tracer& tracer, int threads, RenderStats* stats = nullptr,
                   Progress* progress = nullptr, const AntialiasOptions& aa = {});

// The units a render's progress counts: its pixels, and its corner samples when
// antialiasing.
std::uint64_t render_work(int width, int height, const AntialiasOptions& aa);

// Receives the operations each corner sample of row y cost, row[x] for
// corner (x, y); called once per row, from several host threads at once for
// different rows.
using CornerCostSink = std::function<void(int y, std::span<const OpCounts> row)>;

// Every corner sample of the screen, traced on host threads (the result does
// not depend on their number); progress, if given, advances by each corner.
CornerSamples trace_corners(const Tracer& tracer, int threads, const CornerCostSink& cost,
                            Progress* progress);

}  // namespace capsim
