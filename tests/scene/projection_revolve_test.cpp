// projection() of rotate_extrude(): OpenSCAD's polyhedron of the revolution
// (scene/extrusions/revolved_mesh.h) projected. Against OpenSCAD 2021.01's own
// SVG exports of the same designs, stored in tests/data/projection_revolve
// (and made again when openscad is installed); the mesh's rings, caps and
// fragments; the bounds and refusals at their FILE:LINE:COL. A
// linear_extrude of such a projection is traced in tests/trace/revolution_test.cpp.

#include "scene/extrusions/revolved_mesh.h"
#include "scene/regions/region_2d.h"

#include "capsim/scene/parser.h"
#include "scene/reading/scene_lexer.h"
#include "support/cli_run.h"
#include "support/openscad_svg.h"
#include "support/scene_refusal.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <memory_resource>

namespace capsim {
namespace {

using scene_file::Polygon2d;
using scene_file::RevolvedMeshing;

const std::string kData = std::string(CAPSIM_SOURCE_DIR) + "/tests/data/projection_revolve/";

// A scene text's first call, read as the parser reads it.
class Calls {
 public:
  explicit Calls(std::string_view text)
      : file_(std::make_shared<const std::string>("t.csg")),
        tokens_(scene_file::tokenize(text, file_)),
        calls_(scene_file::read_calls(tokens_, &memory_, &end_)) {}
  const scene_file::Call& first() const { return calls_.front(); }

 private:
  std::shared_ptr<const std::string> file_;  // the locations name it
  scene_file::Tokens tokens_;
  std::pmr::monotonic_buffer_resource memory_;
  scene_file::Loc end_;
  std::pmr::vector<scene_file::Call> calls_;
};

Polygon2d region(const std::string& text) { return scene_file::evaluate_region(Calls(text).first(), {kData, 1 << 20}); }

using testing::refusal;

// Each coordinate within half a unit of the 6th digit OpenSCAD printed, and
// one step of Clipper's 2^-16 grid: both sides truncate onto it, and a
// coordinate a hair below a grid point (capsim's refined 6.5 - 1e-15) lands
// a step lower than the exact one.
bool near(glm::dvec2 ours, glm::dvec2 printed) {
  for (int k = 0; k < 2; ++k) {
    const double p = std::abs(printed[k]);
    const double digit = p > 0 ? 0.5 * std::pow(10.0, std::floor(std::log10(p)) - 5) : 0;
    if (!(std::abs(ours[k] - printed[k]) <= digit + 1 / scene_file::kClipperScale)) return false;
  }
  return true;
}

// A contour without the vertices that lie on the line through their
// neighbours: OpenSCAD's section keeps where the mesh's triangle edges cross
// the plane, capsim's outline only the corners.
std::vector<glm::dvec2> corners(std::vector<glm::dvec2> c) {
  for (std::size_t i = 0; i < c.size() && c.size() > 3;) {
    const glm::dvec2 a = c[(i + c.size() - 1) % c.size()], p = c[i], b = c[(i + 1) % c.size()];
    const glm::dvec2 d = b - a, q = p - a;
    const double off = std::abs(d.x * q.y - d.y * q.x) / glm::length(d);
    if (off <= 1e-5 * std::max(1.0, glm::length(p))) {
      c.erase(c.begin() + static_cast<std::ptrdiff_t>(i));
    } else {
      ++i;
    }
  }
  return c;
}

// Every contour OpenSCAD drew is one of capsim's, corner for corner in the
// same order from some start, and there are as many.
void expect_same_contours(const std::vector<std::vector<glm::dvec2>>& theirs, const Polygon2d& ours,
                          const std::string& what) {
  ASSERT_EQ(theirs.size(), ours.outlines.size()) << what;
  std::vector<bool> used(ours.outlines.size(), false);
  for (const auto& drawn : theirs) {
    const std::vector<glm::dvec2> contour = corners(drawn);
    bool found = false;
    for (std::size_t k = 0; k < ours.outlines.size() && !found; ++k) {
      const auto& mine = ours.outlines[k].vertices;
      if (used[k] || mine.size() != contour.size()) continue;
      for (std::size_t start = 0; start < mine.size() && !found; ++start) {
        bool same = true;
        for (std::size_t i = 0; i < mine.size() && same; ++i) same = near(mine[(start + i) % mine.size()], contour[i]);
        if (same) used[k] = found = true;
      }
    }
    EXPECT_TRUE(found) << what << ": OpenSCAD's contour of " << contour.size() << " corners from (" << contour[0].x
                       << ", " << contour[0].y << ") is not capsim's";
  }
}

// Each design (NAME.scad) and OpenSCAD's export of it (NAME.openscad.svg).
const char* const kDesigns[] = {"torus",     "torus-cut",  "wedge-cut", "odd-turn",  "mirrored-negative",
                                "hole-cut",  "offset-fa",  "text",      "import-cut", "import-dxf",
                                "nested-projection-cut"};

TEST(ProjectionRevolve, MatchesOpenScadsStoredDrawings) {
  for (const std::string name : kDesigns) {
    const Polygon2d ours = region(testing::read_file(kData + name + ".scad"));
    expect_same_contours(testing::read_svg_contours(kData + name + ".openscad.svg"), ours, name);
  }
}

TEST(ProjectionRevolve, StoredDrawingsAreOpenScadsOwn) {
  if (!testing::has_openscad()) GTEST_SKIP() << "needs openscad on PATH (Debian: openscad)";
  testing::TempDir dir;
  for (const std::string name : kDesigns) {
    const std::string out = dir / (name + ".svg");
    ASSERT_EQ(std::system(fmt::format("openscad -o '{}' '{}' >'{}' 2>&1", out, kData + name + ".scad", dir / "log").c_str()),
              0)
        << name;
    const auto fresh = testing::read_svg_contours(out), stored = testing::read_svg_contours(kData + name + ".openscad.svg");
    ASSERT_EQ(fresh.size(), stored.size()) << name;
    for (std::size_t k = 0; k < fresh.size(); ++k) EXPECT_EQ(fresh[k], stored[k]) << name;
  }
}

Polygon2d outline(std::vector<glm::dvec2> points) {
  Polygon2d p;
  p.outlines.push_back({std::move(points), true});
  return p;
}

RevolvedMeshing plan(const Polygon2d& shape, double angle, scene_file::Resolution res = {}) {
  return scene_file::plan_revolved_mesh(shape, angle, res, scene_file::Loc{});
}

TEST(ProjectionRevolve, FragmentsAreOpenScadsForTheFarthestPointAndTheAngle) {
  const Polygon2d ring = outline({{7, -1}, {13, -1}, {13, 1}, {7, 1}});
  EXPECT_EQ(plan(ring, 360).fragments, 30);       // 360 / $fa
  EXPECT_EQ(plan(ring, 90).fragments, 7);         // 30 * 90 / 360, truncated
  EXPECT_EQ(plan(ring, -90).fragments, 7);
  EXPECT_EQ(plan(ring, 1).fragments, 1);          // at least one
  EXPECT_EQ(plan(ring, 360, {0, 1, 1}).fragments, 82);   // 2 pi 13 / $fs, up
  EXPECT_EQ(plan(ring, 360, {0, 0.5, 2}).fragments, 41);  // $fa is not clamped at 0.01 here
  EXPECT_EQ(plan(ring, 360, {7.9, 12, 2}).fragments, 7);
  // Mirrored shapes count from the axis just the same.
  EXPECT_EQ(plan(outline({{-13, -1}, {-7, -1}, {-7, 1}, {-13, 1}}), 360, {0, 1, 1}).fragments, 82);
  // OpenSCAD's flip_faces.
  EXPECT_FALSE(plan(ring, 360).flip);
  EXPECT_TRUE(plan(ring, 90).flip);
  EXPECT_FALSE(plan(ring, -90).flip);
}

TEST(ProjectionRevolve, RingsStartWhereOpenScadsStart) {
  const std::vector<glm::dvec2> square{{2, 0}, {3, 0}, {3, 1}, {2, 1}};
  // A full turn of 5 fragments: rings from the -x axis, no caps.
  RevolvedMeshing full;
  full.fragments = 5;
  const PolygonMesh m = scene_file::revolved_outline_mesh(square, full);
  EXPECT_EQ(m.points.size(), 20u);
  EXPECT_EQ(m.faces.size(), 40u);
  EXPECT_EQ(m.points[0], glm::dvec3(-3, 0, 0));  // the first triangle starts at the second point
  bool at_plus_x = false;
  for (const glm::dvec3& p : m.points) at_plus_x = at_plus_x || (p.x > 0 && p.y == 0);
  EXPECT_FALSE(at_plus_x);  // 5 is odd: no ring on +x
  ASSERT_TRUE(build_closed_mesh(m).mesh.has_value()) << build_closed_mesh(m).defect.reason;
  // A quarter turn of 2: rings on +x, at 45 and on +y, a cap at each end.
  RevolvedMeshing quarter;
  quarter.angle = 90;
  quarter.fragments = 2;
  const PolygonMesh q = scene_file::revolved_outline_mesh(square, quarter);
  EXPECT_EQ(q.points.size(), 12u);
  EXPECT_EQ(q.faces.size(), 2u * 2 * 4 + 2);
  EXPECT_EQ(q.points[0], glm::dvec3(2, 0, 1));  // the first cap, backwards
  EXPECT_NEAR(q.points.back().x, 0, 1e-15);
  EXPECT_EQ(q.points.back().y, 2);
  ASSERT_TRUE(build_closed_mesh(q).mesh.has_value()) << build_closed_mesh(q).defect.reason;
}

TEST(ProjectionRevolve, AProfileOnTheAxisClosesAtIt) {
  // The edge on the axis collapses, and the rings of its ends are points:
  // their triangles are left out and the rest still closes.
  const std::vector<glm::dvec2> square{{0, 0}, {3, 0}, {3, 2}, {0, 2}};
  for (const double angle : {360.0, 120.0}) {
    RevolvedMeshing m;
    m.angle = angle;
    m.fragments = 6;
    const PolygonMesh p = scene_file::revolved_outline_mesh(square, m);
    const MeshBuild b = build_closed_mesh(p);
    ASSERT_TRUE(b.mesh.has_value()) << angle << ": " << b.defect.reason;
    EXPECT_EQ(p.points.size(), angle == 360 ? 2u + 12 : 2u + 14) << angle;
  }
  const Polygon2d shadow = region(
      "projection(cut = true) rotate_extrude(angle = 360, $fn = 6, $fa = 12, $fs = 2) "
      "translate([0, -1, 0]) square([3, 2]);");
  ASSERT_EQ(shadow.outlines.size(), 1u);
  EXPECT_EQ(shadow.outlines[0].vertices.size(), 6u);
}

TEST(ProjectionRevolve, RefusalsNameTheirPlace) {
  // More fragments than capsim tessellates, from $fn or from $fa = $fs = 0.
  EXPECT_EQ(refusal("projection()\n  rotate_extrude($fn = 2e6) translate([1, 0, 0]) square(1);"),
            "t.csg:2:3: $fn = 2000000, $fa = 12, $fs = 2 give 2e+06 fragments for a circle of radius 2, more than the "
            "1000000 capsim tessellates");
  EXPECT_NE(refusal("projection() rotate_extrude($fa = 0, $fs = 0) translate([1, 0, 0]) square(1);")
                .find("t.csg:1:14: $fn = 0, $fa = 0, $fs = 0 give inf fragments"),
            std::string::npos);
  // Fewer fragments, but too many points: 400000 rings of 16.
  EXPECT_EQ(refusal("projection() rotate_extrude($fn = 400000) translate([5, 0, 0]) circle(1, $fn = 16);"),
            "t.csg:1:14: rotate_extrude() would be meshed with 6400000 points (400000 rings of 16), more than the "
            "4000000 capsim tessellates");
  // Both sides of the axis, as OpenSCAD refuses it.
  EXPECT_EQ(refusal("projection() translate([0, 0, 1]) rotate_extrude() square(2, center = true);"),
            "t.csg:1:35: all points for rotate_extrude() must have the same X coordinate sign (the 2-D shape reaches "
            "x = -1 to 1)");
  // rotate_extrude's own file arguments stay refused, under projection too.
  EXPECT_NE(refusal("projection() rotate_extrude(file = \"a.dxf\") square(1);").find("t.csg:1:36: rotate_extrude's 'file' is not supported"), std::string::npos);
  // And a 3-D child is no 2-D shape.
  EXPECT_EQ(refusal("projection() rotate_extrude() cube(1);").rfind("t.csg:1:31: cube() is not a 2-D shape", 0), 0u)
      << refusal("projection() rotate_extrude() cube(1);");
}

}  // namespace
}  // namespace capsim
