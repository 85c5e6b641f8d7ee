#pragma once
// The records of a sweep (docs/sweeps.md): a point's inputs and the figures of
// its run, the speed-ups among them, and the CSV and JSON files that hold
// them. Both files are made from the records alone, so a sweep resumed from
// its JSON writes the same bytes as one run whole.

#include "machine/machine.h"
#include "paper/sweeps/sweep_spec.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace capsim::sim {

// The inputs' keys of a record, in the order of the CSV's columns.
const std::vector<std::string>& sweep_input_keys();

// A point's record: sweep_inputs, the run's figures (as `capsim simulate
// --report` gives them) and the version of capsim that ran it; no speed-up.
nlohmann::json sweep_record(const SweepPoint& p, const SimulationResult& r, const std::string& version);

// The record of `inputs` in a sweep file's JSON (sweep_json's form), if it has
// one. Throws std::runtime_error when `doc` is not a sweep's JSON.
std::optional<nlohmann::json> find_sweep_record(const nlohmann::json& doc, const nlohmann::json& inputs);

// Sets every record's "speedup": the frame cycles of the record with the
// fewest cells among those equal in every other input (the first such in
// order), over its own.
void add_speedups(std::vector<nlohmann::json>& records);

// The files: a CSV with a header row and a row per record, and JSON naming the
// writing version and the sweep file.
std::string sweep_csv(const std::vector<nlohmann::json>& records);
std::string sweep_json(const std::vector<nlohmann::json>& records, const std::string& sweep_file,
                       const std::string& version);

}  // namespace capsim::sim
