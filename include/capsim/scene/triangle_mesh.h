#pragma once
// A closed triangle mesh: the solid a polyhedron() or an imported STL or OFF
// file bounds. Built from polygon faces, checked to be closed (every edge
// shared by exactly two faces that run along it in opposite directions),
// triangulated, and oriented so that every triangle runs counter-clockwise
// seen from outside.

#include "capsim/scene/bounds.h"

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace capsim {

struct TriangleMesh {
  std::vector<glm::dvec3> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;  // counter-clockwise seen from outside
  Aabb bounds;                                          // of the vertices the triangles use
};

// Polygon faces over indexed points, in the winding the caller gives.
struct PolygonMesh {
  std::vector<glm::dvec3> points;
  std::vector<std::vector<std::uint32_t>> faces;
};

// Why a polygon mesh is not a closed solid, with the face it concerns
// (-1 for the mesh as a whole).
struct MeshDefect {
  long face = -1;
  std::string reason;
};

// Checks the faces (indices in range, at least three distinct points each, no
// point twice in a row) and closedness, then triangulates each face (ear
// clipping in the plane it is most nearly parallel to, so a concave planar
// face stays exact) and orients the whole: if the faces run clockwise seen
// from outside (the volume they enclose comes out negative), every triangle is
// turned. Returns the defect instead when the faces do not bound a solid.
struct MeshBuild {
  std::optional<TriangleMesh> mesh;
  MeshDefect defect;
};
MeshBuild build_closed_mesh(const PolygonMesh& polygons);

// Polygon faces from triangles given by their corners' coordinates (STL):
// corners at exactly equal coordinates become one point.
PolygonMesh weld_triangles(const std::vector<std::array<glm::dvec3, 3>>& triangles);

}  // namespace capsim
