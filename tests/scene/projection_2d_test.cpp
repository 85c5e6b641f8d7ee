// projection(): shadows and sections of meshes under a CSG tree.

#include "scene/regions/projection_2d.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace capsim;
using namespace capsim::scene_file;

namespace {

// The closed mesh of the box lo..hi.
TriangleMesh box(glm::dvec3 lo, glm::dvec3 hi) {
  PolygonMesh p;
  for (int k = 0; k < 8; ++k) p.points.emplace_back(k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z);
  p.faces = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  MeshBuild b = build_closed_mesh(p);
  EXPECT_TRUE(b.mesh.has_value()) << b.defect.reason;
  return *b.mesh;
}

CsgNode leaf(int k) {
  CsgNode n;
  n.is_leaf = true;
  n.primitive = k;
  return n;
}

CsgNode op(CsgOp o, std::vector<CsgNode> children) {
  CsgNode n;
  n.op = o;
  n.children = std::move(children);
  return n;
}

double area(const std::vector<std::vector<glm::dvec2>>& paths) {
  double a = 0;  // even-odd: paths at odd depth are holes; here holes run inside outlines
  for (const auto& p : paths) {
    double s = 0;
    for (std::size_t k = 0; k < p.size(); ++k) {
      const glm::dvec2 u = p[k], v = p[(k + 1) % p.size()];
      s += u.x * v.y - u.y * v.x;
    }
    a += 0.5 * s;  // the inside lies to the left: outlines run counter-clockwise, holes clockwise
  }
  return a;
}

// The prism over the regular n-gon of radius r about the origin, z = z0 .. z1.
TriangleMesh prism(int n, double r, double z0, double z1) {
  PolygonMesh p;
  std::vector<std::uint32_t> bottom, top;
  for (int k = 0; k < n; ++k) {
    const double a = 2 * M_PI * k / n;
    p.points.emplace_back(r * std::cos(a), r * std::sin(a), z0);
    p.points.emplace_back(r * std::cos(a), r * std::sin(a), z1);
    bottom.insert(bottom.begin(), static_cast<std::uint32_t>(2 * k));
    top.push_back(static_cast<std::uint32_t>(2 * k + 1));
    const auto j = static_cast<std::uint32_t>(2 * ((k + 1) % n));
    p.faces.push_back({static_cast<std::uint32_t>(2 * k), j, j + 1, static_cast<std::uint32_t>(2 * k + 1)});
  }
  p.faces.push_back(bottom);
  p.faces.push_back(top);
  MeshBuild b = build_closed_mesh(p);
  EXPECT_TRUE(b.mesh.has_value()) << b.defect.reason;
  return *b.mesh;
}

TEST(Projection, SectionOfABoxIsItsSquare) {
  MeshedSolids s{{box({0, 0, -1}, {2, 2, 1})}, leaf(0), {}};
  const auto paths = project_solids(s, true);
  ASSERT_EQ(paths.size(), 1u);
  // The corners the grid cut are restored where the sides' lines meet.
  EXPECT_EQ(paths[0].size(), 4u);
  EXPECT_NEAR(area(paths), 4, 1e-9);
  for (glm::dvec2 p : paths[0]) {
    // Every vertex lies on the square's outline.
    const double off = std::min({std::abs(p.x), std::abs(p.x - 2), std::abs(p.y), std::abs(p.y - 2)});
    EXPECT_LT(off, 1e-12) << p.x << ", " << p.y;
  }
}

TEST(Projection, SectionMissesABoxAboveThePlane) {
  MeshedSolids s{{box({0, 0, 1}, {2, 2, 3})}, leaf(0), {}};
  EXPECT_TRUE(project_solids(s, true).empty());
  EXPECT_NEAR(area(project_solids(s, false)), 4, 1e-9);
}

TEST(Projection, ShadowOfAThroughHoleHasAHole) {
  MeshedSolids s{{box({0, 0, 1}, {4, 4, 3}), box({1, 1, 0}, {3, 3, 4})},
                    op(CsgOp::Difference, {leaf(0), leaf(1)}), {}};
  const auto paths = project_solids(s, false);
  EXPECT_EQ(paths.size(), 2u);
  EXPECT_NEAR(area(paths), 16 - 4, 1e-9);
}

TEST(Projection, ShadowCoversABlindHoleThatTheSectionShows) {
  // The hole goes down from the top to z = 1: the section at z = 0 misses
  // it when the box spans z = -1 .. 3 and the hole reaches z = -0.5.
  MeshedSolids blind{{box({0, 0, -1}, {4, 4, 3}), box({1, 1, 1}, {3, 3, 4})},
                        op(CsgOp::Difference, {leaf(0), leaf(1)}), {}};
  EXPECT_EQ(project_solids(blind, false).size(), 1u);
  EXPECT_EQ(project_solids(blind, true).size(), 1u);
  MeshedSolids deep{{box({0, 0, -1}, {4, 4, 3}), box({1, 1, -0.5}, {3, 3, 4})},
                       op(CsgOp::Difference, {leaf(0), leaf(1)}), {}};
  EXPECT_NEAR(area(project_solids(deep, false)), 16, 1e-9);
  EXPECT_NEAR(area(project_solids(deep, true)), 12, 1e-9);
}

TEST(Projection, IntersectionAndUnion) {
  MeshedSolids meet{{box({0, 0, -1}, {2, 2, 1}), box({1, 1, -1}, {3, 3, 1})},
                       op(CsgOp::Intersection, {leaf(0), leaf(1)}), {}};
  EXPECT_NEAR(area(project_solids(meet, true)), 1, 1e-9);
  // Apart in z, the boxes' shadows still meet; their intersection is empty.
  MeshedSolids apart{{box({0, 0, -1}, {2, 2, 1}), box({1, 1, 2}, {3, 3, 4})},
                        op(CsgOp::Intersection, {leaf(0), leaf(1)}), {}};
  EXPECT_TRUE(project_solids(apart, false).empty());
  apart.root.op = CsgOp::Union;
  EXPECT_NEAR(area(project_solids(apart, false)), 7, 1e-9);
}

TEST(Projection, ATessellatedCircleKeepsItsCorners) {
  // 96 sides of 0.65 against cells of 0.04: every corner is found again.
  MeshedSolids s{{prism(96, 10, -1, 1)}, leaf(0), {}};
  const auto paths = project_solids(s, true);
  ASSERT_EQ(paths.size(), 1u);
  EXPECT_EQ(paths[0].size(), 96u);
  EXPECT_NEAR(area(paths), 0.5 * 96 * 100 * std::sin(2 * M_PI / 96), 1e-9);
}

TEST(Projection, FeaturesFinerThanTheGridAreLost) {
  // A slot of a thousandth of the width, 1/512 of it being a cell: the
  // documented limit, shown so that a change of the grid is noticed.
  MeshedSolids s{{box({0, 0, -1}, {10, 10, 1}), box({4.9995, -1, -2}, {5.0005, 11, 2})},
                    op(CsgOp::Difference, {leaf(0), leaf(1)}), {}};
  EXPECT_EQ(project_solids(s, true).size(), 1u);
  EXPECT_NEAR(area(project_solids(s, true)), 100, 1e-9);
}

TEST(Projection, SameSolidsSamePaths) {
  MeshedSolids s{{box({0, 0, -1}, {4, 4, 3}), box({1, 1, 0}, {3, 3, 4})},
                    op(CsgOp::Difference, {leaf(0), leaf(1)}), {}};
  EXPECT_EQ(project_solids(s, false), project_solids(s, false));
}

}  // namespace
