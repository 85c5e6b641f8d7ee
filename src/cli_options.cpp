#include "cli_options.h"

#include "capsim/image_io.h"
#include "capsim/parser.h"

#include <fmt/core.h>

#include <charconv>
#include <filesystem>
#include <stdexcept>

namespace capsim::cli {

namespace {

int parse_int(const std::string& text, const char* what) {
  int v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || end != text.data() + text.size())
    throw std::invalid_argument(fmt::format("{} '{}' is not a whole number", what, text));
  return v;
}

}  // namespace

void add_tracer_options(CLI::App& cmd, TracerOptions& o) {
  cmd.add_option("scene", o.scene, "Scene file (OpenSCAD CSG grammar; see docs/scene-format.md)")
      ->required();
  cmd.add_option("-o,--output", o.output, "Output image: .png (8-bit sRGB) or .exr (linear float "
                                          "R, G, B, A, Z, id)")
      ->required();
  cmd.add_option("--size", o.size, "Image size WxH (default: the scene camera's, or 512x512)");
  cmd.add_option("--grid", o.grid,
                 "Voxel grid divisions per axis, 1 to 256, or 'auto' (twice the cube root of "
                 "the primitive count, 8 to 64)")
      ->default_val("auto");
  cmd.add_option("--threads", o.threads, "Host threads (0 = all hardware threads); the output "
                                         "does not depend on it")
      ->default_val(0)
      ->check(CLI::NonNegativeNumber);
  cmd.add_flag("--primary-only", o.primary_only,
               "Trace only primary rays with local shading (no shadow, reflection or "
               "refraction rays), as in the paper's Table 4-2");
  cmd.add_option("--aa", o.aa_depth,
                 fmt::format("Adaptive antialiasing from pixel-corner samples, 0 to {} levels of "
                             "subdivision (0 = one sample at each pixel centre; docs/antialiasing.md)",
                             kMaxAntialiasDepth))
      ->default_val(0)
      ->check(CLI::Range(0, kMaxAntialiasDepth));
  cmd.add_option("--aa-threshold", o.aa_threshold,
                 "Split a square whose corners differ by this much or more: |dR|+|dG|+|dB| of "
                 "the 8-bit sRGB colours / 255, 0 to 3")
      ->default_val(0.3)
      ->check(CLI::Range(0.0, 3.0));
}

PreparedScene load_scene(const TracerOptions& o) {
  if (!is_supported_image_path(o.output))
    throw std::invalid_argument(fmt::format("{}: unsupported image type (use .png or .exr)", o.output));
  const std::filesystem::path dir = std::filesystem::path(o.output).parent_path();
  if (!dir.empty() && !std::filesystem::is_directory(dir))
    throw std::invalid_argument(fmt::format("{}: directory {} does not exist", o.output, dir.string()));

  PrepareOptions p;
  if (!o.size.empty()) {
    const auto x = o.size.find('x');
    if (x == std::string::npos)
      throw std::invalid_argument(fmt::format("--size '{}' is not WxH (e.g. 640x480)", o.size));
    p.width = parse_int(o.size.substr(0, x), "--size width");
    p.height = parse_int(o.size.substr(x + 1), "--size height");
    if (p.width <= 0 || p.height <= 0)
      throw std::invalid_argument(fmt::format("--size '{}' must be positive", o.size));
  }
  if (o.grid != "auto") {
    p.grid = parse_int(o.grid, "--grid");
    if (p.grid < 1)
      throw std::invalid_argument(fmt::format("--grid {} is out of range (1 to {}, or auto)", p.grid,
                                              kMaxGridDivisions));
  }
  return prepare_scene(parse_scene_file(o.scene), p);
}

capsim::AntialiasOptions antialias_options(const TracerOptions& o) {
  return {o.aa_depth, o.aa_threshold};
}

capsim::TraceOptions trace_options(const TracerOptions& o) {
  capsim::TraceOptions t;
  t.primary_only = o.primary_only;
  return t;
}

}  // namespace capsim::cli
