// minkowski() of unions and of non-convex meshes, read and traced: the sum
// distributes over union, so it must draw what the union of the sums of its
// children's convex parts, written out by hand, draws; and every refusal at
// its FILE:LINE:COL.

#include "capsim/scene/parser.h"
#include "capsim/trace/tracer.h"
#include "support/cli_run.h"
#include "support/scene_refusal.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

namespace capsim {
namespace {

using capsim::testing::TempDir;

using capsim::testing::refusal;

constexpr int kSide = 64;

// The depth of every pixel's primary ray (+inf on a miss) and the normal it
// meets, from the scene's default view (which the bounds decide, so two
// scenes of the same solid are seen alike).
struct DepthImage {
  std::vector<double> depth;
  std::vector<glm::dvec3> normal;
  int hits = 0;
};

DepthImage depth_image(const Scene& scene) {
  PrepareOptions options;
  options.width = options.height = kSide;
  const PreparedScene ps = prepare_scene(scene, options);
  const Tracer tracer(ps, {});
  Tracer::Scratch s(ps);
  OpCounts ops;
  DepthImage image;
  for (int j = 0; j < kSide; ++j)
    for (int i = 0; i < kSide; ++i) {
      Hit h;
      const bool hit = tracer.first_hit(tracer.primary_ray(i, j), s, ops, h);
      image.depth.push_back(hit ? h.t : kInfinity);
      image.normal.push_back(hit ? h.normal : glm::dvec3(0));
      image.hits += hit;
    }
  return image;
}

// Same hits and misses, depths within `tolerance` (relative), same normals
// within it.
void expect_same_image(const Scene& ours, const Scene& theirs, double tolerance) {
  const DepthImage a = depth_image(ours), b = depth_image(theirs);
  ASSERT_GT(a.hits, kSide * kSide / 8);
  EXPECT_EQ(a.hits, b.hits);
  int differing = 0;
  for (std::size_t k = 0; k < a.depth.size(); ++k) {
    const bool same = a.depth[k] == b.depth[k] ||
                      (std::abs(a.depth[k] - b.depth[k]) <= tolerance * b.depth[k] &&
                       glm::length(a.normal[k] - b.normal[k]) <= tolerance);
    differing += !same;
  }
  EXPECT_EQ(differing, 0);
}

// Whether a convex mesh holds the point: on the inner side of every face.
bool holds(const TriangleMesh& m, const glm::dvec3& p) {
  for (const auto& t : m.triangles) {
    const glm::dvec3 a = m.vertices[t[0]];
    if (glm::dot(p - a, glm::cross(m.vertices[t[1]] - a, m.vertices[t[2]] - a)) > 0) return false;
  }
  return true;
}

void expect_same_image(const std::string& ours, const std::string& theirs, double tolerance) {
  expect_same_image(parse_scene(ours, "t.csg"), parse_scene(theirs, "t.csg"), tolerance);
}

TEST(MinkowskiUnion, OfAUnionIsOneConvexLeafPerPart) {
  const Scene s = parse_scene("color([1, 0, 0]) minkowski() {\n"
                              "  union() { cube(2); translate([5, 0, 0]) cube(2); }\n"
                              "  sphere(1, $fn = 8);\n"
                              "}",
                              "t.csg");
  ASSERT_EQ(s.primitives.size(), 2u);
  for (const Primitive& p : s.primitives) {
    EXPECT_EQ(p.kind, PrimitiveKind::Mesh);
    EXPECT_EQ(p.color.y, 0.0);  // the colour around it
    EXPECT_EQ(p.loc.line, 1);
  }
  const double side = std::sin(67.5 * M_PI / 180);  // the $fn = 8 sphere's widest ring
  EXPECT_DOUBLE_EQ(s.primitives[0].mesh->bounds.hi.x, 2 + side);
  EXPECT_DOUBLE_EQ(s.primitives[1].mesh->bounds.lo.x, 5 - side);
}

TEST(MinkowskiUnion, OfAUnionDrawsTheUnionOfThePairwiseSums) {
  expect_same_image("minkowski() { union() { cube(2); translate([5, 0, 0]) cube(2); } sphere(1, $fn = 8); }",
                    "union() {\n"
                    "  minkowski() { cube(2); sphere(1, $fn = 8); }\n"
                    "  minkowski() { translate([5, 0, 0]) cube(2); sphere(1, $fn = 8); }\n"
                    "}",
                    0);
}

// Two children of two parts each (a union, and the implicit union of a
// transform's several children), and a third convex one: four sums.
TEST(MinkowskiUnion, OfSeveralUnionsDrawsEveryCombinationsSum) {
  const std::string a = "union() { cube(2); translate([6, 0, 0]) cube([1, 3, 2]); }";
  const std::string b = "translate([0, 0, 1]) { sphere(1, $fn = 8); translate([0, 7, 0]) cylinder(h = 2, r = 1, $fn = 6); }";
  const std::string c = "rotate([0, 0, 30]) cube(0.5, center = true);";
  const Scene s = parse_scene(fmt::format("minkowski() {{ {} {} {} }}", a, b, c), "t.csg");
  EXPECT_EQ(s.primitives.size(), 4u);
  std::string by_hand = "union() {\n";
  for (const std::string pa : {"cube(2);", "translate([6, 0, 0]) cube([1, 3, 2]);"})
    for (const std::string pb : {"translate([0, 0, 1]) sphere(1, $fn = 8);",
                                 "translate([0, 0, 1]) translate([0, 7, 0]) cylinder(h = 2, r = 1, $fn = 6);"})
      by_hand += fmt::format("  minkowski() {{ {} {} {} }}\n", pa, pb, c);
  by_hand += "}";
  expect_same_image(fmt::format("minkowski() {{ {} {} {} }}", a, b, c), by_hand, 0);
}

// A nested minkowski of a union is its parts again, and a hull of a union is
// one part.
TEST(MinkowskiUnion, NestedSumsKeepTheirParts) {
  const Scene s = parse_scene("minkowski() {\n"
                              "  minkowski() { union() { cube(1); translate([3, 0, 0]) cube(1); } cube(0.5); }\n"
                              "  hull() { cube(1); translate([0, 3, 0]) cube(1); }\n"
                              "}",
                              "t.csg");
  EXPECT_EQ(s.primitives.size(), 2u);
}

// An L-shaped prism (a non-convex polyhedron) plus a unit cube is the L of
// side 3 extruded to height 2: CGAL's convex pieces of the prism, each
// summed, draw the same solid as the extrusion.
constexpr const char* kLPrism =
    "polyhedron(points = [[0, 0, 0], [2, 0, 0], [2, 1, 0], [1, 1, 0], [1, 2, 0], [0, 2, 0], [0, 0, 1], [2, 0, 1], "
    "[2, 1, 1], [1, 1, 1], [1, 2, 1], [0, 2, 1]], faces = [[5, 4, 3, 2, 1, 0], [6, 7, 8, 9, 10, 11], [0, 1, 7, 6], "
    "[1, 2, 8, 7], [2, 3, 9, 8], [3, 4, 10, 9], [4, 5, 11, 10], [5, 0, 6, 11]]);";

constexpr const char* kLOfSide3 = "linear_extrude(height = 2) polygon([[0, 0], [3, 0], [3, 2], [2, 2], [2, 3], [0, 3]]);";

TEST(MinkowskiNonConvex, APolyhedronIsSummedPieceByPiece) {
  const std::string sum = fmt::format("minkowski() {{ {} cube(1); }}", kLPrism);
  const Scene s = parse_scene(sum, "t.csg");
  EXPECT_GE(s.primitives.size(), 2u);  // at least two convex pieces
  for (const Primitive& p : s.primitives) EXPECT_EQ(p.kind, PrimitiveKind::Mesh);
  expect_same_image(sum, kLOfSide3, 1e-9);
}

TEST(MinkowskiNonConvex, AnImportedMeshIsSummedPieceByPiece) {
  TempDir dir;
  // The L prism as an OFF file, its faces as the polyhedron's.
  std::ofstream(dir / "l.off") << "OFF\n12 8 0\n0 0 0\n2 0 0\n2 1 0\n1 1 0\n1 2 0\n0 2 0\n"
                                  "0 0 1\n2 0 1\n2 1 1\n1 1 1\n1 2 1\n0 2 1\n"
                                  "6 5 4 3 2 1 0\n6 6 7 8 9 10 11\n4 0 1 7 6\n4 1 2 8 7\n4 2 3 9 8\n"
                                  "4 3 4 10 9\n4 4 5 11 10\n4 5 0 6 11\n";
  const Scene imported = parse_scene("minkowski() { import(\"l.off\"); cube(1); }", dir / "t.csg");
  EXPECT_GE(imported.primitives.size(), 2u);
  expect_same_image(imported, parse_scene(kLOfSide3, "t.csg"), 1e-9);
}

// A linear_extrude of a non-convex polygon is split as a mesh is.
TEST(MinkowskiNonConvex, AnExtrudedLIsSummedPieceByPiece) {
  expect_same_image("minkowski() {\n"
                    "  linear_extrude(height = 1) polygon([[0, 0], [2, 0], [2, 1], [1, 1], [1, 2], [0, 2]]);\n"
                    "  cube(1);\n"
                    "}",
                    kLOfSide3, 1e-9);
}

// A region with a hole: the frame's outline less the hole, split by CGAL.
// Summed with a unit cube, the frame grows by one outwards and upwards and
// its hole shrinks by one from two sides.
TEST(MinkowskiNonConvex, AnExtrudedFrameKeepsItsHole) {
  expect_same_image("minkowski() {\n"
                    "  linear_extrude(height = 2, center = true) difference() { square(10); translate([3, 3, 0]) square(4); }\n"
                    "  cube(1);\n"
                    "}",
                    "translate([0, 0, -1]) linear_extrude(height = 3) difference() {\n"
                    "  square(11);\n"
                    "  translate([4, 4, 0]) square(3);\n"
                    "}",
                    1e-9);
}

// hull() takes an extrusion's outline points: the L's hull is a pentagon.
TEST(MinkowskiNonConvex, HullOfAnExtrusionIsItsOutlinesHull) {
  const Scene s = parse_scene(
      "hull() linear_extrude(height = 2, center = true) polygon([[0, 0], [4, 0], [4, 1], [1, 1], [1, 4], [0, 4]]);",
      "t.csg");
  ASSERT_EQ(s.primitives.size(), 1u);
  const TriangleMesh& m = *s.primitives[0].mesh;
  EXPECT_EQ(m.vertices.size(), 10u);  // the pentagon's corners, at both caps
  EXPECT_EQ(m.bounds.lo, glm::dvec3(0, 0, -1));
  EXPECT_EQ(m.bounds.hi, glm::dvec3(4, 4, 1));
}

TEST(MinkowskiNonConvex, HullStillTakesEveryPointAlike) {
  const Scene s = parse_scene(fmt::format("hull() {}", kLPrism), "t.csg");
  ASSERT_EQ(s.primitives.size(), 1u);
  EXPECT_EQ(s.primitives[0].mesh->bounds.hi, glm::dvec3(2, 2, 1));
}

// A cube less its corner, summed with a unit cube: CGAL's convex pieces of
// the evaluated difference, each summed, draw the L-shaped solid the three
// boxes that make it draw, each grown by one.
TEST(MinkowskiEvaluated, ADifferenceIsSummedPieceByPiece) {
  const Scene s = parse_scene("minkowski() {\n"
                              "  difference() { cube(4); translate([2, 2, 2]) cube(4); }\n"
                              "  cube(1);\n"
                              "}",
                              "t.csg");
  EXPECT_GE(s.primitives.size(), 2u);  // at least two convex pieces
  for (const Primitive& p : s.primitives) {
    EXPECT_EQ(p.kind, PrimitiveKind::Mesh);
    EXPECT_EQ(p.loc.line, 1);
  }
  expect_same_image(s, parse_scene("union() { cube([5, 5, 3]); cube([5, 3, 5]); cube([3, 5, 5]); }", "t.csg"), 1e-9);
}

// An intersection of two boxes is one box: one convex piece, summed.
TEST(MinkowskiEvaluated, AnIntersectionIsItsSolidSummed) {
  const Scene s = parse_scene("minkowski() {\n"
                              "  intersection() { cube(4); translate([2, 1, 3]) cube(4); }\n"
                              "  cube(1);\n"
                              "}",
                              "t.csg");
  EXPECT_EQ(s.primitives.size(), 1u);
  expect_same_image(s, parse_scene("translate([2, 1, 3]) cube([3, 4, 2]);", "t.csg"), 1e-9);
}

// The operators under a difference are read as they are anywhere; mirror
// turns its mesh's faces inwards, and the solid is still what it bounds.
TEST(MinkowskiEvaluated, MirroredOperandsBoundTheirSolid) {
  expect_same_image("minkowski() {\n"
                    "  difference() { cube(4); mirror([1, 0, 0]) translate([-6, 2, 2]) cube(4); }\n"
                    "  cube(1);\n"
                    "}",
                    "union() { cube([5, 5, 3]); cube([5, 3, 5]); cube([3, 5, 5]); }", 1e-9);
}

// A difference that leaves nothing is no child, as OpenSCAD skips it.
TEST(MinkowskiEvaluated, AnEmptyDifferenceAddsNothing) {
  expect_same_image("minkowski() { difference() { cube(1); cube(2); } sphere(1, $fn = 8); }",
                    "hull() sphere(1, $fn = 8);", 1e-9);
}

// rotate_extrude is OpenSCAD's mesh of the revolution: a rectangle against
// the axis turns into a convex prism (one part), a ring into several pieces.
TEST(MinkowskiEvaluated, ARevolutionIsOpenScadsMeshOfIt) {
  const Scene prism = parse_scene("minkowski() { rotate_extrude($fn = 8) square([2, 3]); cube(1); }", "t.csg");
  ASSERT_EQ(prism.primitives.size(), 1u);
  EXPECT_NEAR(prism.primitives[0].mesh->bounds.hi.x, 3, 1e-12);  // an octagon's corner on the axis, plus 1
  EXPECT_EQ(prism.primitives[0].mesh->bounds.hi.z, 4);
  const Scene ring = parse_scene("minkowski() { rotate_extrude($fn = 8) translate([2, 0, 0]) square(1); cube(1); }",
                                 "t.csg");
  EXPECT_GE(ring.primitives.size(), 4u);
  // The ring's hole (its inner octagon's sides 2 cos 22.5 from the axis)
  // shrinks by the unit cube but stays open: no part holds the axis.
  for (const Primitive& part : ring.primitives) EXPECT_FALSE(holds(*part.mesh, {0, 0, 1}));
}

// A revolved frame is one mesh of two closed surfaces, the inner one the
// cavity: the solid between them (the even-odd rule) is split and summed,
// and the cavity, shrunk by the cube, stays empty.
TEST(MinkowskiEvaluated, ARevolvedFrameKeepsItsCavity) {
  const Scene s = parse_scene("minkowski() {\n"
                              "  rotate_extrude($fn = 8) translate([4, 0, 0]) difference() { square(6); translate([2, 2, 0]) square(2); }\n"
                              "  cube(0.5, center = true);\n"
                              "}",
                              "t.csg");
  ASSERT_GE(s.primitives.size(), 8u);
  bool wall = false;
  for (const Primitive& part : s.primitives) {
    EXPECT_FALSE(holds(*part.mesh, {7, 0, 3}));  // in the cavity (x 6..8, z 2..4), on the +x axis's corner
    wall = wall || holds(*part.mesh, {5, 0, 3});
  }
  EXPECT_TRUE(wall);
}

// hull() of a difference takes the corners of the solid it evaluates to:
// those of the cube less its corner, not of the cube whole.
TEST(MinkowskiEvaluated, HullOfADifferenceIsItsSolidsHull) {
  expect_same_image("hull() difference() { cube(4); translate([2, 2, 2]) cube(4); }",
                    "hull() { cube([4, 4, 2]); cube([4, 2, 4]); cube([2, 4, 4]); }", 1e-9);
}

// Under projection() too the sum of a union is the union of its parts.
TEST(MinkowskiUnion, ProjectedIsTheUnionOfThePartsShadows) {
  expect_same_image("linear_extrude(height = 1) projection() minkowski() {\n"
                    "  union() { cube(1); translate([3, 0, 0]) cube(1); }\n"
                    "  cube(1);\n"
                    "}",
                    "linear_extrude(height = 1) projection() union() {\n"
                    "  minkowski() { cube(1); cube(1); }\n"
                    "  minkowski() { translate([3, 0, 0]) cube(1); cube(1); }\n"
                    "}",
                    0);
}

TEST(MinkowskiRefusals, NameTheChildConcerned) {
  EXPECT_EQ(refusal("minkowski() { }"), "t.csg:1:1: minkowski() has no solid children: it encloses nothing");
  // Two tetrahedra meeting at one corner: closed, but not a 2-manifold.
  EXPECT_EQ(refusal("minkowski() {\n  cube(1);\n  polyhedron(points = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], "
                    "[-1, 0, 0], [0, -1, 0], [0, 0, -1]], faces = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3], "
                    "[0, 4, 5], [0, 6, 4], [0, 5, 6], [4, 6, 5]]);\n}")
                .substr(0, 85),
            "t.csg:3:3: minkowski() of this non-convex mesh is not supported: its faces meet at an");
}

TEST(MinkowskiRefusals, TooManyPartsAreRefusedAtTheChildThatMakesThem) {
  std::string rows, columns;
  for (int k = 0; k < 101; ++k) rows += fmt::format(" translate([{}, 0, 0]) cube(1);", 2 * k);
  for (int k = 0; k < 100; ++k) columns += fmt::format(" translate([0, {}, 0]) cube(1);", 2 * k);
  EXPECT_EQ(refusal(fmt::format("minkowski() {{\n  union() {{{}}}\n  union() {{{}}}\n}}", rows, columns)),
            "t.csg:3:3: minkowski() would sum 101 convex parts by 100, more than the 10000 parts capsim makes of "
            "one minkowski");
}

// What the evaluation cannot take is refused at the child concerned.
TEST(MinkowskiRefusals, EvaluatedChildrenNameWhatTheyCannotTake) {
  EXPECT_EQ(refusal("minkowski() {\n  cube(1);\n  difference() {\n    cube(2);\n    square(1);\n  }\n}").substr(0, 81),
            "t.csg:5:5: square() under hull() or minkowski() is not supported: capsim meshes s");
  EXPECT_EQ(refusal("minkowski() {\n  cube(1);\n  difference() { cube(2); !sphere(1); }\n}"),
            "t.csg:3:27: the '!' (root) modifier is not supported inside hull() or minkowski()");
  // Two spheres of 100 x 50 fragments: 19,992 triangles to evaluate.
  EXPECT_EQ(refusal("minkowski() {\n  cube(1);\n  difference() { sphere(2, $fn = 100); sphere(1, $fn = 100); }\n}"),
            "t.csg:3:3: minkowski() of this non-convex difference() is not supported: it has 19992 triangles, more "
            "than the 5000 capsim splits into convex pieces");
  EXPECT_EQ(refusal("hull() {\n  intersection() { sphere(2, $fn = 100); sphere(1, $fn = 100); }\n}"),
            "t.csg:2:3: hull() of this intersection() is not supported: it has 19992 triangles, more than the 5000 "
            "capsim evaluates with CGAL");
}

TEST(MinkowskiRefusals, TooLargeANonConvexMeshIsRefused) {
  TempDir dir;
  // 40 x 40 heights: some 6,000 triangles, beyond what capsim splits.
  std::ofstream heights(dir / "h.dat");
  for (int j = 0; j < 40; ++j) {
    for (int i = 0; i < 40; ++i) heights << ((i * 7 + j * 3) % 5) << ' ';
    heights << '\n';
  }
  heights.close();
  const std::string e = refusal("minkowski() {\n  cube(1);\n  surface(\"h.dat\");\n}", dir / "t.csg");
  EXPECT_TRUE(e.starts_with(dir / "t.csg:3:3: minkowski() of this non-convex mesh is not supported: it has ")) << e;
  EXPECT_NE(e.find("more than the 5000 capsim splits into convex pieces"), std::string::npos) << e;
}

}  // namespace
}  // namespace capsim
