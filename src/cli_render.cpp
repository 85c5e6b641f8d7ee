// `capsim render`: the tracer alone, on the host.

#include "capsim/image_io.h"
#include "capsim/render.h"
#include "cli_commands.h"
#include "cli_options.h"

#include <memory>

namespace capsim::cli {

Command add_render_command(CLI::App& app) {
  auto opts = std::make_shared<TracerOptions>();
  CLI::App* cmd = app.add_subcommand("render", "Render a CSG scene file with the paper's tracer");
  add_tracer_options(*cmd, *opts);
  return [opts] {
    const PreparedScene scene = load_scene(*opts);
    const Tracer tracer(scene, trace_options(*opts));
    Progress progress("rendering", static_cast<std::uint64_t>(scene.camera.width) * scene.camera.height,
                      Progress::stderr_is_terminal());
    const Framebuffer fb = render(tracer, opts->threads, nullptr, &progress);
    write_image(opts->output, fb);
    return 0;
  };
}

}  // namespace capsim::cli
