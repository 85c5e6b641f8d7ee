#pragma once
// The HTML pages' own files, compiled into the binary from cap_sim/report/html/ by
// cap_sim/report/embed_html_assets.cmake: the page template (report.html), the
// run report's styles (report.css) and script (report.js), and what the
// mode-comparison page of `capsim bench modes` adds to those styles
// (modes.css) and runs instead of that script (modes.js); a sweep's page of
// plots (paper/sweeps/sweep_page.h) takes the same two.

#include <string_view>

namespace capsim::sim {

struct HtmlAssets {
  std::string_view page;    // with the placeholders html_report fills
  std::string_view style;   // goes inside <style>
  std::string_view script;  // goes inside <script>
  std::string_view modes_style;   // after style, on the mode-comparison page
  std::string_view modes_script;  // that page's <script>
};

const HtmlAssets& html_assets();

}  // namespace capsim::sim
