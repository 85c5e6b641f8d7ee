#include "pov/pov_scene.h"

#include "capsim/trace/csg_bounds.h"

#include <fmt/core.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace capsim::pov {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Shortest text that reads back as the same double.
std::string vec(const glm::dvec3& v) { return fmt::format("<{}, {}, {}>", v.x, v.y, v.z); }

// POV-Ray's `matrix` is the affine map's 4x3 in row-vector form: the point
// (x, y, z) goes to (x, y, z, 1) * M, so its row i is glm's column i.
std::string matrix(const Primitive& p) {
  const glm::dmat4& m = p.to_world;
  if (m[0][3] != 0 || m[1][3] != 0 || m[2][3] != 0 || m[3][3] != 1)
    throw Unsupported(fmt::format("{}: a projective transform (POV-Ray's matrix is affine)", p.loc.str()));
  std::string s = "matrix <";
  for (int col = 0; col < 4; ++col)
    for (int row = 0; row < 3; ++row) s += fmt::format("{}{}", col + row == 0 ? "" : ", ", m[col][row]);
  return s + ">";
}

// capsim's local colour is ambient + diffuse + Phong highlight, weighted by
// 1 - reflect - transmit once the surface also reflects or refracts
// (Tracer::shade). POV-Ray weights ambient and diffuse by 1 - transmit itself
// and the highlight not at all, so the finish carries the rest of the weight.
// A `transmit` pigment passes the refracted colour untinted, as capsim does.
std::string texture(const Primitive& p) {
  const Material& m = p.material;
  const double local = (m.reflect > 0 || m.transmit > 0) ? 1.0 - m.reflect - m.transmit : 1.0;
  const double lit = m.transmit < 1 ? local / (1.0 - m.transmit) : 0.0;
  std::string finish = fmt::format("ambient {} diffuse {}", m.ambient * lit, m.diffuse * lit);
  if (m.specular != 0) finish += fmt::format(" phong {} phong_size {}", m.specular * local, m.shininess);
  if (m.reflect != 0) finish += fmt::format(" reflection {{ {} }}", m.reflect);
  std::string s = fmt::format("texture {{ pigment {{ rgb {}", vec(p.color));
  if (m.transmit != 0) s += fmt::format(" transmit {}", m.transmit);
  s += fmt::format(" }} finish {{ {} }} }}", finish);
  if (m.transmit != 0) s += fmt::format(" interior {{ ior {} }}", m.ior);
  return s;
}

std::string mesh2(const TriangleMesh& mesh) {
  std::string s = fmt::format("mesh2 {{\n  vertex_vectors {{ {}", mesh.vertices.size());
  for (const glm::dvec3& v : mesh.vertices) s += ", " + vec(v);
  s += fmt::format(" }}\n  face_indices {{ {}", mesh.triangles.size());
  for (const auto& t : mesh.triangles) s += fmt::format(", <{}, {}, {}>", t[0], t[1], t[2]);
  // A ray along it tells inside from outside, so the mesh can take part in CSG.
  return s + " }\n  inside_vector <0.31, 0.57, 0.76>\n ";
}

// The canonical primitive (scene.h) in POV-Ray's terms, placed and, unless it
// only casts shadows, textured (a shadow caster keeps POV-Ray's opaque default).
std::string primitive(const Primitive& p, bool textured) {
  std::string shape;
  switch (p.kind) {
    case PrimitiveKind::Sphere: shape = "sphere { <0, 0, 0>, 1"; break;
    case PrimitiveKind::Box: shape = "box { <0, 0, 0>, <1, 1, 1>"; break;
    case PrimitiveKind::Cone:
      shape = p.cone_r1 == p.cone_r2
                  ? fmt::format("cylinder {{ <0, 0, 0>, <0, 0, 1>, {}", p.cone_r1)
                  : fmt::format("cone {{ <0, 0, 0>, {}, <0, 0, 1>, {}", p.cone_r1, p.cone_r2);
      break;
    case PrimitiveKind::Mesh: shape = mesh2(*p.mesh); break;
    case PrimitiveKind::Revolution:
      throw Unsupported(fmt::format(
          "{}: rotate_extrude's revolved profile has no POV-Ray equivalent here", p.loc.str()));
  }
  return fmt::format("{} {} {}}}", shape, matrix(p), textured ? texture(p) + " " : std::string());
}

bool boxes_meet(const Aabb& a, const Aabb& b) {
  return !a.empty() && !b.empty() && a.lo.x <= b.hi.x && b.lo.x <= a.hi.x && a.lo.y <= b.hi.y &&
         b.lo.y <= a.hi.y && a.lo.z <= b.hi.z && b.lo.z <= a.hi.z;
}

// Every line of `text` `indent` further in.
std::string indented(const std::string& text, const std::string& indent) {
  std::string s = indent;
  for (const char c : text) s += c == '\n' ? "\n" + indent : std::string(1, c);
  return s;
}

// `object` with modifiers before its closing brace, which a group has on a
// line of its own and a primitive after a space.
std::string with(std::string object, const std::string& modifiers) {
  const std::size_t brace = object.size() - 1;
  object.insert(brace, object[brace - 1] == '\n' ? "  " + modifiers + "\n" : modifiers + " ");
  return object;
}

class Writer {
 public:
  // A shadow-casting writer leaves out textures (scene_objects' casters).
  Writer(const PreparedScene& scene, bool casting) : scene_(scene), casting_(casting) {}

  // The scene's CSG tree as top-level POV-Ray objects. capsim's
  // shadow rays stop at any surface, transparent or not (Tracer::occluded),
  // where POV-Ray's pass through transparent ones: each top-level object
  // that lets light through is written twice, seen but casting no shadow,
  // and unseen (no_image, no_reflection) but casting an opaque one.
  std::string scene_objects() const {
    const Writer casters(scene_, true);
    std::string s;
    for (const Operands& object : union_objects(scene_.scene.root, "")) {
      if (!object.clear) {
        s += object.text + "\n";
        continue;
      }
      std::vector<std::string> caster;
      for (const CsgNode* n : object.nodes) caster.push_back(*casters.node(*n, "  "));
      s += with(object.text, "no_shadow") + "\n";
      s += with(*group("union", caster, ""), "no_image no_reflection") + "\n";
    }
    return s;
  }

 private:
  // The node as one POV-Ray object, or nothing for the empty set.
  std::optional<std::string> node(const CsgNode& n, const std::string& indent) const {
    if (n.is_leaf) return indented(primitive(scene_.scene.primitives[n.primitive], !casting_), indent);
    if (n.op == CsgOp::Union) {
      std::vector<std::string> parts;
      for (Operands& o : union_objects(n, indent + "  ")) parts.push_back(std::move(o.text));
      return group("union", parts, indent);
    }
    std::vector<std::string> parts;
    for (std::size_t k = 0; k < n.children.size(); ++k) {
      std::optional<std::string> child = node(n.children[k], indent + "  ");
      if (!child) {
        // An empty operand empties an intersection, and a difference whose
        // first operand it is; from a difference's other operands it removes nothing.
        if (n.op == CsgOp::Intersection || k == 0) return std::nullopt;
        continue;
      }
      parts.push_back(std::move(*child));
    }
    return group(n.op == CsgOp::Intersection ? "intersection" : "difference", parts, indent);
  }

  // One object of a union: its text, the operands it writes, and whether
  // light gets through any of them.
  struct Operands {
    std::string text;
    std::vector<const CsgNode*> nodes;
    bool clear = false;
  };

  // A union shows only its outer boundary in capsim: POV-Ray's `merge`. Its
  // plain `union` also shows the surfaces inside, which look the same unless
  // light gets through to them. So nested unions are taken as one, and only
  // the operands whose boxes overlap, directly or through others, in a group
  // that lets light through are merged: merge costs POV-Ray a test of every
  // operand at every hit, which a union of separate objects would not pay.
  // The union's objects, each at `indent`; none for the empty set.
  std::vector<Operands> union_objects(const CsgNode& n, const std::string& indent) const {
    std::vector<const CsgNode*> all;
    flatten_union(n, all);
    std::vector<Operands> parts;
    std::vector<Aabb> boxes;
    for (const CsgNode* c : all)
      if (std::optional<std::string> text = node(*c, indent)) {
        parts.push_back({std::move(*text), {c}, transmits(*c)});
        boxes.push_back(csg_result_bounds(*c, scene_.prims));
      }
    // Groups of overlapping operands (union-find over the pairs whose boxes meet).
    std::vector<std::size_t> root(parts.size());
    for (std::size_t a = 0; a < root.size(); ++a) root[a] = a;
    const auto find = [&](std::size_t a) {
      while (root[a] != a) a = root[a] = root[root[a]];
      return a;
    };
    for (std::size_t a = 0; a < parts.size(); ++a)
      for (std::size_t b = a + 1; b < parts.size(); ++b)
        if (boxes_meet(boxes[a], boxes[b])) root[find(a)] = find(b);
    std::vector<std::vector<std::size_t>> groups(parts.size());
    std::vector<bool> group_clear(parts.size(), false);
    for (std::size_t a = 0; a < parts.size(); ++a) {
      groups[find(a)].push_back(a);
      if (parts[a].clear) group_clear[find(a)] = true;
    }
    std::vector<Operands> objects;
    for (std::size_t g = 0; g < groups.size(); ++g) {
      if (groups[g].size() > 1 && group_clear[g]) {
        Operands merged{{}, {}, true};
        std::vector<std::string> texts;
        for (const std::size_t a : groups[g]) {
          texts.push_back(indented(parts[a].text, "  "));
          merged.nodes.push_back(parts[a].nodes[0]);
        }
        merged.text = *group("merge", texts, indent);
        objects.push_back(std::move(merged));
      } else {
        for (const std::size_t a : groups[g]) objects.push_back(std::move(parts[a]));
      }
    }
    return objects;
  }

  // A union's operands, with those of the unions among them in their place.
  static void flatten_union(const CsgNode& n, std::vector<const CsgNode*>& out) {
    for (const CsgNode& c : n.children) {
      if (!c.is_leaf && c.op == CsgOp::Union) flatten_union(c, out);
      else out.push_back(&c);
    }
  }

  // `keyword { parts }`; one part is itself, none the empty set.
  static std::optional<std::string> group(const char* keyword, const std::vector<std::string>& parts,
                                          const std::string& indent) {
    if (parts.empty()) return std::nullopt;
    if (parts.size() == 1) return indent + parts[0].substr(parts[0].find_first_not_of(' '));
    std::string s = indent + keyword + " {\n";
    for (const std::string& p : parts) s += p + "\n";
    return s + indent + "}";
  }

  bool transmits(const CsgNode& n) const {
    if (n.is_leaf) return scene_.scene.primitives[n.primitive].material.transmit != 0;
    for (const CsgNode& c : n.children)
      if (transmits(c)) return true;
    return false;
  }

  const PreparedScene& scene_;
  bool casting_;
};

// capsim's image right is forward x up (a right-handed frame); POV-Ray's
// camera takes sky x forward unless `right` points the other way, so it is
// given as -x. `angle` is POV-Ray's horizontal field; capsim's fov is vertical.
std::string camera(const Camera& c) {
  // Only OpenSCAD's --projection option makes one, which the bench never gives.
  if (c.projection != Projection::Perspective)
    throw Unsupported("an orthographic camera (OpenSCAD's --projection=ortho) is not written for POV-Ray");
  const double aspect = static_cast<double>(c.width) / c.height;
  const double angle = 2.0 * std::atan(aspect * std::tan(0.5 * c.fov_deg * kPi / 180.0)) * 180.0 / kPi;
  return fmt::format("camera {{\n  perspective\n  location {}\n  right -x * {}\n  up y\n  angle {}\n  sky {}\n"
                     "  look_at {}\n}}\n",
                     vec(c.eye), aspect, angle, vec(c.up), vec(c.center));
}

}  // namespace

std::string pov_scene(const PreparedScene& scene, int max_depth) {
  std::string s = "#version 3.7;\n";
  // Colours are linear, as capsim's; the PNG is encoded to sRGB on output
  // (File_Gamma). Rays are followed to the same depth whatever their weight
  // (adc_bailout 0), as capsim follows them.
  s += fmt::format("global_settings {{ assumed_gamma 1.0 max_trace_level {} adc_bailout 0 ambient_light rgb 1 }}\n",
                   max_depth + 1);
  s += camera(scene.camera);
  s += fmt::format("background {{ rgb {} }}\n", vec(scene.scene.background));
  for (const Light& l : scene.lights)
    s += fmt::format("light_source {{ {} color rgb {} }}\n", vec(l.position), vec(l.color));
  return s + Writer(scene, false).scene_objects();
}

}  // namespace capsim::pov
