#include "paper/sweeps/sweep_records.h"

#include "machine/run_figures.h"

#include <fmt/core.h>

#include <stdexcept>

namespace capsim::sim {

namespace {

using nlohmann::json;

// The inputs' keys, in the order of the CSV's columns.
const std::vector<std::string> kInputKeys = {"scene",        "cells",         "mode",            "balance",
                                             "aa",           "profile",       "size",            "grid",
                                             "primary_only", "frame_average", "voxel_generation"};
// The figures' keys, after them.
const std::vector<std::string> kFigureKeys = {
    "frames",           "width",       "height",      "clock_hz",         "frame_cycles",
    "frame_seconds",    "max_cycles",  "min_cycles",  "max_seconds",      "min_seconds",
    "deviation_percent", "busy_deviation_percent",    "speedup",          "bus_transfers",
    "bus_bytes",        "bus_cycles",  "bus_seconds", "link_messages",    "link_bytes",
    "balance_bus_percent", "tile_wait_cycles", "chunks_stolen", "steal_link_bytes", "voxel_generation_cycles",
    "voxel_bus_bytes",  "capsim_version"};

json inputs_of(const json& record) {
  json inputs = json::object();
  for (const std::string& key : kInputKeys) inputs[key] = record.at(key);
  return inputs;
}

// A CSV field: quoted when it holds a comma, a quote or a line break.
std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string q = "\"";
  for (char ch : s) q += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return q + "\"";
}

// A value as a CSV cell: strings bare, a scene's sequence or animation as its
// JSON text.
std::string csv_value(const json& v) { return csv_field(v.is_string() ? v.get<std::string>() : v.dump()); }

}  // namespace

const std::vector<std::string>& sweep_input_keys() { return kInputKeys; }

json sweep_record(const SweepPoint& p, const SimulationResult& r, const std::string& version) {
  const std::uint64_t hz = r.config.profile.clock_hz;
  const LoadSpread s = load_spread(r);
  const LoadSpread busy = busy_spread(r);
  const LinkTotals links = link_totals(r);
  Cycles tile_wait;
  std::uint64_t stolen = 0;
  for (const CellReport& c : r.cells) {
    tile_wait += c.tile_wait;
    stolen += c.chunks_stolen;
  }
  json record = sweep_inputs(p);
  record.update({{"frames", r.screens.size()},
                 {"width", r.width},
                 {"height", r.height},
                 {"clock_hz", hz},
                 {"frame_cycles", r.frame.count()},
                 {"frame_seconds", r.frame.seconds(hz)},
                 {"max_cycles", s.max_finish.count()},
                 {"min_cycles", s.min_finish.count()},
                 {"max_seconds", s.max_finish.seconds(hz)},
                 {"min_seconds", s.min_finish.seconds(hz)},
                 {"deviation_percent", s.deviation_percent},
                 {"busy_deviation_percent", busy.deviation_percent},
                 {"bus_transfers", r.bus.transfers},
                 {"bus_bytes", r.bus.bytes},
                 {"bus_cycles", r.bus.busy.count()},
                 {"bus_seconds", r.bus.busy.seconds(hz)},
                 {"link_messages", links.messages},
                 {"link_bytes", links.bytes},
                 {"balance_bus_percent", balance_bus_percent(r)},
                 {"tile_wait_cycles", tile_wait.count()},
                 {"chunks_stolen", stolen},
                 {"steal_link_bytes", r.steal_links.bytes},
                 {"voxel_generation_cycles", r.breakdown[CostCategory::VoxelGeneration].count()},
                 {"voxel_bus_bytes", r.voxel_entries_bus.bytes + r.voxel_rows_bus.bytes},
                 {"capsim_version", version}});
  return record;
}

std::optional<json> find_sweep_record(const json& doc, const json& inputs) {
  if (!doc.is_object() || !doc.contains("points") || !doc["points"].is_array())
    throw std::runtime_error("not a sweep's JSON: it has no \"points\" list");
  for (const json& record : doc["points"]) {
    bool same = record.is_object();
    for (const std::string& key : kInputKeys) same = same && record.contains(key) && record[key] == inputs.at(key);
    if (same) return record;
  }
  return std::nullopt;
}

void add_speedups(std::vector<json>& records) {
  for (json& r : records) {
    json others = inputs_of(r);
    others.erase("cells");
    const json* base = nullptr;
    int fewest = 0;
    for (const json& o : records) {
      json o_others = inputs_of(o);
      o_others.erase("cells");
      if (o_others != others) continue;
      const std::string cells = o.at("cells").get<std::string>();
      const int count = std::stoi(cells) * std::stoi(cells.substr(cells.find('x') + 1));
      if (!base || count < fewest) {
        base = &o;
        fewest = count;
      }
    }
    r["speedup"] = base->at("frame_cycles").get<double>() / r.at("frame_cycles").get<double>();
  }
}

std::string sweep_csv(const std::vector<json>& records) {
  std::string out;
  // One line: the value of every input key, then every figure key, by comma.
  const auto line = [&](const auto& value_of) {
    bool first = true;
    for (const auto* keys : {&kInputKeys, &kFigureKeys})
      for (const std::string& key : *keys) {
        if (!first) out += ',';
        first = false;
        out += value_of(key);
      }
    out += '\n';
  };
  line([](const std::string& key) { return key; });
  for (const json& r : records) line([&](const std::string& key) { return csv_value(r.at(key)); });
  return out;
}

std::string sweep_json(const std::vector<json>& records, const std::string& sweep_file, const std::string& version) {
  json doc = {{"sweep", sweep_file}, {"capsim_version", version}, {"points", records}};
  return doc.dump(2) + "\n";
}

}  // namespace capsim::sim
