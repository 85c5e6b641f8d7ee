// A sweep's records: the speed-up against the fewest cells of otherwise equal
// inputs, a record found again by its inputs, and the CSV's quoting.

#include "paper/sweeps/sweep_records.h"

#include <gtest/gtest.h>

using nlohmann::json;

namespace {

json record(const std::string& scene, const std::string& cells, long long frame_cycles) {
  return {{"scene", scene},        {"cells", cells},   {"mode", "dot"},        {"balance", "static"}, {"aa", 0},
          {"profile", "cap"},      {"size", "16x16"},  {"grid", "auto"},       {"primary_only", false},
          {"frame_average", false}, {"voxel_generation", "host"}, {"frame_cycles", frame_cycles}};
}

TEST(SweepRecords, SpeedupIsAgainstTheFewestCellsOfTheSameOtherInputs) {
  std::vector<json> r = {record("a.csg", "8x8", 100), record("a.csg", "4x4", 400), record("b.csg", "8x8", 50)};
  capsim::sim::add_speedups(r);
  EXPECT_DOUBLE_EQ(r[0]["speedup"].get<double>(), 4.0);
  EXPECT_DOUBLE_EQ(r[1]["speedup"].get<double>(), 1.0);
  EXPECT_DOUBLE_EQ(r[2]["speedup"].get<double>(), 1.0);  // alone in its group
}

TEST(SweepRecords, ARecordIsFoundByItsInputs) {
  const json doc = {{"points", {record("a.csg", "8x8", 100), record("a.csg", "4x4", 400)}}};
  json inputs = record("a.csg", "4x4", 0);
  inputs.erase("frame_cycles");
  const auto found = capsim::sim::find_sweep_record(doc, inputs);
  ASSERT_TRUE(found);
  EXPECT_EQ((*found)["frame_cycles"], 400);
  inputs["aa"] = 2;
  EXPECT_FALSE(capsim::sim::find_sweep_record(doc, inputs));
  EXPECT_THROW(capsim::sim::find_sweep_record(json::object(), inputs), std::runtime_error);
}

}  // namespace
