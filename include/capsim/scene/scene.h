#pragma once
// The scene as parsed: a CSG tree over exact primitives, with camera, lights,
// materials and background. Geometry is kept exact (quadrics and planes, and
// the planar faces of meshes); nothing is tessellated.

#include "capsim/scene/bounds.h"
#include "capsim/system/huge_pages.h"
#include "capsim/scene/revolution.h"
#include "capsim/scene/triangle_mesh.h"

#include <glm/glm.hpp>

#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace capsim {

// Where a construct stands in its scene file; every error points back here.
struct SourceLoc {
  std::shared_ptr<const std::string> file;  // shared by every token of one file
  int line = 0;                             // 1-based
  int col = 0;                              // 1-based, in bytes

  std::string str() const;  // "FILE:LINE:COL"
};

// Bad input: what() is "FILE:LINE:COL: message".
class SceneError : public std::runtime_error {
 public:
  SceneError(const SourceLoc& loc, const std::string& message);
  const SourceLoc& loc() const { return loc_; }
  const std::string& message() const { return message_; }

 private:
  SourceLoc loc_;
  std::string message_;
};

// The paper's three primitive kinds, and closed triangle meshes. Cone covers
// OpenSCAD's cylinder: equal radii give a cylinder, r2 = 0 a pointed cone.
// Mesh covers polyhedron() and imported STL and OFF solids; Revolution
// rotate_extrude's turned profiles (revolution.h).
enum class PrimitiveKind { Sphere, Box, Cone, Mesh, Revolution };
const char* to_string(PrimitiveKind kind);

// The object-space bounding box of a canonical convex primitive (before
// to_world): the unit sphere, the unit cube [0,1]^3, the frustum 0 <= z <= 1
// of radius at most 1. A mesh's and a revolution's are their own
// (object_bounds of the primitive).
Aabb object_bounds(PrimitiveKind kind);

struct Material {
  double ambient = 0.1;    // fraction of the surface colour lit regardless of lights
  double diffuse = 0.8;    // Lambert weight
  double specular = 0.3;   // Phong highlight weight
  double shininess = 32;   // Phong exponent
  double reflect = 0;      // mirror reflection weight
  double transmit = 0;     // refraction weight
  double ior = 1.5;        // index of refraction of the solid's interior
};

// One primitive in canonical object space, placed by to_world:
//   Sphere: the unit sphere about the origin.
//   Box:    the unit cube [0,1]^3.
//   Cone:   the frustum 0 <= z <= 1 with radius r(z) = cone_r1 + (cone_r2 - cone_r1) z,
//           where max(cone_r1, cone_r2) = 1 and both caps are closed.
//   Mesh:   the closed triangle mesh `mesh`, in its own coordinates.
//   Revolution: the turned profile `revolution`, about the z axis.
struct Primitive {
  PrimitiveKind kind = PrimitiveKind::Sphere;
  glm::dmat4 to_world{1.0};  // object -> world; invertible (the parser refuses singular ones)
  double cone_r1 = 1;
  double cone_r2 = 1;
  std::shared_ptr<const TriangleMesh> mesh;  // Mesh only; shared by the frames of an animation
  std::shared_ptr<const Revolution> revolution;  // Revolution only
  glm::dvec3 color{0.946, 0.679, 0.025};  // linear RGB albedo: OpenSCAD's default #f9d72c, decoded
  double alpha = 1;
  Material material;
  SourceLoc loc;
};

// The object-space bounding box of a primitive: object_bounds(kind), or a mesh's or
// a revolution's own.
Aabb object_bounds(const Primitive& p);

enum class CsgOp { Union, Intersection, Difference };
const char* to_string(CsgOp op);

// A node of the CSG tree as written: a leaf names a primitive, an operator node has
// any number of children (the status tree later makes them binary). An operator
// node with no children is the empty set (OpenSCAD writes `group();`).
struct CsgNode {
  bool is_leaf = false;
  int primitive = -1;  // index into Scene::primitives when is_leaf
  CsgOp op = CsgOp::Union;
  std::vector<CsgNode> children;
  SourceLoc loc;
};

// Perspective: rays from the eye (a pinhole). Orthographic: parallel rays along
// the view direction, from the plane through the eye facing it (what lies behind
// that plane is not seen), as OpenSCAD's --projection=ortho shows a model.
enum class Projection { Perspective, Orthographic };
const char* to_string(Projection projection);

// The camera. fov is the vertical field of view in degrees; aspect = width/height;
// right = normalize(forward x up); pixel (i, j), column i from the left and row j
// from the top, is sampled through (i + 0.5, j + 0.5). Orthographic, the view is
// 2 |center - eye| tan(fov / 2) high (OpenSCAD's rule: the perspective view's
// height at the centre).
struct Camera {
  glm::dvec3 eye{0, -10, 5};
  glm::dvec3 center{0, 0, 0};
  glm::dvec3 up{0, 0, 1};
  double fov_deg = 40;
  Projection projection = Projection::Perspective;
  int width = 512;
  int height = 512;
  SourceLoc loc;  // where the eye is given (or the camera() statement), for later errors
};

struct Light {
  glm::dvec3 position{0};
  glm::dvec3 color{1, 1, 1};
};

struct Scene {
  LargeVector<Primitive> primitives;  // in the order they appear in the file
  CsgNode root;                       // union of the top-level objects
  std::optional<Camera> camera;       // absent: frame the bounds (see default_camera)
  std::vector<Light> lights;          // empty: one white light at the eye
  glm::dvec3 background{0.05, 0.05, 0.08};
};

}  // namespace capsim
