#pragma once
// One point of a sweep run as `capsim simulate` runs it: the same scene
// loading (sequences, --frames animation, OpenSCAD input, the memory check)
// and the same machine, without the image files.

#include "machine/machine.h"
#include "paper/sweeps/sweep_spec.h"

namespace capsim::cli {

// threads: host threads for the point (0 = all); the result does not depend on it.
sim::SimulationResult run_sweep_point(const sim::SweepPoint& p, int threads);

}  // namespace capsim::cli
