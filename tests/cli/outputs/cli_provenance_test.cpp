// The provenance every `capsim simulate` report carries: the command line as
// typed, capsim's version, each scene file's and the profile's SHA-256, and
// every option's effective value, the same in the --report JSON, the text
// report and the HTML page; stable from run to run, changing with the scene.

#include "support/cli_run.h"
#include "support/html_page.h"

#include "capsim/system/sha256.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <sstream>

using namespace capsim::testing;

namespace {

const std::string kBalls = scene_path("balls.csg");

std::vector<std::string> words(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

// The version `capsim --version` prints ("capsim 0.1.0").
std::string capsim_version(const TempDir& dir) {
  const RunResult r = run_capsim("--version", dir);
  return r.out.substr(r.out.find(' ') + 1, r.out.find('\n') - r.out.find(' ') - 1);
}

nlohmann::json report_of(const TempDir& dir, const std::string& name) {
  return nlohmann::json::parse(read_file(dir / name));
}

TEST(CliProvenance, ReportNamesTheCommandVersionInputsAndEveryOption) {
  TempDir dir;
  const std::string args = "simulate " + kBalls + " -o " + (dir / "s.png") +
                           " --size 40x30 --cells 2x3 --mode line --grid 9 --threads 1 --max-memory 1G --report " +
                           (dir / "r.json");
  const RunResult r = run_capsim(args, dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json p = report_of(dir, "r.json")["provenance"];
  std::vector<std::string> argv = words(args);
  argv.insert(argv.begin(), CAPSIM_EXE);
  EXPECT_EQ(p["argv"], argv);
  EXPECT_EQ(p["capsim_version"], capsim_version(dir));
  ASSERT_EQ(p["scenes"].size(), 1u);
  EXPECT_EQ(p["scenes"][0]["path"], kBalls);
  EXPECT_EQ(p["scenes"][0]["sha256"], capsim::sha256_hex(read_file(kBalls)));
  EXPECT_EQ(p["profile"]["given"], "cap");
  EXPECT_EQ(p["profile"]["name"], "cap");
  EXPECT_EQ(p["profile"]["sha256"],
            capsim::sha256_hex(read_file(std::string(CAPSIM_SOURCE_DIR) + "/cap_sim/profiles/cap.json")));
  const nlohmann::json o = p["options"];
  const nlohmann::json expected = {{"scenes", {kBalls}},
                                   {"frames", nullptr},
                                   {"output", dir / "s.png"},
                                   {"size", "40x30"},
                                   {"grid", 9},
                                   {"grid_divisions", {9}},
                                   {"threads", 1},
                                   {"max_memory", 1u << 30},
                                   {"primary_only", false},
                                   {"aa", 0},
                                   {"aa_threshold", 0.3},
                                   {"cells", "2x3"},
                                   {"mode", "line"},
                                   {"profile", "cap"},
                                   {"report", dir / "r.json"},
                                   {"trace", nullptr},
                                   {"heatmap", nullptr},
                                   {"html", nullptr},
                                   {"frame_average", false},
                                   {"defines", nlohmann::json::array()},
                                   {"camera", nullptr},
                                   {"view", "--camera=14,-18,11,0,0,0 --projection=perspective"},
                                   {"view_statement", "camera(eye = [14, -18, 11], center = [0, 0, 0], up = [0, 0, 1], "
                                                      "fov = 40);"},
                                   {"verbose", false},
                                   {"quiet", false}};
  EXPECT_EQ(o, expected) << o.dump(2);
}

// OpenSCAD's view options are recorded as taken, beside the view they gave.
TEST(CliProvenance, ReportRecordsOpenScadsViewOptions) {
  TempDir dir;
  const RunResult r = run_capsim("simulate " + kBalls + " -o " + (dir / "s.png") +
                                     " --size 16x16 --cells 2x2 --camera=0,0,0,55,0,25,30 --projection=o --quiet "
                                     "--report " + (dir / "r.json"),
                                 dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json o = report_of(dir, "r.json")["provenance"]["options"];
  EXPECT_EQ(o["camera"], (nlohmann::json{{"camera", {0, 0, 0, 55, 0, 25, 30}},
                                         {"viewall", false},
                                         {"autocenter", false},
                                         {"projection", "ortho"}}))
      << o.dump(2);
  EXPECT_NE(o["view"].get<std::string>().find("--projection=ortho"), std::string::npos) << o.dump(2);
  EXPECT_EQ(o["quiet"], true);
}

// The defaults are recorded as the values the run used: the camera's size,
// the grid auto chose, the aa threshold.
TEST(CliProvenance, DefaultsAreRecordedAsTheValuesUsed) {
  TempDir dir;
  const std::string scene = dir / "small.csg";
  std::ofstream(scene) << "camera(eye = [12, -16, 9], center = [0, 0, 0], fov = 35, size = [30, 20]);\n"
                          "sphere(r = 2);\n";
  const RunResult r = run_capsim("simulate " + scene + " -o " + (dir / "s.png") + " --cells 2x2 --primary-only "
                                 "--aa 1 --report " + (dir / "r.json") + " --trace " + (dir / "t.json"),
                                 dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json report = report_of(dir, "r.json");
  const nlohmann::json o = report["provenance"]["options"];
  EXPECT_EQ(o["size"], "30x20");  // the camera's
  EXPECT_EQ(report["width"], 30);
  EXPECT_EQ(o["grid"], "auto");
  ASSERT_EQ(o["grid_divisions"].size(), 1u);
  EXPECT_EQ(o["grid_divisions"][0], 8);  // auto's least, for one primitive
  EXPECT_EQ(o["threads"], 0);
  EXPECT_EQ(o["max_memory"], nullptr);
  EXPECT_EQ(o["primary_only"], true);
  EXPECT_EQ(o["aa"], 1);
  EXPECT_EQ(o["aa_threshold"], 0.3);
  EXPECT_EQ(o["mode"], "dot");
  EXPECT_EQ(o["trace"], dir / "t.json");
}

TEST(CliProvenance, DigestIsStableAndFollowsTheSceneAndTheProfile) {
  TempDir dir;
  const std::string scene = dir / "scene.csg";
  std::ofstream(scene) << read_file(kBalls);
  const std::string profile = dir / "mine.json";
  std::ofstream(profile) << read_file(std::string(CAPSIM_SOURCE_DIR) + "/cap_sim/profiles/cap.json");
  const std::string run = "simulate " + scene + " -o " + (dir / "s.png") + " --size 24x18 --cells 2x2 --profile " +
                          profile + " --report ";
  ASSERT_EQ(run_capsim(run + (dir / "a.json"), dir).status, 0);
  ASSERT_EQ(run_capsim(run + (dir / "b.json"), dir).status, 0);
  const nlohmann::json a = report_of(dir, "a.json")["provenance"], b = report_of(dir, "b.json")["provenance"];
  EXPECT_EQ(a["scenes"], b["scenes"]);
  EXPECT_EQ(a["profile"], b["profile"]);
  EXPECT_EQ(a["profile"]["given"], profile);
  EXPECT_EQ(a["profile"]["sha256"], capsim::sha256_hex(read_file(profile)));
  // A comment changes the file but not the picture.
  std::ofstream(scene, std::ios::app) << "// another comment\n";
  std::ofstream(profile, std::ios::app) << "\n";
  ASSERT_EQ(run_capsim(run + (dir / "c.json"), dir).status, 0);
  const nlohmann::json c = report_of(dir, "c.json")["provenance"];
  EXPECT_NE(c["scenes"][0]["sha256"], a["scenes"][0]["sha256"]);
  EXPECT_EQ(c["scenes"][0]["sha256"], capsim::sha256_hex(read_file(scene)));
  EXPECT_NE(c["profile"]["sha256"], a["profile"]["sha256"]);
  EXPECT_EQ(report_of(dir, "c.json")["total_cycles"], report_of(dir, "a.json")["total_cycles"]);
}

// The text report ends with the same provenance, and the HTML page shows it
// and carries it in its report data.
TEST(CliProvenance, TextReportAndPageShowTheProvenance) {
  TempDir dir;
  const RunResult r = run_capsim("simulate " + kBalls + " -o " + (dir / "s.png") +
                                     " --size 24x18 --cells 2x2 --report " + (dir / "r.json") + " --html " +
                                     (dir / "r.html"),
                                 dir);
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string sha = capsim::sha256_hex(read_file(kBalls));
  const std::size_t block = r.out.find("\nprovenance: capsim " + capsim_version(dir) + "\n");
  ASSERT_NE(block, std::string::npos) << r.out;
  const std::string text = r.out.substr(block);
  EXPECT_NE(text.find("  command  " + std::string(CAPSIM_EXE) + " simulate " + kBalls + " -o "), std::string::npos)
      << text;
  EXPECT_NE(text.find("  scene    " + kBalls + " sha256 " + sha + "\n"), std::string::npos) << text;
  EXPECT_NE(text.find("  profile  cap (name cap) sha256 "), std::string::npos) << text;
  EXPECT_NE(text.find("cells 2x2, "), std::string::npos) << text;
  EXPECT_NE(text.find("size 24x18, threads 0"), std::string::npos) << text;
  const std::string page = read_file(dir / "r.html");
  EXPECT_EQ(unescape_block(data_block_text(page, "report-data")), read_file(dir / "r.json"));
  EXPECT_NE(page.find("<th>SHA-256 of " + kBalls + "</th><td><code>" + sha + "</code></td>"), std::string::npos);
  EXPECT_NE(page.find("<th>Command as typed</th><td><code>" + std::string(CAPSIM_EXE) + " simulate "),
            std::string::npos);
}

}  // namespace
