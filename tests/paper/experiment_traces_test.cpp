// The mode benchmarks run many experiments of one screen in a row and keep
// its trace (ScreenTraces): their figures do not depend on it.

#include "paper/experiment_run.h"

#include <gtest/gtest.h>

#include <string>
#include <thread>
#include <vector>

namespace capsim::sim {
namespace {

// A kept trace gives the figures of runs that trace anew, and a run of
// another screen traces its own.
TEST(ScreenTrace, ExperimentsGiveTheSameFiguresWithAKeptTrace) {
  ScreenTraces traces;
  RunSpec spec;
  spec.scene = std::string(CAPSIM_SOURCE_DIR) + "/scenes/balls.csg";
  spec.width = 24;
  spec.height = 16;
  for (const int aa : {0, 1, 0})
    for (const CellGrid grid : {CellGrid{2, 2}, CellGrid{4, 4}})
      for (const std::string profile : {"cap", "m380"}) {
        spec.aa_depth = aa;
        spec.cells = grid;
        spec.profile = profile;
        const RunFigures kept = run_experiment(spec, 2, &traces);
        const RunFigures anew = run_experiment(spec, 2);
        EXPECT_EQ(kept.frame, anew.frame) << aa << " " << to_string(grid) << " " << profile;
        EXPECT_EQ(kept.ops, anew.ops);
        EXPECT_EQ(kept.breakdown.cycles, anew.breakdown.cycles);
        EXPECT_EQ(kept.grid_divisions, anew.grid_divisions);
        EXPECT_EQ(kept.command, anew.command);
      }
  spec.grid = 3;  // another screen's pixels: traced again
  EXPECT_EQ(run_experiment(spec, 1, &traces).frame, run_experiment(spec, 1).frame);
  EXPECT_EQ(&traces.trace(spec, 1), &traces.trace(spec, 2));
}

// Runs of one kept screen read it at once from several threads, as the mode
// benchmarks run them, and give the figures of runs one after another.
TEST(ScreenTrace, RunsOfOneScreenGoAtOnceWithTheFiguresOfRunsInTurn) {
  ScreenTraces traces;
  std::vector<RunSpec> specs;
  for (const PixelMode mode : {PixelMode::Block, PixelMode::Line, PixelMode::Dot})
    for (const CellGrid grid : {CellGrid{2, 2}, CellGrid{2, 4}}) {
      RunSpec spec;
      spec.scene = std::string(CAPSIM_SOURCE_DIR) + "/scenes/balls.csg";
      spec.width = 24;
      spec.height = 16;
      spec.aa_depth = 1;
      spec.mode = mode;
      spec.cells = grid;
      specs.push_back(spec);
    }
  const ScreenTrace& screen = traces.trace(specs[0], 1);
  std::vector<RunFigures> at_once(specs.size());
  std::vector<std::thread> threads;
  for (std::size_t k = 0; k < specs.size(); ++k)
    threads.emplace_back([&, k] { at_once[k] = run_experiment(specs[k], 1, screen); });
  for (std::thread& t : threads) t.join();
  for (std::size_t k = 0; k < specs.size(); ++k) {
    const RunFigures in_turn = run_experiment(specs[k], 1);
    EXPECT_EQ(at_once[k].frame, in_turn.frame) << k;
    EXPECT_EQ(at_once[k].ops, in_turn.ops) << k;
    EXPECT_EQ(at_once[k].breakdown.cycles, in_turn.breakdown.cycles) << k;
    EXPECT_EQ(at_once[k].links.bytes, in_turn.links.bytes) << k;
    EXPECT_EQ(at_once[k].command, in_turn.command) << k;
  }
}

}  // namespace
}  // namespace capsim::sim
