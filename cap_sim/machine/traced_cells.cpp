#include "machine/traced_cells.h"

#include "machine/parts/balance.h"

#include "capsim/image/image_io.h"
#include "capsim/system/host_threads.h"
#include "capsim/system/progress.h"

#include <fmt/core.h>

#include <algorithm>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>

namespace capsim::sim {

namespace {

// Per-cell operation counts kept per host thread and added at the end: integer
// sums, so the totals do not depend on how rows were spread over threads. A
// cell's cycles come from its summed counts (work_cost), not pixel by pixel.
// When stealing, each pixel's counts go to its chunk's sum only, and a cell's
// are its chunks' added up (cell_ops).
struct Sums {
  std::vector<OpCounts> ops;
  std::vector<std::uint64_t> items;  // pixels or corner samples written
  std::vector<std::vector<OpCounts>> chunk_ops;  // stealing: per cell, per chunk
  explicit Sums(int cells) : ops(cells), items(cells, 0) {}
  // Stealing: per-chunk sums for chunks of chunk_pixels pixels of each window.
  Sums(const WindowLayout& layout, int chunk_pixels) : Sums(layout.grid().cell_count()) {
    if (chunk_pixels <= 0) return;
    chunk_ops.resize(ops.size());
    for (std::size_t c = 0; c < ops.size(); ++c)
      chunk_ops[c].resize(chunk_count(layout.window(static_cast<CellId>(c)).pixel_count(), chunk_pixels));
  }
  // The sum a pixel's counts are added to.
  OpCounts& of(const PixelOwner& owner, int chunk_pixels) {
    return chunk_pixels > 0 ? chunk_ops[owner.cell][owner.video_index / chunk_pixels] : ops[owner.cell];
  }
  OpCounts cell_ops(CellId c) const {
    if (chunk_ops.empty()) return ops[c];
    OpCounts total;
    for (const OpCounts& chunk : chunk_ops[c]) total += chunk;
    return total;
  }
};

// Stealing: the per-thread chunk sums added into the cells' chunk_ops and
// their work. Precondition: fold found every cell's work to fit, so every
// chunk's does.
void fold_chunks(const tbb::enumerable_thread_specific<Sums>& sums, const WindowLayout& layout, const CostTable& costs,
                 int chunk_pixels, std::vector<TracedCell>& cells) {
  if (chunk_pixels <= 0) return;
  for (CellId c = 0; c < layout.grid().cell_count(); ++c) {
    const int pixels = layout.window(c).pixel_count();
    TracedCell& cell = cells[c];
    cell.chunk_ops.assign(chunk_count(pixels, chunk_pixels), OpCounts());
    for (const Sums& sum : sums)
      for (std::size_t k = 0; k < cell.chunk_ops.size(); ++k) cell.chunk_ops[k] += sum.chunk_ops[c][k];
    cell.chunk_work.clear();
    for (std::size_t k = 0; k < cell.chunk_ops.size(); ++k) {
      const ChunkRange r = chunk_range(static_cast<int>(k), pixels, chunk_pixels);
      cell.chunk_work.push_back(*wide_work_cost(cell.chunk_ops[k], static_cast<std::uint64_t>(r.pixels), costs).narrow());
    }
  }
}

std::string cell_name(const WindowLayout& layout, CellId c) {
  const CellPosition p = layout.grid().position(c);
  return fmt::format("cell[{},{}]", p.row, p.col);
}

// A cell whose work does not fit Cycles: its exact sum, for the message.
struct CellOverflow {
  CellId cell = 0;
  std::uint64_t items = 0;
  unsigned __int128 total = 0;
};

// Adds the per-thread sums into the cells: the work of `items` items whose
// operations add up to ops, decided exactly (128 bits), so whether it fits
// does not depend on how the rows were spread over threads. Returns the first
// cell, in id order, whose work does not fit 64 bits; add is then not called.
template <class Add>
std::optional<CellOverflow> fold(const tbb::enumerable_thread_specific<Sums>& sums, int cell_count,
                                 const CostTable& costs, Add add) {
  std::vector<OpCounts> ops(cell_count);
  std::vector<std::uint64_t> items(cell_count, 0);
  for (const Sums& sum : sums)
    for (CellId c = 0; c < cell_count; ++c) {
      ops[c] += sum.cell_ops(c);
      items[c] += sum.items[c];
    }
  std::vector<CostBreakdown> work(cell_count);
  for (CellId c = 0; c < cell_count; ++c) {
    const WideBreakdown wide = wide_work_cost(ops[c], items[c], costs);
    const std::optional<CostBreakdown> fits = wide.narrow();
    if (!fits) return CellOverflow{c, items[c], wide.total()};
    work[c] = *fits;
  }
  for (CellId c = 0; c < cell_count; ++c) add(c, work[c], ops[c]);
  return std::nullopt;
}

// A cell's work does not fit 64 bits. Names the first pixel in screen order
// whose own cost does not fit (traced again: tracing is pure), or else the
// cell and its exact sum; the same on any thread count.
[[noreturn]] void refuse_overflow(const Tracer& tracer, const WindowLayout& layout, const CostTable& costs,
                                  const CellOverflow& cell, const char* items) {
  Tracer::Scratch scratch(tracer.scene());
  for (int y = 0; y < layout.height(); ++y)
    for (int x = 0; x < layout.width(); ++x) {
      OpCounts ops;
      tracer.trace_pixel(x, y, scratch, ops);
      try {
        (void)pixel_cost(ops, costs).total();
      } catch (const CycleOverflow& e) {
        throw e.inside(fmt::format("pixel ({}, {}) of {}", x, y, cell_name(layout, layout.owner({x, y}).cell)));
      }
    }
  throw CycleOverflow(fmt::format("{}'s work for its {} {} adds up to {} cycles", cell_name(layout, cell.cell),
                                  cell.items, items, cell.total));
}

// One item's cycles for a float screen's per-pixel channel, at most
// Cycles::kMax; a cost beyond that makes its cell's sum overflow too, which
// fold refuses.
std::uint64_t saturated_cycles(const OpCounts& ops, const CostTable& costs) {
  const unsigned __int128 total = wide_work_cost(ops, 1, costs).total();
  return total > Cycles::kMax ? Cycles::kMax : static_cast<std::uint64_t>(total);
}

// Video memories of the right size and format for every cell.
std::vector<TracedCell> empty_cells(const WindowLayout& layout, ScreenFormat format, bool antialiased,
                                    bool keep_write_cycles) {
  std::vector<TracedCell> cells(layout.grid().cell_count());
  for (CellId c = 0; c < layout.grid().cell_count(); ++c) {
    const int n = layout.window(c).pixel_count();
    if (keep_write_cycles) cells[c].write_cycles.resize(n);
    if (format == ScreenFormat::Srgb8) {
      cells[c].srgb8.resize(static_cast<std::size_t>(n) * 3);
      continue;
    }
    cells[c].samples = Framebuffer(n, 1);
    cells[c].pixel_cycles.resize(n);
    if (antialiased) cells[c].pixel_samples.resize(n);
  }
  return cells;
}

// Stores pixel k of a cell's video memory in its format. srgb8: the pixel's
// 8-bit encoding when it is known already, else null.
void store(TracedCell& cell, int k, const PixelSample& px, ScreenFormat format, const unsigned char* srgb8) {
  if (format == ScreenFormat::Float) {
    set_pixel(cell.samples, k, 0, px);
    return;
  }
  unsigned char* out = cell.srgb8.data() + static_cast<std::size_t>(k) * 3;
  if (srgb8)
    std::copy(srgb8, srgb8 + 3, out);
  else
    encode_srgb8_row({&px, 1}, out);
}

// Whether a pixel's operations matter only in the sums (its cell's, or its
// chunk's when stealing), which the tracer may then add them to directly: no
// float screen keeps the pixel's own cycles and no write cycles are kept.
bool only_sums(ScreenFormat format, bool keep_write_cycles) {
  return format != ScreenFormat::Float && !keep_write_cycles;
}

// A row of corner samples' operation counts, as the tracer hands them on and
// as a screen traced ahead keeps them: add_to(x, sum) adds corner x's.
struct CountsRow {
  std::span<const OpCounts> ops;
  void add_to(std::size_t x, OpCounts& sum) const { sum += ops[x]; }
  const OpCounts& at(std::size_t x) const { return ops[x]; }
};
struct PackedRow {
  const PackedOpCounts& ops;
  std::size_t first;  // the row's first corner
  void add_to(std::size_t x, OpCounts& sum) const { ops.add_to(first + x, sum); }
  OpCounts at(std::size_t x) const { return ops.at(first + x); }
};

// Where trace_cells' samples and operations come from: the tracer, tracing
// them now, or a screen it traced ahead (ScreenTrace), which holds the same
// samples and counts. Either gives the same cells to the bit.
struct TracingNow {
  const Tracer& tracer;
  // A thread's rows of rays, samples and counts, a row of the screen long.
  using Workspace = ShadedRowWorkspace;
  Workspace workspace(int width) const { return ShadedRowWorkspace(tracer, width); }
  // Row y's pixels: trace them all into w.
  void row(int y, Workspace& w) const {
    tracer.primary_rays(y, w.rays);
    w.shade(tracer, w.samples);
  }
  // Pixel (x, y) of the row traced last into w; its operations are added to ops.
  PixelSample pixel(const Workspace& w, int x, int, OpCounts& ops) const {
    ops += w.ops[static_cast<std::size_t>(x)];
    return w.samples[static_cast<std::size_t>(x)];
  }
  const unsigned char* srgb8(int, int) const { return nullptr; }
  template <class RowCost>
  CornerSamples corners(int threads, const RowCost& cost, Progress* progress) const {
    return trace_corners(
        tracer, threads, [&](int y, std::span<const OpCounts> row) { cost(y, CountsRow{row}); }, progress);
  }
  AntialiasedPixel resolve(int x, int y, const ScreenSample c[4], const AntialiasOptions& aa, Tracer::Scratch& s,
                           OpCounts& ops) const {
    return resolve_pixel(tracer, x, y, c, aa, s, ops);
  }
};

struct TracedAhead {
  const ScreenTrace& screen;
  std::size_t at(int x, int y) const { return static_cast<std::size_t>(y) * screen.width + x; }
  // Nothing to trace: the samples are the screen's.
  struct Workspace {};
  Workspace workspace(int) const { return {}; }
  void row(int, Workspace&) const {}
  PixelSample pixel(const Workspace&, int x, int y, OpCounts& ops) const {
    screen.pixel_ops.add_to(at(x, y), ops);
    return screen.pixels[at(x, y)];
  }
  const unsigned char* srgb8(int x, int y) const { return screen.srgb8.data() + at(x, y) * 3; }
  // The corners' costs handed on in row order, on this thread.
  template <class RowCost>
  CornerSamples corners(int, const RowCost& cost, Progress* progress) const {
    for (int y = 0; y <= screen.height; ++y) cost(y, PackedRow{screen.corner_ops, screen.corners.index(0, y)});
    if (progress) progress->advance(static_cast<std::uint64_t>(screen.width + 1) * (screen.height + 1));
    return screen.corners;
  }
  AntialiasedPixel resolve(int x, int y, const ScreenSample*, const AntialiasOptions&, Tracer::Scratch&,
                           OpCounts& ops) const {
    screen.pixel_ops.add_to(at(x, y), ops);
    return {screen.pixels[at(x, y)], static_cast<int>(screen.subdivision_samples[at(x, y)])};
  }
};

// Antialiased: every corner sample traced and charged to the cell that owns it
// (phase 1), then every pixel resolved from its corners and charged to its
// cell (phase 3).
template <class Source>
std::vector<TracedCell> trace_cells_antialiased(const Source& source, const Tracer& tracer, const WindowLayout& layout,
                                                const CostTable& costs, int threads,
                                                Progress* progress, const AntialiasOptions& aa,
                                                ScreenFormat format, bool keep_write_cycles,
                                                CornerTracing tracing, int chunk_pixels) {
  const int cell_count = layout.grid().cell_count();
  const int width = layout.width(), height = layout.height();
  const bool floats = format == ScreenFormat::Float;
  const bool summed_only = only_sums(format, keep_write_cycles);
  std::vector<TracedCell> cells = empty_cells(layout, format, true, keep_write_cycles);
  const OwnerTable owners(layout);
  auto owner = [&](int x, int y) {
    const CornerPixel p = corner_pixel(x, y, width, height);
    return owners.owner(p.x, p.y);
  };

  // Phase 1. With a float screen each corner's cycles are kept until they are
  // folded into the pixel that owns it (a bottom-row pixel owns corners of two
  // rows, which different threads may trace at once).
  std::vector<std::uint64_t> corner_cycles(floats ? static_cast<std::size_t>(width + 1) * (height + 1) : 0);
  tbb::enumerable_thread_specific<Sums> corner_sums([&] { return Sums(cell_count); });
  const CornerSamples corners = source.corners(
      threads,
      [&](int y, const auto& row) {
        Sums& sum = corner_sums.local();
        for (int x = 0; x <= width; ++x) {
          const auto at = static_cast<std::size_t>(x);
          if (tracing == CornerTracing::ByOwner) {
            const CellId c = owner(x, y).cell;
            row.add_to(at, sum.ops[c]);
            ++sum.items[c];
          } else {
            // Corner (x, y) is a corner of pixels (x - 1 .. x, y - 1 .. y):
            // each distinct window among theirs traces it.
            CellId needers[4];
            int count = 0;
            for (int py = y - 1; py <= y; ++py)
              for (int px = x - 1; px <= x; ++px) {
                if (px < 0 || py < 0 || px >= width || py >= height) continue;
                const CellId c = owners.owner(px, py).cell;
                if (std::find(needers, needers + count, c) == needers + count) needers[count++] = c;
              }
            for (int i = 0; i < count; ++i) {
              row.add_to(at, sum.ops[needers[i]]);
              ++sum.items[needers[i]];
            }
          }
          if (floats) corner_cycles[static_cast<std::size_t>(y) * (width + 1) + x] = saturated_cycles(row.at(at), costs);
        }
      },
      progress);

  // Phase 3.
  tbb::enumerable_thread_specific<Sums> pixel_sums([&] { return Sums(layout, chunk_pixels); });
  tbb::enumerable_thread_specific<Tracer::Scratch> scratch([&] { return Tracer::Scratch(tracer.scene()); });
  parallel_rows(threads, height, [&](const tbb::blocked_range<int>& rows) {
    Tracer::Scratch& s = scratch.local();
    Sums& sum = pixel_sums.local();
    for (int y = rows.begin(); y != rows.end(); ++y)
      for (int x = 0; x < width; ++x) {
        const PixelOwner own = owners.owner(x, y);
        const ScreenSample c[4] = {corners.at(x, y), corners.at(x + 1, y), corners.at(x, y + 1),
                                   corners.at(x + 1, y + 1)};
        TracedCell& out = cells[own.cell];
        ++sum.items[own.cell];
        if (summed_only) {
          // resolve adds its operations to the sum directly.
          store(out, own.video_index, source.resolve(x, y, c, aa, s, sum.of(own, chunk_pixels)).value, format,
                source.srgb8(x, y));
          continue;
        }
        OpCounts ops;
        const AntialiasedPixel px = source.resolve(x, y, c, aa, s, ops);
        store(out, own.video_index, px.value, format, source.srgb8(x, y));
        sum.of(own, chunk_pixels) += ops;
        if (!floats && !keep_write_cycles) continue;
        const std::uint64_t subdivision = saturated_cycles(ops, costs);
        if (keep_write_cycles) out.write_cycles[own.video_index] = subdivision;
        if (!floats) continue;
        std::uint64_t owned = corner_cycles[corners.index(x, y)];
        if (x == width - 1) owned += corner_cycles[corners.index(x + 1, y)];
        if (y == height - 1) owned += corner_cycles[corners.index(x, y + 1)];
        if (x == width - 1 && y == height - 1) owned += corner_cycles[corners.index(x + 1, y + 1)];
        out.pixel_cycles[own.video_index] = owned + subdivision;
        out.pixel_samples[own.video_index] =
            static_cast<std::uint32_t>(owned_corner_count(x, y, width, height) + px.subdivision_samples);
      }
    if (progress) progress->advance(static_cast<std::uint64_t>(rows.size()) * width);
  });
  if (const auto overflow = fold(corner_sums, cell_count, costs, [&](CellId c, const CostBreakdown& work, const OpCounts& ops) {
        cells[c].corner_work = work;
        cells[c].corner_ops = ops;
        cells[c].rays += ops.rays;
        cells[c].ops += ops;
      }))
    throw CycleOverflow(fmt::format("{}'s work for its {} corner samples adds up to {} cycles",
                                    cell_name(layout, overflow->cell), overflow->items, overflow->total));
  if (const auto overflow = fold(pixel_sums, cell_count, costs, [&](CellId c, const CostBreakdown& work, const OpCounts& ops) {
        cells[c].subdivision_work = work;
        cells[c].rays += ops.rays;
        cells[c].ops += ops;
      }))
    throw CycleOverflow(fmt::format("{}'s subdivision of its {} pixels adds up to {} cycles",
                                    cell_name(layout, overflow->cell), overflow->items, overflow->total));
  fold_chunks(pixel_sums, layout, costs, chunk_pixels, cells);
  for (TracedCell& c : cells) {
    c.work = c.corner_work;
    try {
      c.work += c.subdivision_work;
    } catch (const CycleOverflow& e) {
      throw e.inside("a cell's corner and subdivision work");
    }
  }
  return cells;
}


// Without antialiasing: every pixel traced and charged to its cell.
template <class Source>
std::vector<TracedCell> trace_cells_plain(const Source& source, const Tracer& tracer, const WindowLayout& layout,
                                          const CostTable& costs, int threads, Progress* progress,
                                          ScreenFormat format, bool keep_write_cycles, int chunk_pixels) {
  const int cell_count = layout.grid().cell_count();
  const bool floats = format == ScreenFormat::Float;
  const bool summed_only = only_sums(format, keep_write_cycles);
  std::vector<TracedCell> cells = empty_cells(layout, format, false, keep_write_cycles);
  const OwnerTable owners(layout);
  // Pixels are traced in screen order, row by row as `capsim render` traces
  // them (neighbouring rays share voxels and primitives in the caches), and each
  // sample goes to the video-memory slot of the cell whose window shows it.
  tbb::enumerable_thread_specific<Sums> sums([&] { return Sums(layout, chunk_pixels); });
  tbb::enumerable_thread_specific<typename Source::Workspace> workspaces(
      [&] { return source.workspace(layout.width()); });
  parallel_rows(threads, layout.height(), [&](const tbb::blocked_range<int>& rows) {
    typename Source::Workspace& w = workspaces.local();
    Sums& sum = sums.local();
    for (int y = rows.begin(); y != rows.end(); ++y) {
      source.row(y, w);
      for (int x = 0; x < layout.width(); ++x) {
        const PixelOwner owner = owners.owner(x, y);
        TracedCell& out = cells[owner.cell];
        ++sum.items[owner.cell];
        if (summed_only) {
          // The pixel's operations go to the sum directly.
          store(out, owner.video_index, source.pixel(w, x, y, sum.of(owner, chunk_pixels)), format,
                source.srgb8(x, y));
          continue;
        }
        OpCounts ops;
        store(out, owner.video_index, source.pixel(w, x, y, ops), format, source.srgb8(x, y));
        const std::uint64_t cycles = saturated_cycles(ops, costs);
        if (floats) out.pixel_cycles[owner.video_index] = cycles;
        if (keep_write_cycles) out.write_cycles[owner.video_index] = cycles;
        sum.of(owner, chunk_pixels) += ops;
      }
    }
    if (progress) progress->advance(static_cast<std::uint64_t>(rows.size()) * layout.width());
  });
  if (const auto overflow = fold(sums, cell_count, costs, [&](CellId c, const CostBreakdown& work, const OpCounts& ops) {
        cells[c].work = work;
        cells[c].rays = ops.rays;
        cells[c].ops = ops;
      }))
    refuse_overflow(tracer, layout, costs, *overflow, "pixels");
  fold_chunks(sums, layout, costs, chunk_pixels, cells);
  return cells;
}

}  // namespace

std::vector<TracedCell> trace_cells(const Tracer& tracer, const WindowLayout& layout,
                                    const CostTable& costs, int threads, Progress* progress,
                                    const AntialiasOptions& aa, ScreenFormat format, bool keep_write_cycles,
                                    CornerTracing corners, int chunk_pixels) {
  const TracingNow now{tracer};
  if (aa.depth > 0)
    return trace_cells_antialiased(now, tracer, layout, costs, threads, progress, aa, format, keep_write_cycles,
                                   corners, chunk_pixels);
  return trace_cells_plain(now, tracer, layout, costs, threads, progress, format, keep_write_cycles, chunk_pixels);
}

std::vector<TracedCell> trace_cells(const ScreenTrace& screen, const WindowLayout& layout, const CostTable& costs,
                                    int threads, ScreenFormat format, bool keep_write_cycles, CornerTracing corners,
                                    int chunk_pixels) {
  if (layout.width() != screen.width || layout.height() != screen.height)
    throw std::invalid_argument("a screen traced ahead is laid out at its own size");
  const TracedAhead ahead{screen};
  if (screen.aa.depth > 0)
    return trace_cells_antialiased(ahead, *screen.tracer, layout, costs, threads, nullptr, screen.aa, format,
                                   keep_write_cycles, corners, chunk_pixels);
  return trace_cells_plain(ahead, *screen.tracer, layout, costs, threads, nullptr, format, keep_write_cycles,
                           chunk_pixels);
}

ScreenTrace trace_screen(const Tracer& tracer, const AntialiasOptions& aa, int threads) {
  const Camera& cam = tracer.scene().camera;
  ScreenTrace t;
  t.tracer = &tracer;
  t.aa = aa;
  t.width = cam.width;
  t.height = cam.height;
  const std::size_t pixels = static_cast<std::size_t>(cam.width) * cam.height;
  t.pixels.resize(pixels);
  t.pixel_ops = PackedOpCounts(pixels);
  if (aa.depth > 0) {
    t.corner_ops = PackedOpCounts(static_cast<std::size_t>(cam.width + 1) * (cam.height + 1));
    t.subdivision_samples.resize(pixels);
    t.corners = trace_corners(
        tracer, threads,
        [&](int y, std::span<const OpCounts> row) {
          const std::size_t first = static_cast<std::size_t>(y) * (cam.width + 1);
          for (std::size_t x = 0; x < row.size(); ++x) t.corner_ops.set(first + x, row[x]);
        },
        nullptr);
  }
  // Antialiased pixels trace from the corners; only unantialiased rows are
  // made as rows of rays, and shaded as rows.
  const int row_rays = aa.depth == 0 ? cam.width : 0;
  parallel_rows_with(
      threads, cam.height, [&] { return ShadedRowWorkspace(tracer, row_rays); },
      [&](const tbb::blocked_range<int>& rows, ShadedRowWorkspace& w) {
    Tracer::Scratch& s = w.scratch;
    for (int y = rows.begin(); y != rows.end(); ++y) {
      const std::size_t first = static_cast<std::size_t>(y) * cam.width;
      if (aa.depth == 0) {
        tracer.primary_rays(y, w.rays);
        w.shade(tracer, std::span<PixelSample>(t.pixels).subspan(first, w.rays.size()));
        for (std::size_t x = 0; x < w.ops.size(); ++x) t.pixel_ops.set(first + x, w.ops[x]);
        continue;
      }
      for (int x = 0; x < cam.width; ++x) {
        const std::size_t i = first + x;
        OpCounts ops;
        const ScreenSample c[4] = {t.corners.at(x, y), t.corners.at(x + 1, y), t.corners.at(x, y + 1),
                                   t.corners.at(x + 1, y + 1)};
        const AntialiasedPixel px = resolve_pixel(tracer, x, y, c, aa, s, ops);
        t.pixel_ops.set(i, ops);
        t.pixels[i] = px.value;
        t.subdivision_samples[i] = static_cast<std::uint32_t>(px.subdivision_samples);
      }
    }
  });
  t.srgb8.resize(pixels * 3);
  encode_srgb8_row(t.pixels, t.srgb8.data());
  return t;
}

}  // namespace capsim::sim
