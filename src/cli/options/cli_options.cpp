#include "cli/options/cli_options.h"

#include "capsim/image/image_io.h"
#include "capsim/scene/parser.h"
#include "capsim/system/memory_limit.h"
#include "cli/options/cli_usage.h"
#include "cli/console.h"
#include "cli/scad_export.h"

#include <fmt/core.h>

#include <filesystem>
#include <tuple>

namespace capsim::cli {

CLI::Validator image_size_check() {
  return whole_number_pair("WxH", kMaxImageSide)
      .description(fmt::format("WxH, W and H whole numbers from 1 to {}, e.g. 640x480", kMaxImageSide));
}

CLI::Validator host_threads_check() {
  return whole_number(0, kMaxThreadsOption)
      .description(fmt::format("0 to {}; 0 = all hardware threads", kMaxThreadsOption));
}

CLI::Validator image_output_check() {
  return satisfying(is_supported_image_path, "has an unsupported image type")
      .description("a path ending in .png or .exr");
}

CLI::Validator shipped_models_check() {
  return refusing(CLI::ExistingDirectory, "is not a directory")
      .description("a directory holding the shipped models (balls.csg, chess.csg, ..., disb/)");
}

CLI::Validator flag_values() { return CLI::Validator("no value, or true or false"); }

void add_tracer_options(CLI::App& cmd, TracerOptions& o) {
  add_option(cmd, "scene", o.scenes,
             "Scene file (OpenSCAD CSG grammar; see docs/scene-format.md); several files are the frames of one "
             "sequence, e.g. OpenSCAD's --animate exports (docs/animation.md)",
             CLI::Validator("one or more scene files in the CSG grammar of docs/scene-format.md (several are the "
                            "frames of a sequence)"));
  add_option(cmd, "--frames", o.frames,
             fmt::format("Animate the one scene file as 'openscad --animate K' does: K frames, 1 to {}, at $t = k "
                         "/ K for k = 0 .. K-1, written as out00000.png, ... (docs/animation.md)",
                         kMaxFramesOption),
             whole_number(1, kMaxFramesOption)
                 .description(fmt::format("1 to {}, with one scene file", kMaxFramesOption)));
  add_option(cmd, "-o,--output", o.output,
             "Output image (required): .png (8-bit sRGB) or .exr (linear float R, G, B, A, Z, id)",
             image_output_check());
  add_option(cmd, "--size", o.size,
             fmt::format("Image size WxH, W and H from 1 to {} (default: the scene camera's, or 512x512)",
                         kMaxImageSide),
             image_size_check());
  add_option(cmd, "--grid", o.grid,
             fmt::format("Voxel grid divisions per axis, 1 to {}, or 'auto' (twice the cube root of the primitive "
                         "count, 8 to 64)",
                         kMaxGridDivisions),
             CLI::Validator(
                 [whole = whole_number(1, kMaxGridDivisions)](std::string& value) {
                   return value == "auto" ? std::string() : whole(value);
                 },
                 fmt::format("1 to {}, or auto", kMaxGridDivisions)))
      ->default_val("auto");
  add_option(cmd, "--threads", o.threads,
             fmt::format("Host threads, 0 to {} (0 = all hardware threads; more than the host has run as many as "
                         "it has); the output does not depend on it",
                         kMaxThreadsOption),
             host_threads_check())
      ->default_val("0");
  add_option(cmd, "--max-memory", o.max_memory,
             "Refuse a run whose image buffers would need more memory than this: bytes, or with K, M, G or T "
             "(powers of 1024), e.g. 8G (default: the memory available, or less if the process has a limit; see "
             "README)",
             byte_size().description("a whole number of bytes, or of K, M, G or T (powers of 1024), e.g. 8G"));
  accepts(cmd.add_flag("--primary-only", o.primary_only,
                       "Trace only primary rays with local shading (no shadow, reflection or refraction rays), as "
                       "in the paper's Table 4-2"),
          flag_values());
  add_option(cmd, "--aa", o.aa,
             fmt::format("Adaptive antialiasing from pixel-corner samples, 0 to {} levels of subdivision (0 = one "
                         "sample at each pixel centre; docs/antialiasing.md)",
                         kMaxAntialiasDepth),
             whole_number(0, kMaxAntialiasDepth)
                 .description(fmt::format("0 to {}; 0 = one sample at each pixel centre", kMaxAntialiasDepth)))
      ->default_val("0");
  add_option(cmd, "--aa-threshold", o.aa_threshold,
             "Split a square whose corners differ by this much or more: |dR|+|dG|+|dB| of the 8-bit sRGB "
             "colours / 255, 0 to 3",
             decimal_number(0, 3).description("a number from 0 to 3"))
      ->default_val("0.3");
  add_openscad_options(cmd, o.openscad);
  accepts(cmd.add_flag("--verbose", o.verbose,
                       "Print the camera used, as OpenSCAD options that give the same view (docs/openscad.md)"),
          flag_values());
  add_option(cmd, "-D", o.defines,
             "For .scad input: an OpenSCAD variable assignment var=value, passed to openscad as its -D "
             "(repeatable; docs/scene-format.md)",
             CLI::Validator("var=value, as OpenSCAD's -D takes it"))
      ->allow_extra_args(false);
}

TracerSettings check_tracer_options(const TracerOptions& o) {
  TracerSettings s;
  if (o.scenes.text.empty())
    throw UsageError(fmt::format("SCENE is required (accepted: {})", accepted_values(*o.scenes.option)));
  s.scenes = o.scenes.text;
  s.frames = static_cast<int>(s.scenes.size());
  if (!o.frames.text.empty()) {
    if (s.scenes.size() > 1)
      throw UsageError(fmt::format("--frames animates one scene file, not a sequence of {} (the files of a "
                                   "sequence already are its frames)",
                                   s.scenes.size()));
    s.frames = whole_value(checked(o.frames));
    s.animate = true;
  }
  if (o.output.text.empty())
    throw UsageError(fmt::format("-o/--output is required (accepted: {})", accepted_values(*o.output.option)));
  s.output = checked(o.output);
  if (!o.size.text.empty()) std::tie(s.prepare.width, s.prepare.height) = pair_value(checked(o.size));
  if (const auto imgsize = check_imgsize(o.openscad)) {
    if (!o.size.text.empty() && *imgsize != std::pair{s.prepare.width, s.prepare.height})
      throw UsageError(fmt::format("--size {} and --imgsize {} give different image sizes; give one of them",
                                   o.size.text, o.openscad.imgsize.text));
    std::tie(s.prepare.width, s.prepare.height) = *imgsize;
  }
  s.prepare.openscad = check_openscad_camera(o.openscad);
  s.verbose = o.verbose;
  if (const std::string& grid = checked(o.grid); grid != "auto") s.prepare.grid = whole_value(grid);
  s.threads = whole_value(checked(o.threads));
  if (!o.max_memory.text.empty()) s.max_memory = byte_size_value(checked(o.max_memory));
  s.trace.primary_only = o.primary_only;
  s.aa.depth = whole_value(checked(o.aa));
  s.aa.threshold = number_value(checked(o.aa_threshold));
  s.defines = o.defines.text;
  if (!s.defines.empty()) {
    for (const std::string& scene : s.scenes) {
      if (!is_scad_file(scene))
        throw UsageError(fmt::format("-D sets a variable of an OpenSCAD program and applies only to .scad input; "
                                     "{} is not a .scad file (the CSG tree of a .csg holds no variables to set)",
                                     scene));
    }
  }
  return s;
}

namespace {

// A scene OpenSCAD exported: its errors are the export's, and say so.
Scene parse_export(const std::string& csg, const std::string& scad) {
  try {
    // Its import() paths are as the .scad gives them: relative to the .scad's directory.
    return parse_scene_file(csg, {}, 0, std::filesystem::path(scad).parent_path().string());
  } catch (const SceneError& e) {
    throw SceneError(e.loc(), fmt::format("{}\n{}: the errors above are in OpenSCAD's CSG export of it, removed "
                                          "after the run ('openscad -o model.csg {}' writes it to read)",
                                          e.message(), scad, scad));
  }
}

// The scenes of the run's frames. A .scad file is exported by OpenSCAD (with
// --frames, by its --animate) and its export read; any other file is read by
// capsim itself (with --frames, once, its text parsed at each frame's $t).
std::vector<Scene> read_scenes(const TracerSettings& s) {
  std::vector<Scene> scenes;
  scenes.reserve(static_cast<std::size_t>(s.frames));
  ScadExports exports(s.defines);  // removed once the scenes are read
  if (s.animate && is_scad_file(s.scenes[0])) {
    const std::string& scad = s.scenes[0];
    const std::string stem = std::filesystem::path(scad).stem().string();
    for (const std::string& csg : exports.export_csg(scad, stem, s.frames)) scenes.push_back(parse_export(csg, scad));
  } else if (s.animate) {
    // Read once: every frame sees the same text.
    const std::string text = read_scene_file(s.scenes[0]);
    for (int k = 0; k < s.frames; ++k) scenes.push_back(parse_scene(text, s.scenes[0], {}, animation_time(k, s.frames)));
  } else {
    for (std::size_t i = 0; i < s.scenes.size(); ++i) {
      const std::string& file = s.scenes[i];
      if (!is_scad_file(file)) {
        scenes.push_back(parse_scene_file(file));
        continue;
      }
      // Numbered, as a sequence may hold two files of the same name.
      const std::string stem = std::filesystem::path(file).stem().string();
      const std::string name = s.scenes.size() == 1 ? stem : fmt::format("{:05d}-{}", i, stem);
      scenes.push_back(parse_export(exports.export_csg(file, name).front(), file));
    }
  }
  return scenes;
}

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

std::vector<PreparedScene> load_scenes(const TracerSettings& s, const MemoryNeed& need, StageTimes* times) {
  std::vector<Scene> scenes = read_scenes(s);
  if (times) times->end("read");
  // Every frame takes the first one's size: --size, or the first camera's.
  const ImageSize size = image_size(scenes[0], s.prepare);
  check_memory(s, size, need, static_cast<int>(scenes.size()));
  PrepareOptions prepare = s.prepare;
  prepare.width = size.width;
  prepare.height = size.height;
  prepare.threads = s.threads;
  std::vector<PreparedScene> prepared;
  prepared.reserve(scenes.size());
  for (Scene& scene : scenes) prepared.push_back(prepare_scene(std::move(scene), prepare));
  frame_sequence(prepared);
  if (times) times->end("prepare");
  return prepared;
}

void print_cameras(const TracerSettings& s, const std::vector<PreparedScene>& frames) {
  if (!s.verbose) return;
  for (std::size_t k = 0; k < frames.size(); ++k) {
    const Camera& c = frames[k].camera;
    const std::string args = camera_arguments(c);
    if (k > 0 && args == camera_arguments(frames[k - 1].camera) && c.fov_deg == frames[k - 1].camera.fov_deg)
      continue;
    const std::string frame = frames.size() > 1 ? fmt::format(" (frame {})", k) : "";
    fmt::print(stderr, "camera{}: {}\n", frame, args);
    if (!expressible_as_openscad(c))
      fmt::print(stderr,
                 "camera{}: a {:g} degree field with up [{:g}, {:g}, {:g}]; OpenSCAD's --camera sees from the same "
                 "eye and centre with a {:g} degree field and z up; this view exactly, in the scene file: {}\n",
                 frame, c.fov_deg, c.up.x, c.up.y, c.up.z, kOpenScadFov, camera_statement(c));
  }
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
