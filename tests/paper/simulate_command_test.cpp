// The command line of a `capsim simulate` run, built from its settings: every
// option as the HTML page gives it, or only the changed ones as the
// reproduction prints them. sim_command_line_test.cpp runs such commands.

#include "paper/experiment_run.h"
#include "paper/simulate_command.h"

#include <gtest/gtest.h>

namespace capsim::sim {
namespace {

SimulateSettings one_scene() {
  SimulateSettings s;
  s.scenes = {"scenes/balls.csg"};
  s.output = "s.png";
  return s;
}

SimulateSettings every_setting_changed() {
  SimulateSettings s;
  s.scenes = {"f0.csg", "f1.csg"};
  s.output = "out/s.exr";
  s.width = 640;
  s.height = 480;
  s.grid = 12;
  s.cells = {4, 2};
  s.mode = PixelMode::Line;
  s.profile = "m380";
  s.frames = 5;
  s.primary_only = true;
  s.aa = {2, 0.25};
  s.frame_average = true;
  s.threads = 3;
  return s;
}

TEST(SimulateCommand, EveryOptionGivesTheDefaultsToo) {
  EXPECT_EQ(simulate_command(one_scene(), CommandForm::EveryOption),
            "capsim simulate scenes/balls.csg -o s.png --grid auto --cells 8x8 --mode dot --profile cap --threads 0");
  SimulateSettings s = one_scene();
  s.width = 64;
  s.height = 48;
  s.aa.depth = 1;
  EXPECT_EQ(simulate_command(s, CommandForm::EveryOption),
            "capsim simulate scenes/balls.csg -o s.png --size 64x48 --grid auto --cells 8x8 --mode dot --profile cap "
            "--aa 1 --aa-threshold 0.3 --threads 0");
}

// On demand --balance is given and --mode, which it refuses, is not; a static
// run gives no --balance, as before it could be chosen.
TEST(SimulateCommand, DemandGivesItsTilesAndNoMode) {
  SimulateSettings s = one_scene();
  s.balance = {BalanceScheme::Demand, 16};
  EXPECT_EQ(simulate_command(s, CommandForm::EveryOption),
            "capsim simulate scenes/balls.csg -o s.png --grid auto --cells 8x8 --profile cap --balance demand:16 "
            "--threads 0");
  s.mode = PixelMode::Line;
  EXPECT_EQ(simulate_command(s, CommandForm::NonDefaults),
            "capsim simulate scenes/balls.csg -o s.png --balance demand:16");
}

TEST(SimulateCommand, NonDefaultsLeavesTheDefaultsOut) {
  EXPECT_EQ(simulate_command(one_scene(), CommandForm::NonDefaults), "capsim simulate scenes/balls.csg -o s.png");
  SimulateSettings s = one_scene();
  s.aa.depth = 2;
  EXPECT_EQ(simulate_command(s, CommandForm::NonDefaults), "capsim simulate scenes/balls.csg -o s.png --aa 2");
  s.aa.threshold = 0.5;
  EXPECT_EQ(simulate_command(s, CommandForm::NonDefaults),
            "capsim simulate scenes/balls.csg -o s.png --aa 2 --aa-threshold 0.5");
}

TEST(SimulateCommand, EachFormListsEveryChangedSettingInItsOwnOrder) {
  // --primary-only after the tracer's options in the reproduction's commands,
  // after --frames on the pages.
  EXPECT_EQ(simulate_command(every_setting_changed(), CommandForm::EveryOption),
            "capsim simulate f0.csg f1.csg -o out/s.exr --size 640x480 --grid 12 --cells 4x2 --mode line --profile "
            "m380 --frames 5 --primary-only --aa 2 --aa-threshold 0.25 --frame-average --threads 3");
  EXPECT_EQ(simulate_command(every_setting_changed(), CommandForm::NonDefaults),
            "capsim simulate f0.csg f1.csg -o out/s.exr --size 640x480 --grid 12 --primary-only --cells 4x2 --mode "
            "line --profile m380 --frames 5 --aa 2 --aa-threshold 0.25 --frame-average --threads 3");
}

// OpenSCAD's -D assignments come last, in order, each one shell word as
// written ($ and quotes kept from the shell).
TEST(SimulateCommand, DefinesAreSingleQuotedInOrder) {
  SimulateSettings s = one_scene();
  s.scenes = {"m.scad"};
  s.defines = {"$fn=64", "label=\"it's\""};
  EXPECT_EQ(simulate_command(s, CommandForm::NonDefaults),
            "capsim simulate m.scad -o s.png -D '$fn=64' -D 'label=\"it'\\''s\"'");
}

TEST(SimulateCommand, TheReproductionsCommandsAreItsNonDefaultsForm) {
  RunSpec spec;
  spec.scene = "scenes/chess.csg";
  spec.cells = {4, 8};
  spec.mode = PixelMode::Line;
  EXPECT_EQ(run_command(spec), "capsim simulate scenes/chess.csg -o screen.png --cells 4x8 --mode line");
  spec.width = spec.height = 48;
  spec.aa_depth = 2;
  EXPECT_EQ(run_command(spec), "capsim simulate scenes/chess.csg -o screen.png --size 48x48 --cells 4x8 --mode line --aa 2");
  // A lattice is written first, at the run's size.
  RunSpec lattice;
  lattice.lattice = lattice_shape(512);
  lattice.width = lattice.height = 48;
  lattice.grid = 8;
  lattice.primary_only = true;
  lattice.cells = {1, 1};
  lattice.profile = "m380";
  EXPECT_EQ(run_command(lattice),
            "capsim lattice 512 -o lattice-512.csg --size 48x48 && capsim simulate lattice-512.csg -o screen.png "
            "--grid 8 --primary-only --cells 1x1 --profile m380");
}

}  // namespace
}  // namespace capsim::sim
