// Mesh leaves: closedness, the exact crossings of a line with a mesh (against
// brute force over every triangle, and on lines through shared edges and
// vertices), and meshes inside the tracer's CSG evaluation.

#include "capsim/trace/mesh_geometry.h"
#include "capsim/trace/render.h"
#include "capsim/trace/tracer.h"
#include "support/scene_builders.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

using namespace capsim;
using namespace capsim::testing;

namespace {

// A unit cube [0,1]^3 of six quads, counter-clockwise seen from outside.
PolygonMesh cube_faces() {
  PolygonMesh m;
  for (int k = 0; k < 8; ++k) m.points.push_back({k & 1, (k >> 1) & 1, (k >> 2) & 1});
  m.faces = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  return m;
}

// A square ring: the 4 x 4 x 1 block [0,4]^2 x [0,1] with the 2 x 2 hole
// [1,3]^2 through it, so a line can cross it four times.
PolygonMesh ring_faces() {
  PolygonMesh m;
  const glm::dvec2 outer[4] = {{0, 0}, {4, 0}, {4, 4}, {0, 4}}, inner[4] = {{1, 1}, {3, 1}, {3, 3}, {1, 3}};
  for (double z : {0.0, 1.0}) {
    for (const glm::dvec2& p : outer) m.points.push_back({p, z});
    for (const glm::dvec2& p : inner) m.points.push_back({p, z});
  }
  // Outer bottom 0-3, inner bottom 4-7, outer top 8-11, inner top 12-15.
  for (std::uint32_t k = 0; k < 4; ++k) {
    const std::uint32_t n = (k + 1) % 4;
    m.faces.push_back({8 + k, 8 + n, 12 + n, 12 + k});  // top
    m.faces.push_back({k, 4 + k, 4 + n, n});            // bottom
    m.faces.push_back({k, n, 8 + n, 8 + k});            // outer wall
    m.faces.push_back({4 + k, 12 + k, 12 + n, 4 + n});  // inner wall
  }
  return m;
}

// The octahedron |x| + |y| + |z| <= 1: four triangles meet at each vertex.
PolygonMesh octahedron_faces() {
  PolygonMesh m;
  m.points = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (std::uint32_t x : {0u, 1u})
    for (std::uint32_t y : {2u, 3u})
      for (std::uint32_t z : {4u, 5u}) {
        // Counter-clockwise seen from outside when the signs' product is positive.
        const bool ccw = ((x == 0) == (y == 2)) == (z == 4);
        m.faces.push_back(ccw ? std::vector<std::uint32_t>{x, y, z} : std::vector<std::uint32_t>{x, z, y});
      }
  return m;
}

std::shared_ptr<const TriangleMesh> closed(const PolygonMesh& faces) {
  MeshBuild b = build_closed_mesh(faces);
  EXPECT_TRUE(b.mesh) << b.defect.reason;
  return std::make_shared<const TriangleMesh>(std::move(*b.mesh));
}

std::vector<LineCrossing> crossings(const MeshHierarchy& h, glm::dvec3 o, glm::dvec3 d, OpCounts* counts = nullptr) {
  std::vector<LineCrossing> out, work;
  OpCounts ops;
  mesh_line_crossings(h, o, d, out, work, ops);
  if (counts) *counts = ops;
  return out;
}

// Every triangle tested (Moller-Trumbore, no hierarchy), the hits sorted: for
// a line that passes no edge, the crossings exactly.
std::vector<LineCrossing> brute_force(const TriangleMesh& m, glm::dvec3 o, glm::dvec3 d) {
  std::vector<LineCrossing> hits;
  for (std::size_t i = 0; i < m.triangles.size(); ++i) {
    const glm::dvec3 a = m.vertices[m.triangles[i][0]], b = m.vertices[m.triangles[i][1]],
                     c = m.vertices[m.triangles[i][2]];
    const glm::dvec3 e1 = b - a, e2 = c - a, p = glm::cross(d, e2);
    const double det = glm::dot(e1, p);
    if (det == 0) continue;
    const glm::dvec3 s = o - a, q = glm::cross(s, e1);
    const double u = glm::dot(s, p) / det, v = glm::dot(d, q) / det;
    if (u < 0 || v < 0 || u + v > 1) continue;
    hits.push_back({glm::dot(e2, q) / det, static_cast<int>(i), glm::dot(glm::cross(e1, e2), d) < 0});
  }
  std::sort(hits.begin(), hits.end(), [](const LineCrossing& x, const LineCrossing& y) { return x.t < y.t; });
  return hits;
}

}  // namespace

TEST(TriangleMesh, ClosedMeshesAreTriangulatedAndTurnedOutward) {
  PolygonMesh inward = cube_faces();
  for (auto& f : inward.faces) std::reverse(f.begin(), f.end());
  for (const PolygonMesh& m : {cube_faces(), inward}) {
    const MeshBuild b = build_closed_mesh(m);
    ASSERT_TRUE(b.mesh) << b.defect.reason;
    EXPECT_EQ(b.mesh->triangles.size(), 12u);
    EXPECT_EQ(b.mesh->bounds.lo, glm::dvec3(0));
    EXPECT_EQ(b.mesh->bounds.hi, glm::dvec3(1));
    double volume6 = 0;
    for (const auto& t : b.mesh->triangles)
      volume6 += glm::dot(b.mesh->vertices[t[0]], glm::cross(b.mesh->vertices[t[1]], b.mesh->vertices[t[2]]));
    EXPECT_DOUBLE_EQ(volume6, 6.0);  // outward: positive
  }
  EXPECT_EQ(build_closed_mesh(ring_faces()).mesh->triangles.size(), 32u);
}

TEST(TriangleMesh, ConcaveFacesAreCutByEars) {
  // An L-shaped prism: its two caps are concave hexagons.
  PolygonMesh m;
  const glm::dvec2 l[6] = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  for (double z : {0.0, 1.0})
    for (const glm::dvec2& p : l) m.points.push_back({p, z});
  m.faces.push_back({6, 7, 8, 9, 10, 11});
  m.faces.push_back({5, 4, 3, 2, 1, 0});
  for (std::uint32_t k = 0; k < 6; ++k) m.faces.push_back({k, (k + 1) % 6, 6 + (k + 1) % 6, 6 + k});
  const auto mesh = closed(m);
  const MeshHierarchy h = build_mesh_hierarchy(mesh);
  // Down through the notch: no solid there.
  EXPECT_TRUE(crossings(h, {1.5, 1.5, 5}, {0, 0, -1}).empty());
  const std::vector<LineCrossing> c = crossings(h, {0.5, 1.5, 5}, {0, 0, -1});
  ASSERT_EQ(c.size(), 2u);
  EXPECT_DOUBLE_EQ(c[0].t, 4);
  EXPECT_DOUBLE_EQ(c[1].t, 5);
}

TEST(TriangleMesh, OpenMeshesAreRefusedWithTheReason) {
  PolygonMesh hole = cube_faces();
  hole.faces.pop_back();
  MeshBuild b = build_closed_mesh(hole);
  EXPECT_FALSE(b.mesh);
  EXPECT_NE(b.defect.reason.find("has no face on its other side"), std::string::npos) << b.defect.reason;
  EXPECT_GE(b.defect.face, 0);

  PolygonMesh flipped = cube_faces();
  std::reverse(flipped.faces[3].begin(), flipped.faces[3].end());
  b = build_closed_mesh(flipped);
  EXPECT_FALSE(b.mesh);
  EXPECT_NE(b.defect.reason.find("both run from point"), std::string::npos) << b.defect.reason;

  PolygonMesh flat;  // two triangles back to back: closed, but no volume
  flat.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  flat.faces = {{0, 1, 2}, {0, 2, 1}};
  b = build_closed_mesh(flat);
  EXPECT_FALSE(b.mesh);
  EXPECT_NE(b.defect.reason.find("enclose no volume"), std::string::npos) << b.defect.reason;

  PolygonMesh bad = cube_faces();
  bad.faces[2][1] = 8;
  b = build_closed_mesh(bad);
  EXPECT_EQ(b.defect.face, 2);
  EXPECT_NE(b.defect.reason.find("names point 8, but there are only 8 points"), std::string::npos);
  bad.faces[2] = {0, 1};
  EXPECT_NE(build_closed_mesh(bad).defect.reason.find("needs at least 3"), std::string::npos);
}

TEST(TriangleMesh, StlCornersAreWeldedByTheirCoordinates) {
  const PolygonMesh m = weld_triangles({{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}}, {{{1, 0, 0}, {0, 0, 0}, {0, 0, 1}}}});
  EXPECT_EQ(m.points.size(), 4u);
  ASSERT_EQ(m.faces.size(), 2u);
  EXPECT_EQ(m.faces[1], (std::vector<std::uint32_t>{1, 0, 3}));
}

TEST(MeshGeometry, AgreesWithBruteForceOnRandomLines) {
  const auto mesh = closed(ring_faces());
  const MeshHierarchy h = build_mesh_hierarchy(mesh);
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> pos(-1, 5), dir(-1, 1);
  int with_four = 0;
  for (int i = 0; i < 2000; ++i) {
    const glm::dvec3 o{pos(rng), pos(rng), pos(rng) / 2};
    const glm::dvec3 d{dir(rng), dir(rng), dir(rng) / 8};
    const std::vector<LineCrossing> got = crossings(h, o, d), want = brute_force(*mesh, o, d);
    ASSERT_EQ(got.size(), want.size()) << "line " << i;
    for (std::size_t k = 0; k < got.size(); ++k) {
      EXPECT_NEAR(got[k].t, want[k].t, 1e-9 * (1 + std::abs(want[k].t))) << "line " << i;
      EXPECT_EQ(got[k].enter, k % 2 == 0) << "line " << i;
      EXPECT_EQ(got[k].enter, want[k].enter) << "line " << i;
      EXPECT_EQ(got[k].surface, want[k].surface) << "line " << i;
    }
    with_four += got.size() == 4;
  }
  EXPECT_GT(with_four, 50);  // the lines do cross the hole
}

TEST(MeshGeometry, ThroughTheHoleFourCrossings) {
  const MeshHierarchy h = build_mesh_hierarchy(closed(ring_faces()));
  OpCounts ops;
  const std::vector<LineCrossing> c = crossings(h, {-1, 2, 0.5}, {1, 0, 0}, &ops);
  ASSERT_EQ(c.size(), 4u);
  const double t[4] = {1, 2, 4, 5};
  for (int k = 0; k < 4; ++k) {
    EXPECT_DOUBLE_EQ(c[k].t, t[k]);
    EXPECT_EQ(c[k].enter, k % 2 == 0);
  }
  // 32 triangles in leaves of at most 4: the hierarchy tests fewer than all.
  EXPECT_GT(ops.triangle_tests, 0u);
  EXPECT_LT(ops.triangle_tests, 32u);
  EXPECT_GT(ops.mesh_node_tests, 0u);
}

TEST(MeshGeometry, SharedEdgesAndVerticesAreCrossedOnce) {
  // Both diagonals of the cube's top and bottom quads pass through their
  // centres: whichever way the quads were cut, the line meets a shared edge.
  const MeshHierarchy cube = build_mesh_hierarchy(closed(cube_faces()));
  std::vector<LineCrossing> c = crossings(cube, {0.5, 0.5, -1}, {0, 0, 1});
  ASSERT_EQ(c.size(), 2u);
  EXPECT_EQ(c[0].t, 1);
  EXPECT_EQ(c[1].t, 2);
  // Through the octahedron's apexes, where four triangles meet, straight and
  // slanted.
  const MeshHierarchy octa = build_mesh_hierarchy(closed(octahedron_faces()));
  c = crossings(octa, {0, 0, -3}, {0, 0, 1});
  ASSERT_EQ(c.size(), 2u);
  EXPECT_EQ(c[0].t, 2);
  EXPECT_EQ(c[1].t, 4);
  c = crossings(octa, {-0.25, -0.125, -2}, {0.25, 0.125, 3});  // through (0, 0, 1) at t = 1
  ASSERT_EQ(c.size(), 2u);
  EXPECT_TRUE(c[0].enter);
  EXPECT_DOUBLE_EQ(c[1].t, 1);
  // Touching the apex from outside: nothing, or an interval of no length.
  c = crossings(octa, {-1, 0, 1}, {1, 0, 0});
  EXPECT_TRUE(c.empty());
}

TEST(MeshGeometry, MeshCubeMatchesTheBoxPrimitive) {
  Primitive mesh_cube;
  mesh_cube.kind = PrimitiveKind::Mesh;
  mesh_cube.mesh = closed(cube_faces());
  const glm::dmat4 place = glm::rotate(glm::translate(glm::dmat4(1.0), {1, 2, 3}), 0.3, glm::dvec3(1, 2, 3)) *
                           glm::scale(glm::dmat4(1.0), glm::dvec3(2, 3, 4));
  mesh_cube.to_world = place;
  Primitive box_cube;
  box_cube.kind = PrimitiveKind::Box;
  box_cube.to_world = place;
  const PreparedPrimitive pm = prepare_primitive(mesh_cube), pb = prepare_primitive(box_cube);
  EXPECT_EQ(pm.world_bounds.lo, pb.world_bounds.lo);
  EXPECT_EQ(pm.world_bounds.hi, pb.world_bounds.hi);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-6, 10);
  std::vector<LineCrossing> out, work;
  int met = 0;
  for (int i = 0; i < 1000; ++i) {
    const Ray r{{u(rng), u(rng), u(rng)}, glm::normalize(glm::dvec3{u(rng), u(rng), u(rng)} - glm::dvec3(2)), 0,
                kInfinity};
    OpCounts ops;
    LineSpan s;
    const bool hit = intersect_line(pb, r, s, ops);
    mesh_crossings(pm, r, out, work, ops);
    EXPECT_EQ(ops.mesh_tests, 1u);
    ASSERT_EQ(out.size(), hit ? 2u : 0u) << "ray " << i;
    if (!hit) continue;
    ++met;
    EXPECT_NEAR(out[0].t, s.t_enter, 1e-9);
    EXPECT_NEAR(out[1].t, s.t_exit, 1e-9);
    const glm::dvec3 nm = world_normal(pm, r.at(out[0].t), out[0].surface, ops);
    const glm::dvec3 nb = world_normal(pb, r.at(s.t_enter), s.enter_surface, ops);
    EXPECT_NEAR(glm::length(nm - nb), 0, 1e-12);
  }
  EXPECT_GT(met, 50);
}

TEST(MeshTracer, SeveralIntervalsOfOneLeafUnderCsg) {
  // The ring minus a bar through its hole along x: a ray along x at the bar's
  // height sees nothing; above the bar, the ring's near wall.
  Primitive ring;
  ring.kind = PrimitiveKind::Mesh;
  ring.mesh = closed(ring_faces());
  Scene scene = make_scene({ring, box({-1, 1.5, 0.25}, {6, 1, 0.25})},
                           op(CsgOp::Difference, {leaf(0), leaf(1)}));
  Camera cam;
  cam.eye = {-10, 2, 0.375};
  cam.center = {0, 2, 0.375};
  cam.width = cam.height = 4;
  scene.camera = cam;
  const PreparedScene ps = prepare_scene(std::move(scene), {});
  const Tracer tracer(ps, {});
  Tracer::Scratch s(ps);
  OpCounts ops;
  Hit h;
  EXPECT_FALSE(tracer.first_hit(Ray{{-10, 2, 0.375}, {1, 0, 0}, 0, kInfinity}, s, ops, h));
  ASSERT_TRUE(tracer.first_hit(Ray{{-10, 2, 0.75}, {1, 0, 0}, 0, kInfinity}, s, ops, h));
  EXPECT_DOUBLE_EQ(h.t, 10);
  EXPECT_EQ(h.normal, glm::dvec3(-1, 0, 0));
  // Starting inside the ring's near wall: the first crossing is its exit.
  ASSERT_TRUE(tracer.first_hit(Ray{{0.5, 2, 0.75}, {1, 0, 0}, 0, kInfinity}, s, ops, h));
  EXPECT_DOUBLE_EQ(h.t, 0.5);
  EXPECT_FALSE(h.entering);
  // From inside the hole, the far wall.
  ASSERT_TRUE(tracer.first_hit(Ray{{2, 2, 0.75}, {1, 0, 0}, 0, kInfinity}, s, ops, h));
  EXPECT_DOUBLE_EQ(h.t, 1);
  EXPECT_TRUE(h.entering);
  EXPECT_GT(ops.mesh_tests, 0u);
  EXPECT_GT(ops.triangle_tests, 0u);
}

TEST(MeshTracer, ImageOfAMeshCubeIsTheBoxImage) {
  auto render_of = [](Primitive p) {
    Scene s = make_scene({p});
    Camera cam;
    cam.eye = {3, -4, 2.5};
    cam.center = {0.5, 0.5, 0.5};
    cam.width = cam.height = 48;
    s.camera = cam;
    const PreparedScene ps = prepare_scene(std::move(s), {});
    return render(Tracer(ps, {}), 1);
  };
  Primitive m;
  m.kind = PrimitiveKind::Mesh;
  m.mesh = closed(cube_faces());
  const Framebuffer a = render_of(m), b = render_of(box({0, 0, 0}, {1, 1, 1}));
  int covered = 0;
  for (int j = 0; j < 48; ++j)
    for (int i = 0; i < 48; ++i) {
      const std::size_t k = static_cast<std::size_t>(j) * 48 + static_cast<std::size_t>(i);
      ASSERT_EQ(a.id[k], b.id[k]) << i << "," << j;
      if (b.id[k] < 0) continue;
      ++covered;
      EXPECT_NEAR(a.depth[k], b.depth[k], 1e-5);  // float depths
      for (int c = 0; c < 4; ++c) EXPECT_NEAR(a.rgba[4 * k + c], b.rgba[4 * k + c], 1e-6);
    }
  EXPECT_GT(covered, 200);
}
