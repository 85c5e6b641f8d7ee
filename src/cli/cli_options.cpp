#include "cli/cli_options.h"

#include "capsim/image_io.h"
#include "capsim/memory_limit.h"
#include "capsim/parser.h"
#include "cli/cli_usage.h"

#include <fmt/core.h>

#include <cctype>
#include <charconv>
#include <filesystem>
#include <limits>

namespace capsim::cli {

void add_tracer_options(CLI::App& cmd, TracerOptions& o) {
  cmd.add_option("scene", o.scenes,
                 "Scene file (OpenSCAD CSG grammar; see docs/scene-format.md); several files are the "
                 "frames of one sequence, e.g. OpenSCAD's --animate exports (docs/animation.md)");
  cmd.add_option("--frames", o.frames,
                 fmt::format("Animate the one scene file as 'openscad --animate K' does: K frames, "
                             "1 to {}, at $t = k / K for k = 0 .. K-1, written as out00000.png, ... "
                             "(docs/animation.md)",
                             kMaxFramesOption));
  cmd.add_option("-o,--output", o.output, "Output image (required): .png (8-bit sRGB) or .exr (linear "
                                          "float R, G, B, A, Z, id)");
  cmd.add_option("--size", o.size,
                 fmt::format("Image size WxH, W and H from 1 to {} (default: the scene camera's, or "
                             "512x512)",
                             kMaxImageSide));
  cmd.add_option("--grid", o.grid,
                 fmt::format("Voxel grid divisions per axis, 1 to {}, or 'auto' (twice the cube root of "
                             "the primitive count, 8 to 64)",
                             kMaxGridDivisions))
      ->default_val("auto");
  cmd.add_option("--threads", o.threads,
                 fmt::format("Host threads, 0 to {} (0 = all hardware threads; more than the host has "
                             "run as many as it has); the output does not depend on it",
                             kMaxThreadsOption))
      ->default_val("0");
  cmd.add_option("--max-memory", o.max_memory,
                 "Refuse a run whose image buffers would need more memory than this: bytes, or with K, "
                 "M, G or T (powers of 1024), e.g. 8G (default: the memory available, or less if the "
                 "process has a limit; see README)");
  cmd.add_flag("--primary-only", o.primary_only,
               "Trace only primary rays with local shading (no shadow, reflection or "
               "refraction rays), as in the paper's Table 4-2");
  cmd.add_option("--aa", o.aa,
                 fmt::format("Adaptive antialiasing from pixel-corner samples, 0 to {} levels of "
                             "subdivision (0 = one sample at each pixel centre; docs/antialiasing.md)",
                             kMaxAntialiasDepth))
      ->default_val("0");
  cmd.add_option("--aa-threshold", o.aa_threshold,
                 "Split a square whose corners differ by this much or more: |dR|+|dG|+|dB| of the "
                 "8-bit sRGB colours / 255, 0 to 3")
      ->default_val("0.3");
}

int parse_whole_option(const std::string& option, const std::string& value, int lo, int hi) {
  long long v = 0;
  const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), v);
  if (value.empty() || end != value.data() + value.size()) refuse(option, value, "is not a whole number");
  if (ec == std::errc::result_out_of_range || v < lo || v > hi) refuse(option, value, "is out of range");
  return static_cast<int>(v);
}

double parse_number_option(const std::string& option, const std::string& value, double lo, double hi) {
  double v = 0;
  const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), v);
  if (value.empty() || end != value.data() + value.size() || ec != std::errc()) refuse(option, value, "is not a number");
  if (!(v >= lo && v <= hi)) refuse(option, value, "is out of range");
  return v;
}

std::pair<int, int> parse_pair_option(const std::string& option, const std::string& value,
                                      const std::string& form, int max) {
  const auto x = value.find_first_of("xX");
  if (x == std::string::npos) refuse(option, value, "is not " + form);
  const auto side = [&](const std::string& text) {
    long long v = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (text.empty() || end != text.data() + text.size()) refuse(option, value, "is not " + form);
    if (ec == std::errc::result_out_of_range || v < 1 || v > max) refuse(option, value, "is out of range");
    return static_cast<int>(v);
  };
  const int first = side(value.substr(0, x));
  return {first, side(value.substr(x + 1))};
}

std::uint64_t parse_bytes_option(const std::string& option, const std::string& value) {
  std::string digits = value;
  int shift = 0;
  if (!digits.empty()) {
    const std::string units = "KMGT";
    const auto unit = units.find(static_cast<char>(std::toupper(static_cast<unsigned char>(digits.back()))));
    if (unit != std::string::npos) {
      shift = 10 * static_cast<int>(unit + 1);
      digits.pop_back();
    }
  }
  std::uint64_t v = 0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), v);
  if (digits.empty() || end != digits.data() + digits.size()) refuse(option, value, "is not a size");
  if (ec == std::errc::result_out_of_range || v == 0 || v > (std::numeric_limits<std::uint64_t>::max() >> shift))
    refuse(option, value, "is out of range");
  return v << shift;
}

TracerSettings check_tracer_options(const TracerOptions& o) {
  TracerSettings s;
  if (o.scenes.empty()) throw UsageError(fmt::format("SCENE is required (accepted: {})", accepted_values("scene")));
  s.scenes = o.scenes;
  s.frames = static_cast<int>(o.scenes.size());
  if (!o.frames.empty()) {
    if (o.scenes.size() > 1)
      throw UsageError(fmt::format("--frames animates one scene file, not a sequence of {} (the files of a "
                                   "sequence already are its frames)",
                                   o.scenes.size()));
    s.frames = parse_whole_option("--frames", o.frames, 1, kMaxFramesOption);
    s.animate = true;
  }
  if (o.output.empty())
    throw UsageError(fmt::format("-o/--output is required (accepted: {})", accepted_values("--output")));
  if (!is_supported_image_path(o.output)) refuse("--output", o.output, "has an unsupported image type");
  s.output = o.output;
  if (!o.size.empty())
    std::tie(s.prepare.width, s.prepare.height) = parse_pair_option("--size", o.size, "WxH", kMaxImageSide);
  if (o.grid != "auto") s.prepare.grid = parse_whole_option("--grid", o.grid, 1, kMaxGridDivisions);
  s.threads = parse_whole_option("--threads", o.threads, 0, kMaxThreadsOption);
  if (!o.max_memory.empty()) s.max_memory = parse_bytes_option("--max-memory", o.max_memory);
  s.trace.primary_only = o.primary_only;
  s.aa.depth = parse_whole_option("--aa", o.aa, 0, kMaxAntialiasDepth);
  s.aa.threshold = parse_number_option("--aa-threshold", o.aa_threshold, 0, 3);
  return s;
}

namespace {

// Refuses an image whose buffers would not fit, before any of them is allocated.
void check_memory(const TracerSettings& s, ImageSize size, const MemoryNeed& need, int frames) {
  const std::uint64_t bytes = need(size, frames);
  MemoryLimit limit{s.max_memory, "set by --max-memory"};
  if (s.max_memory == 0) {
    const std::optional<MemoryLimit> tightest_limit = tightest(process_memory_limits());
    if (!tightest_limit) return;  // nothing known to compare with
    limit = *tightest_limit;
  }
  if (bytes <= limit.bytes) return;
  throw UsageError(fmt::format(
      "{} needs about {} of image buffers, more than the {} {}; give a smaller --size{}",
      frames == 1 ? fmt::format("a {}x{} image", size.width, size.height)
                  : fmt::format("{} frames of {}x{}", frames, size.width, size.height),
      format_bytes(bytes), format_bytes(limit.bytes), limit.source,
      s.max_memory == 0 ? ", or --max-memory to set the limit" : " or a larger --max-memory"));
}

}  // namespace

std::vector<PreparedScene> load_scenes(const TracerSettings& s, const MemoryNeed& need) {
  std::vector<Scene> scenes;
  scenes.reserve(s.scenes.size());
  if (s.animate) {
    // Read once: every frame sees the same text.
    const std::string text = read_scene_file(s.scenes[0]);
    for (int k = 0; k < s.frames; ++k) scenes.push_back(parse_scene(text, s.scenes[0], {}, animation_time(k, s.frames)));
  } else {
    for (const std::string& file : s.scenes) scenes.push_back(parse_scene_file(file));
  }
  // Every frame takes the first one's size: --size, or the first camera's.
  const ImageSize size = image_size(scenes[0], s.prepare);
  check_memory(s, size, need, static_cast<int>(scenes.size()));
  PrepareOptions prepare = s.prepare;
  prepare.width = size.width;
  prepare.height = size.height;
  std::vector<PreparedScene> prepared;
  prepared.reserve(scenes.size());
  for (Scene& scene : scenes) prepared.push_back(prepare_scene(std::move(scene), prepare));
  frame_sequence(prepared);
  return prepared;
}

double animation_time(int k, int frames) { return k * (1.0 / frames); }

std::string frame_output_option(int k, bool numbered) {
  return numbered ? fmt::format("--output (frame {})", k) : "--output";
}

std::string frame_output(const std::string& output, int k, bool numbered) {
  if (!numbered) return output;
  const std::filesystem::path p(output);
  return (p.parent_path() / fmt::format("{}{:05d}{}", p.stem().string(), k, p.extension().string())).string();
}

}  // namespace capsim::cli
