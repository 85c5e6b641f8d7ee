#pragma once
// The height maps surface() reads, as OpenSCAD 2021.01's surface.cc reads
// them: a PNG image (its grey level, 0.2126 R + 0.7152 G + 0.0722 B, scaled
// to 0 .. 100) or a text .dat file of rows of numbers.

#include "capsim/scene/triangle_mesh.h"

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace capsim::scene_file {

// A file that cannot be read as a height map: what() is "PATH:LINE:COL:
// message" for a bad number of a .dat file, "PATH: message" otherwise.
class HeightMapError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Heights by row and column; row 0 is y = 0 (for an image its bottom row).
// Cells a short row of a .dat file leaves out are 0, as in OpenSCAD.
struct HeightMap {
  int rows = 0, columns = 0;
  std::vector<double> z;  // row-major
  double at(int row, int column) const { return z[static_cast<std::size_t>(row) * columns + column]; }
};

// The most cells a height map may have (each gives four triangles).
inline constexpr std::size_t kMaxHeightMapCells = 1000000;

// Reads a PNG (by its signature) or a .dat file; refuses files larger than
// max_bytes, maps of more than kMaxHeightMapCells cells or fewer than 2 rows
// or columns, and numbers that are not finite or lie beyond 1e30. `invert`
// is OpenSCAD 2021.01's for images: height 100/255 (1 - grey), grey in
// 0 .. 255 (so mostly below zero); a .dat file ignores it, as OpenSCAD does.
HeightMap read_height_map(const std::string& path, std::size_t max_bytes, bool invert);

// OpenSCAD's closed mesh of a height map: each cell four triangles about its
// centre at the mean of its corners, walls down to a base one below the
// lowest height (or at 0, if that is lower), the base flat. Cell (i, j) spans
// x = j .. j + 1, y = i .. i + 1, less half the size when centred.
PolygonMesh height_map_mesh(const HeightMap& map, bool center);

}  // namespace capsim::scene_file
