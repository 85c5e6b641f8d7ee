// Grid measurements on the shipped scenes:
//  1. voxel entries written by Algorithm-3 against plain world-axis bounding boxes;
//  2. render time for fixed divisions N against the automatic choice.
// Usage: bench_grid [SCENE...]   (default: every scenes/*.csg)
// Times are wall-clock medians of 3 runs on one thread; entries are exact.

#include "capsim/scene/parser.h"
#include "capsim/trace/render.h"

#include <fmt/core.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <vector>

using namespace capsim;

namespace {

double render_seconds(const PreparedScene& ps) {
  std::vector<double> runs;
  for (int r = 0; r < 3; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    const Tracer tracer(ps, {});
    render(tracer, 1);
    runs.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
  }
  std::sort(runs.begin(), runs.end());
  return runs[1];
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> scenes(argv + 1, argv + argc);
  if (scenes.empty()) {
    for (const auto& e : std::filesystem::directory_iterator(CAPSIM_SOURCE_DIR "/scenes"))
      if (e.path().extension() == ".csg") scenes.push_back(e.path().string());
    std::sort(scenes.begin(), scenes.end());
  }
  for (const std::string& path : scenes) {
    const Scene scene = parse_scene_file(path);
    const PreparedScene automatic = prepare_scene(scene, {});
    fmt::print("{}: {} primitives, {}x{} pixels, auto N = {}\n", path, scene.primitives.size(),
               automatic.camera.width, automatic.camera.height, automatic.grid.n);
    fmt::print("  {:>4} {:>12} {:>12} {:>8} {:>10}\n", "N", "Alg-3", "AABB", "saved", "render s");
    std::vector<int> ns = {1, 2, 4, 8, 12, 16, 24, 32, 48, 64, automatic.grid.n};
    std::sort(ns.begin(), ns.end());
    ns.erase(std::unique(ns.begin(), ns.end()), ns.end());
    for (int n : ns) {
      PrepareOptions o;
      o.grid = n;
      const PreparedScene ps = prepare_scene(scene, o);
      const VoxelGrid aabb = generate_voxels_aabb(ps.prims, ps.placed, ps.grid.universe, n);
      const double saved = 100.0 * (1.0 - double(ps.grid.entries()) / double(aabb.entries()));
      fmt::print("  {:>4} {:>12} {:>12} {:>7.1f}% {:>10.3f}{}\n", n, ps.grid.entries(), aabb.entries(), saved,
                 render_seconds(ps), n == automatic.grid.n ? "  (auto)" : "");
    }
  }
  return 0;
}
