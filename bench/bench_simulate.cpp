// `capsim simulate` against `capsim render`, side by side on the same scene with
// the same host threads and antialiasing depth: the machine simulation should
// cost at most 1.2x the tracing alone. Also reports simulated seconds per host
// second.
//
//   bench_simulate [--benchmark_filter=...]
// Scene: scenes/balls.csg at 512x512; machine: 8x8 cells, dot mode, cap profile.
// Arguments: host threads, antialiasing depth (0 or 2).
// BM_PlanExchange: planning one antialiased frame's corner exchange (phase 2)
// at 512x512; arguments: pixel mode (0 block, 1 line, 2 dot), grid side.

#include "machine/machine.h"
#include "machine/parts/corner_exchange.h"

#include "capsim/scene/parser.h"
#include "capsim/trace/render.h"

#include <benchmark/benchmark.h>

#include <string>

namespace {

using namespace capsim;

const PreparedScene& balls() {
  static const PreparedScene scene = prepare_scene(
      parse_scene_file(std::string(CAPSIM_SOURCE_DIR) + "/scenes/balls.csg"), PrepareOptions{});
  return scene;
}

AntialiasOptions antialiasing(const benchmark::State& state) {
  return {static_cast<int>(state.range(1)), 0.3};
}

void BM_Render(benchmark::State& state) {
  const Tracer tracer(balls(), TraceOptions{});
  const int threads = static_cast<int>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(render(tracer, threads, nullptr, nullptr, antialiasing(state)));
}

void BM_Simulate(benchmark::State& state) {
  const Tracer tracer(balls(), TraceOptions{});
  const int threads = static_cast<int>(state.range(0));
  sim::MachineConfig config;  // 8x8 cells, dot mode
  config.profile = sim::load_cost_profile("cap");
  config.aa = antialiasing(state);
  double simulated_seconds = 0;
  for (auto _ : state) {
    const sim::SimulationResult r = sim::simulate_frame(tracer, config, threads, false);
    simulated_seconds = r.frame.seconds(config.profile.clock_hz);
    benchmark::DoNotOptimize(r.screens[0].screen.rgba.data());
  }
  state.counters["simulated_s"] = simulated_seconds;
  // Simulated seconds per host second: simulated_s divided by the wall time of one run.
  state.counters["simulated_s_per_host_s"] =
      benchmark::Counter(simulated_seconds * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate);
}

void BM_PlanExchange(benchmark::State& state) {
  const int side = static_cast<int>(state.range(1));
  const sim::WindowLayout layout(static_cast<sim::PixelMode>(state.range(0)), sim::CellGrid{side, side}, 512, 512);
  for (auto _ : state) {
    const sim::CornerExchange exchange(layout);
    benchmark::DoNotOptimize(exchange.needs(0).data());
  }
}

BENCHMARK(BM_Render)->ArgsProduct({{1, 2}, {0, 2}})->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(3.0);
BENCHMARK(BM_Simulate)->ArgsProduct({{1, 2}, {0, 2}})->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(3.0);
BENCHMARK(BM_PlanExchange)->ArgsProduct({{0, 1, 2}, {4, 8, 16}})->Unit(benchmark::kMillisecond)->MinTime(1.0);

}  // namespace

BENCHMARK_MAIN();
