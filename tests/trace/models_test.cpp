// Tests of the shipped models (scenes/, described in docs/models.md): each
// export parses with exactly the primitives and operators the doc gives,
// counted three ways: the calls OpenSCAD wrote (what the doc's grep counts),
// the n-ary tree capsim parses, and the binary status tree the tracer
// evaluates. Every frame of the DISB animation parses to the same primitives
// and operators and is framed by the same default view, because the rails
// bound every frame, and the bars slide along their rails in every frame.

#include "capsim/scene/parser.h"
#include "capsim/scene/scene.h"
#include "capsim/trace/prepared_scene.h"
#include "capsim/trace/status_tree.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

namespace capsim {
namespace {

std::string source_path(const std::string& relative) {
  return std::string(CAPSIM_SOURCE_DIR) + "/" + relative;
}

struct ModelCounts {
  // Primitives by kind.
  int spheres = 0, boxes = 0, cones = 0;
  // Calls as written in the export: union(), group(), difference(), intersection().
  int written_unions = 0, written_groups = 0, written_differences = 0, written_intersections = 0;
  // Difference and intersection nodes of the parsed n-ary tree.
  int tree_differences = 0, tree_intersections = 0;
  // Nodes of the binary status tree, by operator.
  int status_unions = 0, status_differences = 0, status_intersections = 0;

  bool operator==(const ModelCounts&) const = default;
};

std::ostream& operator<<(std::ostream& os, const ModelCounts& c) {
  return os << fmt::format(
             "{{spheres {}, boxes {}, cones {}; written union {}, group {}, difference {}, "
             "intersection {}; tree difference {}, intersection {}; status union {}, "
             "difference {}, intersection {}}}",
             c.spheres, c.boxes, c.cones, c.written_unions, c.written_groups,
             c.written_differences, c.written_intersections, c.tree_differences,
             c.tree_intersections, c.status_unions, c.status_differences,
             c.status_intersections);
}

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Calls of `name` in OpenSCAD's export: `name(` not preceded by a letter,
// digit or underscore (exports hold no comments or strings with such text).
int calls_of(const std::string& text, const std::string& name) {
  const std::string needle = name + "(";
  int n = 0;
  for (std::size_t at = text.find(needle); at != std::string::npos;
       at = text.find(needle, at + 1)) {
    const bool starts_word =
        at == 0 || !(std::isalnum(static_cast<unsigned char>(text[at - 1])) || text[at - 1] == '_');
    n += starts_word;
  }
  return n;
}

void count_tree(const Scene& scene, const CsgNode& node, ModelCounts& c) {
  if (node.is_leaf) {
    switch (scene.primitives.at(node.primitive).kind) {
      case PrimitiveKind::Sphere: ++c.spheres; break;
      case PrimitiveKind::Box: ++c.boxes; break;
      case PrimitiveKind::Cone: ++c.cones; break;
      case PrimitiveKind::Mesh:
      case PrimitiveKind::Revolution: ADD_FAILURE() << "the shipped models hold no meshes or revolutions"; break;
    }
    return;
  }
  if (node.op == CsgOp::Difference) ++c.tree_differences;
  if (node.op == CsgOp::Intersection) ++c.tree_intersections;
  for (const CsgNode& child : node.children) count_tree(scene, child, c);
}

// The truth tables of the status tree's binary operators (bit 2 * left + right).
constexpr std::uint8_t kUnionTruth = 0b1110, kDifferenceTruth = 0b0100,
                       kIntersectionTruth = 0b1000;

ModelCounts count_model(const std::string& path) {
  ModelCounts c;
  const Scene scene = parse_scene_file(path);
  count_tree(scene, scene.root, c);
  EXPECT_EQ(scene.primitives.size(), static_cast<std::size_t>(c.spheres + c.boxes + c.cones))
      << path << ": every primitive is a leaf of the tree";

  const std::string text = read_text(path);
  c.written_unions = calls_of(text, "union");
  c.written_groups = calls_of(text, "group");
  c.written_differences = calls_of(text, "difference");
  c.written_intersections = calls_of(text, "intersection");
  EXPECT_EQ(calls_of(text, "sphere"), c.spheres) << path;
  EXPECT_EQ(calls_of(text, "cube"), c.boxes) << path;
  EXPECT_EQ(calls_of(text, "cylinder"), c.cones) << path;

  const StatusTree tree(scene.root, scene.primitives.size());
  for (std::size_t p = 0; p < scene.primitives.size(); ++p)
    EXPECT_TRUE(tree.present(static_cast<std::uint32_t>(p))) << path << ": primitive " << p
                                                              << " is cut away as empty";
  for (const StatusNode& node : tree.nodes()) {
    if (node.truth == kUnionTruth) ++c.status_unions;
    else if (node.truth == kDifferenceTruth) ++c.status_differences;
    else if (node.truth == kIntersectionTruth) ++c.status_intersections;
    else ADD_FAILURE() << path << ": status tree node with truth table " << int(node.truth);
  }
  return c;
}

int primitives(const ModelCounts& c) { return c.spheres + c.boxes + c.cones; }

struct Model {
  const char* file;
  ModelCounts counts;
};

void PrintTo(const Model& m, std::ostream* os) { *os << m.file; }

// The figures of docs/models.md.
const Model kModels[] = {
    {"scenes/balls.csg", {125, 0, 0, 1, 0, 0, 0, 0, 0, 124, 0, 0}},
    {"scenes/chess.csg", {25, 32, 87, 2, 48, 7, 3, 7, 3, 133, 7, 3}},
    {"scenes/piston.csg", {1, 46, 132, 6, 94, 33, 14, 33, 14, 118, 33, 27}},
    {"scenes/cad.csg", {0, 63, 115, 4, 133, 22, 1, 22, 1, 153, 22, 2}},
    {"scenes/disb/f00000.csg", {0, 4, 0, 0, 0, 0, 0, 0, 0, 3, 0, 0}},
};

class ShippedModel : public ::testing::TestWithParam<Model> {};

TEST_P(ShippedModel, HasTheDocumentedPrimitivesAndOperators) {
  const Model& m = GetParam();
  EXPECT_EQ(count_model(source_path(m.file)), m.counts) << m.file;
}

INSTANTIATE_TEST_SUITE_P(Models, ShippedModel, ::testing::ValuesIn(kModels),
                         [](const ::testing::TestParamInfo<Model>& info) {
                           std::string name = std::filesystem::path(info.param.file).stem();
                           return name == "f00000" ? std::string("disb_f00000") : name;
                         });

// The paper's sizes (DIGEST §4-5): CHESS 143-144 objects, PISTON 179 parts,
// CAD 178-185, BALLS 125.
TEST(ShippedModels, HaveThePapersSizes) {
  EXPECT_EQ(primitives(kModels[0].counts), 125);
  EXPECT_GE(primitives(kModels[1].counts), 143);
  EXPECT_LE(primitives(kModels[1].counts), 144);
  EXPECT_EQ(primitives(kModels[2].counts), 179);
  EXPECT_GE(primitives(kModels[3].counts), 178);
  EXPECT_LE(primitives(kModels[3].counts), 185);
}

// Every frame OpenSCAD's --animate 64 wrote parses to the same primitives and
// operators as frame 0, and frames the same default view.
TEST(ShippedModels, DisbFramesAllParseAlike) {
  const std::string dir = source_path("scenes/disb");
  std::vector<std::string> frames;
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    frames.push_back(entry.path().filename().string());
  std::sort(frames.begin(), frames.end());
  ASSERT_EQ(frames.size(), 64u);
  for (int k = 0; k < 64; ++k) EXPECT_EQ(frames[k], fmt::format("f{:05d}.csg", k));

  const ModelCounts first = kModels[4].counts;
  PrepareOptions small;
  small.width = small.height = 16;
  const Camera view = prepare_scene(parse_scene_file(dir + "/f00000.csg"), small).camera;
  for (const std::string& frame : frames) {
    const std::string path = dir + "/" + frame;
    EXPECT_EQ(count_model(path), first) << frame;
    const Camera cam = prepare_scene(parse_scene_file(path), small).camera;
    EXPECT_EQ(cam.eye, view.eye) << frame;
    EXPECT_EQ(cam.center, view.center) << frame;
  }
}

// The centre of a primitive: its canonical shape's centre, placed.
glm::dvec3 centre_of(const Primitive& p) {
  const glm::dvec4 c = p.kind == PrimitiveKind::Box    ? glm::dvec4(0.5, 0.5, 0.5, 1)
                       : p.kind == PrimitiveKind::Cone ? glm::dvec4(0, 0, 0.5, 1)
                                                       : glm::dvec4(0, 0, 0, 1);
  return glm::dvec3(p.to_world * c);
}

// The frames are the motion disb.scad describes, in order: the two rails
// (primitives 0 and 1) stay; the horizontal bar (2) slides along the screen's
// right, (cos 25, sin 25, 0) in the world, and the vertical bar (3) along the
// screen's down, each by its 78 units of travel over 64 frames (1.21875 a
// frame) and by nothing across, so that their long edges stay on the same
// pixel rows and columns. A frame repeated, missing or out of order fails.
TEST(ShippedModels, DisbBarsSlideAlongTheirRails) {
  const std::string dir = source_path("scenes/disb");
  const double pi = std::acos(-1.0);
  const double a = 25 * pi / 180, e = 35 * pi / 180;
  const glm::dvec3 right{std::cos(a), std::sin(a), 0};
  const glm::dvec3 up{-std::sin(a) * std::sin(e), std::cos(a) * std::sin(e), std::cos(e)};
  const double step = 78.0 / 64;
  Scene before = parse_scene_file(dir + "/f00000.csg");
  ASSERT_EQ(before.primitives.size(), 4u);
  for (int k = 1; k < 64; ++k) {
    Scene now = parse_scene_file(dir + fmt::format("/f{:05d}.csg", k));
    ASSERT_EQ(now.primitives.size(), before.primitives.size());
    for (std::size_t p = 0; p < 2; ++p)
      EXPECT_TRUE(now.primitives[p].to_world == before.primitives[p].to_world) << "frame " << k << ", rail " << p;
    const glm::dvec3 h = centre_of(now.primitives[2]) - centre_of(before.primitives[2]);
    const glm::dvec3 v = centre_of(now.primitives[3]) - centre_of(before.primitives[3]);
    EXPECT_LT(glm::length(h - step * right), 1e-3) << "frame " << k << ", horizontal bar";
    EXPECT_LT(glm::length(v + step * up), 1e-3) << "frame " << k << ", vertical bar";
    before = std::move(now);
  }
}

}  // namespace
}  // namespace capsim
