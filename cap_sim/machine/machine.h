#pragma once
// The whole machine: host, command bus, neighbour links and an R x C grid of
// cells, run by the event kernel, for one frame or a sequence of frames. The
// tracing itself is done ahead by host threads (trace_cells); the event loop
// alone decides simulated time.

#include "kernel/timeline.h"
#include "machine/parts/balance.h"
#include "machine/parts/cell_grid.h"
#include "machine/cell_record.h"
#include "machine/parts/corner_exchange.h"
#include "machine/costs/cost_profile.h"
#include "machine/frame_work.h"
#include "machine/parts/host.h"
#include "machine/parts/neighbour_links.h"
#include "machine/parts/voxel_shares.h"
#include "machine/scene_footprint.h"
#include "machine/traced_cells.h"
#include "machine/parts/window_controller.h"

#include "capsim/trace/prepared_scene.h"
#include "capsim/trace/render.h"
#include "capsim/trace/tracer.h"

#include <cstdint>
#include <vector>

namespace capsim::sim {

struct MachineConfig {
  CellGrid cells{8, 8};
  PixelMode mode = PixelMode::Dot;
  CostProfile profile;
  AntialiasOptions aa;  // depth 0: one sample per pixel, no exchange
  ScreenFormat screen = ScreenFormat::Float;
  // Frame-averaged distribution (dot mode only): frames go out in groups of
  // frame_average_group frames, frame k of a group with the dot shift
  // dot_shift_for_frame(grid, k), and the cells run through a group without
  // waiting for each other.
  bool frame_average = false;
  // 0 until the machine resolves it: then as many frames as a cell's memory
  // and video memory hold, at most R x C (frames_per_unit,
  // machine/unit_memory.h). The result's config holds the resolved value.
  int frame_average_group = 0;
  // Keep when every pixel reached video memory (FrameScreen::completion_cycles);
  // off, a run keeps no per-pixel figures it does not need.
  bool completion_cycles = false;
  // Keep every corner each cell took in (CellReport::received_corners), for
  // tests of the exchange; off, a cell keeps only their count.
  bool keep_received_corners = false;
  // How the cells share a frame's pixels (balance.h): static, by the windows
  // of `mode`; on demand, tile by tile (antialiased, a tile traces every
  // corner of its pixels itself); or stealing, the windows of `mode` cut into
  // chunks that idle neighbours take (antialiased, the subdivision's). On
  // demand and stealing, frame averaging is refused.
  BalanceOptions balance;
  // Who generates each frame's voxel grid (Algorithm-3): the host, which
  // broadcasts it (the paper's), or the cells, each its share, exchanged over
  // the command bus (voxel_shares.h).
  VoxelGeneration voxel_generation = VoxelGeneration::Host;
};

// One frame as the video bus showed it, in the run's screen format: floats
// (with the cycles spent on each pixel and, antialiased, its primary samples),
// or the 8-bit sRGB bytes a PNG holds; the other members stay empty.
struct FrameScreen {
  Framebuffer screen;
  std::vector<float> pixel_cycles;   // row-major
  std::vector<float> pixel_samples;  // row-major
  std::vector<unsigned char> screen_srgb8;
  // With MachineConfig::completion_cycles, in either format, row-major: the
  // cycle of the run at which the pixel was in its cell's video memory, so on
  // the screen. A cell writes its pixels in video-memory order from the start
  // of its tracing (antialiased, of its subdivision), each when the cycles of
  // its own operations have passed.
  std::vector<std::uint64_t> completion_cycles;
};

// A distribution unit as it ran: its frames, and when the host started it and
// collected it.
struct UnitTimes {
  int first_frame = 0;
  int frames = 1;
  Cycles start, end;
  // What a cell held for the unit (machine/unit_memory.h): its memory
  // (program, and every frame's scene and voxel data) and the most video
  // memory one cell needed.
  std::uint64_t cell_memory_bytes = 0;
  std::uint64_t video_memory_bytes = 0;
};

// The command bus over a run: every transfer (broadcasts and messages).
struct BusTotals {
  std::uint64_t transfers = 0, bytes = 0;
  Cycles busy;  // the cycles the bus was held, grant to release, summed
};

struct SimulationResult {
  MachineConfig config;
  SceneFootprint footprint;  // the first frame's
  std::vector<CellReport> cells;
  CostBreakdown breakdown;  // every cell's work plus the host's voxel generation
  VoxelGenCounts voxel_counts;  // the host's Algorithm-3 operations, all frames (none when the cells generate)
  Cycles frame;             // the last completion reached the host: the run's time
                            // (for one frame, the frame time)
  int width = 0, height = 0;
  std::vector<FrameScreen> screens;  // one per frame
  std::vector<UnitTimes> units;
  BusTotals bus;
  // Balanced on demand: what the host handled, and per frame, tile by tile
  // (in tile order), the cell that traced it.
  Host::Balancing balancing;
  BusTotals balance_bus;  // the bus's requests, grants and "no tile" answers
  // Voxel generation on the cells: the bus's "voxel entries" and "voxel rows"
  // broadcasts, and every cell's share of each frame's grid (by frame, by cell).
  BusTotals voxel_entries_bus, voxel_rows_bus;
  std::vector<std::vector<VoxelShare>> voxel_shares;
  std::vector<std::vector<CellId>> tile_cells;
  // Stealing: per frame, per cell's window, per chunk (balance.h), the cell
  // that traced it; and the links' stealing messages (requests, answers,
  // pixels sent back).
  std::vector<std::vector<std::vector<CellId>>> chunk_cells;
  struct StealTraffic {
    std::uint64_t messages = 0, bytes = 0;
  } steal_links;
  std::vector<LinkTraffic> links;          // every link that carried a message
  std::vector<LinkMessage> link_messages;  // in order of arrival
  Timeline timeline;
  std::uint64_t events = 0;  // events the kernel ran
};

// The work of one frame, traced ahead, and its voxel generation by the host
// or by config's cells: precondition: traced came from trace_cells on `scene`
// with `layout` and the profile's cell costs.
FrameWork frame_work(const PreparedScene& scene, const WindowLayout& layout, std::vector<TracedCell> traced,
                     const MachineConfig& config);

// Throws std::invalid_argument when the config asks for what the machine
// does not model: frame averaging outside dot mode; balanced on demand, a
// tile that is not square, or frame averaging; stealing, frame averaging.
void check_balance(const MachineConfig& config);

// Runs the frames on the machine, in the units config asks for (an unresolved
// frame_average_group resolved by frames_per_unit). Precondition: the frames
// share one screen size; their layouts are frame_layout's with the resolved
// config. Throws std::runtime_error, naming the unit, when a unit does not fit
// a cell's memory or video memory (check_unit_memory).
SimulationResult run_frames(std::vector<FrameWork> frames, const MachineConfig& config);

// One frame traced ahead, as run_frames.
SimulationResult run_frame(const PreparedScene& scene, const WindowLayout& layout,
                           std::vector<TracedCell> traced, const MachineConfig& config);

// The memory a run of `frames` frames of width x height takes at its peak,
// beyond the scenes: every frame's video memories and composed screen (kept to
// the end), the owner count per pixel composing checks, and, antialiased, one
// frame's corner samples and a distribution unit's exchange plan while they
// are built. docs/simulation.md gives the bytes per pixel.
std::uint64_t simulation_memory(const MachineConfig& config, int width, int height, int frames);

// What the SimulationResult of such a run keeps: the frames' screens.
std::uint64_t simulation_result_memory(const MachineConfig& config, int width, int height, int frames);

// The most memory such a run takes until its screens are in image files, as
// `capsim simulate` writes them (an 8-bit screen to PNG, a float one to EXR):
// the run's peak (simulation_memory), or, if more, its result while a screen
// is written. A PNG compresses the screen's bytes; an EXR copies the screen's
// cycles and, antialiased, its samples into channels, then makes planes of all.
std::uint64_t simulation_memory_until_written(const MachineConfig& config, int width, int height, int frames);

// The window layout of frame f of a run: frame averaged, frame k of its unit
// (k = f mod unit_frames(config)) takes dot_shift_for_frame(grid, k).
// Balanced on demand, the tiles (tile_layout): each window is a tile.
WindowLayout frame_layout(const MachineConfig& config, int width, int height, int frame);

// trace_cells for every frame + run_frames. threads: 0 = all hardware threads;
// the result does not depend on it. show_progress: progress on stderr (see
// Progress), by pixels for one frame, by frames for several. Precondition: the
// frames' cameras have one size.
SimulationResult simulate_frames(const std::vector<const Tracer*>& frames, const MachineConfig& config,
                                 int threads, bool show_progress);
SimulationResult simulate_frame(const Tracer& tracer, const MachineConfig& config, int threads,
                                bool show_progress);

// simulate_frame of the screen's tracer, laid out from the screen traced
// ahead (traced_cells.h): the same result, without tracing again. Throws
// std::invalid_argument when config's antialiasing is not the screen's.
SimulationResult simulate_traced_frame(const ScreenTrace& screen, const MachineConfig& config, int threads);

}  // namespace capsim::sim
