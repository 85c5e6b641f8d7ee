#pragma once
// What the calibration fits and how a run's time depends on it
// (docs/calibration.md). The paper's Table 4-1 measured eight operations on
// both machines; the costs it does not give are fitted, once, to every
// published time. A fitted parameter is a cost in M380 microseconds; a CAP
// cell pays kCapOverM380 times it (Table 4-1's median ratio) and the CAP's
// host the same as the M380 (one host: the runs give no way to tell two
// apart, docs/calibration.md).

#include "machine/costs/cost_profile.h"
#include "paper/calibration/joint_fit.h"

#include "capsim/trace/op_counts.h"

#include <optional>
#include <string>
#include <vector>

namespace capsim::sim {

struct FitParameter {
  CostTerm term;  // the profile term it sets (the cell's or the host's)
  double cap_multiplier() const;  // a CAP cell: kCapOverM380; the host: 1
};

// The fitted costs, in the order the reports list them.
std::vector<FitParameter> fit_parameters();

// The machines the published times ran on.
enum class Machine { Cap, M380 };

// Operations of a piece of a run: a cell's (or every cell's) and the host's
// voxel generation ahead of it.
struct WorkCounts {
  OpCounts ops;
  std::uint64_t pixels = 0;
  VoxelGenCounts voxels;
};

// A time the run measured as `simulated_seconds` at `profile`'s costs,
// written as a linear function of the fitted parameters: the work the fitted
// terms charge for (only those of `category` when given) moves with them,
// the rest stays.
LinearTime linear_time(double simulated_seconds, const WorkCounts& counts, const CostProfile& profile,
                       Machine machine, std::optional<CostCategory> category = std::nullopt);

// A profile's cost of term t in microseconds (its cycles / clock).
double profile_value_us(CostTerm t, const CostProfile& profile);

// The parameters' values in a profile of `machine` (M380 microseconds).
std::vector<double> parameter_values(const CostProfile& profile, Machine machine);

// The shipped profile of `machine` with the parameters set to x (M380
// microseconds; each rounded to 4 significant digits), as the JSON text
// written to cap_sim/profiles/ and as the profile that text gives.
std::string calibrated_profile_json(const std::vector<double>& x, Machine machine);
CostProfile calibrated_profile(const std::vector<double>& x, Machine machine);

}  // namespace capsim::sim
