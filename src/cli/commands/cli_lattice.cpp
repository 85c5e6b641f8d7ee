// `capsim lattice`: writes a sphere lattice of the paper's Table 4-2 as a scene file.

#include "capsim/trace/prepared_scene.h"
#include "cli/commands/cli_commands.h"
#include "cli/options/cli_options.h"
#include "cli/cli_outputs.h"
#include "cli/console.h"
#include "paper/lattice_scene.h"
#include "report/text_output.h"

#include <fmt/core.h>

#include <memory>

namespace capsim::cli {

namespace {

struct LatticeOptions {
  OptionText<> spheres;
  std::string output;
  OptionText<> size{"512x512"};
};

}  // namespace

Command add_lattice_command(CLI::App& app) {
  auto o = std::make_shared<LatticeOptions>();
  CLI::App* cmd = app.add_subcommand(
      "lattice",
      "Write a lattice of equal spheres, the test model of the paper's Table 4-2 (16, 512, 1000, 4096 and "
      "6859 spheres), as a scene file (docs/calibration.md gives the geometry)");
  add_option(*cmd, "spheres", o->spheres,
             fmt::format("Number of spheres, 1 to {}: a x a in the near face and spheres / a^2 deep, a the largest "
                         "whole number with a^2 dividing it and no more than the depth",
                         sim::kMaxLatticeSpheres),
             whole_number(1, sim::kMaxLatticeSpheres)
                 .description(fmt::format("a whole number from 1 to {}", sim::kMaxLatticeSpheres)))
      ->required();
  // Its usage errors quote what an image --output accepts, as they always have.
  accepts(cmd->add_option("-o,--output", o->output, "Scene file to write (.csg)")->required(),
          CLI::Validator(image_output_check().get_description()));
  add_option(*cmd, "--size", o->size, "The camera's image size WxH", image_size_check())->default_val("512x512");
  return [o] {
    const int spheres = whole_value(checked(o->spheres));
    const auto [width, height] = pair_value(checked(o->size));
    StagedOutputs outputs({{"--output", o->output}}, {});
    const sim::LatticeShape shape = sim::lattice_shape(spheres);
    sim::write_text_file(outputs["--output"], sim::lattice_scene_text(shape, width, height));
    outputs.commit();
    Console console(false);
    if (outputs.stdout_taken()) console.divert_to_stderr();
    console.summary(
        fmt::format("{}: {} spheres, {} x {} x {}\n", o->output, shape.count(), shape.nx, shape.ny, shape.nz));
    return 0;
  };
}

}  // namespace capsim::cli
