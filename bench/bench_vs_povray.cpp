// CPU time of a full Whitted render by capsim against POV-Ray 3.7, one thread,
// on the same scenes: the goal is at least 5 times less CPU than POV-Ray.
//
//   bench_vs_povray [--size 512] [--repeats 3] [--json FILE] [--keep DIR] [--scene FILE]...
//
// Scenes: scenes/balls.csg, scenes/showcase.csg and a 10 x 10 x 10 lattice of
// polished spheres under two lights (written to a temporary directory), or
// the scene files given with --scene instead. Each is read with capsim's
// parser and written as POV-Ray SDL (pov/pov_scene.h:
// camera, point lights with shadows, background, primitives, CSG, materials,
// reflection and refraction to capsim's depth); a scene with a construct the
// writer cannot express is skipped, with the reason. Then, interleaved over
// the repeats, two child processes render it at SIZE x SIZE:
//   povray   povray +W +H -D +WT1 -A -P File_Gamma=sRGB (one render thread,
//            no display, no antialiasing; the scene asks for no radiosity
//            or photons);
//   capsim   capsim render SCENE -o OUT.png --size WxH --threads 1 (full
//            Whitted shading, one sample per pixel: its defaults).
// Each figure is the median of the child's CPU time (user + system, all its
// threads: parsing, set-up, tracing and PNG output); ratio = povray / capsim.
// The two images are compared as a check that they show the same scene: the
// mean and the largest absolute difference per channel (0-255), and the
// shares of pixels where some channel differs at all and by more than 32.
// The POV-Ray scene uses capsim's shading formulas, so the images should
// differ only by rounding; a wrong camera, a missing object or a material
// POV-Ray treats otherwise shows as a large share.
//
// Needs the capsim executable (CAPSIM_EXE) and povray on PATH.

#include "capsim/scene/parser.h"
#include "capsim/trace/tracer.h"
#include "pov/pov_scene.h"

#include <fmt/core.h>
#include <fmt/os.h>
#include <fcntl.h>
#include <png.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

extern char** environ;

namespace {

namespace fs = std::filesystem;

// --- The lattice scene ---------------------------------------------------------

// n^3 spheres of radius 0.8 on a 2-unit grid (the spacing of scenes/balls.csg),
// all polished, coloured across the lattice, seen from BALLS' direction with
// its two lights, everything scaled to the lattice's size.
std::string lattice_csg(int n, int size) {
  const double half = 0.5 * (n - 1) * 2.0;
  const double k = half / 4.0;  // BALLS' lattice is 4 units from centre to face
  std::string s = fmt::format("// {0} x {0} x {0} lattice of polished spheres, written by bench_vs_povray.\n", n);
  s += fmt::format("camera(eye = [{}, {}, {}], center = [0, 0, 0], up = [0, 0, 1], fov = 40, size = [{}, {}]);\n",
                   14 * k, -18 * k, 11 * k, size, size);
  s += fmt::format("light(position = [{}, {}, {}], color = [1, 1, 1]);\n", 20 * k, -10 * k, 25 * k);
  s += fmt::format("light(position = [{}, {}, {}], color = [0.35, 0.35, 0.4]);\n", -15 * k, -20 * k, 10 * k);
  s += "background(color = [0.08, 0.09, 0.14]);\n";
  s += "material(reflect = 0.3, specular = 0.5, shininess = 48) union() {\n";
  for (int z = 0; z < n; ++z)
    for (int y = 0; y < n; ++y)
      for (int x = 0; x < n; ++x) {
        const double f = 1.0 / std::max(1, n - 1);
        s += fmt::format("  color([{}, {}, {}]) translate([{}, {}, {}]) sphere(r = 0.8);\n", 0.25 + 0.6 * x * f,
                         0.3 + 0.5 * y * f, 0.85 - 0.3 * z * f, 2.0 * x - half, 2.0 * y - half, 2.0 * z - half);
      }
  return s + "}\n";
}

// --- Child processes -----------------------------------------------------------

// One child process to completion, its output (stdout and stderr) into `log`;
// its CPU time (all its threads, user + system). Throws, with the log's end,
// if it fails.
double run_process(const std::vector<std::string>& args, const fs::path& log) {
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t files;
  posix_spawn_file_actions_init(&files);
  posix_spawn_file_actions_addopen(&files, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&files, 1, 2);
  pid_t pid = 0;
  const int spawned = posix_spawnp(&pid, argv[0], &files, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&files);
  if (spawned != 0) throw std::runtime_error(fmt::format("cannot start {}", args[0]));
  int status = 0;
  rusage usage{};
  wait4(pid, &status, 0, &usage);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::ifstream in(log);
    std::stringstream text;
    text << in.rdbuf();
    const std::string all = text.str();
    throw std::runtime_error(fmt::format("{} failed (status {}); its output ends:\n{}", args[0], status,
                                         all.substr(all.size() > 2000 ? all.size() - 2000 : 0)));
  }
  const auto secs = [](const timeval& tv) { return tv.tv_sec + 1e-6 * tv.tv_usec; };
  return secs(usage.ru_utime) + secs(usage.ru_stime);
}

bool on_path(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "");
  for (std::string dir; std::getline(dirs, dir, ':');)
    if (!dir.empty() && access((fs::path(dir) / name).c_str(), X_OK) == 0) return true;
  return false;
}

// The first line of `povray --version` that names it ("POV-Ray 3.7.0.10...").
std::string povray_version(const fs::path& dir) {
  const fs::path log = dir / "version.txt";
  run_process({"povray", "--version"}, log);
  std::ifstream in(log);
  for (std::string line; std::getline(in, line);)
    if (line.rfind("POV-Ray", 0) == 0) return line;
  return "POV-Ray (version not reported)";
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// --- Image agreement -----------------------------------------------------------

struct Rgb8 {
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;
};

Rgb8 read_png(const fs::path& path) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&image, path.c_str()))
    throw std::runtime_error(fmt::format("{}: {}", path.string(), image.message));
  image.format = PNG_FORMAT_RGB;
  Rgb8 out;
  out.width = static_cast<int>(image.width);
  out.height = static_cast<int>(image.height);
  out.rgb.resize(PNG_IMAGE_SIZE(image));
  if (!png_image_finish_read(&image, nullptr, out.rgb.data(), 0, nullptr))
    throw std::runtime_error(fmt::format("{}: {}", path.string(), image.message));
  return out;
}

constexpr int kDifferBy = 32;  // of 255, in some channel

struct Agreement {
  double mean_abs = 0;    // per channel, 0-255
  int max_abs = 0;        // the largest difference in any channel
  double share_any = 0;   // of pixels with some channel apart at all
  double share_over = 0;  // of pixels with some channel more than kDifferBy apart
};

Agreement compare(const Rgb8& a, const Rgb8& b) {
  if (a.width != b.width || a.height != b.height)
    throw std::runtime_error(fmt::format("images differ in size: {}x{} and {}x{}", a.width, a.height, b.width,
                                         b.height));
  double sum = 0;
  int largest = 0;
  std::size_t any = 0, over = 0;
  const std::size_t pixels = static_cast<std::size_t>(a.width) * a.height;
  for (std::size_t p = 0; p < pixels; ++p) {
    int most = 0;
    for (int c = 0; c < 3; ++c) {
      const int d = std::abs(static_cast<int>(a.rgb[3 * p + c]) - static_cast<int>(b.rgb[3 * p + c]));
      sum += d;
      most = std::max(most, d);
    }
    largest = std::max(largest, most);
    any += most > 0;
    over += most > kDifferBy;
  }
  return {sum / (3.0 * pixels), largest, static_cast<double>(any) / pixels, static_cast<double>(over) / pixels};
}

// --- One scene -----------------------------------------------------------------

struct Row {
  std::string name;
  std::string skipped;  // the reason, when the scene was not measured
  double povray = 0, capsim = 0;  // median CPU seconds
  Agreement agreement;
};

Row measure(const std::string& name, const fs::path& scene_path, int size, int repeats, const fs::path& dir) {
  Row row;
  row.name = name;
  capsim::PrepareOptions options;
  options.width = options.height = size;
  const capsim::PreparedScene prepared = capsim::prepare_scene(capsim::parse_scene_file(scene_path.string()), options);
  const fs::path pov_path = dir / (name + ".pov");
  try {
    auto out = fmt::output_file(pov_path.string());
    out.print("{}", capsim::pov::pov_scene(prepared, capsim::TraceOptions{}.max_depth));
  } catch (const capsim::pov::Unsupported& e) {
    row.skipped = e.what();
    return row;
  }
  const fs::path pov_png = dir / (name + "-povray.png");
  const fs::path capsim_png = dir / (name + "-capsim.png");
  const std::string wh = std::to_string(size);
  const std::vector<std::string> povray = {
      "povray", "+I" + pov_path.string(), "+O" + pov_png.string(), "+FN8", "+W" + wh, "+H" + wh, "-D", "+WT1", "-A",
      "-P", "File_Gamma=sRGB"};
  const std::vector<std::string> capsim = {CAPSIM_EXE, "render", scene_path.string(), "-o", capsim_png.string(),
                                           "--size", fmt::format("{}x{}", size, size), "--threads", "1", "--quiet"};
  // Interleaved, so that both see the same share of whatever else the
  // machine is doing.
  std::vector<double> t_povray, t_capsim;
  for (int r = 0; r < repeats; ++r) {
    t_povray.push_back(run_process(povray, dir / (name + "-povray.log")));
    t_capsim.push_back(run_process(capsim, dir / (name + "-capsim.log")));
  }
  row.povray = median(t_povray);
  row.capsim = median(t_capsim);
  row.agreement = compare(read_png(pov_png), read_png(capsim_png));
  return row;
}

void print_table(const std::vector<Row>& rows) {
  fmt::print("{:<10} | {:>10} {:>10} {:>6} | {:>8} {:>6} {:>8} {:>8}\n", "scene", "povray s", "capsim s", "ratio",
             "mean|d|", "max|d|", "px d>0", fmt::format("px d>{}", kDifferBy));
  for (const Row& r : rows) {
    if (!r.skipped.empty()) {
      fmt::print("{:<10} | skipped: {}\n", r.name, r.skipped);
      continue;
    }
    fmt::print("{:<10} | {:>10.3f} {:>10.3f} {:>6.2f} | {:>8.3f} {:>6} {:>7.3f}% {:>7.3f}%\n", r.name, r.povray,
               r.capsim, r.povray / r.capsim, r.agreement.mean_abs, r.agreement.max_abs, 100 * r.agreement.share_any,
               100 * r.agreement.share_over);
  }
}

void write_json(const std::string& path, const std::string& version, int size, int repeats,
                const std::vector<Row>& rows) {
  auto out = fmt::output_file(path);
  out.print("{{\n  \"povray\": \"{}\", \"size\": {}, \"repeats\": {},\n  \"scenes\": [\n", version, size, repeats);
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const Row& r = rows[k];
    const char* comma = k + 1 < rows.size() ? "," : "";
    if (!r.skipped.empty()) {
      std::string reason;
      for (const char c : r.skipped) reason += c == '"' || c == '\\' ? std::string("\\") + c : std::string(1, c);
      out.print("    {{\"scene\": \"{}\", \"skipped\": \"{}\"}}{}\n", r.name, reason, comma);
      continue;
    }
    out.print("    {{\"scene\": \"{}\", \"povray_cpu_s\": {:.4f}, \"capsim_cpu_s\": {:.4f}, \"ratio\": {:.3f}, "
              "\"mean_abs_diff\": {:.4f}, \"max_abs_diff\": {}, \"share_differing\": {:.6f}, "
              "\"share_over_{}\": {:.6f}}}{}\n",
              r.name, r.povray, r.capsim, r.povray / r.capsim, r.agreement.mean_abs, r.agreement.max_abs,
              r.agreement.share_any, kDifferBy, r.agreement.share_over, comma);
  }
  out.print("  ]\n}}\n");
}

}  // namespace

int main(int argc, char** argv) {
  int size = 512, repeats = 3;
  std::string json_path, keep;
  std::vector<fs::path> scene_files;
  for (int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    const bool has_value = a + 1 < argc;
    if (arg == "--size" && has_value) size = std::stoi(argv[++a]);
    else if (arg == "--repeats" && has_value) repeats = std::stoi(argv[++a]);
    else if (arg == "--json" && has_value) json_path = argv[++a];
    else if (arg == "--keep" && has_value) keep = argv[++a];
    else if (arg == "--scene" && has_value) scene_files.emplace_back(argv[++a]);
    else {
      fmt::print(stderr,
                 "usage: bench_vs_povray [--size 512] [--repeats 3] [--json FILE] [--keep DIR] [--scene FILE]...\n");
      return 2;
    }
  }
  if (size < 1 || repeats < 1) {
    fmt::print(stderr, "bench_vs_povray: --size and --repeats must be at least 1\n");
    return 2;
  }
  if (!on_path("povray")) {
    fmt::print(stderr, "bench_vs_povray: povray is not on PATH; install POV-Ray 3.7 (Debian: apt-get install povray)\n");
    return 1;
  }
  if (!fs::exists(CAPSIM_EXE)) {
    fmt::print(stderr, "bench_vs_povray: {} not found; build the capsim target first\n", CAPSIM_EXE);
    return 1;
  }
  // --keep: the scenes, POV-Ray files, images and logs stay there to be looked at.
  fs::path dir;
  if (keep.empty()) {
    std::string dir_template = (fs::temp_directory_path() / "capsim-povray-XXXXXX").string();
    if (!mkdtemp(dir_template.data())) {
      fmt::print(stderr, "bench_vs_povray: cannot create a temporary directory\n");
      return 1;
    }
    dir = dir_template;
  } else {
    dir = fs::absolute(keep);
    fs::create_directories(dir);
  }

  std::vector<Row> rows;
  std::string version;
  int status = 0;
  try {
    version = povray_version(dir);
    std::vector<std::pair<std::string, fs::path>> measured;
    for (const fs::path& f : scene_files) measured.emplace_back(f.stem().string(), fs::absolute(f));
    if (measured.empty()) {
      const fs::path lattice = dir / "lattice10.csg";
      auto out = fmt::output_file(lattice.string());
      out.print("{}", lattice_csg(10, size));
      out.close();  // written before capsim reads it
      const fs::path scenes = fs::path(CAPSIM_SOURCE_DIR) / "scenes";
      measured = {{"balls", scenes / "balls.csg"}, {"showcase", scenes / "showcase.csg"}, {"lattice10", lattice}};
    }
    for (const auto& [name, path] : measured) {
      rows.push_back(measure(name, path, size, repeats, dir));
      fmt::print(stderr, "bench_vs_povray: {} done\n", name);
    }
  } catch (const std::exception& e) {
    fmt::print(stderr, "bench_vs_povray: {}\n", e.what());
    status = 1;
  }
  if (status == 0) {
    fmt::print("{}; median CPU seconds (user + system) of each process over {} interleaved runs, {}x{} pixels, "
               "one thread; ratio = povray / capsim\n",
               version, repeats, size, size);
    print_table(rows);
    if (!json_path.empty()) write_json(json_path, version, size, repeats, rows);
  }
  if (keep.empty()) {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
  return status;
}
