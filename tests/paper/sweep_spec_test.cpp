// The sweep file: its axes checked value by value, each error naming the file
// and the JSON path of the value; the cross product in its fixed order; and
// frame_average outside dot mode left out.

#include "paper/sweeps/sweep_spec.h"

#include <gtest/gtest.h>

#include <string>

using capsim::sim::parse_sweep_spec;
using capsim::sim::SweepSpec;
using capsim::sim::SweepSpecError;

namespace {

const std::string kScenesDir = std::string(CAPSIM_SOURCE_DIR) + "/scenes";
// A sweep file in the scenes directory, so that scene paths are relative to it.
const std::string kFile = kScenesDir + "/sweep.json";

// What simulate's --balance says of a bad scheme.
std::string balance_error(const std::string& scheme) {
  try {
    capsim::sim::parse_balance(scheme);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no error)";
}

std::string error_of(const std::string& text) {
  try {
    parse_sweep_spec(text, kFile);
  } catch (const SweepSpecError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(SweepSpec, CrossProductVariesTheCellsFastestAndResolvesPaths) {
  const SweepSpec s = parse_sweep_spec(
      R"({"axes": {"cells": ["4x4", "8x8"], "scenes": ["balls.csg", "chess.csg"], "modes": ["line", "dot"]}})",
      kFile);
  ASSERT_EQ(s.points.size(), 8u);
  EXPECT_EQ(s.left_out.total(), 0);
  EXPECT_EQ(s.left_out.summary(), "");
  EXPECT_EQ(s.points[0].scene.files, std::vector<std::string>{kScenesDir + "/balls.csg"});
  EXPECT_EQ(capsim::sim::to_string(s.points[0].cells), "4x4");
  EXPECT_EQ(capsim::sim::to_string(s.points[1].cells), "8x8");
  EXPECT_EQ(s.points[1].mode, capsim::sim::PixelMode::Line);
  EXPECT_EQ(s.points[2].mode, capsim::sim::PixelMode::Dot);
  EXPECT_EQ(s.points[4].scene.written, "chess.csg");
}

TEST(SweepSpec, MissingAxesTakeSimulatesDefaults) {
  const SweepSpec s = parse_sweep_spec(R"({"axes": {"scenes": ["balls.csg"]}})", kFile);
  ASSERT_EQ(s.points.size(), 1u);
  const capsim::sim::SweepPoint& p = s.points[0];
  EXPECT_EQ(capsim::sim::to_string(p.cells), "8x8");
  EXPECT_EQ(p.mode, capsim::sim::PixelMode::Dot);
  EXPECT_EQ(p.aa_depth, 0);
  EXPECT_EQ(p.profile, "cap");
  EXPECT_EQ(p.width, 0);
  EXPECT_EQ(p.grid, 0);
  EXPECT_FALSE(p.primary_only);
  EXPECT_FALSE(p.frame_average);
  EXPECT_EQ(p.voxel_generation, capsim::sim::VoxelGeneration::Host);
  EXPECT_EQ(capsim::sim::sweep_inputs(p).dump(),
            R"({"aa":0,"balance":"static","cells":"8x8","frame_average":false,"grid":"auto","mode":"dot",)"
            R"("primary_only":false,)"
            R"("profile":"cap","scene":"balls.csg","size":"camera","voxel_generation":"host"})");
}

TEST(SweepSpec, SequencesAndAnimatedScenes) {
  const SweepSpec s = parse_sweep_spec(
      R"({"axes": {"scenes": [["disb/f00000.csg", "disb/f00001.csg"], {"scene": "balls.csg", "frames": 3}]}})",
      kFile);
  ASSERT_EQ(s.points.size(), 2u);
  EXPECT_EQ(s.points[0].scene.files.size(), 2u);
  EXPECT_EQ(s.points[0].scene.frames, 0);
  EXPECT_EQ(s.points[1].scene.frames, 3);
}

TEST(SweepSpec, FrameAverageOutsideDotModeIsLeftOut) {
  const SweepSpec s = parse_sweep_spec(
      R"({"axes": {"scenes": ["balls.csg"], "modes": ["block", "dot"], "frame_average": [false, true]}})", kFile);
  ASSERT_EQ(s.points.size(), 3u);
  EXPECT_EQ(s.left_out.frame_average_outside_dot, 1);
  EXPECT_EQ(s.left_out.summary(), "1 left out: 1 frame_average outside dot mode");
  for (const auto& p : s.points) EXPECT_TRUE(!p.frame_average || p.mode == capsim::sim::PixelMode::Dot);
}

TEST(SweepSpec, ADemandPointStandsForEveryModeAndTakesNoFrameAveraging) {
  const SweepSpec s = parse_sweep_spec(
      R"({"axes": {"scenes": ["balls.csg"], "modes": ["line", "dot"], "frame_average": [false, true],)"
      R"( "balance": ["static", "demand:16"], "cells": ["4x4", "8x8"]}})",
      kFile);
  // Static: line and dot plain, dot frame-averaged; demand: once, plain; each on 2 grids.
  ASSERT_EQ(s.points.size(), 8u);
  EXPECT_EQ(s.left_out.frame_average_outside_dot, 2);  // static line, frame averaged
  EXPECT_EQ(s.left_out.frame_average_balanced, 4);    // demand, frame averaged, both modes
  EXPECT_EQ(s.left_out.demand_per_mode, 2);            // demand, plain, at dot (line stands for it)
  EXPECT_EQ(s.left_out.summary(),
            "8 left out: 2 frame_average outside dot mode, 4 frame_average with demand or steal, 2 demand points repeated per "
            "mode");
  // The balance axis varies before the modes: static line, static dot, demand, then the same frame averaged.
  const auto inputs = [&](std::size_t i) { return capsim::sim::sweep_inputs(s.points[i]); };
  EXPECT_EQ(inputs(0)["mode"], "line");
  EXPECT_EQ(inputs(0)["balance"], "static");
  EXPECT_EQ(inputs(2)["mode"], "dot");
  EXPECT_EQ(inputs(4)["mode"], "tiles");
  EXPECT_EQ(inputs(4)["balance"], "demand:16");
  EXPECT_EQ(inputs(5)["cells"], "8x8");
  EXPECT_TRUE(s.points[4].balance.on_demand());
  EXPECT_EQ(s.points[4].balance.tile_pixels, 16);
  EXPECT_EQ(inputs(6)["frame_average"], true);
  EXPECT_EQ(inputs(6)["balance"], "static");
  EXPECT_EQ(inputs(6)["mode"], "dot");
}

TEST(SweepSpec, ErrorsNameTheFileAndTheValuesPath) {
  EXPECT_EQ(error_of(R"({"axes": {"scenes": ["balls.csg"], "cells": ["4x4", "8x8", "9x99"]}})"),
            kFile + R"(: axes.cells[2]: "9x99" is out of range (accepted: 1x1 to 32x32))");
  EXPECT_EQ(error_of(R"({"axes": {"scenes": ["balls.csg"], "cells": ["big"]}})"),
            kFile + R"(: axes.cells[0]: "big" is not of the form AxB (accepted: 1x1 to 32x32))");
  EXPECT_EQ(error_of(R"({"axes": {"scenes": ["balls.csg"], "modes": ["dots"]}})"),
            kFile + R"(: axes.modes[0]: "dots" is not a pixel mode (accepted: block, line or dot))");
  EXPECT_EQ(error_of(R"({"axes": {"scenes": ["balls.csg"], "balance": ["static", "demand:15"]}})"),
            kFile + R"(: axes.balance[1]: "demand:15": )" + balance_error("demand:15"));
  EXPECT_EQ(error_of(R"({"axes": {"scenes": ["balls.csg"], "balance": ["steady"]}})"),
            kFile + R"(: axes.balance[0]: "steady": )" + balance_error("steady"));
  EXPECT_EQ(error_of(R"({"axes": {"scenes": ["balls.csg"], "aa": [2, 9]}})"),
            kFile + R"(: axes.aa[1]: 9 is out of range (accepted: 0 to 8))");
  EXPECT_EQ(error_of(R"({"axes": {"scenes": ["balls.csg"], "grid": ["auto", 1.5]}})"),
            kFile + R"(: axes.grid[1]: 1.5 is not a whole number (accepted: 1 to 256))");
  EXPECT_EQ(error_of(R"({"axes": {"scenes": ["balls.csg", ["chess.csg", "nope.csg"]]}})"),
            kFile + R"(: axes.scenes[1][1]: "nope.csg" is not a readable file)");
  EXPECT_EQ(error_of(R"({"axes": {"scenes": [{"scene": "balls.csg", "frames": 0}]}})"),
            kFile + R"(: axes.scenes[0].frames: 0 is out of range (accepted: 1 to 99999))");
  EXPECT_EQ(error_of(R"({"axes": {"scenes": ["balls.csg"], "profiles": ["cap", "fast"]}})"),
            kFile + R"(: axes.profiles[1]: "fast" is neither a built-in profile nor a readable file (accepted: )"
                    R"(cap, m380 or a profile file))");
  EXPECT_EQ(error_of(R"({"axes": {"scenes": ["balls.csg"], "primary_only": ["yes"]}})"),
            kFile + R"(: axes.primary_only[0]: "yes" is not true or false)");
  EXPECT_EQ(error_of(R"({"axes": {"scenes": ["balls.csg"], "colours": [1]}})"),
            kFile + ": axes.colours: is not an axis (accepted: scenes, cells, modes, balance, voxel_generation, aa, "
                    "profiles, sizes, grid, primary_only, frame_average)");
  EXPECT_EQ(error_of(R"({"axes": {"scenes": ["balls.csg"], "voxel_generation": ["gpu"]}})"),
            kFile + R"(: axes.voxel_generation[0]: "gpu" is not who generates the voxels (accepted: host or cells))");
  EXPECT_EQ(error_of(R"({"axes": {"scenes": []}})"), kFile + ": axes.scenes: an axis is a list of one value or more");
  EXPECT_EQ(error_of(R"({"axes": {"cells": ["4x4"]}})"), kFile + ": axes.scenes: is required: the scenes to run");
  EXPECT_EQ(error_of(R"({"axes": {}, "extra": 1})"), kFile + ": extra: is not a key of a sweep file (accepted: axes)");
  EXPECT_EQ(error_of("{").rfind(kFile + ": not JSON: ", 0), 0u);
}

}  // namespace

namespace {

TEST(SweepSpec, TheShippedExampleParses) {
  const SweepSpec s = capsim::sim::read_sweep_spec(std::string(CAPSIM_SOURCE_DIR) + "/bench/sweeps/small.json");
  EXPECT_EQ(s.points.size(), 36u);  // 2 scenes x 2 depths x 3 modes x 3 grids
  EXPECT_EQ(s.points[0].width, 64);
}

TEST(SweepSpec, TheBalancingFindingsSweepsParse) {
  const std::string dir = std::string(CAPSIM_SOURCE_DIR) + "/bench/sweeps/";
  const SweepSpec grid = capsim::sim::read_sweep_spec(dir + "balancing.json");
  EXPECT_EQ(grid.points.size(), 280u);  // 5 scenes x 2 depths x 7 schemes x 4 grids
  EXPECT_EQ(grid.left_out.total(), 0);
  const SweepSpec disb = capsim::sim::read_sweep_spec(dir + "balancing-disb.json");
  ASSERT_EQ(disb.points.size(), 7u);  // 6 schemes, and static frame averaged
  EXPECT_EQ(disb.left_out.frame_average_balanced, 5);
  EXPECT_EQ(disb.points[0].scene.files.size(), 64u);
  const SweepSpec voxels = capsim::sim::read_sweep_spec(dir + "voxel-generation.json");
  ASSERT_EQ(voxels.points.size(), 80u);  // 5 lattices x 2 grids x host and cells x 4 machines
  EXPECT_EQ(voxels.points[0].voxel_generation, capsim::sim::VoxelGeneration::Host);
  EXPECT_EQ(voxels.points[4].voxel_generation, capsim::sim::VoxelGeneration::Cells);
  EXPECT_EQ(voxels.points[4].cells, (capsim::sim::CellGrid{4, 4}));
}

}  // namespace
