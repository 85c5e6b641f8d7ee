// import() of AMF and 3MF files: OpenSCAD 2021.01's exports give the same
// solid as its STL export of the same model, several objects are their union,
// and every bad file is refused at its path (and line, for AMF's XML).

#include "capsim/scene/parser.h"
#include "support/cli_run.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <zip.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <set>
#include <vector>

namespace capsim {
namespace {

using capsim::testing::read_file;
using capsim::testing::run_capsim;
using capsim::testing::TempDir;

const std::string kData = std::string(CAPSIM_SOURCE_DIR) + "/tests/data/mesh_import/";

void write(const std::string& path, const std::string& bytes) { std::ofstream(path, std::ios::binary) << bytes; }

std::string refusal(const std::string& scene_file, const std::string& text) {
  try {
    parse_scene(text, scene_file);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "parsed without error";
}

// Why `import("NAME");` in dir/s.csg is refused, after the prefix every such
// message shares ("dir/s.csg:1:8: cannot import 'NAME': dir/NAME"): the line,
// if any, and the message.
std::string located_refusal(const TempDir& dir, const std::string& name) {
  const std::string message = refusal(dir / "s.csg", fmt::format("import(\"{}\");", name));
  const std::string prefix = (dir / "s.csg") + ":1:8: cannot import '" + name + "': " + (dir / name);
  return message.rfind(prefix, 0) == 0 ? message.substr(prefix.size()) : message;
}

// A 3MF package (the zip the 3MF core specification lays out) around `model`,
// the text of 3D/3dmodel.model.
void write_3mf(const std::string& path, const std::string& model) {
  const std::array<std::array<std::string, 2>, 3> parts = {{
      {"[Content_Types].xml",
       "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<Types xmlns=\"http://schemas.openxmlformats.org/package/2006/"
       "content-types\"><Default Extension=\"rels\" ContentType=\"application/"
       "vnd.openxmlformats-package.relationships+xml\"/><Default Extension=\"model\" ContentType=\"application/"
       "vnd.ms-package.3dmanufacturing-3dmodel+xml\"/></Types>"},
      {"_rels/.rels",
       "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<Relationships xmlns=\"http://schemas.openxmlformats.org/package/"
       "2006/relationships\"><Relationship Target=\"/3D/3dmodel.model\" Id=\"rel0\" "
       "Type=\"http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel\"/></Relationships>"},
      {"3D/3dmodel.model", model},
  }};
  int error = 0;
  zip_t* z = zip_open(path.c_str(), ZIP_CREATE | ZIP_TRUNCATE, &error);
  ASSERT_NE(z, nullptr) << "libzip error " << error;
  for (const auto& [name, text] : parts) {
    zip_source_t* source = zip_source_buffer(z, text.data(), text.size(), 0);
    ASSERT_NE(source, nullptr);
    ASSERT_GE(zip_file_add(z, name.c_str(), source, ZIP_FL_ENC_UTF_8), 0) << zip_strerror(z);
  }
  ASSERT_EQ(zip_close(z), 0);  // the buffers are read here, while `parts` lives
}

// A unit-less model of 3MF mesh objects, each the axis-aligned box from lo to
// hi, and its build.
std::string box_object(int id, std::array<int, 3> lo, std::array<int, 3> hi) {
  std::string s = fmt::format("<object id=\"{}\" type=\"model\"><mesh><vertices>", id);
  for (int v = 0; v < 8; ++v)
    s += fmt::format("<vertex x=\"{}\" y=\"{}\" z=\"{}\"/>", v & 1 ? hi[0] : lo[0], v & 2 ? hi[1] : lo[1],
                     v & 4 ? hi[2] : lo[2]);
  s += "</vertices><triangles>";
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads)
    s += fmt::format("<triangle v1=\"{}\" v2=\"{}\" v3=\"{}\"/><triangle v1=\"{}\" v2=\"{}\" v3=\"{}\"/>", q[0], q[1],
                     q[2], q[0], q[2], q[3]);
  return s + "</triangles></mesh></object>";
}

std::string model_3mf(const std::string& objects, const std::string& build) {
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<model unit=\"millimeter\" xml:lang=\"en-US\" "
         "xmlns=\"http://schemas.microsoft.com/3dmanufacturing/core/2015/02\">\n<resources>" +
         objects + "</resources>\n<build>" + build + "</build>\n</model>\n";
}

// The same box as an AMF object, one vertex or triangle a line.
std::string amf_box(int id, std::array<int, 3> lo, std::array<int, 3> hi) {
  std::string s = fmt::format(" <object id=\"{}\">\n  <mesh>\n   <vertices>\n", id);
  for (int v = 0; v < 8; ++v)
    s += fmt::format("    <vertex><coordinates><x>{}</x><y>{}</y><z>{}</z></coordinates></vertex>\n",
                     v & 1 ? hi[0] : lo[0], v & 2 ? hi[1] : lo[1], v & 4 ? hi[2] : lo[2]);
  s += "   </vertices>\n   <volume>\n";
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads)
    for (const auto& t : {std::array<int, 3>{q[0], q[1], q[2]}, std::array<int, 3>{q[0], q[2], q[3]}})
      s += fmt::format("    <triangle><v1>{}</v1><v2>{}</v2><v3>{}</v3></triangle>\n", t[0], t[1], t[2]);
  return s + "   </volume>\n  </mesh>\n </object>\n";
}

std::string amf(const std::string& objects, const std::string& unit = "millimeter") {
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<amf unit=\"" + unit + "\">\n" + objects + "</amf>\n";
}

// What a closed mesh bounds, independent of how its faces are cut into
// triangles (OpenSCAD's STL, AMF and 3MF exports cut a quad along different
// diagonals): the corners its triangles use, six times its volume and twice
// its area, each exact for the small integer coordinates of the models here.
struct Solid {
  std::set<std::array<double, 3>> corners;
  double volume6 = 0, area2 = 0;
  bool operator==(const Solid&) const = default;
};

Solid solid(const TriangleMesh& m) {
  Solid s;
  for (const auto& t : m.triangles) {
    const glm::dvec3 a = m.vertices[t[0]], b = m.vertices[t[1]], c = m.vertices[t[2]];
    for (const glm::dvec3& p : {a, b, c}) s.corners.insert({p.x, p.y, p.z});
    s.volume6 += glm::dot(a, glm::cross(b, c));
    s.area2 += glm::length(glm::cross(b - a, c - a));
  }
  return s;
}

constexpr const char* kView =
    "camera(eye = [12, -9, 10], center = [2, 1.5, 1], up = [0, 0, 1], fov = 40, size = [96, 96]);\n"
    "light(position = [20, -10, 25], color = [1, 1, 1]);\n";

// The PNG capsim renders of kView and `solid`, written in dir.
std::string rendered(const TempDir& dir, const std::string& name, const std::string& solid) {
  write(dir / (name + ".csg"), kView + solid);
  const auto r =
      run_capsim(fmt::format("render --quiet '{}' -o '{}'", dir / (name + ".csg"), dir / (name + ".png")), dir);
  EXPECT_EQ(r.status, 0) << r.err;
  return read_file(dir / (name + ".png"));
}

TEST(ImportMeshFiles, OpenScadAmfAnd3mfExportsAreItsStlSolid) {
  TempDir dir;
  for (const std::string model : {"cube", "notch"}) {
    SCOPED_TRACE(model);
    const auto mesh = [&](const std::string& ext) {
      const Scene s = parse_scene(fmt::format("import(\"{}{}.{}\");", kData, model, ext), dir / "s.csg");
      EXPECT_EQ(s.primitives.size(), 1u);
      EXPECT_EQ(s.primitives.at(0).mesh->triangles.size(), model == "cube" ? 12u : 28u) << ext;
      return solid(*s.primitives.at(0).mesh);
    };
    const Solid stl = mesh("stl");
    EXPECT_EQ(stl.corners.size(), model == "cube" ? 8u : 16u);
    EXPECT_EQ(stl.volume6, model == "cube" ? 6 * 24 : 6 * 16);
    EXPECT_EQ(mesh("amf"), stl);
    EXPECT_EQ(mesh("3mf"), stl);
    const std::string png = rendered(dir, "stl", fmt::format("import(\"{}{}.stl\");", kData, model));
    EXPECT_GT(png.size(), 100u);
    EXPECT_EQ(rendered(dir, "amf", fmt::format("import(\"{}{}.amf\");", kData, model)), png);
    EXPECT_EQ(rendered(dir, "3mf", fmt::format("import(\"{}{}.3mf\");", kData, model)), png);
  }
}

TEST(ImportMeshFiles, AmfObjectsAreTheirUnionInMillimetres) {
  TempDir dir;
  // Two overlapping boxes, in inches by the file's word: OpenSCAD reads no
  // attribute, so they are millimetres.
  write(dir / "two.amf", amf(amf_box(0, {0, 0, 0}, {3, 2, 2}) + amf_box(1, {2, 1, 1}, {4, 3, 3}), "inch"));
  write(dir / "a.amf", amf(amf_box(0, {0, 0, 0}, {3, 2, 2})));
  write(dir / "b.amf", amf(amf_box(0, {2, 1, 1}, {4, 3, 3})));
  const Scene s = parse_scene("import(\"two.amf\");", dir / "s.csg");
  ASSERT_EQ(s.primitives.size(), 2u);
  EXPECT_EQ(s.primitives[0].mesh->bounds.hi, glm::dvec3(3, 2, 2));
  EXPECT_EQ(s.primitives[1].mesh->bounds.lo, glm::dvec3(2, 1, 1));
  EXPECT_EQ(rendered(dir, "two", "import(\"two.amf\");"),
            rendered(dir, "union", "union() { import(\"a.amf\"); import(\"b.amf\"); }"));
  // hull() takes the points of both.
  const Scene h = parse_scene("hull() import(\"two.amf\");", dir / "s.csg");
  ASSERT_EQ(h.primitives.size(), 1u);
  EXPECT_EQ(h.primitives[0].mesh->bounds.lo, glm::dvec3(0));
  EXPECT_EQ(h.primitives[0].mesh->bounds.hi, glm::dvec3(4, 3, 3));
}

TEST(ImportMeshFiles, ThreeMfMeshObjectsAreReadWithoutTheBuild) {
  TempDir dir;
  // Object 2 is in no build item and object 1's item moves it: OpenSCAD reads
  // every mesh object where its vertices put it.
  write_3mf(dir / "two.3mf", model_3mf(box_object(1, {0, 0, 0}, {3, 2, 2}) + box_object(2, {2, 1, 1}, {4, 3, 3}),
                                       "<item objectid=\"1\" transform=\"1 0 0 0 1 0 0 0 1 10 0 0\"/>"));
  write_3mf(dir / "a.3mf", model_3mf(box_object(1, {0, 0, 0}, {3, 2, 2}), "<item objectid=\"1\"/>"));
  write_3mf(dir / "b.3mf", model_3mf(box_object(1, {2, 1, 1}, {4, 3, 3}), "<item objectid=\"1\"/>"));
  const Scene s = parse_scene("import(\"two.3mf\");", dir / "s.csg");
  ASSERT_EQ(s.primitives.size(), 2u);
  EXPECT_EQ(s.primitives[0].mesh->bounds.lo, glm::dvec3(0));
  EXPECT_EQ(s.primitives[1].mesh->bounds.hi, glm::dvec3(4, 3, 3));
  EXPECT_EQ(rendered(dir, "two", "import(\"two.3mf\");"),
            rendered(dir, "union", "union() { import(\"a.3mf\"); import(\"b.3mf\"); }"));
}

TEST(ImportMeshFiles, AmfRefusals) {
  TempDir dir;
  auto refused = [&](const std::string& name, const std::string& bytes) {
    write(dir / name, bytes);
    return located_refusal(dir, name);
  };
  const std::string box = amf_box(0, {0, 0, 0}, {1, 1, 1});
  auto with = [&](const std::string& from, const std::string& to) {
    std::string s = amf(box);
    s.replace(s.find(from), from.size(), to);
    return s;
  };
  EXPECT_EQ(refused("cut.amf", amf(box).substr(0, 300)), ":8: malformed XML: expected '>'");
  EXPECT_EQ(refused("tags.amf", with("</volume>", "</mesh>")),
            ":28: malformed XML: Opening and ending tag mismatch: volume line 15 and mesh");
  EXPECT_EQ(refused("noz.amf", with("<z>0</z>", "")), ":6: the vertex has no <z> coordinate");
  EXPECT_EQ(refused("twice.amf", with("<z>0</z>", "<z>0</z><z>1</z>")), ":6: <z> is given twice");
  EXPECT_EQ(refused("word.amf", with("<x>1</x>", "<x>one</x>")), ":7: expected a number for <x>, found 'one'");
  EXPECT_EQ(refused("inf.amf", with("<x>1</x>", "<x>inf</x>")), ":7: coordinate inf is not a finite number");
  EXPECT_EQ(refused("far.amf", with("<x>1</x>", "<x>1e31</x>")),
            ":7: coordinate 1e31 lies beyond 1e30, the farthest capsim traces");
  EXPECT_EQ(refused("range.amf", with("<v3>1</v3>", "<v3>8</v3>")),
            ":17: <v3> names vertex 8, but the object's vertices are numbered 0 to 7");
  EXPECT_EQ(refused("minus.amf", with("<v3>1</v3>", "<v3>-1</v3>")),
            ":17: expected a vertex index for <v3>, found '-1'");
  EXPECT_EQ(refused("corner.amf", with("<v3>1</v3>", "")), ":17: the triangle has no <v3> corner");
  std::string open = amf(box);
  const std::size_t first = open.find("    <triangle>");
  open.erase(first, open.find('\n', first) + 1 - first);  // the first triangle gone: a hole
  EXPECT_EQ(refused("open.amf", open).rfind(":3: object 0 is not a closed solid: the edge from point", 0), 0u)
      << refused("open.amf", open);
  EXPECT_EQ(refused("empty.amf", ""), ": the file is empty");
  EXPECT_EQ(refused("none.amf", amf("")),
            ": no <object> in the file has a triangle (an AMF file is "
            "<amf><object><mesh><vertices>...<volume><triangle>)");
  EXPECT_EQ(refused("zipped.amf", std::string("PK\x03\x04", 4) + "rest of a zip"),
            ": a zipped (compressed) AMF file: capsim reads AMF as XML text; unzip it first");
  // The command line: the message, a failure status, no image.
  write(dir / "bad.csg", "import(\"noz.amf\");");
  const auto r = run_capsim(fmt::format("render --quiet '{}' -o '{}'", dir / "bad.csg", dir / "bad.png"), dir);
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("noz.amf:6: the vertex has no <z> coordinate"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "bad.png"));
}

TEST(ImportMeshFiles, ThreeMfRefusals) {
  TempDir dir;
  auto refused = [&](const std::string& name) { return located_refusal(dir, name); };
  const std::string box = box_object(1, {0, 0, 0}, {1, 1, 1});
  auto with = [&](const std::string& from, const std::string& to) {
    std::string s = model_3mf(box, "<item objectid=\"1\"/>");
    s.replace(s.find(from), from.size(), to);
    return s;
  };
  write(dir / "text.3mf", "solid not a zip\n");
  EXPECT_EQ(refused("text.3mf"),
            ": lib3mf cannot read it as a 3MF package: Could not read ZIP file (lib3mf error "
            "0x1035)");
  write(dir / "empty.3mf", "");
  EXPECT_EQ(refused("empty.3mf"), ": the file is empty");
  write_3mf(dir / "range.3mf",
            with("<triangle v1=\"0\" v2=\"2\" v3=\"3\"/>", "<triangle v1=\"0\" v2=\"2\" v3=\"8\"/>"));
  EXPECT_EQ(refused("range.3mf"),
            ": lib3mf cannot read it as a 3MF package: Invalid model node index (lib3mf "
            "error 0x8028)");
  write_3mf(dir / "nan.3mf", with("<vertex x=\"0\"", "<vertex x=\"nan\""));
  EXPECT_EQ(refused("nan.3mf"),
            ": lib3mf cannot read it as a 3MF package: Invalid Model Coordinates (lib3mf "
            "error 0x8025)");
  write_3mf(dir / "open.3mf", with("<triangle v1=\"0\" v2=\"2\" v3=\"3\"/>", ""));
  EXPECT_EQ(refused("open.3mf").rfind(": object 1 is not a closed solid: the edge from point", 0), 0u)
      << refused("open.3mf");
  write_3mf(dir / "none.3mf", model_3mf("", ""));
  EXPECT_EQ(refused("none.3mf"), ": the model has no mesh object with a triangle");
  // Past the size limit: refused before it is read.
  ParseLimits limits;
  limits.max_file_bytes = 100;
  for (const std::string name : {"range.3mf", "cut.amf"}) {
    write(dir / "cut.amf", amf(box));
    try {
      parse_scene(fmt::format("import(\"{}\");", name), dir / "s.csg", limits);
      ADD_FAILURE() << "read " << name << " past the limit";
    } catch (const SceneError& e) {
      EXPECT_NE(std::string(e.what()).find("the file is larger than 100 bytes"), std::string::npos) << e.what();
    }
  }
  write(dir / "bad.csg", "import(\"text.3mf\");");
  const auto r = run_capsim(fmt::format("render --quiet '{}' -o '{}'", dir / "bad.csg", dir / "bad.png"), dir);
  EXPECT_NE(r.status, 0);
  EXPECT_NE(r.err.find("Could not read ZIP file"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "bad.png"));
}

}  // namespace
}  // namespace capsim
