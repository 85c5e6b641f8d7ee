#include "paper/sweeps/sweep_spec.h"

#include "capsim/trace/antialias.h"
#include "capsim/trace/prepared_scene.h"
#include "capsim/trace/voxel_grid.h"
#include "machine/costs/cost_profile.h"

#include <fmt/core.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <regex>
#include <sstream>

namespace capsim::sim {

namespace {

using nlohmann::json;

// The most frames a {"scene", "frames"} takes, as simulate's --frames.
constexpr int kMaxSweepFrames = 99999;

const std::vector<std::string> kAxes = {"scenes",        "sizes",   "profiles",         "grid",
                                        "primary_only",  "aa",      "frame_average",    "balance",
                                        "voxel_generation", "modes", "cells"};

struct Context {
  std::string file;
  std::filesystem::path dir;  // the sweep file's, against which paths resolve

  [[noreturn]] void fail(const std::string& where, const std::string& message) const {
    throw SweepSpecError(fmt::format("{}: {}: {}", file, where, message));
  }
  std::string resolve(const std::string& path) const {
    return std::filesystem::path(path).is_absolute() ? path : (dir / path).lexically_normal().string();
  }
};

bool readable_file(const std::string& path) {
  std::error_code ec;
  return std::filesystem::is_regular_file(path, ec) && std::ifstream(path).good();
}

int whole(const Context& c, const json& v, const std::string& where, int lo, int hi) {
  if (!v.is_number_integer()) c.fail(where, fmt::format("{} is not a whole number (accepted: {} to {})", v.dump(), lo, hi));
  const auto n = v.get<long long>();
  if (n < lo || n > hi) c.fail(where, fmt::format("{} is out of range (accepted: {} to {})", v.dump(), lo, hi));
  return static_cast<int>(n);
}

std::string text(const Context& c, const json& v, const std::string& where, const std::string& accepted) {
  if (!v.is_string()) c.fail(where, fmt::format("{} is not a string (accepted: {})", v.dump(), accepted));
  return v.get<std::string>();
}

// "AxB", each from 1 to hi.
std::pair<int, int> pair_of(const Context& c, const json& v, const std::string& where, int hi) {
  const std::string accepted = fmt::format("1x1 to {0}x{0}", hi);
  const std::string s = text(c, v, where, accepted);
  static const std::regex form(R"(([0-9]{1,9})x([0-9]{1,9}))");
  std::smatch m;
  if (!std::regex_match(s, m, form)) c.fail(where, fmt::format("{} is not of the form AxB (accepted: {})", v.dump(), accepted));
  const int a = std::stoi(m[1]), b = std::stoi(m[2]);
  if (a < 1 || b < 1 || a > hi || b > hi)
    c.fail(where, fmt::format("{} is out of range (accepted: {})", v.dump(), accepted));
  return {a, b};
}

bool boolean(const Context& c, const json& v, const std::string& where) {
  if (!v.is_boolean()) c.fail(where, fmt::format("{} is not true or false", v.dump()));
  return v.get<bool>();
}

std::string scene_file(const Context& c, const json& v, const std::string& where) {
  const std::string path = c.resolve(text(c, v, where, "a scene file's path"));
  if (!readable_file(path)) c.fail(where, fmt::format("{} is not a readable file", v.dump()));
  return path;
}

SweepScene scene(const Context& c, const json& v, const std::string& where) {
  SweepScene s;
  s.written = v;
  if (v.is_array()) {
    if (v.empty()) c.fail(where, "a sequence needs at least one file");
    for (std::size_t i = 0; i < v.size(); ++i) s.files.push_back(scene_file(c, v[i], fmt::format("{}[{}]", where, i)));
  } else if (v.is_object()) {
    for (const auto& [key, value] : v.items())
      if (key != "scene" && key != "frames")
        c.fail(where + "." + key, "is not a key of an animated scene (accepted: scene, frames)");
    if (!v.contains("scene") || !v.contains("frames")) c.fail(where, "an animated scene needs \"scene\" and \"frames\"");
    s.files = {scene_file(c, v["scene"], where + ".scene")};
    s.frames = whole(c, v["frames"], where + ".frames", 1, kMaxSweepFrames);
  } else {
    s.files = {scene_file(c, v, where)};
  }
  return s;
}

std::string profile(const Context& c, const json& v, const std::string& where, std::string& path) {
  const std::string name = text(c, v, where, "cap, m380 or a profile file");
  const std::vector<std::string> builtin = builtin_profile_names();
  if (std::find(builtin.begin(), builtin.end(), name) != builtin.end()) {
    path = name;
    return name;
  }
  path = c.resolve(name);
  if (!readable_file(path))
    c.fail(where, fmt::format("{} is neither a built-in profile nor a readable file (accepted: cap, m380 or a "
                              "profile file)",
                              v.dump()));
  return name;
}

// Applies axis value v (at `where`) to p.
void apply(const Context& c, const std::string& axis, const json& v, const std::string& where, SweepPoint& p) {
  if (axis == "scenes") {
    p.scene = scene(c, v, where);
  } else if (axis == "cells") {
    const auto [r, k] = pair_of(c, v, where, kMaxGridSide);
    p.cells = CellGrid{r, k};
  } else if (axis == "modes") {
    const auto mode = parse_pixel_mode(text(c, v, where, "block, line or dot"));
    if (!mode) c.fail(where, fmt::format("{} is not a pixel mode (accepted: block, line or dot)", v.dump()));
    p.mode = *mode;
  } else if (axis == "aa") {
    p.aa_depth = whole(c, v, where, 0, kMaxAntialiasDepth);
  } else if (axis == "profiles") {
    p.profile = profile(c, v, where, p.profile_path);
  } else if (axis == "sizes") {
    std::tie(p.width, p.height) = pair_of(c, v, where, kMaxImageSide);
  } else if (axis == "grid") {
    p.grid = v.is_string() && v.get<std::string>() == "auto" ? 0 : whole(c, v, where, 1, kMaxGridDivisions);
  } else if (axis == "primary_only") {
    p.primary_only = boolean(c, v, where);
  } else if (axis == "balance") {
    const std::string scheme = text(c, v, where, "static, demand, demand:TILE, steal or steal:CHUNK");
    try {
      p.balance = parse_balance(scheme);
    } catch (const std::invalid_argument& e) {
      c.fail(where, fmt::format("{}: {}", v.dump(), e.what()));
    }
  } else if (axis == "voxel_generation") {
    const auto by = parse_voxel_generation(text(c, v, where, "host or cells"));
    if (!by) c.fail(where, fmt::format("{} is not who generates the voxels (accepted: host or cells)", v.dump()));
    p.voxel_generation = *by;
  } else {
    p.frame_average = boolean(c, v, where);
  }
}

}  // namespace

std::string LeftOutPoints::summary() const {
  if (total() == 0) return "";
  std::string reasons;
  for (const auto& [n, why] : {std::pair{frame_average_outside_dot, "frame_average outside dot mode"},
                               std::pair{frame_average_balanced, "frame_average with demand or steal"},
                               std::pair{demand_per_mode, "demand points repeated per mode"}})
    if (n > 0) reasons += fmt::format("{}{} {}", reasons.empty() ? "" : ", ", n, why);
  return fmt::format("{} left out: {}", total(), reasons);
}

SweepSpec parse_sweep_spec(const std::string& text, const std::string& file) {
  Context c{file, std::filesystem::path(file).parent_path()};
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::parse_error& e) {
    throw SweepSpecError(fmt::format("{}: not JSON: {}", file, e.what()));
  }
  if (!doc.is_object()) c.fail("(top)", "a sweep file is an object with \"axes\"");
  for (const auto& [key, value] : doc.items())
    if (key != "axes") c.fail(key, "is not a key of a sweep file (accepted: axes)");
  if (!doc.contains("axes") || !doc["axes"].is_object()) c.fail("axes", "an object of axes is required");
  const json& axes = doc["axes"];
  for (const auto& [key, value] : axes.items()) {
    if (std::find(kAxes.begin(), kAxes.end(), key) == kAxes.end())
      c.fail("axes." + key, "is not an axis (accepted: scenes, cells, modes, balance, voxel_generation, aa, profiles, "
                            "sizes, grid, primary_only, frame_average)");
    if (!value.is_array() || value.empty()) c.fail("axes." + key, "an axis is a list of one value or more");
  }
  if (!axes.contains("scenes")) c.fail("axes.scenes", "is required: the scenes to run");

  // The last axis varies fastest; every value is checked as the first point takes it.
  std::vector<SweepPoint> points(1);
  for (const std::string& axis : kAxes) {
    if (!axes.contains(axis)) continue;
    const json& values = axes[axis];
    std::vector<SweepPoint> next;
    for (const SweepPoint& p : points)
      for (std::size_t i = 0; i < values.size(); ++i) {
        SweepPoint q = p;
        apply(c, axis, values[i], fmt::format("axes.{}[{}]", axis, i), q);
        next.push_back(q);
      }
    points = std::move(next);
  }
  // A demand point stands for every mode: it is kept at the first.
  PixelMode first_mode = PixelMode::Dot;
  if (axes.contains("modes")) first_mode = *parse_pixel_mode(axes["modes"][0].get<std::string>());
  SweepSpec spec;
  for (SweepPoint& p : points) {
    // The dot pattern turns only in dot mode, and demand and steal share one
    // frame's work at a time: simulate refuses these combinations, which a
    // cross product of the axes yields.
    if (!p.balance.is_static() && p.frame_average) {
      ++spec.left_out.frame_average_balanced;
    } else if (p.balance.on_demand() && p.mode != first_mode) {
      ++spec.left_out.demand_per_mode;
    } else if (p.frame_average && p.mode != PixelMode::Dot) {
      ++spec.left_out.frame_average_outside_dot;
    } else {
      if (p.balance.on_demand()) p.mode = PixelMode::Dot;  // simulate's default, which the tiles override
      spec.points.push_back(std::move(p));
    }
  }
  return spec;
}

std::string read_sweep_text(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw SweepSpecError(fmt::format("{}: cannot read the sweep file", file));
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

SweepSpec read_sweep_spec(const std::string& file) { return parse_sweep_spec(read_sweep_text(file), file); }

json sweep_inputs(const SweepPoint& p) {
  return {{"scene", p.scene.written},
          {"cells", to_string(p.cells)},
          {"mode", p.balance.on_demand() ? std::string("tiles") : std::string(to_string(p.mode))},
          {"balance", to_string(p.balance)},
          {"aa", p.aa_depth},
          {"profile", p.profile},
          {"size", p.width > 0 ? fmt::format("{}x{}", p.width, p.height) : std::string("camera")},
          {"grid", p.grid > 0 ? json(p.grid) : json("auto")},
          {"primary_only", p.primary_only},
          {"frame_average", p.frame_average},
          {"voxel_generation", to_string(p.voxel_generation)}};
}

}  // namespace capsim::sim
