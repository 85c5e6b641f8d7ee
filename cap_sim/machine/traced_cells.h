#pragma once
// The tracing the cells will do, computed ahead of the event loop by host threads
// (tracing is pure, so the result does not depend on the thread count): every
// pixel's sample and its cost on a cell, grouped by the cell whose window shows
// it, in that cell's video-memory order (traced in screen order, as render does). The event loop then decides, in
// simulated time, when each cell does that work and writes its video memory.

#include "machine/costs/cost_profile.h"
#include "machine/packed_op_counts.h"
#include "machine/parts/window_controller.h"

#include "capsim/system/progress.h"
#include "capsim/trace/antialias.h"
#include "capsim/trace/render.h"
#include "capsim/trace/tracer.h"

#include <cstdint>
#include <vector>

namespace capsim::sim {

// What the screen, and so every video memory, holds: float samples with depth
// and primitive id and each pixel's cycles (for an EXR), or only the 8-bit sRGB
// colour a PNG shows (3 bytes a pixel, which keeps a PNG-only run's memory near
// a render's).
enum class ScreenFormat { Float, Srgb8 };

// One cell's pixels, traced: pixel k of its window at samples (k, 0) (or at
// srgb8[3k .. 3k+2]), costing pixel_cycles[k] on a cell (Float only); work and
// rays are the sums over all its pixels.
// Antialiased, a pixel's cycles are those of the corners it owns (phase 1) and
// of its subdivision (phase 3), and work = corner_work + subdivision_work.
struct TracedCell {
  Framebuffer samples;  // as Framebuffer::set stores them (Float)
  std::vector<unsigned char> srgb8;  // as the PNG output encodes them (Srgb8)
  std::vector<std::uint64_t> pixel_cycles;  // (Float)
  CostBreakdown work;  // pixel_cost() summed over the cell's pixels
  std::uint64_t rays = 0;
  OpCounts ops;  // the operations work charges for (rays = ops.rays)
  // Antialiasing only.
  CostBreakdown corner_work;               // phase 1: tracing its corners (CornerTracing)
  OpCounts corner_ops;                     // and its operations
  CostBreakdown subdivision_work;          // phase 3: its pixels' subdivision
  std::vector<std::uint32_t> pixel_samples;  // primary samples traced per pixel (Float)
  // Kept only when asked (trace_cells' keep_write_cycles), in either format: per
  // pixel, the cycles of the step that writes it into video memory, its tracing
  // (antialiased, its subdivision in phase 3). They add up to work.total()
  // (antialiased, to subdivision_work.total()).
  std::vector<std::uint64_t> write_cycles;
  // Kept only when asked (trace_cells' chunk_pixels), stealing: per chunk of
  // the window (balance.h), the work a chunk takes wherever it is traced (its
  // tracing; antialiased, its subdivision in phase 3) and its operations.
  // They add up to work and ops (antialiased, to subdivision_work and phase
  // 3's share of ops).
  std::vector<CostBreakdown> chunk_work;
  std::vector<OpCounts> chunk_ops;
};

// Antialiased, who traces a corner sample (phase 1): the window that owns it
// (its pixel's, corner_pixel), which the others get it from over the links;
// or every window with a pixel it is a corner of, each tracing it on its own
// (a tile balanced on demand, which has no neighbour to take it from).
enum class CornerTracing { ByOwner, ByEveryWindowThatNeedsIt };

// One entry per cell of the layout. threads: 0 = all hardware threads.
// progress may be null; it advances by render_work(width, height, aa).
// keep_write_cycles: fill TracedCell::write_cycles. chunk_pixels > 0: fill
// TracedCell::chunk_work and chunk_ops for chunks of that many pixels.
std::vector<TracedCell> trace_cells(const Tracer& tracer, const WindowLayout& layout,
                                    const CostTable& costs, int threads, Progress* progress,
                                    const AntialiasOptions& aa = {},
                                    ScreenFormat format = ScreenFormat::Float, bool keep_write_cycles = false,
                                    CornerTracing corners = CornerTracing::ByOwner, int chunk_pixels = 0);

// A screen traced once, to be laid out on any cells: every pixel's sample and
// operations (antialiased, its subdivision's, and every corner sample with its
// operations), in screen order. Runs that differ only in how the cells share
// the screen (cells, mode, balance, profile) trace the same pixels: laying out
// this trace gives each the cells trace_cells gives, to the bit, without
// tracing again. It holds a sample, 3 bytes of its 8-bit encoding and packed
// operation counts per pixel (antialiased, also per corner). The tracer must
// outlive it.
struct ScreenTrace {
  const Tracer* tracer = nullptr;
  AntialiasOptions aa;
  int width = 0, height = 0;
  std::vector<PixelSample> pixels;
  std::vector<unsigned char> srgb8;  // the pixels as an 8-bit screen stores them, 3 bytes each
  PackedOpCounts pixel_ops;
  std::vector<std::uint32_t> subdivision_samples;  // antialiased
  CornerSamples corners;                           // antialiased
  PackedOpCounts corner_ops;                       // antialiased, in corners' order
};

// The tracer's screen (its camera's size) traced with `aa`. threads: 0 = all
// hardware threads; the trace does not depend on it.
ScreenTrace trace_screen(const Tracer& tracer, const AntialiasOptions& aa, int threads);

// trace_cells of the screen's tracer with the screen's antialiasing, from the
// trace. Precondition: layout is of the screen's size.
std::vector<TracedCell> trace_cells(const ScreenTrace& screen, const WindowLayout& layout, const CostTable& costs,
                                    int threads, ScreenFormat format = ScreenFormat::Float,
                                    bool keep_write_cycles = false, CornerTracing corners = CornerTracing::ByOwner,
                                    int chunk_pixels = 0);

}  // namespace capsim::sim
