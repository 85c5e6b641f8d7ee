#pragma once
// The whole machine for one frame: host, command bus, neighbour links and an
// R x C grid of cells, run by the event kernel. The tracing itself is done ahead
// by host threads (trace_cells); the event loop alone decides simulated time.

#include "cell_grid.h"
#include "corner_exchange.h"
#include "cost_profile.h"
#include "neighbour_links.h"
#include "scene_footprint.h"
#include "timeline.h"
#include "traced_cells.h"
#include "window_controller.h"

#include "capsim/prepared_scene.h"
#include "capsim/render.h"
#include "capsim/tracer.h"

#include <cstdint>
#include <vector>

namespace capsim::sim {

struct MachineConfig {
  CellGrid cells{8, 8};
  PixelMode mode = PixelMode::Dot;
  CostProfile profile;
  AntialiasOptions aa;  // depth 0: one sample per pixel, no exchange
  ScreenFormat screen = ScreenFormat::Float;
};

struct CellReport {
  CellId id = 0;
  CellPosition position;
  std::uint64_t pixels = 0;
  std::uint64_t rays = 0;
  Cycles busy, idle, comm, finish;  // idle = finish - busy - comm
  CostBreakdown work;
  // Antialiasing: each phase from its start to its end (the exchange includes
  // its waits), and the corners it took in over the links.
  Cycles trace_corners, exchange, subdivide;
  std::vector<CornerIndex> corners_received;  // ascending
};

struct SimulationResult {
  MachineConfig config;
  SceneFootprint footprint;
  std::vector<CellReport> cells;
  CostBreakdown breakdown;   // every cell's work plus the host's voxel generation
  Cycles frame;              // the last completion reached the host: the frame time
  int width = 0, height = 0;  // the screen's
  // What the video bus shows, in the config's screen format: floats (with the
  // cycles spent on each pixel and, antialiased, its primary samples), or the
  // 8-bit sRGB bytes a PNG holds; the other members stay empty.
  Framebuffer screen;
  std::vector<float> pixel_cycles;   // row-major
  std::vector<float> pixel_samples;  // row-major
  std::vector<unsigned char> screen_srgb8;
  std::vector<LinkTraffic> links;    // every link that carried a message
  std::vector<LinkMessage> link_messages;  // in order of arrival
  Timeline timeline;
  std::uint64_t events = 0;  // events the kernel ran
};

// Program + scene + voxel data must fit a cell's memory. Throws std::runtime_error
// naming the needed and the available bytes.
void check_cell_memory(const SceneFootprint& footprint, const CostProfile& profile);

// Runs one frame on the machine with the work traced ahead.
// Precondition: traced came from trace_cells on `scene` with `layout` and
// config.profile's cell costs; layout has config's mode and grid.
SimulationResult run_frame(const PreparedScene& scene, const WindowLayout& layout,
                           std::vector<TracedCell> traced, const MachineConfig& config);

// trace_cells + run_frame. threads: 0 = all hardware threads; the result does not
// depend on it. show_progress: progress on stderr (see Progress).
SimulationResult simulate_frame(const Tracer& tracer, const MachineConfig& config, int threads,
                                bool show_progress);

}  // namespace capsim::sim
