#pragma once
// Reading back what the HTML report holds, independently of the code that
// writes it: its data blocks, its images, and each frame's packed completion
// cycles (docs/report.md gives the format).

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdint>
#include <map>
#include <regex>
#include <stdexcept>
#include <string>
#include <vector>

namespace capsim::testing {

// The text inside <script type="application/json" id="ID">, as written
// (escaped). Throws if the page has no such element or more than one.
inline std::string data_block_text(const std::string& page, const std::string& id) {
  const std::string open = "<script type=\"application/json\" id=\"" + id + "\">";
  const std::size_t begin = page.find(open);
  if (begin == std::string::npos) throw std::runtime_error("no data block " + id);
  if (page.find(open, begin + 1) != std::string::npos) throw std::runtime_error("two data blocks " + id);
  const std::size_t start = begin + open.size();
  const std::size_t end = page.find("</script>", start);
  return page.substr(start, end - start);
}

// The escaping undone: "<\/" -> "</", "\u003c!--" -> "<!--".
inline std::string unescape_block(std::string text) {
  for (const auto& [from, to] : {std::pair<std::string, std::string>{"\\u003c!--", "<!--"}, {"<\\/", "</"}}) {
    std::string out;
    std::size_t at = 0;
    for (std::size_t hit; (hit = text.find(from, at)) != std::string::npos; at = hit + from.size())
      out += text.substr(at, hit - at) + to;
    text = out + text.substr(at);
  }
  return text;
}

inline std::vector<unsigned char> from_base64(const std::string& text) {
  auto value = [](char c) -> int {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+') return 62;
    if (c == '/') return 63;
    throw std::runtime_error(std::string("not base64: ") + c);
  };
  std::vector<unsigned char> out;
  std::uint32_t bits = 0;
  int count = 0;
  for (const char c : text) {
    if (c == '=') break;
    bits = (bits << 6) | static_cast<std::uint32_t>(value(c));
    count += 6;
    if (count >= 8) {
      count -= 8;
      out.push_back(static_cast<unsigned char>((bits >> count) & 0xff));
    }
  }
  return out;
}

// The base64 of the data URI in the src of the <img> with this id.
inline std::string image_data_uri(const std::string& page, const std::string& id) {
  const std::size_t at = page.find("<img id=\"" + id + "\"");
  if (at == std::string::npos) throw std::runtime_error("no image " + id);
  const std::string prefix = " src=\"data:image/png;base64,";
  const std::size_t src = page.find(prefix, at);
  if (src == std::string::npos || src > page.find('>', at)) throw std::runtime_error("image " + id + " has no PNG");
  const std::size_t begin = src + prefix.size();
  return page.substr(begin, page.find('"', begin) - begin);
}

// Frame f's completion cycles, row-major, unpacked from #page-data with the
// frame's windows: per cell, per pixel in video-memory order, LEB128
// differences from the cell's previous pixel.
inline std::vector<std::uint64_t> unpack_completion(const std::string& page, int frame, int width, int height) {
  const nlohmann::json data = nlohmann::json::parse(unescape_block(data_block_text(page, "page-data")));
  const nlohmann::json& f = data.at("frames").at(frame);
  const std::vector<unsigned char> bytes = from_base64(f.at("completion"));
  std::vector<std::uint64_t> done(static_cast<std::size_t>(width) * height, 0);
  std::size_t pos = 0;
  for (const auto& w : f.at("windows")) {
    const int ox = w[0], oy = w[1], columns = w[2], rows = w[3], sx = w[4], sy = w[5];
    std::uint64_t t = 0;
    for (int k = 0; k < columns * rows; ++k) {
      std::uint64_t v = 0;
      for (int shift = 0;; shift += 7) {
        const unsigned char b = bytes.at(pos++);
        v |= static_cast<std::uint64_t>(b & 127) << shift;
        if (!(b & 128)) break;
      }
      t += v;
      done.at(static_cast<std::size_t>(oy + (k / columns) * sy) * width + ox + (k % columns) * sx) = t;
    }
  }
  if (pos != bytes.size()) throw std::runtime_error("completion data longer than the windows");
  return done;
}

// The data-* attributes of the element with this id, as the DOM holds them.
inline std::map<std::string, std::string> data_attributes(const std::string& dom, const std::string& id) {
  const std::size_t at = dom.find("id=\"" + id + "\"");
  if (at == std::string::npos) return {};
  const std::size_t open = dom.rfind('<', at), close = dom.find('>', at);
  const std::string tag = dom.substr(open, close - open);
  std::map<std::string, std::string> out;
  const std::regex attribute("data-([a-z-]+)=\"([^\"]*)\"");
  for (auto it = std::sregex_iterator(tag.begin(), tag.end(), attribute); it != std::sregex_iterator(); ++it)
    out[(*it)[1]] = (*it)[2];
  return out;
}

// The order the pages' table script records in data-order after a sort by
// `values` (a row's each, in the page's order), largest first, ties in the
// page's order: the rows' positions, "2 0 1".
inline std::vector<std::size_t> descending_order(const std::vector<double>& values) {
  std::vector<std::size_t> index(values.size());
  for (std::size_t i = 0; i < index.size(); ++i) index[i] = i;
  std::stable_sort(index.begin(), index.end(), [&](std::size_t a, std::size_t b) { return values[a] > values[b]; });
  return index;
}
inline std::string order_text(const std::vector<std::size_t>& order) {
  std::string text;
  for (const std::size_t i : order) {
    if (!text.empty()) text += ' ';
    text += std::to_string(i);
  }
  return text;
}

// The first row of the body of the table with this id, as the DOM holds it.
inline std::string first_row(const std::string& dom, const std::string& table_id) {
  const std::size_t body = dom.find("<tbody>", dom.find("id=\"" + table_id + "\""));
  const std::size_t first = dom.find("<tr ", body);
  return dom.substr(first, dom.find("</tr>", first) - first);
}

}  // namespace capsim::testing
