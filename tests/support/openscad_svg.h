#pragma once
// OpenSCAD 2021.01 as an oracle for 2-D shapes: whether it is installed, and
// the contours of its SVG export of a 2-D design.

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace capsim::testing {

inline bool has_openscad() { return std::system("command -v openscad >/dev/null 2>&1") == 0; }

// The contours of OpenSCAD's SVG export: "M x,y L x,y ... z" per contour,
// y pointing down in the file and turned up here. The export prints 6
// significant digits.
inline std::vector<std::vector<glm::dvec2>> read_svg_contours(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream all;
  all << in.rdbuf();
  const std::string svg = all.str();
  const std::size_t d = svg.find(" d=\"");
  EXPECT_NE(d, std::string::npos) << svg;
  std::istringstream path(svg.substr(d + 4, svg.find('"', d + 4) - d - 4));
  std::vector<std::vector<glm::dvec2>> contours;
  std::string token;
  while (path >> token) {
    if (token == "M") contours.emplace_back();
    if (token == "M" || token == "L") {
      std::string xy;
      path >> xy;
      const std::size_t comma = xy.find(',');
      contours.back().push_back({std::stod(xy.substr(0, comma)), -std::stod(xy.substr(comma + 1))});
    }
  }
  return contours;
}

}  // namespace capsim::testing
