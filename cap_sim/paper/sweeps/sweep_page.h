#pragma once
// The page of plots of a sweep (`capsim sweep`, PREFIX.html, docs/sweeps.md),
// built like the mode-comparison page: a header naming the sweep, its points
// and the axes it varies; a note on reading d, the time and the speed-up as
// the paper uses them; per scene, inline SVG plots of d, the frame time and the
// speed-up against the number of cells, one series per combination of the
// other axes the sweep varies; and one table of every point, plain HTML, which
// the mode-comparison page's script (cap_sim/report/html/modes.js) sorts by any
// column. Nothing on it comes from outside the page. It is made from the
// records alone, as PREFIX.csv and PREFIX.json are, so the same records give
// the same bytes, a resumed sweep's included.

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace capsim::sim {

// records: sweep_record's, with their speed-ups (add_speedups), in the
// sweep's order; sweep_file: the sweep file's name, as PREFIX.json gives it.
std::string sweep_page(const std::vector<nlohmann::json>& records, const std::string& sweep_file,
                       const std::string& version);

}  // namespace capsim::sim
