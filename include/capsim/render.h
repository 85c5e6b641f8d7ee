#pragma once
// Renders every pixel of a prepared scene with the tracer (host threads via TBB;
// the result does not depend on the thread count).

#include "capsim/antialias.h"
#include "capsim/progress.h"
#include "capsim/tracer.h"

#include <cstdint>
#include <functional>
#include <span>
#include <vector>

namespace capsim {

struct Framebuffer {
  int width = 0, height = 0;
  std::vector<float> rgba;   // linear, 4 floats per pixel, row 0 at the top
  std::vector<float> depth;  // distance from the eye to the visible surface; +inf on a miss
  std::vector<float> id;     // 0-based visible primitive index in file order; -1 on a miss

  Framebuffer() = default;
  Framebuffer(int w, int h);
  void set(int i, int j, const PixelSample& s);

  // The bytes the buffers of a w x h framebuffer hold.
  static std::uint64_t bytes(int w, int h);
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
// antialiased from the screen's corner samples (capsim/antialias.h).
void render_rows(const Tracer& tracer, int threads, const RowSink& store,
                 RenderStats* stats = nullptr, Progress* progress = nullptr,
                 const AntialiasOptions& aa = {});

// render_rows into a Framebuffer.
Framebuffer render(const Tracer& tracer, int threads, RenderStats* stats = nullptr,
                   Progress* progress = nullptr, const AntialiasOptions& aa = {});

// The units a render's progress counts: its pixels, and its corner samples when
// antialiasing.
std::uint64_t render_work(int width, int height, const AntialiasOptions& aa);

// Receives the operations each corner sample cost; called from several host
// threads at once, for different corner rows.
using CornerCostSink = std::function<void(int x, int y, const OpCounts& ops)>;

// Every corner sample of the screen, traced on host threads (the result does
// not depend on their number); progress, if given, advances by each corner.
CornerSamples trace_corners(const Tracer& tracer, int threads, const CornerCostSink& cost,
                            Progress* progress);

}  // namespace capsim
