// `capsim simulate` end to end: the screen is byte-identical to `capsim render`,
// every output is byte-identical across runs and host thread counts (but for
// --threads itself, which the reports' provenance records), and bad options
// fail with a message.

#include "support/cli_run.h"
#include "support/provenance.h"

#include <nlohmann/json.hpp>

using namespace capsim::testing;

namespace {

const std::string kBalls = scene_path("balls.csg");

TEST(CliSimulate, ScreenIsByteIdenticalToRenderInEveryMode) {
  TempDir dir;
  ASSERT_EQ(run_capsim("render " + kBalls + " -o " + (dir / "render.png") + " --size 120x90", dir).status, 0);
  const std::string rendered = read_file(dir / "render.png");
  for (const std::string mode : {"dot", "line", "block"}) {
    const RunResult r = run_capsim("simulate " + kBalls + " -o " + (dir / "sim.png") +
                                       " --size 120x90 --cells 8x8 --mode " + mode, dir);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(read_file(dir / "sim.png"), rendered) << mode;
  }
}

TEST(CliSimulate, OutputsAreByteIdenticalAcrossRunsAndThreadCounts) {
  TempDir dir;
  std::string first[5];
  for (const std::string threads : {"1", "2", "2"}) {
    const RunResult r = run_capsim("simulate " + kBalls + " -o " + (dir / "s.png") + " --size 96x72" +
                                       " --report " + (dir / "r.json") + " --trace " + (dir / "t.json") +
                                       " --heatmap " + (dir / "h.png") + " --threads " + threads, dir);
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string now[5] = {read_file(dir / "s.png"), without_threads(read_file(dir / "r.json")),
                                read_file(dir / "t.json"), read_file(dir / "h.png"), text_without_threads(r.out)};
    EXPECT_EQ(nlohmann::json::parse(read_file(dir / "r.json"))["provenance"]["options"]["threads"],
              std::stoi(threads));
    EXPECT_NE(r.out.find("  options  "), std::string::npos) << r.out;
    if (first[0].empty()) {
      std::copy(std::begin(now), std::end(now), std::begin(first));
      continue;
    }
    for (int i = 0; i < 5; ++i) EXPECT_EQ(now[i], first[i]) << "output " << i << " with --threads " << threads;
  }
}

TEST(CliSimulate, ReportHasTheDocumentedKeys) {
  TempDir dir;
  const RunResult r = run_capsim("simulate " + kBalls + " -o " + (dir / "s.png") +
                                     " --size 40x30 --cells 2x3 --mode line --report " + (dir / "r.json"), dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(read_file(dir / "r.json"));
  EXPECT_EQ(j["mode"], "line");
  EXPECT_EQ(j["cells_grid"], "2x3");
  EXPECT_EQ(j["profile"], "cap");
  EXPECT_EQ(j["clock_hz"], 8000000);
  ASSERT_EQ(j["cells"].size(), 6u);
  for (const char* key : {"row", "col", "pixels", "rays", "busy_cycles", "idle_cycles", "comm_cycles", "finish_cycles"})
    EXPECT_TRUE(j["cells"][0].contains(key)) << key;
  for (const char* key : {"intersection", "dda", "csg", "voxel_generation", "other"})
    EXPECT_TRUE(j["breakdown"].contains(key)) << key;
  std::uint64_t max_finish = 0;
  for (const auto& c : j["cells"]) max_finish = std::max<std::uint64_t>(max_finish, c["finish_cycles"]);
  EXPECT_EQ(j["total_cycles"], max_finish);
  EXPECT_DOUBLE_EQ(j["max_seconds"].get<double>(), static_cast<double>(max_finish) / 8e6);
  EXPECT_NE(r.out.find("d = (Max - Min) / Max"), std::string::npos);
  EXPECT_NE(r.out.find("CSG evaluation"), std::string::npos);
  // The spread of the cells' busy time alone, without the host's prefix.
  std::uint64_t busy_max = 0, busy_min = UINT64_MAX;
  for (const auto& c : j["cells"]) {
    busy_max = std::max<std::uint64_t>(busy_max, c["busy_cycles"]);
    busy_min = std::min<std::uint64_t>(busy_min, c["busy_cycles"]);
  }
  EXPECT_EQ(j["busy_max_cycles"], busy_max);
  EXPECT_EQ(j["busy_min_cycles"], busy_min);
  EXPECT_DOUBLE_EQ(j["busy_deviation_percent"].get<double>(),
                   100.0 * static_cast<double>(busy_max - busy_min) / static_cast<double>(busy_max));
  EXPECT_NE(r.out.find("busy only (the cycles each cell computed): Max "), std::string::npos) << r.out;
  // What a cell held for its unit (one frame), against the profile's sizes.
  EXPECT_EQ(j["unit_memory"]["unit_frames"], 1);
  EXPECT_EQ(j["unit_memory"]["cell_memory_bytes"],
            j["program_bytes"].get<std::uint64_t>() + j["scene_bytes"].get<std::uint64_t>() +
                j["voxel_bytes"].get<std::uint64_t>());
  EXPECT_EQ(j["unit_memory"]["cell_memory_limit_bytes"], 1048576);
  EXPECT_EQ(j["unit_memory"]["video_memory_bytes"], 5 * 40 * 3);  // 40x30 in line mode on 6 cells: 5 rows each
  EXPECT_EQ(j["unit_memory"]["video_memory_limit_bytes"], 1048576);
}

TEST(CliSimulate, TraceHasAHostABusAndOneTrackPerCell) {
  TempDir dir;
  const RunResult r = run_capsim("simulate " + kBalls + " -o " + (dir / "s.png") +
                                     " --size 20x20 --cells 2x2 --trace " + (dir / "t.json"), dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(read_file(dir / "t.json"));
  std::vector<std::string> tracks;
  int spans = 0;
  for (const auto& e : j["traceEvents"]) {
    if (e["ph"] == "M" && e["name"] == "thread_name") tracks.push_back(e["args"]["name"]);
    if (e["ph"] == "X") ++spans;
  }
  EXPECT_EQ(tracks, (std::vector<std::string>{"host", "command bus", "cell[0,0]", "cell[0,1]", "cell[1,0]", "cell[1,1]"}));
  EXPECT_GT(spans, 0);
}

TEST(CliSimulate, ExrCarriesACyclesChannel) {
  TempDir dir;
  const RunResult r = run_capsim("simulate " + kBalls + " -o " + (dir / "s.exr") + " --size 16x16 --cells 2x2", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(read_file(dir / "s.exr").find("cycles"), std::string::npos);
}

TEST(CliSimulate, BadOptionsFailWithAMessage) {
  TempDir dir;
  const std::string base = "simulate " + kBalls + " -o " + (dir / "s.png") + " --size 8x8 ";
  struct Case {
    std::string args, message;
  };
  const Case cases[] = {{"--cells 0x8", "out of range"},
                        {"--cells 33x1", "out of range"},
                        {"--cells 8by8", "RxC"},
                        {"--mode diagonal", "diagonal"},
                        {"--profile no-such-profile", "cap, m380"},
                        {"--heatmap " + (dir / "h.jpg"), ".png"}};
  for (const Case& c : cases) {
    const RunResult r = run_capsim(base + c.args, dir);
    EXPECT_EQ(r.status, 2) << c.args;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << ": " << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "s.png")) << c.args;
  }
}

// A copy of the cap profile with one value changed, written to `path`.
void write_cap_profile_with(const std::string& path, const std::string& section,
                            const std::string& key, const nlohmann::json& value) {
  nlohmann::json p = nlohmann::json::parse(
      read_file(std::string(CAPSIM_SOURCE_DIR) + "/cap_sim/profiles/cap.json"));
  (section.empty() ? p : p[section])[key] = value;
  std::ofstream(path) << p.dump(2);
}

TEST(CliSimulate, WarnsOfCostsThatRoundingToCyclesMoved) {
  TempDir dir;
  write_cap_profile_with(dir / "slow.json", "", "clock_hz", 1000);  // 1 ms a cycle
  const RunResult r = run_capsim("simulate " + kBalls + " -o " + (dir / "s.png") + " --size 16x16 --profile " +
                                     (dir / "slow.json"), dir);
  ASSERT_EQ(r.status, 0) << r.err;
  // Table 4-1's 160 us is 0.16 cycles: the 3DDDA's steps become free.
  EXPECT_NE(r.err.find("capsim: warning: cost profile " + (dir / "slow.json") +
                       ": cell_costs_us.dda_step = 160 us becomes 0 cycles at clock_hz 1000 (0.16 exactly, "
                       "100.0 % off); the run charges 0 cycles\n"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("cell_costs_us.matvec = 597 us becomes 1 cycles"), std::string::npos) << r.err;
  // 2980 us is 2.98 cycles: 3 is within 1 %.
  EXPECT_EQ(r.err.find("sphere_test"), std::string::npos) << r.err;
  // The built-in profile gives no warning.
  const RunResult plain = run_capsim("simulate " + kBalls + " -o " + (dir / "s.png") + " --size 16x16", dir);
  ASSERT_EQ(plain.status, 0) << plain.err;
  EXPECT_EQ(plain.err.find("warning"), std::string::npos) << plain.err;
}

TEST(CliSimulate, CycleCountsBeyond64BitsFailNamingTheProfileAndWriteNothing) {
  TempDir dir;
  struct Case {
    std::string section, key;
    nlohmann::json value;
    std::string message;
  };
  const Case cases[] = {
      // Each cost fits; a cell's sum does not (it used to wrap, exit 0).
      {"cell_costs_us", "sphere_test", 1e17,
       "slow.json: the simulated time exceeds the 64-bit cycle counter (18446744073709551615 cycles"},
      // The cost itself does not fit (it used to become 2^63 cycles, exit 0).
      {"cell_costs_us", "sphere_test", 1e19,
       "slow.json: cell_costs_us.sphere_test = 1e+19 us is 8e+19 cycles at clock_hz 8000000, more "
       "than a 64-bit cycle count holds"},
      // Fits per cost, not per cell (it used to fail with "event scheduled in the past").
      {"", "clock_hz", 18446744073709551615u,
       "slow.json: the simulated time exceeds the 64-bit cycle counter (18446744073709551615 "
       "cycles, 1 s at clock_hz 18446744073709551615): cell[0,0]'s work for its 64 pixels adds up to "}};
  for (const Case& c : cases) {
    write_cap_profile_with(dir / "slow.json", c.section, c.key, c.value);
    const RunResult r = run_capsim("simulate " + kBalls + " -o " + (dir / "s.png") + " --size 64x64 --profile " +
                                       (dir / "slow.json") + " --report " + (dir / "r.json") + " --heatmap " +
                                       (dir / "h.png"),
                                   dir);
    EXPECT_EQ(r.status, 1) << c.key << " " << c.value;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.value << ": " << r.err;
    EXPECT_EQ(r.err.rfind("capsim: cost profile ", 0), 0u) << r.err;
    EXPECT_EQ(r.out, "");
    for (const char* f : {"s.png", "r.json", "h.png"}) EXPECT_FALSE(std::filesystem::exists(dir / f)) << f;
  }
}

}  // namespace
