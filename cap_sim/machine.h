#pragma once
// The whole machine for one frame: host, command bus, neighbour links and an
// R x C grid of cells, run by the event kernel. The tracing itself is done ahead
// by host threads (trace_cells); the event loop alone decides simulated time.

#include "cell_grid.h"
#include "cost_profile.h"
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
};

struct CellReport {
  CellId id = 0;
  CellPosition position;
  std::uint64_t pixels = 0;
  std::uint64_t rays = 0;
  Cycles busy, idle, comm, finish;  // idle = finish - busy - comm
  CostBreakdown work;
};

struct SimulationResult {
  MachineConfig config;
  SceneFootprint footprint;
  std::vector<CellReport> cells;
  CostBreakdown breakdown;   // every cell's work plus the host's voxel generation
  Cycles frame;              // the last completion reached the host: the frame time
  Framebuffer screen;        // what the video bus shows
  std::vector<float> pixel_cycles;  // cycles spent on each screen pixel, row-major
  Timeline timeline;
  std::uint64_t events = 0;  // events the kernel ran
};

// Program + scene + voxel data must fit a cell's memory. Throws std::runtime_error
// naming the needed and the available bytes.
void check_cell_memory(const SceneFootprint& footprint, const CostProfile& profile);

// The memory simulate_frame takes at its peak for a width x height screen,
// beyond the scene: every cell's traced samples and per-pixel cycles, with the
// screen they are composed into and the per-pixel cycles of the result.
std::uint64_t simulate_frame_memory(int width, int height);

// What a SimulationResult keeps of a width x height screen: the screen and the
// per-pixel cycles.
std::uint64_t simulation_result_memory(int width, int height);

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
