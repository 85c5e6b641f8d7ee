// `capsim render`: the tracer alone, on the host.

#include "capsim/image/image_io.h"
#include "capsim/trace/render.h"
#include "cli/commands/cli_commands.h"
#include "cli/options/cli_options.h"
#include "cli/cli_outputs.h"
#include "cli/console.h"

#include <cstdio>
#include <memory>
#include <optional>
#include <vector>

namespace capsim::cli {

Command add_render_command(CLI::App& app) {
  auto opts = std::make_shared<TracerOptions>();
  auto quiet = std::make_shared<bool>(false);
  CLI::App* cmd = app.add_subcommand("render", "Render a CSG scene file with the paper's tracer");
  add_tracer_options(*cmd, *opts);
  add_quiet_flag(*cmd, *quiet, "");  // render prints no summary: --quiet drops the percentage on a terminal
  auto timings = std::make_shared<bool>(false);
  accepts(cmd->add_flag("--timings", *timings,
                        "Print on stderr at the end the wall time of each stage: read (the scene, with OpenSCAD's "
                        "export of a .scad), prepare (voxel grids and status trees), trace, write (docs/performance.md)"),
          flag_values());
  return [opts, quiet, timings] {
    StageTimes times;
    const TracerSettings settings = check_tracer_options(*opts);
    const int frames = settings.frames;
    const bool numbered = settings.numbered_outputs();
    std::vector<OutputOption> staged;
    for (int k = 0; k < frames; ++k)
      staged.push_back({frame_output_option(k, numbered), frame_output(settings.output, k, numbered)});
    StagedOutputs outputs(staged, settings.scenes);
    const bool png = is_png_path(settings.output);
    const AntialiasOptions aa = settings.aa;
    const std::vector<PreparedScene> scenes = load_scenes(settings, [png, aa](ImageSize size, int) {
      // One frame at a time: each is written to its staged file before the next.
      const std::uint64_t pixels = static_cast<std::uint64_t>(size.width) * static_cast<std::uint64_t>(size.height);
      const std::uint64_t corners = aa.depth > 0 ? static_cast<std::uint64_t>(size.width + 1) *
                                                       static_cast<std::uint64_t>(size.height + 1) * sizeof(ScreenSample)
                                                 : 0;
      if (png)
        return corners + PngScanlines::bytes(size.width, size.height) + write_png_memory(size.width, size.height);
      return corners + Framebuffer::bytes(size.width, size.height) + (aa.depth > 0 ? pixels * sizeof(float) : 0) +
             write_image_memory(".exr", size.width, size.height, aa.depth > 0 ? 1 : 0);
    }, &times);
    print_cameras(settings, scenes);
    const int width = scenes[0].camera.width, height = scenes[0].camera.height;
    // Ended before the timings are printed: its last line comes first.
    std::optional<Progress> progress(std::in_place, frames == 1 ? "rendering" : "frames",
                                     frames == 1 ? render_work(width, height, aa) : frames,
                                     Console(*quiet).progress_bar());
    for (int k = 0; k < frames; ++k) {
      const Tracer tracer(scenes[k], settings.trace);
      Progress* rows = frames == 1 ? &*progress : nullptr;
      PendingFile& out = outputs[frame_output_option(k, numbered)];
      if (png) {
        // Colour only, straight to the PNG's 8-bit rows, each put by the
        // thread that traced it, which compresses the bands it makes whole:
        // no float framebuffer to fill and convert.
        PngScanlines image(width, height);
        render_rows(
            tracer, settings.threads,
            [&](int j, std::span<const PixelSample> row) {
              thread_local std::vector<unsigned char> rgb;
              rgb.resize(3 * row.size());
              encode_srgb8_row(row, rgb.data());
              image.put_row(j, rgb);
            },
            nullptr, rows, aa);
        times.end("trace");
        write_png(out, image);
      } else if (aa.depth == 0) {
        const Framebuffer fb = render(tracer, settings.threads, nullptr, rows);
        times.end("trace");
        write_image(out, fb);
      } else {
        // Antialiased EXR: also the samples traced for each pixel.
        Framebuffer fb(width, height);
        ExtraChannel samples{"samples", std::vector<float>(static_cast<std::size_t>(width) * height)};
        render_rows(
            tracer, settings.threads,
            [&](int j, std::span<const PixelSample> row) {
              for (int i = 0; i < width; ++i) {
                set_pixel(fb, i, j, row[i]);
                samples.values[static_cast<std::size_t>(j) * width + i] = static_cast<float>(row[i].samples);
              }
            },
            nullptr, rows, aa);
        times.end("trace");
        write_image(out, fb, {samples});
      }
      times.end("write");
      if (frames > 1) progress->advance(1);
    }
    progress.reset();
    outputs.commit();
    times.end("write");
    if (*timings) std::fputs(times.line().c_str(), stderr);
    return 0;
  };
}

}  // namespace capsim::cli
