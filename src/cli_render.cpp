// `capsim render`: the tracer alone, on the host.

#include "capsim/image_io.h"
#include "capsim/render.h"
#include "cli_commands.h"
#include "cli_options.h"

#include <memory>
#include <vector>

namespace capsim::cli {

Command add_render_command(CLI::App& app) {
  auto opts = std::make_shared<TracerOptions>();
  CLI::App* cmd = app.add_subcommand("render", "Render a CSG scene file with the paper's tracer");
  add_tracer_options(*cmd, *opts);
  return [opts] {
    const PreparedScene scene = load_scene(*opts);
    const Tracer tracer(scene, trace_options(*opts));
    const AntialiasOptions aa = antialias_options(*opts);
    Progress progress("rendering", render_work(scene.camera.width, scene.camera.height, aa),
                      Progress::stderr_is_terminal());
    if (is_png_path(opts->output)) {
      // Colour only, straight to 8 bits: no float framebuffer to fill and convert.
      const int width = scene.camera.width;
      std::vector<unsigned char> rgb(static_cast<std::size_t>(width) * scene.camera.height * 3);
      render_rows(
          tracer, opts->threads,
          [&](int j, std::span<const PixelSample> row) {
            encode_srgb8_row(row, rgb.data() + static_cast<std::size_t>(j) * width * 3);
          },
          nullptr, &progress, aa);
      write_png_rgb8(opts->output, width, scene.camera.height, rgb);
    } else if (aa.depth == 0) {
      write_image(opts->output, render(tracer, opts->threads, nullptr, &progress));
    } else {
      // Antialiased EXR: also the samples traced for each pixel.
      Framebuffer fb(scene.camera.width, scene.camera.height);
      ExtraChannel samples{"samples", std::vector<float>(static_cast<std::size_t>(fb.width) * fb.height)};
      render_rows(
          tracer, opts->threads,
          [&](int j, std::span<const PixelSample> row) {
            for (int i = 0; i < fb.width; ++i) {
              fb.set(i, j, row[i]);
              samples.values[static_cast<std::size_t>(j) * fb.width + i] = static_cast<float>(row[i].samples);
            }
          },
          nullptr, &progress, aa);
      write_image(opts->output, fb, {samples});
    }
    return 0;
  };
}

}  // namespace capsim::cli
