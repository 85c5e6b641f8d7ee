// Host speed of every shipped model: wall time of `render` (the tracer alone)
// and of `simulate` (8x8 cells, dot mode, cap profile) at 512 x 512 with full
// ray tracing. The simulated figures are checked exactly by `capsim bench
// modes` against its baseline; this measures only how long the host takes,
// and is never asserted in tests (docs/benchmarks.md).
//
//   bench_models [--benchmark_filter=...]
// Arguments: host threads (1 or 2).

#include "machine/machine.h"

#include "capsim/scene/parser.h"
#include "capsim/trace/render.h"

#include <benchmark/benchmark.h>

#include <map>
#include <string>

namespace {

using namespace capsim;

const char* const kModels[] = {"balls", "chess", "piston", "cad", "disb/f00000"};

const PreparedScene& model(int index) {
  static std::map<int, PreparedScene> scenes;
  auto it = scenes.find(index);
  if (it == scenes.end())
    it = scenes
             .emplace(index, prepare_scene(parse_scene_file(std::string(CAPSIM_SOURCE_DIR) + "/scenes/" +
                                                            kModels[index] + ".csg"),
                                           PrepareOptions{}))
             .first;
  return it->second;
}

void BM_Render(benchmark::State& state) {
  const int m = static_cast<int>(state.range(0));
  state.SetLabel(kModels[m]);
  const Tracer tracer(model(m), TraceOptions{});
  for (auto _ : state) benchmark::DoNotOptimize(render(tracer, static_cast<int>(state.range(1))).rgba.data());
}

void BM_Simulate(benchmark::State& state) {
  const int m = static_cast<int>(state.range(0));
  state.SetLabel(kModels[m]);
  const Tracer tracer(model(m), TraceOptions{});
  sim::MachineConfig config;  // 8x8 cells, dot mode
  config.profile = sim::load_cost_profile("cap");
  config.screen = sim::ScreenFormat::Srgb8;
  for (auto _ : state) {
    const sim::SimulationResult r = sim::simulate_frame(tracer, config, static_cast<int>(state.range(1)), false);
    benchmark::DoNotOptimize(r.frame);
  }
}

BENCHMARK(BM_Render)->ArgsProduct({{0, 1, 2, 3, 4}, {1, 2}})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_Simulate)->ArgsProduct({{0, 1, 2, 3, 4}, {1, 2}})->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
