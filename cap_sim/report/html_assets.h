#pragma once
// The HTML report's own files, compiled into the binary from cap_sim/report/html/ by
// cap_sim/report/embed_html_assets.cmake: the page template (report.html), its styles
// (report.css) and its script (report.js).

#include <string_view>

namespace capsim::sim {

struct HtmlAssets {
  std::string_view page;    // with the placeholders html_report fills
  std::string_view style;   // goes inside <style>
  std::string_view script;  // goes inside <script>
};

const HtmlAssets& html_assets();

}  // namespace capsim::sim
