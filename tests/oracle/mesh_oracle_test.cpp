// Mesh leaves, extrusions and revolutions against OpenSCAD's own result:
// OpenSCAD's examples that use polyhedron(), import(), surface(), hull(),
// projection(), linear_extrude() and rotate_extrude() are exported twice with
// $fn = 96, to CSG (which capsim reads) and, rendered by OpenSCAD, to STL;
// Embree casts capsim's
// primary rays at the STL's triangles. The depths must agree within 1 % on
// at least 98 % of the pixels, leaving out those within one pixel of either
// image's silhouette (the tessellated spheres and cylinders of the STL move
// it). Skipped when openscad or the examples are not installed.

#include "capsim/scene/parser.h"
#include "capsim/trace/prepared_scene.h"
#include "capsim/trace/tracer.h"
#include "oracle/oracle_embree.h"
#include "scene/meshes/mesh_files.h"
#include "support/cli_run.h"

#include <fmt/core.h>
#include <gtest/gtest.h>

#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>

using namespace capsim;
using namespace capsim::testing;

namespace {

const std::filesystem::path kExamples = "/usr/share/openscad/examples";
constexpr int kSide = 96;

bool have_openscad() { return std::system("command -v openscad >/dev/null 2>&1") == 0; }

// The triangles of an STL (ASCII or binary) as Embree's scene.
class StlScene {
 public:
  explicit StlScene(const std::string& stl) {
    // The file's triangles as OpenSCAD wrote them, not checked for closure:
    // where OpenSCAD's parts only touch (example017's tripods on their
    // discs) its export is not a closed mesh, and Embree needs none.
    const PolygonMesh m = scene_file::read_mesh_file(stl, std::size_t(1) << 30).at(0).mesh;
    RTCDevice device = oracle::shared_device();
    scene_.reset(rtcNewScene(device));
    RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* v = static_cast<float*>(
        rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), m.points.size()));
    for (std::size_t i = 0; i < m.points.size(); ++i)
      for (int k = 0; k < 3; ++k) v[3 * i + k] = static_cast<float>(m.points[i][k]);
    auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                3 * sizeof(unsigned), m.faces.size()));
    for (std::size_t i = 0; i < m.faces.size(); ++i)
      for (int k = 0; k < 3; ++k) idx[3 * i + k] = m.faces[i].at(static_cast<std::size_t>(k));
    rtcCommitGeometry(g);
    rtcAttachGeometry(scene_.get(), g);
    rtcReleaseGeometry(g);
    rtcCommitScene(scene_.get());
  }

  // The distance along a unit ray to the first triangle, +inf on a miss.
  double depth(const Ray& r) const {
    RTCIntersectContext ctx;
    rtcInitIntersectContext(&ctx);
    RTCRayHit rh = oracle::embree_ray(r);
    rtcIntersect1(scene_.get(), &ctx, &rh);
    return rh.hit.geomID == RTC_INVALID_GEOMETRY_ID ? kInfinity : rh.ray.tfar;
  }

 private:
  oracle::SceneHandle scene_;
};

struct Agreement {
  int compared = 0, agreeing = 0;
};

// Pixels with the same hit or miss in their whole 3 x 3 neighbourhood, in
// both images, are compared: both miss, or both hit within 1 % of the depth.
Agreement compare(const std::vector<double>& a, const std::vector<double>& b) {
  Agreement r;
  auto hit = [](const std::vector<double>& d, int i, int j) { return d[static_cast<std::size_t>(j) * kSide + i] < kInfinity; };
  for (int j = 1; j + 1 < kSide; ++j)
    for (int i = 1; i + 1 < kSide; ++i) {
      bool edge = false;
      for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di)
          edge = edge || hit(a, i + di, j + dj) != hit(a, i, j) || hit(b, i + di, j + dj) != hit(b, i, j);
      if (edge) continue;
      ++r.compared;
      const double da = a[static_cast<std::size_t>(j) * kSide + i], db = b[static_cast<std::size_t>(j) * kSide + i];
      if ((da == kInfinity && db == kInfinity) || std::abs(da - db) <= 0.01 * db) ++r.agreeing;
    }
  return r;
}

// capsim's depth image of a CSG export against Embree's of an STL;
// `import_dir`: where the export's imports lie. `built`: the model has
// leaves capsim builds (meshes, revolutions), which the rays must meet.
void expect_depth_agreement(const std::string& csg, const std::string& stl, const std::filesystem::path& import_dir,
                            const std::string& label, bool built = true) {
  PrepareOptions options;
  options.width = options.height = kSide;
  const PreparedScene ps = prepare_scene(parse_scene_file(csg, {}, 0, import_dir.string()), options);
  const Tracer tracer(ps, {true, 0});
  const StlScene reference(stl);
  std::vector<double> ours(kSide * kSide), theirs(kSide * kSide);
  Tracer::Scratch scratch(ps);
  OpCounts ops;
  for (int j = 0; j < kSide; ++j)
    for (int i = 0; i < kSide; ++i) {
      const Ray r = tracer.primary_ray(i, j);
      Hit h;
      ours[static_cast<std::size_t>(j) * kSide + i] = tracer.first_hit(r, scratch, ops, h) ? h.t : kInfinity;
      theirs[static_cast<std::size_t>(j) * kSide + i] = reference.depth(r);
    }
  EXPECT_GT(built ? ops.mesh_tests + ops.revolution_tests : ops.intersection_tests(), 0u) << label;
  const Agreement a = compare(ours, theirs);
  ASSERT_GT(a.compared, kSide * kSide / 2) << label;
  const double share = static_cast<double>(a.agreeing) / a.compared;
  std::printf("%s: %d of %d pixels agree (%.4f)\n", label.c_str(), a.agreeing, a.compared, share);
  EXPECT_GE(share, 0.98) << label;
}

// capsim's depth image of the .scad against Embree's of OpenSCAD's STL.
// Both exports with `fn` (e.g. "-D '$fn=96'"): what capsim meshes as
// OpenSCAD does (projected solids, hulls, twisted extrusions, text) is then
// meshed alike.
void expect_agreement(const std::filesystem::path& scad, const std::string& label, const TempDir& dir,
                      const std::string& fn = "-D '$fn=96'", bool built = true) {
  const std::string csg = dir / "model.csg", stl = dir / "model.stl";
  ASSERT_EQ(std::system(fmt::format("openscad {} -o '{}' '{}' >/dev/null 2>&1", fn, csg, scad.string()).c_str()), 0);
  ASSERT_EQ(std::system(fmt::format("openscad {} -o '{}' '{}' >/dev/null 2>&1", fn, stl, scad.string()).c_str()),
            0);
  // The export names its imports as the .scad does: beside the .scad.
  expect_depth_agreement(csg, stl, scad.parent_path(), label, built);
}

// A 2-D-only design, which OpenSCAD cannot export as STL: its CSG export
// under linear_extrude(height = 1, center = true), the thickness capsim
// draws it with, exported by OpenSCAD.
void expect_flat_agreement(const std::filesystem::path& scad, const std::string& label, const TempDir& dir) {
  const std::string csg = dir / "model.csg", flat = dir / "flat.scad", stl = dir / "flat.stl";
  ASSERT_EQ(std::system(fmt::format("openscad -o '{}' '{}' >/dev/null 2>&1", csg, scad.string()).c_str()), 0);
  {
    std::ifstream in(csg);
    std::ofstream out(flat);
    out << "linear_extrude(height = 1, center = true) {\n" << in.rdbuf() << "}\n";
  }
  ASSERT_EQ(std::system(fmt::format("openscad -o '{}' '{}' >/dev/null 2>&1", stl, flat).c_str()), 0);
  expect_depth_agreement(csg, stl, scad.parent_path(), label, false);  // squares are boxes
}

// A test's name: the example's file name ("Old/example011": example011), a
// character a test name cannot hold made '_' ("CSG-modules": CSG_modules).
std::string example_name(const ::testing::TestParamInfo<const char*>& info) {
  const std::string path(info.param);
  std::string name = path.substr(path.rfind('/') + 1);
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

class MeshOracle : public ::testing::TestWithParam<const char*> {};

TEST_P(MeshOracle, DepthAgreesWithOpenScadsStl) {
  const std::filesystem::path scad = kExamples / (std::string(GetParam()) + ".scad");
  if (!have_openscad() || !std::filesystem::exists(scad)) GTEST_SKIP() << "openscad or its examples not installed";
  TempDir dir;
  expect_agreement(scad, GetParam(), dir);
}

INSTANTIATE_TEST_SUITE_P(Examples, MeshOracle, ::testing::Values("Old/example011", "Old/example012", "Old/example016",
                                                                 "Basics/text_on_cube", "Basics/LetterBlock",
                                                                 "Old/example010", "Basics/linear_extrude",
                                                                 "Advanced/offset", "Old/example008", "Old/example013",
                                                                 "Basics/projection", "Old/example021",
                                                                 "Advanced/surface_image", "Advanced/GEB",
                                                                 "Basics/rotate_extrude", "Old/example017",
                                                                 "Old/example007", "Old/example009"),
                         example_name);

// Examples whose render at $fn = 96 takes OpenSCAD minutes (CGAL over many
// finely cut spheres and cylinders: Advanced/animation more than 300 s,
// example006 more than 7 minutes and 3 GB), compared at their own $fn, $fa
// and $fs: capsim's exact spheres and cylinders against OpenSCAD's polyhedra
// of them, which the 1 % depth tolerance and the left-out silhouettes take.
class CoarseMeshOracle : public ::testing::TestWithParam<const char*> {};

TEST_P(CoarseMeshOracle, DepthAgreesWithOpenScadsStlAtItsOwnFragments) {
  const std::filesystem::path scad = kExamples / (std::string(GetParam()) + ".scad");
  if (!have_openscad() || !std::filesystem::exists(scad)) GTEST_SKIP() << "openscad or its examples not installed";
  TempDir dir;
  expect_agreement(scad, GetParam(), dir, "", false);
}

INSTANTIATE_TEST_SUITE_P(Examples, CoarseMeshOracle,
                         ::testing::Values("Old/example006", "Advanced/animation", "Advanced/assert", "Advanced/children",
                                           "Advanced/children_indexed", "Basics/CSG-modules", "Basics/CSG",
                                           "Basics/logo", "Basics/logo_and_text", "Functions/functions",
                                           "Old/example001", "Old/example002", "Old/example003", "Old/example004",
                                           "Old/example005", "Old/example014", "Old/example018", "Old/example019",
                                           "Old/example022", "Old/example023", "Old/example024",
                                           "Parametric/candleStand", "Parametric/sign", "Old/example020"),
                         example_name);

class FlatOracle : public ::testing::TestWithParam<const char*> {};

TEST_P(FlatOracle, DepthAgreesWithOpenScadsExtrusionOfIt) {
  const std::filesystem::path scad = kExamples / (std::string(GetParam()) + ".scad");
  if (!have_openscad() || !std::filesystem::exists(scad)) GTEST_SKIP() << "openscad or its examples not installed";
  TempDir dir;
  expect_flat_agreement(scad, GetParam(), dir);
}

INSTANTIATE_TEST_SUITE_P(Examples, FlatOracle, ::testing::Values("Old/example015", "Functions/recursion",
                                                                 "Functions/list_comprehensions",
                                                                 "Functions/polygon_areas", "Advanced/module_recursion"),
                         example_name);

// Clipped regions: a polygon that crosses itself (even-odd), offsets by
// r, delta and chamfer, under a mirror.
TEST(MeshOracle, ClippedRegionsAgreeWithOpenScadsStl) {
  if (!have_openscad()) GTEST_SKIP() << "openscad not installed";
  TempDir dir;
  const std::string scad = dir / "regions.scad";
  std::ofstream(scad) << "linear_extrude(height = 4) polygon([[0, 0], [12, 12], [12, 0], [0, 12]]);\n"
                         "translate([20, 0, 0]) linear_extrude(height = 3) offset(r = 2) square(8);\n"
                         "translate([0, 20, 0]) linear_extrude(height = 3) offset(delta = 2, chamfer = true) "
                         "square(8);\n"
                         "translate([20, 20, 0]) linear_extrude(height = 5) mirror([1, 0]) difference() {\n"
                         "  offset(delta = 1) square(10);\n  offset(r = -2) square(10);\n}\n";
  expect_agreement(scad, "regions", dir);
}

// Straight extrusions: a frustum of a polygon with a hole, less a circle and
// a square, beside a scaled circle: each 2-D leaf its own solid, the caps cut once.
TEST(MeshOracle, ExtrusionsAgreeWithOpenScadsStl) {
  if (!have_openscad()) GTEST_SKIP() << "openscad not installed";
  TempDir dir;
  const std::string scad = dir / "extrusions.scad";
  std::ofstream(scad) << "linear_extrude(height = 6, scale = 0.6) difference() {\n"
                         "  polygon([[0, 0], [10, 0], [10, 4], [4, 4], [4, 10], [0, 10], [1, 1], [3, 1], [1, 3]],\n"
                         "          [[0, 1, 2, 3, 4, 5], [6, 7, 8]]);\n"
                         "  translate([7, 2]) circle(r = 1);\n"
                         "  translate([1, 6]) square([2, 2]);\n"
                         "}\n"
                         "translate([16, 4, 0]) linear_extrude(height = 5, center = true, scale = 1.5) circle(3);\n";
  expect_agreement(scad, "extrusions", dir);
}

// Revolutions: example017's bottle (a tube, a dome of a scaled circle met
// with a square, a half-circle knob), a torus, an ellipse turned off the
// axis through three quarters, and a polygon with a hole turned clockwise.
TEST(MeshOracle, RevolutionsAgreeWithOpenScadsStl) {
  if (!have_openscad()) GTEST_SKIP() << "openscad not installed";
  TempDir dir;
  const std::string scad = dir / "revolutions.scad";
  std::ofstream(scad) << "rotate_extrude() {\n"
                         "  square([25, 68]);\n"
                         "  translate([0, 68]) intersection() { square([25, 25]); scale([1, 0.7]) circle(25); }\n"
                         "  translate([0, 93]) intersection() { translate([0, -6.25]) square([12.5, 25]); circle(12.5); }\n"
                         "}\n"
                         "translate([70, 0, 0]) rotate_extrude() translate([20, 0]) circle(6);\n"
                         "translate([0, 70, 0]) rotate_extrude(angle = 270) translate([15, 0]) rotate(30) scale([1, 2]) "
                         "circle(5);\n"
                         "translate([70, 70, 0]) rotate_extrude(angle = -120)\n"
                         "  polygon([[5, 0], [25, 0], [25, 10], [5, 30], [10, 5], [20, 5], [20, 8], [10, 15]],\n"
                         "          [[0, 1, 2, 3], [4, 5, 6, 7]]);\n";
  expect_agreement(scad, "revolutions", dir);
}

// minkowski() of a union (the sum of each solid), of a non-convex
// polyhedron (CGAL's convex pieces of it, summed each), of two unions, one
// of them a transform's implicit union (a sum for each pair of solids), of a
// twisted extrusion of a region with a hole and of a straight one of an L.
TEST(MeshOracle, MinkowskiSumsOfUnionsNonConvexMeshesAndExtrusionsAgreeWithOpenScadsStl) {
  if (!have_openscad()) GTEST_SKIP() << "openscad not installed";
  TempDir dir;
  const std::string scad = dir / "minkowski.scad";
  std::ofstream(scad) << "minkowski() { union() { cube(4); translate([8, 0, 0]) cube([2, 6, 3]); } sphere(1); }\n"
                         "translate([0, 14, 0]) minkowski() {\n"
                         "  polyhedron(points = [[0, 0, 0], [8, 0, 0], [8, 4, 0], [4, 4, 0], [4, 8, 0], [0, 8, 0],\n"
                         "                       [0, 0, 3], [8, 0, 3], [8, 4, 3], [4, 4, 3], [4, 8, 3], [0, 8, 3]],\n"
                         "             faces = [[5, 4, 3, 2, 1, 0], [6, 7, 8, 9, 10, 11], [0, 1, 7, 6], [1, 2, 8, 7],\n"
                         "                      [2, 3, 9, 8], [3, 4, 10, 9], [4, 5, 11, 10], [5, 0, 6, 11]]);\n"
                         "  cylinder(r = 1, h = 1);\n"
                         "}\n"
                         "translate([16, 14, 0]) minkowski() {\n"
                         "  translate([0, 0, 0]) { cube(2); translate([0, 5, 0]) cube(2); }\n"
                         "  union() { rotate([0, 0, 45]) cube(1, center = true); translate([3, 0, 0]) sphere(0.5); }\n"
                         "}\n"
                         "translate([0, 30, 0]) minkowski() {\n"
                         "  linear_extrude(height = 3, twist = 40, slices = 3)\n"
                         "    difference() { square(10); translate([3, 3]) square(4); }\n"
                         "  rotate([0, 0, 45]) cube(1, center = true);\n"
                         "}\n"
                         "translate([16, 30, 0]) minkowski() {\n"
                         "  linear_extrude(height = 2) polygon([[0, 0], [6, 0], [6, 2], [2, 2], [2, 6], [0, 6]]);\n"
                         "  cylinder(r = 1, h = 1);\n"
                         "}\n";
  // 24 fragments: OpenSCAD unites the sums' Nef polyhedra, slow at 96.
  expect_agreement(scad, "minkowski", dir, "-D '$fn=24'");
}

// minkowski() of a difference (a cube less a cylinder: CGAL's convex pieces
// of the Nef result, summed each), of an intersection, of a revolved ring
// and of a difference of revolutions, and hull() of a difference (the
// corners of the evaluated solid, not of its operands).
TEST(MeshOracle, MinkowskiSumsOfEvaluatedSolidsAgreeWithOpenScadsStl) {
  if (!have_openscad()) GTEST_SKIP() << "openscad not installed";
  TempDir dir;
  const std::string scad = dir / "evaluated.scad";
  std::ofstream(scad) << "minkowski() {\n"
                         "  difference() { cube(8, center = true); cylinder(r = 2.5, h = 10, center = true); }\n"
                         "  sphere(0.6, $fn = 8);\n"
                         "}\n"
                         "translate([14, 0, 0]) minkowski() {\n"
                         "  intersection() { cube(8, center = true); rotate([0, 0, 45]) cube([10, 4, 6], center = true); }\n"
                         "  cylinder(r = 0.5, h = 1);\n"
                         "}\n"
                         "translate([0, 14, 0]) minkowski() {\n"
                         "  rotate_extrude() translate([3, 0, 0]) square([1.5, 2]);\n"
                         "  cube(0.8, center = true);\n"
                         "}\n"
                         "translate([14, 14, 0]) minkowski() {\n"
                         "  difference() {\n"
                         "    rotate_extrude($fn = 10) translate([2, 0, 0]) circle(1.5, $fn = 6);\n"
                         "    translate([0, -5, -5]) cube(10);\n"
                         "  }\n"
                         "  sphere(0.4);\n"
                         "}\n"
                         "translate([0, 28, 0]) hull() {\n"
                         "  difference() { cube(8, center = true); translate([2, 2, 2]) cube(8); }\n"
                         "  translate([8, 0, 0]) sphere(1);\n"
                         "}\n";
  // Few fragments: OpenSCAD's sums of the revolutions' many pieces are slow.
  expect_agreement(scad, "evaluated", dir, "-D '$fn=16'");
}

// hull() and minkowski() of 2-D shapes (CGAL's hull, Clipper's sum as
// OpenSCAD forms them) under linear_extrude and rotate_extrude.
TEST(MeshOracle, TwoDHullsAndSumsAgreeWithOpenScadsStl) {
  if (!have_openscad()) GTEST_SKIP() << "openscad not installed";
  TempDir dir;
  const std::string scad = dir / "hulls2d.scad";
  std::ofstream(scad) << "linear_extrude(height = 3) hull() { circle(2); translate([8, 0]) square(3); }\n"
                         "translate([0, 12, 0]) linear_extrude(height = 2) minkowski() {\n"
                         "  difference() { square(10); translate([3, 3]) square(4); }\n"
                         "  circle(1);\n"
                         "}\n"
                         "translate([20, 0, 0]) rotate_extrude() translate([5, 0]) hull() {\n"
                         "  circle(1);\n"
                         "  translate([2, 2]) circle(0.5);\n"
                         "}\n";
  expect_agreement(scad, "hulls2d", dir);
}

// resize() of a sphere (its tessellation's box), of a difference (the
// evaluated solid's box), with auto, and of a 2-D circle under an
// extrusion: the scale OpenSCAD derives, applied to capsim's exact solids
// (so the silhouettes differ as the tessellation does).
TEST(MeshOracle, ResizedSolidsAgreeWithOpenScadsStl) {
  if (!have_openscad()) GTEST_SKIP() << "openscad not installed";
  TempDir dir;
  const std::string scad = dir / "resize.scad";
  std::ofstream(scad) << "resize([12, 6, 4]) sphere(3);\n"
                         "translate([16, 0, 0]) resize([10, 0, 0], auto = true)\n"
                         "  difference() { cube([4, 4, 2]); translate([2, -1, -1]) cube([3, 2, 4]); }\n"
                         "translate([0, 14, 0]) resize(newsize = [0, 0, 9], auto = [true, false, false]) cylinder(r = 2, h = 3);\n"
                         "translate([16, 14, 0]) linear_extrude(height = 3) resize([9, 5]) circle(2);\n";
  expect_agreement(scad, "resize", dir, "-D '$fn=96'", false);  // exact solids
}

}  // namespace
