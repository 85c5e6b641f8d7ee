// polyhedron() and import() of STL and OFF: the meshes they make, where
// import() finds its file, and every refusal at its FILE:LINE:COL.

#include "capsim/scene/parser.h"
#include "support/cli_run.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>

namespace capsim {
namespace {

using capsim::testing::TempDir;

// OpenSCAD's tetrahedron, faces clockwise seen from outside, as its export writes it.
constexpr const char* kTetrahedron =
    "polyhedron(points = [[0, 0, 0], [10, 0, 0], [0, 10, 0], [0, 0, 10]], faces = [[0, 1, 2], [0, 3, 1], "
    "[0, 2, 3], [1, 3, 2]], convexity = 1);";

std::string refusal(std::string_view text, const std::string& file = "t.csg") {
  try {
    parse_scene(text, file);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "parsed without error";
}

void write(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

// The unit cube as an ASCII STL, 12 facets.
std::string ascii_stl_cube() {
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  std::string s = "solid cube\n";
  for (const auto& q : quads)
    for (const auto& t : {std::array<int, 3>{q[0], q[1], q[2]}, std::array<int, 3>{q[0], q[2], q[3]}}) {
      s += "  facet normal 0 0 0\n    outer loop\n";
      for (int v : t) s += fmt::format("      vertex {} {} {}\n", v & 1, (v >> 1) & 1, (v >> 2) & 1);
      s += "    endloop\n  endfacet\n";
    }
  return s + "endsolid cube\n";
}

// The same cube as a binary STL.
std::string binary_stl_cube() {
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  std::string s(80, ' ');
  const std::uint32_t n = 12;
  s.append(reinterpret_cast<const char*>(&n), 4);  // the build is little-endian, as the format
  for (const auto& q : quads)
    for (const auto& t : {std::array<int, 3>{q[0], q[1], q[2]}, std::array<int, 3>{q[0], q[2], q[3]}}) {
      float f[12] = {};
      for (int c = 0; c < 3; ++c)
        for (int k = 0; k < 3; ++k) f[3 + 3 * c + k] = static_cast<float>((t[c] >> k) & 1);
      s.append(reinterpret_cast<const char*>(f), sizeof f);
      s.append(2, '\0');
    }
  return s;
}

constexpr const char* kOffCube =
    "OFF\n# a unit cube\n8 6 12\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n1 1 1\n"
    "4 0 2 3 1\n4 4 5 7 6\n4 0 1 5 4 255 0 0\n4 2 6 7 3\n4 0 4 6 2\n4 1 3 7 5\n";

TEST(ParserMeshes, PolyhedronIsAClosedMesh) {
  const Scene s = parse_scene(kTetrahedron, "t.csg");
  ASSERT_EQ(s.primitives.size(), 1u);
  const Primitive& p = s.primitives[0];
  EXPECT_EQ(p.kind, PrimitiveKind::Mesh);
  ASSERT_TRUE(p.mesh);
  EXPECT_EQ(p.mesh->triangles.size(), 4u);
  EXPECT_EQ(p.mesh->bounds.hi, glm::dvec3(10));
  EXPECT_EQ(object_bounds(p).lo, glm::dvec3(0));
  EXPECT_EQ(p.loc.line, 1);
  // The older name of faces, and the same mesh placed by a transform.
  const Scene t = parse_scene(
      "translate([1, 2, 3]) polyhedron([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], triangles = [[0, 1, 2], "
      "[0, 3, 1], [0, 2, 3], [1, 3, 2]]);",
      "t.csg");
  EXPECT_EQ(t.primitives[0].mesh->triangles.size(), 4u);
  EXPECT_EQ(glm::dvec3(t.primitives[0].to_world[3]), glm::dvec3(1, 2, 3));
}

TEST(ParserMeshes, PolyhedronRefusals) {
  // An open mesh: its last face left out; located at the face whose edge is bare.
  EXPECT_EQ(refusal("polyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]],\n"
                    "  faces = [[0, 1, 2], [0, 3, 1], [0, 2, 3]]);"),
            "t.csg:2:12: polyhedron is not a closed solid: the edge from point 1 to point 2 of face 0 has no face "
            "on its other side running from point 2 to point 1: the mesh is not closed (it has a hole there, or "
            "the face beside it is turned the wrong way)");
  // One face turned against the others.
  EXPECT_EQ(refusal("polyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]],\n"
                    "  faces = [[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 2, 3]]);"),
            "t.csg:2:45: polyhedron is not a closed solid: faces 0 and 3 both run from point 1 to point 2: the "
            "mesh is not closed (more than two faces meet at that edge, or one of them is turned the wrong way)");
  EXPECT_EQ(refusal("polyhedron(points = [[0, 0, 0], [1, 0, 0]], faces = [[0, 1, 5]]);"),
            "t.csg:1:61: face 0 names point 5, but the points are numbered 0 to 1");
  EXPECT_EQ(refusal("polyhedron(points = [[0, 0, 0], [1, 0]], faces = [[0, 1, 0]]);"),
            "t.csg:1:33: argument 'points' of polyhedron must be a vector of [x, y, z] points, but point 1 is a "
            "vector of 2 elements");
  EXPECT_EQ(refusal("polyhedron(faces = [[0, 1, 2]]);"), "t.csg:1:1: polyhedron needs its points");
  EXPECT_EQ(refusal("polyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0]]);"), "t.csg:1:1: polyhedron needs its faces");
  EXPECT_EQ(refusal("polyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0]], faces = [[0, 1, 2]], "
                    "triangles = [[0, 1, 2]]);"),
            "t.csg:1:77: polyhedron takes faces or triangles (its older name), not both");
  EXPECT_EQ(refusal("polyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0]], faces = [[0, 1, 2], [0, 2, 1]]);"),
            "t.csg:1:1: polyhedron is not a closed solid: the faces enclose no volume (every point lies in one "
            "plane, or the faces cancel out)");
}

TEST(ParserMeshes, ImportsStlAndOffBesideTheSceneFile) {
  TempDir dir;
  std::filesystem::create_directories(dir.path() / "parts");
  write(dir / "parts/ascii.stl", ascii_stl_cube());
  write(dir / "parts/binary.STL", binary_stl_cube());
  write(dir / "parts/cube.off", kOffCube);
  const std::string scene = dir / "scene.csg";
  write(scene, "import(file = \"parts/ascii.stl\", layer = \"\", origin = [0, 0], scale = 1, convexity = 1, "
               "$fn = 0, $fa = 12, $fs = 2, timestamp = 1795683931);\n"
               "translate([2, 0, 0]) import(\"parts/binary.STL\");\n"
               "translate([4, 0, 0]) import(\"parts/cube.off\");\n");
  const Scene s = parse_scene_file(scene);
  ASSERT_EQ(s.primitives.size(), 3u);
  for (const Primitive& p : s.primitives) {
    EXPECT_EQ(p.kind, PrimitiveKind::Mesh);
    EXPECT_EQ(p.mesh->vertices.size(), 8u);
    EXPECT_EQ(p.mesh->triangles.size(), 12u);
    EXPECT_EQ(p.mesh->bounds.hi, glm::dvec3(1));
  }
  // The directory a .scad's export is read with: its paths are the .scad's.
  const std::string elsewhere = dir / "parts/elsewhere.csg";
  write(elsewhere, "import(\"parts/cube.off\");");
  EXPECT_EQ(parse_scene_file(elsewhere, {}, 0, dir.path().string()).primitives.size(), 1u);
  const std::string missing = refusal("import(\"parts/cube.off\");", elsewhere);
  EXPECT_EQ(missing, fmt::format("{0}:1:8: cannot import 'parts/cube.off': there is no such file beside the scene "
                                 "file ({1}/parts/parts/cube.off) nor in the current directory",
                                 elsewhere, dir.path().string()));
}

TEST(ParserMeshes, ImportRefusals) {
  TempDir dir;
  auto refused = [&](const std::string& name, const std::string& bytes) {
    write(dir / name, bytes);
    return refusal(fmt::format("import(\"{}\");", name), dir / "s.csg");
  };
  const std::string at = dir / "s.csg:1:8: cannot import ";
  std::string stl = ascii_stl_cube();
  const std::size_t first = stl.find("  facet");
  stl.erase(first, stl.find("  facet", first + 1) - first);  // a facet gone: a hole
  EXPECT_EQ(refused("open.stl", stl).rfind(at + "'open.stl': the mesh in " + (dir / "open.stl") +
                                               " is not a closed solid: the edge from point",
                                           0),
            0u);
  EXPECT_EQ(refused("bad.stl", "solid x\n facet normal 0 0 1\n outer loop\n vertex 0 0 zero\n"),
            at + "'bad.stl': " + (dir / "bad.stl") + ":4: expected a coordinate, found 'zero'");
  EXPECT_EQ(refused("short.off", "OFF\n2 1 0\n0 0 0\n"),
            at + "'short.off': " + (dir / "short.off") + ":3: the file ends where a coordinate was expected");
  EXPECT_EQ(refused("huge.off", "OFF\n8 6 0\n0 0 0\n"),
            at + "'huge.off': " + (dir / "huge.off") + ":2: 8 vertices and 6 faces cannot fit in a file of 16 bytes");
  EXPECT_EQ(refused("range.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n"),
            at + "'range.off': " + (dir / "range.off") + ":6: point index 3 is out of range (0 to 2)");
  EXPECT_EQ(refused("model.obj", ""),
            at + "'model.obj': capsim imports STL (.stl), OFF (.off), AMF (.amf) and 3MF (.3mf) meshes, and DXF "
                 "(.dxf) and SVG (.svg) as 2-D shapes");
  EXPECT_EQ(refusal("import(file = 3);", "t.csg"), "t.csg:1:15: argument 'file' of import must be a string, got a number");
  EXPECT_EQ(refusal("import();", "t.csg"), "t.csg:1:1: import needs the file to read: import(\"model.stl\")");
  // A file past the size limit is refused before it is read.
  write(dir / "big.off", std::string(200, ' '));
  ParseLimits limits;
  limits.max_file_bytes = 100;
  try {
    parse_scene("import(\"big.off\");", dir / "s.csg", limits);
    FAIL() << "read a file past the limit";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("the file is larger than 100 bytes"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace capsim
