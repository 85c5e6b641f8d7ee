// STL and OFF readers for import(), and the dispatch to the AMF and 3MF ones.

#include "scene/meshes/mesh_files.h"

#include "scene/meshes/amf_import.h"
#include "scene/meshes/threemf_import.h"

#include "capsim/scene/scene_limits.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace capsim::scene_file {

namespace {

std::string extension(const std::string& path) {
  std::string e = std::filesystem::path(path).extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return std::tolower(c); });
  return e;
}

}  // namespace

std::string read_whole(const std::string& path, std::size_t max_bytes) {
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (!ec && size > max_bytes)
    throw MeshFileError(fmt::format("{}: the file is larger than {} bytes, the most capsim reads", path, max_bytes));
  std::ifstream in(path, std::ios::binary);
  if (!in) throw MeshFileError(fmt::format("{}: cannot read: {}", path, std::strerror(errno)));
  std::ostringstream text;
  text << in.rdbuf();
  if (text.str().size() > max_bytes)
    throw MeshFileError(fmt::format("{}: the file is larger than {} bytes, the most capsim reads", path, max_bytes));
  return text.str();
}

namespace {

// Whitespace-separated words of a text file, each with its line; '#' starts a
// comment to the end of the line where `comments` is set (OFF).
class Words {
 public:
  Words(const std::string& path, const std::string& text, bool comments)
      : path_(path), text_(text), comments_(comments) {}

  bool next(std::string_view& word) {
    for (;;) {
      while (at_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[at_]))) {
        if (text_[at_] == '\n') ++line_;
        ++at_;
      }
      if (comments_ && at_ < text_.size() && text_[at_] == '#') {
        while (at_ < text_.size() && text_[at_] != '\n') ++at_;
        continue;
      }
      break;
    }
    if (at_ == text_.size()) return false;
    const std::size_t start = at_;
    while (at_ < text_.size() && !std::isspace(static_cast<unsigned char>(text_[at_]))) ++at_;
    word = std::string_view(text_).substr(start, at_ - start);
    word_line_ = line_;
    return true;
  }

  std::string_view expect(std::string_view what) {
    std::string_view w;
    if (!next(w)) fail(fmt::format("the file ends where {} was expected", what));
    return w;
  }

  double coordinate() {
    const std::string w(expect("a coordinate"));
    char* end = nullptr;
    const double v = std::strtod(w.c_str(), &end);
    if (end != w.c_str() + w.size() || !std::isfinite(v))
      fail(fmt::format("expected a coordinate, found '{}'", w));
    if (const std::string fault = coordinate_fault(v); !fault.empty()) fail(fmt::format("coordinate {} {}", w, fault));
    return v;
  }

  std::uint64_t count(std::string_view what) {
    const std::string w(expect(what));
    std::uint64_t v = 0;
    for (char c : w) {
      if (c < '0' || c > '9' || v > (std::uint64_t{1} << 40)) fail(fmt::format("expected {}, found '{}'", what, w));
      v = 10 * v + static_cast<std::uint64_t>(c - '0');
    }
    return v;
  }

  void skip_line() {
    while (at_ < text_.size() && text_[at_] != '\n') ++at_;
  }

  [[noreturn]] void fail(const std::string& message) const {
    throw MeshFileError(fmt::format("{}:{}: {}", path_, word_line_, message));
  }

 private:
  const std::string& path_;
  const std::string& text_;
  bool comments_;
  std::size_t at_ = 0;
  int line_ = 1, word_line_ = 1;
};

std::vector<std::array<glm::dvec3, 3>> read_ascii_stl(const std::string& path, const std::string& text) {
  Words words(path, text, false);
  std::vector<std::array<glm::dvec3, 3>> triangles;
  std::string_view w;
  if (!words.next(w) || w != "solid") words.fail("an ASCII STL file starts with 'solid'");
  while (words.next(w)) {
    if (w == "endsolid") break;
    if (w != "facet") continue;  // the solid's name
    if (words.expect("'normal'") != "normal") words.fail("expected 'normal' after 'facet'");
    for (int k = 0; k < 3; ++k) words.coordinate();  // recomputed from the corners
    if (words.expect("'outer'") != "outer" || words.expect("'loop'") != "loop")
      words.fail("expected 'outer loop'");
    std::array<glm::dvec3, 3> t;
    for (glm::dvec3& corner : t) {
      if (words.expect("'vertex'") != "vertex") words.fail("expected 'vertex' (a facet has exactly 3 vertices)");
      for (int k = 0; k < 3; ++k) corner[k] = words.coordinate();
    }
    if (words.expect("'endloop'") != "endloop") words.fail("expected 'endloop' (a facet has exactly 3 vertices)");
    if (words.expect("'endfacet'") != "endfacet") words.fail("expected 'endfacet'");
    triangles.push_back(t);
  }
  return triangles;
}

float little_endian_float(const unsigned char* p) {
  const std::uint32_t bits = std::uint32_t{p[0]} | std::uint32_t{p[1]} << 8 | std::uint32_t{p[2]} << 16 |
                             std::uint32_t{p[3]} << 24;
  float f;
  std::memcpy(&f, &bits, sizeof f);
  return f;
}

// Binary STL: an 80-byte header, a 32-bit triangle count, then 50 bytes per
// triangle (normal, three corners, attribute word), little-endian floats.
std::vector<std::array<glm::dvec3, 3>> read_binary_stl(const std::string& path, const std::string& data) {
  const auto* p = reinterpret_cast<const unsigned char*>(data.data());
  const std::uint64_t n = std::uint64_t{p[80]} | std::uint64_t{p[81]} << 8 | std::uint64_t{p[82]} << 16 |
                          std::uint64_t{p[83]} << 24;
  std::vector<std::array<glm::dvec3, 3>> triangles(n);
  for (std::uint64_t i = 0; i < n; ++i) {
    const unsigned char* f = p + 84 + 50 * i + 12;
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < 3; ++k) {
        const float v = little_endian_float(f + 12 * c + 4 * k);
        if (!std::isfinite(v))
          throw MeshFileError(fmt::format("{}: triangle {} has a coordinate that is not a finite number", path, i));
        triangles[i][c][k] = v;
      }
  }
  return triangles;
}

PolygonMesh read_stl(const std::string& path, const std::string& data) {
  // Binary when the size is what the count in the header says: binary files
  // may start with "solid" too.
  if (data.size() >= 84) {
    const auto* p = reinterpret_cast<const unsigned char*>(data.data());
    const std::uint64_t n = std::uint64_t{p[80]} | std::uint64_t{p[81]} << 8 | std::uint64_t{p[82]} << 16 |
                            std::uint64_t{p[83]} << 24;
    if (data.size() == 84 + 50 * n) return weld_triangles(read_binary_stl(path, data));
  }
  return weld_triangles(read_ascii_stl(path, data));
}

// OFF: "OFF", the vertex, face and edge counts, the vertices, then each face
// as its point count and indices (any colour after them on its line is
// ignored, as OpenSCAD does).
PolygonMesh read_off(const std::string& path, const std::string& text) {
  Words words(path, text, true);
  PolygonMesh m;
  std::string_view w = words.expect("'OFF'");
  if (w != "OFF") words.fail(fmt::format("an OFF file starts with 'OFF', found '{}'", w));
  const std::uint64_t nv = words.count("the vertex count"), nf = words.count("the face count");
  words.count("the edge count");
  // Each vertex takes at least 6 bytes of text and each face 8, which bounds
  // the counts by the file's size before anything is allocated.
  if (nv > text.size() / 6 || nf > text.size() / 8)
    words.fail(fmt::format("{} vertices and {} faces cannot fit in a file of {} bytes", nv, nf, text.size()));
  m.points.resize(nv);
  for (glm::dvec3& p : m.points)
    for (int k = 0; k < 3; ++k) p[k] = words.coordinate();
  m.faces.resize(nf);
  for (std::vector<std::uint32_t>& face : m.faces) {
    const std::uint64_t n = words.count("a face's point count");
    if (n > nv) words.fail(fmt::format("a face of {} points, more than the file's {} vertices", n, nv));
    for (std::uint64_t k = 0; k < n; ++k) {
      const std::uint64_t i = words.count("a point index");
      if (i >= nv) words.fail(fmt::format("point index {} is out of range (0 to {})", i, nv - 1));
      face.push_back(static_cast<std::uint32_t>(i));
    }
    words.skip_line();  // a colour, if any: the next face starts on the next line
  }
  return m;
}

}  // namespace

std::string coordinate_fault(double v) {
  static_assert(kMaxLength == 1e30, "the message names the range");
  if (!std::isfinite(v)) return "is not a finite number";
  if (!(std::abs(v) <= kMaxLength)) return "lies beyond 1e30, the farthest capsim traces";
  return "";
}

bool is_mesh_file_name(const std::string& path) {
  const std::string e = extension(path);
  return e == ".stl" || e == ".off" || e == ".amf" || e == ".3mf";
}

std::vector<MeshObject> read_mesh_file(const std::string& path, std::size_t max_bytes) {
  std::string data = read_whole(path, max_bytes);
  if (data.empty()) throw MeshFileError(fmt::format("{}: the file is empty", path));
  const std::string e = extension(path);
  if (e == ".amf") return read_amf(path, data);
  if (e == ".3mf") return read_3mf(path, std::move(data));
  return {{fmt::format("the mesh in {}", path), e == ".stl" ? read_stl(path, data) : read_off(path, data)}};
}

}  // namespace capsim::scene_file
