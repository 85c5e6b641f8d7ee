// The whole `capsim simulate` process over DISB's 64 frames at 512 x 512 on 8x8
// cells in dot mode (docs/animation.md): without antialiasing, with --aa 2,
// and with --aa 2 --frame-average: the host wall time of each command, on two
// and on one host thread. The goal for --aa 2 on two threads is under 60 s.
//
//   bench_sequence [--benchmark_filter=BM_SimulateDisb/2/]   (two threads only)
// Arguments: host threads; 0 = plain, 1 = --aa 2, 2 = --aa 2 --frame-average.

#include <benchmark/benchmark.h>

#include <fmt/core.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace {

std::string disb_frames() {
  std::string files;
  for (int f = 0; f < 64; ++f) files += fmt::format(" {}/scenes/disb/f{:05}.csg", CAPSIM_SOURCE_DIR, f);
  return files;
}

void BM_SimulateDisb(benchmark::State& state) {
  static const char* const kProcessing[] = {"", " --aa 2", " --aa 2 --frame-average"};
  const std::filesystem::path out = std::filesystem::temp_directory_path() / "capsim-bench-sequence";
  std::filesystem::create_directories(out);
  const std::string command =
      fmt::format("{} simulate{} -o {} --threads {}{} > /dev/null", CAPSIM_EXE, disb_frames(),
                  (out / "d.png").string(), state.range(0), kProcessing[state.range(1)]);
  for (auto _ : state)
    if (std::system(command.c_str()) != 0) state.SkipWithError("capsim simulate failed");
  std::filesystem::remove_all(out);
}

BENCHMARK(BM_SimulateDisb)
    ->ArgsProduct({{2, 1}, {0, 1, 2}})
    ->Unit(benchmark::kSecond)
    ->UseRealTime()
    ->Iterations(3)
    ->Repetitions(1);

}  // namespace

BENCHMARK_MAIN();
