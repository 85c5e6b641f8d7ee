// `capsim lattice`: writes a sphere lattice of the paper's Table 4-2 as a scene file.

#include "cli_commands.h"
#include "lattice_scene.h"
#include "text_output.h"

#include <fmt/core.h>

#include <charconv>
#include <filesystem>
#include <memory>
#include <stdexcept>

namespace capsim::cli {

namespace {

struct LatticeOptions {
  int spheres = 0;
  std::string output;
  std::string size = "512x512";
};

std::pair<int, int> parse_size(const std::string& text) {
  int w = 0, h = 0;
  const auto x = text.find('x');
  const char* end = text.data() + text.size();
  if (x == std::string::npos ||
      std::from_chars(text.data(), text.data() + x, w).ptr != text.data() + x ||
      std::from_chars(text.data() + x + 1, end, h).ptr != end || w < 1 || h < 1 || w > 16384 || h > 16384)
    throw std::invalid_argument(fmt::format("--size '{}' is not WxH with sides 1 to 16384", text));
  return {w, h};
}

}  // namespace

Command add_lattice_command(CLI::App& app) {
  auto o = std::make_shared<LatticeOptions>();
  CLI::App* cmd = app.add_subcommand(
      "lattice",
      "Write a lattice of equal spheres, the test model of the paper's Table 4-2 (16, 512, 1000, 4096 and "
      "6859 spheres), as a scene file (docs/calibration.md gives the geometry)");
  cmd->add_option("spheres", o->spheres,
                  fmt::format("Number of spheres, 1 to {}: a x a in the near face and spheres / a^2 deep, a "
                              "the largest whole number with a^2 dividing it and no more than the depth",
                              sim::kMaxLatticeSpheres))
      ->required();
  cmd->add_option("-o,--output", o->output, "Scene file to write (.csg)")->required();
  cmd->add_option("--size", o->size, "The camera's image size WxH")->default_val("512x512");
  return [o] {
    const auto [width, height] = parse_size(o->size);
    const sim::LatticeShape shape = sim::lattice_shape(o->spheres);
    const std::filesystem::path dir = std::filesystem::path(o->output).parent_path();
    if (!dir.empty() && !std::filesystem::is_directory(dir))
      throw std::invalid_argument(fmt::format("{}: directory {} does not exist", o->output, dir.string()));
    sim::write_text_file(o->output, sim::lattice_scene_text(shape, width, height));
    fmt::print("{}: {} spheres, {} x {} x {}\n", o->output, shape.count(), shape.nx, shape.ny, shape.nz);
    return 0;
  };
}

}  // namespace capsim::cli
