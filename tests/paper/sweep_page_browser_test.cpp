// A sweep's page in headless Chromium: written by `capsim sweep`, its script
// sorts the table of points by the column a fragment names; skipped where
// Chromium is not installed.

#include "support/chromium.h"
#include "support/cli_run.h"
#include "support/html_page.h"

#include <fmt/core.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <string>
#include <vector>

namespace capsim::sim {
namespace {

using namespace capsim::testing;

TEST(SweepPageInBrowser, ScriptSortsTheTableOfPointsByTheColumnNamed) {
  const std::string chromium = find_chromium();
  SKIP_WITHOUT_CHROMIUM(chromium);
  TempDir dir;
  const std::string scenes = std::string(CAPSIM_SOURCE_DIR) + "/scenes";
  std::ofstream(dir / "spec.json", std::ios::binary)
      << R"({"axes": {"scenes": [")" + scenes + R"(/balls.csg"], "sizes": ["16x16"], "modes": ["block", "dot"], )"
      << R"("cells": ["1x1", "2x2", "4x4"]}})";
  const auto run = run_capsim("sweep " + (dir / "spec.json") + " -o " + (dir / "out") + " --quiet", dir);
  ASSERT_EQ(run.status, 0) << run.err;
  const std::string dom = dump_dom(chromium, dir, dir / "out.html", "#sort=-speedup");

  const std::size_t root = dom.find("<html");
  const std::string html_tag = dom.substr(root, dom.find('>', root) - root);
  EXPECT_NE(html_tag.find("data-built=\"table\""), std::string::npos) << html_tag;

  // Sorted by the speed-up, most first, ties in the page's order.
  const nlohmann::json points = nlohmann::json::parse(read_file(dir / "out.json")).at("points");
  const auto table = data_attributes(dom, "runs-table");
  EXPECT_EQ(table.at("rows"), std::to_string(points.size()));
  EXPECT_EQ(table.at("sort-key"), "speedup");
  EXPECT_EQ(table.at("sort-order"), "descending");
  std::vector<double> speedups;
  for (const nlohmann::json& p : points) speedups.push_back(p.at("speedup").get<double>());
  const std::vector<std::size_t> index = descending_order(speedups);
  EXPECT_EQ(table.at("order"), order_text(index));
  ASSERT_NE(index[0], 0u) << "the sort must move rows for the test to tell";
  // The rows themselves moved: the first in the DOM is the point with the largest speed-up.
  const std::string row = first_row(dom, "runs-table");
  EXPECT_NE(row.find(fmt::format("<td>{}</td>", index[0] + 1)), std::string::npos) << row;
  EXPECT_NE(row.find(fmt::format("{:.3f}</td>", points[index[0]].at("speedup").get<double>())), std::string::npos)
      << row;
}

}  // namespace
}  // namespace capsim::sim
