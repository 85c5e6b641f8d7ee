// `capsim bench modes --html FILE` at 48x48 against the stored baseline
// (bench/baselines/modes-48x48.json): the page is written, says the baseline
// matched, and is the same bytes on one and two host threads; with a moved
// figure it lists it; a path that cannot be written is a usage error before
// any run, and nothing is written.

#include "support/cli_run.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

namespace capsim::sim {
namespace {

using capsim::testing::read_file;
using capsim::testing::run_capsim;
using capsim::testing::TempDir;

const std::string kBaseline = std::string(CAPSIM_SOURCE_DIR) + "/bench/baselines/modes-48x48.json";
const std::string kArgs = " --size 48x48 --scenes " + std::string(CAPSIM_SOURCE_DIR) + "/scenes";

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(CliBenchModesHtml, WritesThePageSayingTheBaselineMatchedTheSameOnOneAndTwoThreads) {
  TempDir dir;
  const auto one = run_capsim("bench modes" + kArgs + " --baseline " + kBaseline + " --threads 1 --html " +
                                  (dir / "one.html"),
                              dir);
  ASSERT_EQ(one.status, 0) << one.out << one.err;
  EXPECT_NE(one.out.find("all 200 runs identical to the baseline"), std::string::npos) << one.out;
  const std::string page = read_file(dir / "one.html");
  EXPECT_TRUE(page.starts_with("<!DOCTYPE html>\n"));
  EXPECT_TRUE(page.ends_with("</html>\n"));
  EXPECT_NE(page.find("<strong id=\"screen-size\">48x48</strong> pixels, profile <strong>cap</strong>"),
            std::string::npos);
  EXPECT_NE(page.find("<strong id=\"run-count\">200 runs</strong>"), std::string::npos);
  EXPECT_NE(page.find("class=\"baseline matched\">Matched the baseline <code>" + kBaseline +
                      "</code>: all 200 runs identical"),
            std::string::npos);
  EXPECT_EQ(count(page, "<svg "), 6u);  // the overview and one per model
  // Every run of the baseline is a row, with its exact frame cycles.
  const nlohmann::json base = nlohmann::json::parse(read_file(kBaseline));
  EXPECT_EQ(count(page, "<tr title=\"capsim simulate "), base["runs"].size());
  for (const nlohmann::json& run : base["runs"])
    EXPECT_NE(page.find("<td data-value=\"" + std::to_string(run["frame_cycles"].get<std::uint64_t>()) + "\""),
              std::string::npos)
        << run.dump();

  const auto two = run_capsim("bench modes" + kArgs + " --baseline " + kBaseline + " --threads 2 --html " +
                                  (dir / "two.html"),
                              dir);
  ASSERT_EQ(two.status, 0) << two.err;
  EXPECT_EQ(read_file(dir / "two.html"), page);
}

TEST(CliBenchModesHtml, ListsWhatMovedWhenTheRunDiffersFromTheBaseline) {
  TempDir dir;
  nlohmann::json base = nlohmann::json::parse(read_file(kBaseline));
  nlohmann::json& run = base["runs"][10];  // balls, plain, dot mode, 8x8 cells
  ASSERT_EQ(run["model"], "balls");
  ASSERT_EQ(run["mode"], "dot");
  ASSERT_EQ(run["cells"], "8x8");
  const std::uint64_t frame = run["frame_cycles"].get<std::uint64_t>();
  run["frame_cycles"] = frame * 2;
  {
    std::ofstream out(dir / "old.json");
    out << base.dump(2);
  }
  const auto r = run_capsim("bench modes" + kArgs + " --baseline " + (dir / "old.json") + " --html " +
                                (dir / "modes.html"),
                            dir);
  EXPECT_EQ(r.status, 1) << r.out << r.err;
  const std::string page = read_file(dir / "modes.html");
  EXPECT_NE(page.find("class=\"baseline moved\">Differs from the baseline"), std::string::npos);
  EXPECT_NE(page.find("<tr><td>balls dot 8x8 aa0</td><td>frame_cycles</td><td>" + std::to_string(frame * 2) +
                      "</td><td>" + std::to_string(frame) + "</td><td>0.500000</td></tr>"),
            std::string::npos);
}

TEST(CliBenchModesHtml, APathThatCannotBeWrittenIsAUsageErrorBeforeAnyRun) {
  TempDir dir;
  const auto r = run_capsim("bench modes" + kArgs + " --baseline " + kBaseline + " --json " + (dir / "now.json") +
                                " --html " + (dir / "missing/modes.html"),
                            dir);
  EXPECT_EQ(r.status, 2) << r.out << r.err;
  EXPECT_NE(r.err.find("--html " + (dir / "missing/modes.html") + ": directory"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("balls block 4x4 aa0"), std::string::npos) << r.err;  // no run started
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

}  // namespace
}  // namespace capsim::sim
