#include "report/page_data.h"

#include <fmt/core.h>

#include <stdexcept>

namespace capsim::sim {

std::string grouped(std::uint64_t n) {
  std::string digits = std::to_string(n), out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

std::string fill_template(std::string_view page,
                          const std::vector<std::pair<std::string_view, std::string_view>>& parts) {
  std::string out;
  std::size_t at = 0;
  for (const auto& [placeholder, text] : parts) {
    const std::size_t hit = page.find(placeholder, at);
    if (hit == std::string_view::npos)
      throw std::logic_error(fmt::format("the page template lacks {}", placeholder));
    out.append(page.substr(at, hit - at));
    out.append(text);
    at = hit + placeholder.size();
  }
  out.append(page.substr(at));
  return out;
}

std::string html_escape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

namespace {

// Replaces every `from` by `to`, scanning left to right.
std::string replace_all(std::string_view text, std::string_view from, std::string_view to) {
  std::string out;
  out.reserve(text.size());
  std::size_t at = 0;
  for (std::size_t hit; (hit = text.find(from, at)) != std::string_view::npos; at = hit + from.size()) {
    out.append(text.substr(at, hit - at));
    out.append(to);
  }
  out.append(text.substr(at));
  return out;
}

}  // namespace

std::string script_safe_json(std::string_view json) {
  return replace_all(replace_all(json, "</", "<\\/"), "<!--", "\\u003c!--");
}

std::string unescape_script_json(std::string_view text) {
  return replace_all(replace_all(text, "\\u003c!--", "<!--"), "<\\/", "</");
}

std::string base64(std::span<const unsigned char> bytes) {
  static constexpr char kDigits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 3 <= bytes.size(); i += 3) {
    const std::uint32_t v = (bytes[i] << 16) | (bytes[i + 1] << 8) | bytes[i + 2];
    out += kDigits[v >> 18];
    out += kDigits[(v >> 12) & 63];
    out += kDigits[(v >> 6) & 63];
    out += kDigits[v & 63];
  }
  if (i + 1 == bytes.size()) {
    const std::uint32_t v = bytes[i] << 16;
    out += kDigits[v >> 18];
    out += kDigits[(v >> 12) & 63];
    out += "==";
  } else if (i + 2 == bytes.size()) {
    const std::uint32_t v = (bytes[i] << 16) | (bytes[i + 1] << 8);
    out += kDigits[v >> 18];
    out += kDigits[(v >> 12) & 63];
    out += kDigits[(v >> 6) & 63];
    out += '=';
  }
  return out;
}

std::string png_data_uri(std::span<const unsigned char> png) { return "data:image/png;base64," + base64(png); }

std::vector<unsigned char> pack_completion_cycles(const std::vector<std::uint64_t>& completion,
                                                  const WindowLayout& layout, bool signed_differences) {
  if (completion.size() != static_cast<std::size_t>(layout.width()) * layout.height())
    throw std::invalid_argument(fmt::format("{} completion cycles for a {}x{} screen", completion.size(),
                                            layout.width(), layout.height()));
  std::vector<unsigned char> out;
  out.reserve(completion.size() * 3);
  for (CellId c = 0; c < layout.grid().cell_count(); ++c) {
    const CellWindow& w = layout.window(c);
    std::uint64_t previous = 0;
    for (int k = 0; k < w.pixel_count(); ++k) {
      const ScreenPixel p = w.screen_pixel(k);
      const std::uint64_t t = completion[static_cast<std::size_t>(p.y) * layout.width() + p.x];
      if (t < previous && !signed_differences)
        throw std::invalid_argument(fmt::format("cell {} pixel {} completes before the one before it", c, k));
      const std::uint64_t difference =
          !signed_differences ? t - previous : t >= previous ? 2 * (t - previous) : 2 * (previous - t) - 1;
      for (std::uint64_t d = difference;; d >>= 7) {
        if (d < 128) {
          out.push_back(static_cast<unsigned char>(d));
          break;
        }
        out.push_back(static_cast<unsigned char>((d & 127) | 128));
      }
      previous = t;
    }
  }
  return out;
}

}  // namespace capsim::sim
