// The mode benchmark's page in headless Chromium: its script sorts the table
// of runs by the column a fragment names; skipped where Chromium is not
// installed.

#include "paper/modes/modes_bench.h"
#include "paper/modes/modes_page.h"
#include "support/chromium.h"
#include "support/cli_run.h"
#include "support/html_page.h"

#include <fmt/core.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace capsim::sim {
namespace {

using namespace capsim::testing;

void write(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

std::uint64_t number(const std::map<std::string, std::string>& attributes, const std::string& key) {
  const auto it = attributes.find(key);
  if (it == attributes.end()) throw std::runtime_error("no data-" + key);
  return std::stoull(it->second);
}

TEST(ModesPageInBrowser, ScriptSortsTheTableOfRunsByTheColumnNamed) {
  const std::string chromium = find_chromium();
  SKIP_WITHOUT_CHROMIUM(chromium);
  TempDir dir;
  ModesBenchOptions options;
  options.width = options.height = 16;
  options.scenes_dir = std::string(CAPSIM_SOURCE_DIR) + "/scenes";
  const ModesBench bench = run_modes_bench(options);
  write(dir / "modes.html", modes_page(bench, {"bench/baselines/modes-16x16.json", false, true, "", {}}, "0.1.0"));
  const std::string dom = dump_dom(chromium, dir, dir / "modes.html", "#sort=-d");

  const std::size_t root = dom.find("<html");
  const std::string html_tag = dom.substr(root, dom.find('>', root) - root);
  EXPECT_NE(html_tag.find("data-built=\"table\""), std::string::npos) << html_tag;

  // Sorted by d, most first, ties in the page's order: the rows' positions
  // as written.
  const auto table = data_attributes(dom, "runs-table");
  EXPECT_EQ(number(table, "rows"), bench.runs.size());
  EXPECT_EQ(table.at("sort-key"), "d");
  EXPECT_EQ(table.at("sort-order"), "descending");
  std::vector<double> d;
  for (const ModeRun& r : bench.runs) d.push_back(r.figures.spread.deviation_percent);
  const std::vector<std::size_t> index = descending_order(d);
  EXPECT_EQ(table.at("order"), order_text(index));
  ASSERT_NE(index[0], 0u) << "the sort must move rows for the test to tell";
  // The rows themselves moved: the first in the DOM is the run with the largest d.
  const std::string row = first_row(dom, "runs-table");
  EXPECT_NE(row.find(fmt::format("data-index=\"{}\"", index[0])), std::string::npos) << row;
  EXPECT_NE(row.find(fmt::format("{:.2f}</td>", bench.runs[index[0]].figures.spread.deviation_percent)),
            std::string::npos)
      << row;
}

}  // namespace
}  // namespace capsim::sim
