// Primary rays per second of capsim against Embree 3 closest-hit, in the same
// run, on the same sphere lattices seen by the same camera through the same rays.
//
//   bench_vs_embree [--sizes 5,10,19] [--resolution 1024] [--repeats 5] [--json FILE]
//
// For each n x n x n lattice (spheres of radius 0.8 on a 2-unit grid, the paper's
// BALLS spacing) a scene file is written to a temporary directory and measured:
//   embree          rtcIntersect1 per primary ray (coherent context) on native
//                   RTC_GEOMETRY_TYPE_SPHERE_POINT spheres; trace loop only;
//   capsim hit      Tracer::first_hit per primary ray, in process: the same
//                   question Embree answers (visible distance and primitive);
//   capsim render   capsim::render with primary-only shading: every pixel shaded,
//                   the frame buffer filled;
//   capsim process  the whole `capsim render SCENE -o OUT.png --size WxH
//                   --primary-only --threads T` process, wall clock: start-up,
//                   parsing, voxel generation, tracing, shading and PNG output.
// Each figure is pixels / median wall time over the repeats (run interleaved),
// with one thread and with every hardware thread; ratios are capsim / embree.
// One-thread figures are also given from median CPU time, which other work on a
// shared machine does not inflate. The last column counts
// pixels where capsim and Embree see a different sphere (or one sees none):
// Embree traces in float, so a few silhouette pixels may differ.
//
// Needs the capsim executable (CAPSIM_EXE, built by the `capsim` target).

#include "capsim/scene/parser.h"
#include "capsim/trace/render.h"

#include <embree3/rtcore.h>
#include <fmt/core.h>
#include <fmt/os.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

extern char** environ;

namespace {

namespace fs = std::filesystem;

// --- The lattice scene ---------------------------------------------------------

constexpr double kSpacing = 2.0;  // centre to centre, as in scenes/balls.csg
constexpr double kRadius = 0.8;

glm::dvec3 sphere_center(int n, int x, int y, int z) {
  const double half = 0.5 * (n - 1) * kSpacing;
  return {x * kSpacing - half, y * kSpacing - half, z * kSpacing - half};
}

// The camera looks along +y at the lattice's near face (y = min) and frames it:
// the face's half-size h is seen from 2.5 h in front of it. The eye is moved a
// little off the axis so that rays through the gaps meet deeper layers at
// different places rather than repeating one pattern.
capsim::Camera lattice_camera(int n, int resolution) {
  const double half = 0.5 * (n - 1) * kSpacing;
  const double h = half + kRadius;
  capsim::Camera c;
  c.eye = {0.37 * kSpacing, -half - kRadius - 2.5 * h, 0.23 * kSpacing};
  c.center = {0, 0, 0};
  c.up = {0, 0, 1};
  c.fov_deg = 2.0 * std::atan(h / (2.5 * h)) * 180.0 / std::acos(-1.0);
  c.width = c.height = resolution;
  return c;
}

// Spheres in x-fastest order: primitive k of the file is Embree's primID k.
std::string lattice_csg(int n, const capsim::Camera& c) {
  std::string s = fmt::format("// {0} x {0} x {0} lattice of spheres, written by bench_vs_embree.\n", n);
  s += fmt::format(
      "camera(eye = [{:.17g}, {:.17g}, {:.17g}], center = [0, 0, 0], up = [0, 0, 1], "
      "fov = {:.17g}, size = [{}, {}]);\n",
      c.eye.x, c.eye.y, c.eye.z, c.fov_deg, c.width, c.height);
  s += "union() {\n";
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const glm::dvec3 p = sphere_center(n, x, y, z);
        s += fmt::format("  translate([{}, {}, {}]) sphere(r = {});\n", p.x, p.y, p.z, kRadius);
      }
  return s + "}\n";
}

// --- Embree --------------------------------------------------------------------

class EmbreeLattice {
 public:
  explicit EmbreeLattice(int n) {
    device_ = rtcNewDevice(nullptr);
    if (!device_) throw std::runtime_error("rtcNewDevice failed");
    scene_ = rtcNewScene(device_);
    RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_SPHERE_POINT);
    auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
        g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float),
        static_cast<std::size_t>(n) * n * n));
    for (int z = 0, k = 0; z < n; ++z)
      for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x, ++k) {
          const glm::dvec3 p = sphere_center(n, x, y, z);
          v[4 * k + 0] = static_cast<float>(p.x);
          v[4 * k + 1] = static_cast<float>(p.y);
          v[4 * k + 2] = static_cast<float>(p.z);
          v[4 * k + 3] = static_cast<float>(kRadius);
        }
    rtcCommitGeometry(g);
    rtcAttachGeometry(scene_, g);
    rtcReleaseGeometry(g);
    rtcCommitScene(scene_);
    if (rtcGetDeviceError(device_) != RTC_ERROR_NONE)
      throw std::runtime_error("Embree scene construction failed");
  }
  ~EmbreeLattice() {
    rtcReleaseScene(scene_);
    rtcReleaseDevice(device_);
  }
  EmbreeLattice(const EmbreeLattice&) = delete;
  EmbreeLattice& operator=(const EmbreeLattice&) = delete;

  // Closest hit: the sphere index, or -1.
  int closest(const capsim::Ray& r) const {
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    ctx.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    RTCRayHit rh;
    rh.ray.org_x = static_cast<float>(r.origin.x);
    rh.ray.org_y = static_cast<float>(r.origin.y);
    rh.ray.org_z = static_cast<float>(r.origin.z);
    rh.ray.dir_x = static_cast<float>(r.dir.x);
    rh.ray.dir_y = static_cast<float>(r.dir.y);
    rh.ray.dir_z = static_cast<float>(r.dir.z);
    rh.ray.tnear = 0.0f;
    rh.ray.tfar = INFINITY;
    rh.ray.time = 0.0f;
    rh.ray.mask = 0xFFFFFFFFu;
    rh.ray.id = 0;
    rh.ray.flags = 0;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene_, &ctx, &rh);
    return rh.hit.geomID == RTC_INVALID_GEOMETRY_ID ? -1 : static_cast<int>(rh.hit.primID);
  }

 private:
  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
};

// --- Timing --------------------------------------------------------------------

// Wall-clock and CPU seconds of one run. CPU time (this process's, or the
// child's) does not grow when other work shares the machine, so with one thread
// it is the steadier figure; wall time is what a user waits.
struct Seconds {
  double wall = 0;
  double cpu = 0;
};

double process_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

Seconds time_in_process(const std::function<void()>& run) {
  const double c0 = process_cpu_seconds();
  const auto t0 = std::chrono::steady_clock::now();
  run();
  return {std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(),
          process_cpu_seconds() - c0};
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// Every row of the image, on `threads` threads (1: the calling thread alone, no
// scheduler), each thread with its own state made by make_state.
template <class State, class MakeState, class Row>
void for_rows(int height, int threads, MakeState make_state, Row row) {
  if (threads == 1) {
    State st = make_state();
    for (int j = 0; j < height; ++j) row(j, st);
    return;
  }
  tbb::enumerable_thread_specific<State> states(make_state);
  tbb::task_arena arena(threads);
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<int>(0, height), [&](const tbb::blocked_range<int>& rows) {
      State& st = states.local();
      for (int j = rows.begin(); j != rows.end(); ++j) row(j, st);
    });
  });
}

// A thread's state for the `hit` contender: its scratch and a row of rays.
struct HitWorker {
  capsim::Tracer::Scratch scratch;
  std::vector<capsim::Ray> rays;
};

// One child process to completion; wall time and its CPU time (all its
// threads, user + system). Throws if it fails.
Seconds run_process(const std::vector<std::string>& args) {
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  const auto t0 = std::chrono::steady_clock::now();
  pid_t pid = 0;
  if (posix_spawn(&pid, argv[0], nullptr, nullptr, argv.data(), environ) != 0)
    throw std::runtime_error(fmt::format("cannot start {}", args[0]));
  int status = 0;
  rusage usage{};
  wait4(pid, &status, 0, &usage);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error(fmt::format("{} failed (status {})", args[0], status));
  const auto secs = [](const timeval& tv) { return tv.tv_sec + 1e-6 * tv.tv_usec; };
  return {wall, secs(usage.ru_utime) + secs(usage.ru_stime)};
}

// --- One lattice ---------------------------------------------------------------

// Rays (pixels) per second of each contender, from median wall and median CPU time.
struct Rate {
  double wall = 0;
  double cpu = 0;
};

struct Row {
  int n = 0, threads = 0, grid = 0;
  Rate embree, hit, render, process;
  std::int64_t differing = 0;
};

Rate rate(double pixels, const std::vector<Seconds>& runs) {
  std::vector<double> wall, cpu;
  for (const Seconds& s : runs) wall.push_back(s.wall), cpu.push_back(s.cpu);
  return {pixels / median(wall), pixels / median(cpu)};
}

std::vector<Row> measure_lattice(int n, int resolution, int repeats, const fs::path& dir,
                                 const std::vector<int>& thread_counts) {
  const capsim::Camera cam = lattice_camera(n, resolution);
  const fs::path scene_path = dir / fmt::format("lattice{}.csg", n);
  const fs::path image_path = dir / fmt::format("lattice{}.png", n);
  {
    auto out = fmt::output_file(scene_path.string());
    out.print("{}", lattice_csg(n, cam));
  }
  const capsim::PreparedScene prepared =
      capsim::prepare_scene(capsim::parse_scene_file(scene_path.string()), {});
  capsim::TraceOptions primary;
  primary.primary_only = true;
  const capsim::Tracer tracer(prepared, primary);
  const EmbreeLattice embree(n);
  const double pixels = static_cast<double>(resolution) * resolution;

  // The same rays answered by both: which sphere each pixel sees.
  std::int64_t differing = 0;
  {
    capsim::Tracer::Scratch s(prepared);
    for (int j = 0; j < resolution; ++j)
      for (int i = 0; i < resolution; ++i) {
        const capsim::Ray r = tracer.primary_ray(i, j);
        capsim::Hit h;
        capsim::OpCounts ops;
        const int ours = tracer.first_hit(r, s, ops, h) ? static_cast<int>(h.primitive) : -1;
        differing += ours != embree.closest(r);
      }
  }

  std::vector<Row> rows;
  for (const int threads : thread_counts) {
    std::vector<int> sink(resolution);  // results land somewhere so no loop is dropped
    const auto run_embree = [&] {
      for_rows<std::vector<capsim::Ray>>(
          resolution, threads, [&] { return std::vector<capsim::Ray>(resolution); },
          [&](int j, std::vector<capsim::Ray>& rays) {
            tracer.primary_rays(j, rays);
            int seen = 0;
            for (const capsim::Ray& r : rays) seen += embree.closest(r);
            sink[j] = seen;
          });
    };
    const auto run_hit = [&] {
      for_rows<HitWorker>(
          resolution, threads, [&] {
            return HitWorker{capsim::Tracer::Scratch(prepared), std::vector<capsim::Ray>(resolution)};
          },
          [&](int j, HitWorker& w) {
            tracer.primary_rays(j, w.rays);
            int seen = 0;
            for (const capsim::Ray& r : w.rays) {
              capsim::Hit h;
              capsim::OpCounts ops;
              if (tracer.first_hit(r, w.scratch, ops, h)) seen += h.primitive;
            }
            sink[j] = seen;
          });
    };
    const auto run_render = [&] { capsim::render(tracer, threads); };
    const std::vector<std::string> args = {
        CAPSIM_EXE, "render", scene_path.string(), "-o", image_path.string(), "--size",
        fmt::format("{}x{}", resolution, resolution), "--primary-only", "--threads",
        std::to_string(threads)};
    // Interleaved, so that every contender sees the same share of whatever else
    // the machine is doing.
    std::vector<Seconds> t_embree, t_hit, t_render, t_process;
    for (int r = 0; r < repeats; ++r) {
      t_embree.push_back(time_in_process(run_embree));
      t_hit.push_back(time_in_process(run_hit));
      t_render.push_back(time_in_process(run_render));
      t_process.push_back(run_process(args));
    }
    Row row;
    row.n = n;
    row.threads = threads;
    row.grid = prepared.grid.n;
    row.differing = differing;
    row.embree = rate(pixels, t_embree);
    row.hit = rate(pixels, t_hit);
    row.render = rate(pixels, t_render);
    row.process = rate(pixels, t_process);
    rows.push_back(row);
  }
  return rows;
}

void print_table(const std::vector<Row>& rows, bool cpu) {
  const auto pick = [cpu](const Rate& r) { return cpu ? r.cpu : r.wall; };
  fmt::print("{:>8} {:>6} {:>4} {:>7} | {:>7} | {:>7} {:>6} | {:>7} {:>6} | {:>7} {:>6} | {:>9}\n",
             "lattice", "balls", "N", "threads", "embree", "hit", "ratio", "render", "ratio",
             "process", "ratio", "px differ");
  for (const Row& r : rows) {
    if (cpu && r.threads != 1) continue;
    const double e = pick(r.embree);
    fmt::print("{:>8} {:>6} {:>4} {:>7} | {:>7.2f} | {:>7.2f} {:>6.2f} | {:>7.2f} {:>6.2f} | "
               "{:>7.2f} {:>6.2f} | {:>9}\n",
               fmt::format("{0}x{0}x{0}", r.n), r.n * r.n * r.n, r.grid, r.threads, e / 1e6,
               pick(r.hit) / 1e6, pick(r.hit) / e, pick(r.render) / 1e6, pick(r.render) / e,
               pick(r.process) / 1e6, pick(r.process) / e, r.differing);
  }
}

std::vector<int> parse_sizes(const std::string& text) {
  std::vector<int> out;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = text.find(',', start);
    out.push_back(std::stoi(text.substr(start, comma - start)));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<int> sizes = {5, 10, 19};
  int resolution = 1024, repeats = 5;
  std::string json_path;
  for (int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    const bool has_value = a + 1 < argc;
    if (arg == "--sizes" && has_value) sizes = parse_sizes(argv[++a]);
    else if (arg == "--resolution" && has_value) resolution = std::stoi(argv[++a]);
    else if (arg == "--repeats" && has_value) repeats = std::stoi(argv[++a]);
    else if (arg == "--json" && has_value) json_path = argv[++a];
    else {
      fmt::print(stderr,
                 "usage: bench_vs_embree [--sizes 5,10,19] [--resolution 1024] [--repeats 5] "
                 "[--json FILE]\n");
      return 2;
    }
  }
  if (!fs::exists(CAPSIM_EXE)) {
    fmt::print(stderr, "bench_vs_embree: {} not found; build the capsim target first\n", CAPSIM_EXE);
    return 1;
  }
  const int all = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  std::vector<int> thread_counts = {1};
  if (all > 1) thread_counts.push_back(all);

  std::string dir_template = (fs::temp_directory_path() / "capsim-bench-XXXXXX").string();
  if (!mkdtemp(dir_template.data())) {
    fmt::print(stderr, "bench_vs_embree: cannot create a temporary directory\n");
    return 1;
  }
  const fs::path dir = dir_template;

  std::vector<Row> rows;
  int status = 0;
  try {
    for (const int n : sizes) {
      const std::vector<Row> r = measure_lattice(n, resolution, repeats, dir, thread_counts);
      rows.insert(rows.end(), r.begin(), r.end());
      fmt::print(stderr, "bench_vs_embree: {0}x{0}x{0} done\n", n);
    }
  } catch (const std::exception& e) {
    fmt::print(stderr, "bench_vs_embree: {}\n", e.what());
    status = 1;
  }
  if (status == 0) {
    fmt::print("Primary rays per second (millions) from median wall time, {}x{} pixels, {} "
               "interleaved runs; ratio = capsim / embree\n",
               resolution, resolution, repeats);
    print_table(rows, false);
    fmt::print("\nThe same, one thread, from median CPU time (this process's; the capsim "
               "process's own)\n");
    print_table(rows, true);
  }
  if (!json_path.empty() && status == 0) {
    auto out = fmt::output_file(json_path);
    out.print("{{\n  \"resolution\": {}, \"repeats\": {},\n  \"rows\": [\n", resolution, repeats);
    for (std::size_t k = 0; k < rows.size(); ++k) {
      const Row& r = rows[k];
      const auto pair = [](const Rate& x) {
        return fmt::format("{{\"wall\": {:.0f}, \"cpu\": {:.0f}}}", x.wall, x.cpu);
      };
      out.print("    {{\"lattice\": {}, \"grid\": {}, \"threads\": {}, \"embree\": {}, "
                "\"capsim_hit\": {}, \"capsim_render\": {}, \"capsim_process\": {}, "
                "\"pixels_differing\": {}}}{}\n",
                r.n, r.grid, r.threads, pair(r.embree), pair(r.hit), pair(r.render),
                pair(r.process), r.differing, k + 1 < rows.size() ? "," : "");
    }
    out.print("  ]\n}}\n");
  }
  std::error_code ec;
  fs::remove_all(dir, ec);
  return status;
}
