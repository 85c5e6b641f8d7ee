#pragma once
// Data carried inside the HTML report: text made safe for an HTML page, bytes as
// base64 (images as data URIs), and the completion cycles of a frame packed for
// the page's player (docs/report.md describes the format).

#include "machine/parts/window_controller.h"

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace capsim::sim {

// 1234567 -> "1,234,567".
std::string grouped(std::uint64_t n);

// The page template (html_assets().page) with each placeholder, in the order
// given, replaced once by its text; what is put in is not searched again.
// Throws std::logic_error if the template lacks one.
std::string fill_template(std::string_view page,
                          const std::vector<std::pair<std::string_view, std::string_view>>& parts);

// Text for HTML element content or a quoted attribute value: & < > " ' escaped.
std::string html_escape(std::string_view text);

// JSON text for the inside of a <script type="application/json"> element:
// every "</" becomes "<\/" and every "<!--" becomes "\u003c!--", so nothing
// in it can end the element or change how the browser reads it. JSON.parse
// gives the same value; unescape_script_json gives back the same text
// (precondition for that: json is what nlohmann::json::dump writes, which
// never holds "<\/" or "\u003c").
std::string script_safe_json(std::string_view json);
std::string unescape_script_json(std::string_view text);

// RFC 4648 base64, with padding.
std::string base64(std::span<const unsigned char> bytes);

// "data:image/png;base64,..."
std::string png_data_uri(std::span<const unsigned char> png);

// A frame's completion cycles (row-major, one per screen pixel) packed in the
// order the cells wrote them: for each cell in id order, for each pixel k of
// its window in video-memory order, the cycles since its previous pixel
// completed (for k = 0, since cycle 0) as an unsigned LEB128 number: 7 bits a
// byte, low bits first, the high bit set on every byte but the last. A cell's
// pixels complete in order, so no difference is negative; stealing, chunks
// traced by a neighbour come back out of order, and `signed_differences`
// writes each difference zig-zag coded first (d >= 0 as 2d, d < 0 as
// -2d - 1). Throws std::invalid_argument if a difference is negative without
// it, or if the sizes do not match.
std::vector<unsigned char> pack_completion_cycles(const std::vector<std::uint64_t>& completion,
                                                  const WindowLayout& layout, bool signed_differences = false);

}  // namespace capsim::sim
