// AMF through libxml2's streaming reader, the one OpenSCAD uses. OpenSCAD
// follows the elements by their path from the root and nothing else: it reads
// no attribute, so the unit (<amf unit="inch">) is ignored and coordinates are
// taken as millimetres, as here; materials, colours, constellations and curved
// edges are ignored too. Where OpenSCAD would go on silently (a coordinate or
// a corner missing keeps the previous vertex's or triangle's, an index out of
// range reads past its list), capsim refuses the file at the line concerned.

#include "scene/meshes/amf_import.h"

#include "scene/libxml2_library.h"

#include <fmt/format.h>
#include <libxml/xmlreader.h>

#include <array>
#include <climits>
#include <cstdlib>
#include <optional>

namespace capsim::scene_file {

namespace {

const std::string kObject = "/amf/object";
const std::string kCoordinates = kObject + "/mesh/vertices/vertex/coordinates";
const std::string kTriangle = kObject + "/mesh/volume/triangle";
constexpr std::array<const char*, 3> kAxes = {"x", "y", "z"};
constexpr std::array<const char*, 3> kCorners = {"v1", "v2", "v3"};

// libxml2, opened on the first import; a library that cannot be loaded is
// refused naming the file.
const Libxml2& opened_libxml2(const std::string& path) {
  try {
    return libxml2();
  } catch (const std::runtime_error& e) {
    throw MeshFileError(fmt::format("{}: {}", path, e.what()));
  }
}

class AmfReader {
 public:
  AmfReader(const std::string& path, const std::string& data) : path_(path), xml_(opened_libxml2(path)) {
    // No entity substitution and no network: a file reads nothing but itself.
    reader_ = xml_.xmlReaderForMemory(data.data(), static_cast<int>(data.size()), path.c_str(), nullptr,
                                      XML_PARSE_NONET | XML_PARSE_NOERROR | XML_PARSE_NOWARNING);
    if (!reader_) throw MeshFileError(fmt::format("{}: libxml2 cannot start reading it", path));
    xml_.xmlTextReaderSetStructuredErrorHandler(reader_, &AmfReader::on_error, this);
  }
  ~AmfReader() { xml_.xmlFreeTextReader(reader_); }
  AmfReader(const AmfReader&) = delete;
  AmfReader& operator=(const AmfReader&) = delete;

  std::vector<MeshObject> read() {
    int status;
    while ((status = xml_.xmlTextReaderRead(reader_)) == 1) {
      switch (xml_.xmlTextReaderNodeType(reader_)) {
        case XML_READER_TYPE_ELEMENT: {
          const bool empty = xml_.xmlTextReaderIsEmptyElement(reader_) == 1;
          start(reinterpret_cast<const char*>(xml_.xmlTextReaderConstName(reader_)));
          if (empty) end();  // <x/> has no end element of its own
          break;
        }
        case XML_READER_TYPE_END_ELEMENT:
          end();
          break;
        case XML_READER_TYPE_TEXT:
          text(reinterpret_cast<const char*>(xml_.xmlTextReaderConstValue(reader_)));
          break;
        default:
          break;
      }
    }
    if (status != 0) {
      if (error_line_ > 0) fail(error_line_, fmt::format("malformed XML: {}", error_));
      throw MeshFileError(fmt::format("{}: malformed XML{}", path_, error_.empty() ? "" : ": " + error_));
    }
    if (objects_.empty())
      throw MeshFileError(
          fmt::format("{}: no <object> in the file has a triangle (an AMF file is "
                      "<amf><object><mesh><vertices>...<volume><triangle>)",
                      path_));
    return std::move(objects_);
  }

 private:
  static void on_error(void* self, xmlErrorPtr e) {
    auto* r = static_cast<AmfReader*>(self);
    if (!r->error_.empty() || !e || !e->message) return;  // the first error is the cause
    r->error_ = e->message;
    while (!r->error_.empty() && (r->error_.back() == '\n' || r->error_.back() == ' ')) r->error_.pop_back();
    r->error_line_ = e->line;
  }

  [[noreturn]] void fail(long line, const std::string& message) const {
    throw MeshFileError(fmt::format("{}:{}: {}", path_, line, message));
  }

  long line() const { return xml_.xmlGetLineNo(xml_.xmlTextReaderCurrentNode(reader_)); }

  void start(const char* name) {
    at_ += '/';
    at_ += name;
    if (at_ == kObject) {
      xmlChar* id = xml_.xmlTextReaderGetAttribute(reader_, BAD_CAST "id");
      object_ = {fmt::format("{}:{}: {}", path_, line(),
                             id ? fmt::format("object {}", reinterpret_cast<const char*>(id)) : "the object"),
                 {}};
      xml_.free(id);
    } else if (at_ == kCoordinates) {
      part_line_ = line();
      xyz_ = {};
    } else if (at_ == kTriangle) {
      part_line_ = line();
      corners_ = {};
    }
  }

  void end() {
    if (at_ == kCoordinates) {
      for (std::size_t k = 0; k < 3; ++k)
        if (!xyz_[k]) fail(part_line_, fmt::format("the vertex has no <{}> coordinate", kAxes[k]));
      object_.mesh.points.emplace_back(*xyz_[0], *xyz_[1], *xyz_[2]);
    } else if (at_ == kTriangle) {
      std::vector<std::uint32_t> face;
      for (std::size_t k = 0; k < 3; ++k) {
        if (!corners_[k]) fail(part_line_, fmt::format("the triangle has no <{}> corner", kCorners[k]));
        face.push_back(*corners_[k]);
      }
      object_.mesh.faces.push_back(std::move(face));
    } else if (at_ == kObject) {
      // An object without triangles adds nothing to OpenSCAD's union.
      if (!object_.mesh.faces.empty()) objects_.push_back(std::move(object_));
      object_ = {};
    }
    at_.erase(at_.rfind('/'));
  }

  // The text of <x>, <y>, <z> or <v1>, <v2>, <v3>; surrounding white space is
  // allowed, as XML numbers allow it.
  void text(const char* value) {
    const std::size_t slash = at_.rfind('/');
    const std::string_view parent = std::string_view(at_).substr(0, slash),
                           leaf = std::string_view(at_).substr(slash + 1);
    if (parent == kCoordinates) {
      for (std::size_t k = 0; k < 3; ++k)
        if (leaf == kAxes[k]) set(xyz_[k], coordinate(value, kAxes[k]), leaf);
    } else if (parent == kTriangle) {
      for (std::size_t k = 0; k < 3; ++k)
        if (leaf == kCorners[k]) set(corners_[k], index(value, kCorners[k]), leaf);
    }
  }

  template <class T>
  void set(std::optional<T>& slot, T value, std::string_view what) {
    if (slot) fail(line(), fmt::format("<{}> is given twice", what));
    slot = value;
  }

  static std::string_view trimmed(const char* value) {
    std::string_view v(value);
    const auto space = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; };
    while (!v.empty() && space(v.front())) v.remove_prefix(1);
    while (!v.empty() && space(v.back())) v.remove_suffix(1);
    return v;
  }

  double coordinate(const char* value, const char* axis) {
    const std::string w(trimmed(value));
    char* end = nullptr;
    const double v = std::strtod(w.c_str(), &end);
    if (w.empty() || end != w.c_str() + w.size())
      fail(line(), fmt::format("expected a number for <{}>, found '{}'", axis, w));
    if (const std::string fault = coordinate_fault(v); !fault.empty())
      fail(line(), fmt::format("coordinate {} {}", w, fault));
    return v;
  }

  std::uint32_t index(const char* value, const char* corner) {
    const std::string_view w = trimmed(value);
    std::uint64_t i = 0;
    bool ok = !w.empty();
    for (char c : w) {
      ok = ok && c >= '0' && c <= '9' && i <= UINT32_MAX;
      if (ok) i = 10 * i + static_cast<std::uint64_t>(c - '0');
    }
    if (!ok) fail(line(), fmt::format("expected a vertex index for <{}>, found '{}'", corner, w));
    const std::size_t n = object_.mesh.points.size();
    if (i >= n)
      fail(line(), n == 0 ? fmt::format("<{}> names vertex {}, but the object has no vertex before it", corner, i)
                          : fmt::format("<{}> names vertex {}, but the object's vertices are numbered 0 to {}", corner,
                                        i, n - 1));
    return static_cast<std::uint32_t>(i);
  }

  const std::string& path_;
  const Libxml2& xml_;
  xmlTextReaderPtr reader_ = nullptr;
  std::string at_;  // the open elements from the root, "/amf/object/mesh"
  std::string error_;
  long error_line_ = 0;
  MeshObject object_;
  long part_line_ = 0;  // of the vertex's <coordinates> or the <triangle> being read
  std::array<std::optional<double>, 3> xyz_;
  std::array<std::optional<std::uint32_t>, 3> corners_;
  std::vector<MeshObject> objects_;
};

}  // namespace

std::vector<MeshObject> read_amf(const std::string& path, const std::string& data) {
  // A zip's local file header: OpenSCAD reads zipped AMF only when built with
  // libzip; capsim reads the XML itself.
  if (data.rfind("PK\x03\x04", 0) == 0)
    throw MeshFileError(
        fmt::format("{}: a zipped (compressed) AMF file: capsim reads AMF as XML text; unzip it first", path));
  if (data.size() > INT_MAX)
    throw MeshFileError(fmt::format("{}: the file is larger than {} bytes, the most libxml2 reads", path, INT_MAX));
  AmfReader reader(path, data);
  return reader.read();
}

}  // namespace capsim::scene_file
