// `capsim render`: the tracer alone, on the host.

#include "capsim/image_io.h"
#include "capsim/render.h"
#include "cli_commands.h"
#include "cli_options.h"
#include "cli_outputs.h"

#include <memory>
#include <vector>

namespace capsim::cli {

Command add_render_command(CLI::App& app) {
  auto opts = std::make_shared<TracerOptions>();
  CLI::App* cmd = app.add_subcommand("render", "Render a CSG scene file with the paper's tracer");
  add_tracer_options(*cmd, *opts);
  return [opts] {
    const TracerSettings settings = check_tracer_options(*opts);
    StagedOutputs outputs({{"--output", settings.output}}, {settings.scene});
    const bool png = is_png_path(settings.output);
    const PreparedScene scene = load_scene(settings, [png](ImageSize size) {
      // The 8-bit rows and their encoding, or the frame buffer and its writing.
      if (png) return size.pixels() * 3 + write_png_rgb8_memory(size.width, size.height);
      return Framebuffer::bytes(size.width, size.height) + write_image_memory(".exr", size.width, size.height, 0);
    });
    const Tracer tracer(scene, settings.trace);
    Progress progress("rendering", static_cast<std::uint64_t>(scene.camera.width) * scene.camera.height,
                      Progress::stderr_is_terminal());
    if (png) {
      // Colour only, straight to 8 bits: no float framebuffer to fill and convert.
      const int width = scene.camera.width;
      std::vector<unsigned char> rgb(static_cast<std::size_t>(width) * scene.camera.height * 3);
      render_rows(
          tracer, settings.threads,
          [&](int j, std::span<const PixelSample> row) {
            encode_srgb8_row(row, rgb.data() + static_cast<std::size_t>(j) * width * 3);
          },
          nullptr, &progress);
      write_png_rgb8(outputs["--output"], width, scene.camera.height, rgb);
    } else {
      write_image(outputs["--output"], render(tracer, settings.threads, nullptr, &progress));
    }
    outputs.commit();
    return 0;
  };
}

}  // namespace capsim::cli
