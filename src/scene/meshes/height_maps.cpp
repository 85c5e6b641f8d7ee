// surface()'s height maps: .dat text and PNG images, and OpenSCAD's mesh of them.

#include "scene/meshes/height_maps.h"

#include "capsim/scene/scene_limits.h"
#include "scene/extrusions/openscad_tessellation.h"

#include <fmt/format.h>
#include <png.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>

namespace capsim::scene_file {

namespace {

bool is_png(const std::string& bytes) {
  static constexpr unsigned char kSignature[8] = {0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a};
  return bytes.size() >= 8 && std::memcmp(bytes.data(), kSignature, 8) == 0;
}

void check_cells(const std::string& path, double rows, double columns) {
  if (rows < 2 || columns < 2)
    throw HeightMapError(fmt::format("{}: a height map needs at least 2 rows and 2 columns, this one has {} by {}", path,
                                     rows, columns));
  if (rows * columns > static_cast<double>(kMaxHeightMapCells))
    throw HeightMapError(fmt::format("{}: {} by {} heights, more than the {} capsim reads", path, rows, columns,
                                     kMaxHeightMapCells));
}

HeightMap read_png(const std::string& path, const std::string& bytes, bool invert) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_memory(&image, bytes.data(), bytes.size()))
    throw HeightMapError(fmt::format("{}: not a PNG image capsim can read ({})", path, image.message));
  // Freed however this ends.
  std::unique_ptr<png_image, void (*)(png_image*)> guard(&image, &png_image_free);
  check_cells(path, image.height, image.width);
  image.format = PNG_FORMAT_RGBA;
  std::vector<unsigned char> rgba(PNG_IMAGE_SIZE(image));
  if (!png_image_finish_read(&image, nullptr, rgba.data(), 0, nullptr))
    throw HeightMapError(fmt::format("{}: the PNG image is damaged ({})", path, image.message));
  HeightMap map;
  map.rows = static_cast<int>(image.height);
  map.columns = static_cast<int>(image.width);
  map.z.resize(static_cast<std::size_t>(map.rows) * map.columns);
  for (int y = 0; y < map.rows; ++y)
    for (int x = 0; x < map.columns; ++x) {
      const unsigned char* px = &rgba[4 * (static_cast<std::size_t>(y) * map.columns + x)];
      const double grey = 0.2126 * px[0] + 0.7152 * px[1] + 0.0722 * px[2];
      // The image's top row is the far edge: row 0 of the map is its bottom.
      map.z[static_cast<std::size_t>(map.rows - 1 - y) * map.columns + x] = 100.0 / 255 * (invert ? 1 - grey : grey);
    }
  return map;
}

HeightMap read_dat(const std::string& path, const std::string& text) {
  std::vector<std::vector<double>> rows;
  std::size_t columns = 0, cells = 0;
  std::istringstream lines(text);
  std::string line;
  for (int number = 1; std::getline(lines, line); ++number) {
    const auto first = line.find_first_not_of(" \t\r\n\f\v");
    // OpenSCAD skips blank lines and comments.
    if (first == std::string::npos || line[first] == '#') continue;
    std::vector<double> row;
    for (std::size_t at = 0; (at = line.find_first_not_of(" \t\r", at)) != std::string::npos;) {
      const std::size_t end = std::min(line.find_first_of(" \t\r", at), line.size());
      const std::string_view token(line.data() + at, end - at);
      double v = 0;
      const auto [ptr, ec] = std::from_chars(token.data(), token.data() + token.size(), v);
      if (ec != std::errc() || ptr != token.data() + token.size() || !(std::abs(v) <= kMaxLength))
        throw HeightMapError(fmt::format("{}:{}:{}: '{}' is not a height (a finite number within 1e30)", path, number,
                                         at + 1, token));
      row.push_back(v);
      at = end;
    }
    cells += row.size();
    if (cells > kMaxHeightMapCells)
      throw HeightMapError(fmt::format("{}:{}: more than the {} heights capsim reads", path, number, kMaxHeightMapCells));
    columns = std::max(columns, row.size());
    rows.push_back(std::move(row));
  }
  check_cells(path, static_cast<double>(rows.size()), static_cast<double>(columns));
  HeightMap map;
  map.rows = static_cast<int>(rows.size());
  map.columns = static_cast<int>(columns);
  map.z.assign(rows.size() * columns, 0.0);
  for (std::size_t i = 0; i < rows.size(); ++i) std::copy(rows[i].begin(), rows[i].end(), map.z.begin() + static_cast<std::ptrdiff_t>(i * columns));
  return map;
}

}  // namespace

HeightMap read_height_map(const std::string& path, std::size_t max_bytes, bool invert) {
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  if (!ec && size > max_bytes)
    throw HeightMapError(fmt::format("{}: the file is larger than {} bytes, the most capsim reads", path, max_bytes));
  std::ifstream in(path, std::ios::binary);
  if (!in) throw HeightMapError(fmt::format("{}: cannot read: {}", path, std::strerror(errno)));
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.size() > max_bytes)
    throw HeightMapError(fmt::format("{}: the file is larger than {} bytes, the most capsim reads", path, max_bytes));
  return is_png(bytes) ? read_png(path, bytes, invert) : read_dat(path, bytes);
}

PolygonMesh height_map_mesh(const HeightMap& map, bool center) {
  const int lines = map.rows, columns = map.columns;
  double min_val = 0;
  for (const double v : map.z) min_val = std::min(v - 1, min_val);
  const double ox = center ? -(columns - 1) / 2.0 : 0;
  const double oy = center ? -(lines - 1) / 2.0 : 0;
  const auto d = [&map](int i, int j) { return map.at(i, j); };
  PolySetBuilder p;
  const auto triangle = [&p](double x1, double y1, double z1, double x2, double y2, double z2, double x3, double y3,
                             double z3) {
    p.append_poly();
    p.append_vertex(x1, y1, z1);
    p.append_vertex(x2, y2, z2);
    p.append_vertex(x3, y3, z3);
  };
  for (int i = 1; i < lines; ++i)
    for (int j = 1; j < columns; ++j) {
      const double v1 = d(i - 1, j - 1), v2 = d(i - 1, j), v3 = d(i, j - 1), v4 = d(i, j);
      const double vx = (v1 + v2 + v3 + v4) / 4;
      const double cx = ox + j - 0.5, cy = oy + i - 0.5;
      triangle(ox + j - 1, oy + i - 1, v1, ox + j, oy + i - 1, v2, cx, cy, vx);
      triangle(ox + j, oy + i - 1, v2, ox + j, oy + i, v4, cx, cy, vx);
      triangle(ox + j, oy + i, v4, ox + j - 1, oy + i, v3, cx, cy, vx);
      triangle(ox + j - 1, oy + i, v3, ox + j - 1, oy + i - 1, v1, cx, cy, vx);
    }
  // The walls: quads from the edge of the top down to the base.
  const auto wall = [&p](bool insert, double x1, double y1, double z1, double x2, double y2, double z2, double base) {
    p.append_poly();
    const auto add = [&](double x, double y, double z) { insert ? p.insert_vertex(x, y, z) : p.append_vertex(x, y, z); };
    add(x1, y1, base);
    add(x1, y1, z1);
    add(x2, y2, z2);
    add(x2, y2, base);
  };
  for (int i = 1; i < lines; ++i) {
    wall(false, ox, oy + i - 1, d(i - 1, 0), ox, oy + i, d(i, 0), min_val);
    wall(true, ox + columns - 1, oy + i - 1, d(i - 1, columns - 1), ox + columns - 1, oy + i, d(i, columns - 1), min_val);
  }
  for (int i = 1; i < columns; ++i) {
    wall(true, ox + i - 1, oy, d(0, i - 1), ox + i, oy, d(0, i), min_val);
    wall(false, ox + i - 1, oy + lines - 1, d(lines - 1, i - 1), ox + i, oy + lines - 1, d(lines - 1, i), min_val);
  }
  // The base: OpenSCAD's one polygon round the edge, here a fan about its
  // centre (the same plane; a fan from the centre has no triangle of zero
  // area, which one from a corner along the straight edges would).
  std::vector<std::array<double, 2>> edge;
  for (int i = 0; i < columns - 1; ++i) edge.push_back({ox + i, oy});
  for (int i = 0; i < lines - 1; ++i) edge.push_back({ox + columns - 1, oy + i});
  for (int i = columns - 1; i > 0; i--) edge.push_back({ox + i, oy + lines - 1});
  for (int i = lines - 1; i > 0; i--) edge.push_back({ox, oy + i});
  const double mx = ox + (columns - 1) / 2.0, my = oy + (lines - 1) / 2.0;
  for (std::size_t k = 0; k < edge.size(); ++k) {
    const auto& a = edge[k];
    const auto& b = edge[(k + 1) % edge.size()];
    // Clockwise seen from above, as OpenSCAD winds the base.
    triangle(b[0], b[1], min_val, a[0], a[1], min_val, mx, my, min_val);
  }
  return p.take();
}

}  // namespace capsim::scene_file
