#include "paper/calibration/calibration.h"

#include "machine/costs/builtin_profiles.h"
#include "paper/repro/paper_figures.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <stdexcept>

namespace capsim::sim {

double FitParameter::cap_multiplier() const {
  return info(term).payer == CostPayer::Cell ? paper::kCapOverM380 : 1.0;
}

std::vector<FitParameter> fit_parameters() {
  return {{CostTerm::RayOther},     {CostTerm::VoxelVisit},  {CostTerm::VoxelPass},  {CostTerm::TreeVisit},
          {CostTerm::HitSort},      {CostTerm::ShadingEval}, {CostTerm::PixelWrite}, {CostTerm::AaSquare},
          {CostTerm::HostPrimitive}, {CostTerm::HostColumn}, {CostTerm::HostEntry}, {CostTerm::HostGridVoxel}};
}

namespace {

double multiplier(const FitParameter& p, Machine machine) {
  return machine == Machine::Cap ? p.cap_multiplier() : 1.0;
}

double term_count(CostTerm t, const WorkCounts& c) {
  const CostTermInfo& i = info(t);
  return static_cast<double>(i.payer == CostPayer::Cell ? i.cell_count(c.ops, c.pixels) : i.voxel_count(c.voxels));
}

std::string_view builtin_json(Machine machine) {
  const std::string_view name = machine == Machine::Cap ? "cap" : "m380";
  for (const BuiltinProfile& b : builtin_profiles())
    if (b.name == name) return b.json;
  throw std::logic_error("no built-in profile " + std::string(name));
}

// x rounded to 4 significant digits, as the profile files print it.
double four_digits(double x) {
  if (x == 0) return 0;
  const double scale = std::pow(10.0, 3 - std::floor(std::log10(std::abs(x))));
  return std::round(x * scale) / scale;
}

// A term's cost in microseconds into its section; whole values as integers,
// as the files write them.
void set_cost(nlohmann::ordered_json& j, CostTerm t, double us) {
  const CostTermInfo& i = info(t);
  if (us == std::floor(us) && us < 1e15)
    j[profile_section(i.payer)][i.key] = static_cast<std::int64_t>(us);
  else
    j[profile_section(i.payer)][i.key] = us;
}

}  // namespace

double profile_value_us(CostTerm t, const CostProfile& p) {
  return static_cast<double>(p.costs[t].count()) * 1e6 / static_cast<double>(p.clock_hz);
}

LinearTime linear_time(double simulated_seconds, const WorkCounts& counts, const CostProfile& profile,
                       Machine machine, std::optional<CostCategory> category) {
  LinearTime t;
  t.fixed = simulated_seconds;
  for (const FitParameter& p : fit_parameters()) {
    const bool counted = !category || info(p.term).category == *category;
    const double n = counted ? term_count(p.term, counts) : 0.0;
    t.per_param.push_back(n * multiplier(p, machine) * 1e-6);
    t.fixed -= n * profile_value_us(p.term, profile) * 1e-6;
  }
  return t;
}

std::vector<double> parameter_values(const CostProfile& profile, Machine machine) {
  std::vector<double> x;
  for (const FitParameter& p : fit_parameters()) x.push_back(profile_value_us(p.term, profile) / multiplier(p, machine));
  return x;
}

std::string calibrated_profile_json(const std::vector<double>& x, Machine machine) {
  const std::vector<FitParameter> params = fit_parameters();
  if (x.size() != params.size()) throw std::invalid_argument("calibrated profile: one value per fitted cost");
  nlohmann::ordered_json j = nlohmann::ordered_json::parse(builtin_json(machine));
  for (std::size_t k = 0; k < params.size(); ++k) {
    const CostTermInfo& i = info(params[k].term);
    const double us = four_digits(x[k] * multiplier(params[k], machine));
    set_cost(j, params[k].term, us);
    // A cell generating voxels pays the host's fitted costs (as written) at a
    // cell's speed: on the CAP 164 times them, on the M380 (one machine) the
    // same.
    if (i.payer == CostPayer::Host)
      set_cost(j, cell_voxel_twin(params[k].term), four_digits(us * (machine == Machine::Cap ? paper::kCapOverM380 : 1.0)));
  }
  return j.dump(2) + "\n";
}

CostProfile calibrated_profile(const std::vector<double>& x, Machine machine) {
  return parse_cost_profile(calibrated_profile_json(x, machine), machine == Machine::Cap ? "cap" : "m380");
}

}  // namespace capsim::sim
