// The mode benchmarks run many experiments of one screen in a row and keep
// its trace (ScreenTraces): their figures do not depend on it.

#include "paper/experiment_run.h"

#include <gtest/gtest.h>

#include <string>

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

}  // namespace
}  // namespace capsim::sim
