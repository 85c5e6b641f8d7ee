// The meaning of each supported module call: argument checks and the maths of
// primitives, transforms, colours, materials, camera, lights and background.

#include "scene/reading/scene_modules.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "capsim/scene/scene_limits.h"
#include "scene/reading/scene_args.h"
#include "scene/reading/scene_colors.h"

namespace capsim::scene_file {
namespace {

// "[1, 0, 1]"
std::string vec_str(const glm::dvec3& v) { return fmt::format("[{}, {}, {}]", v.x, v.y, v.z); }

// A matrix from its rows as written (glm stores columns).
glm::dmat4 from_rows(const double r[4][4]) {
  glm::dmat4 m(1.0);
  for (int row = 0; row < 4; ++row) {
    for (int col = 0; col < 4; ++col) m[col][row] = r[row][col];
  }
  return m;
}

glm::dmat4 from_rows3(const glm::dvec3& r0, const glm::dvec3& r1, const glm::dvec3& r2) {
  const double rows[4][4] = {
      {r0.x, r0.y, r0.z, 0}, {r1.x, r1.y, r1.z, 0}, {r2.x, r2.y, r2.z, 0}, {0, 0, 0, 1}};
  return from_rows(rows);
}

// v / |v|, computed without overflow for huge components; empty for the zero vector.
std::optional<glm::dvec3> unit_vector(const glm::dvec3& v) {
  double largest = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
  if (!(largest > 0)) return std::nullopt;
  return glm::normalize(v / largest);
}

glm::dmat4 translation(const glm::dvec3& t) {
  glm::dmat4 m(1.0);
  m[3] = glm::dvec4(t, 1.0);
  return m;
}

glm::dmat4 scaling(const glm::dvec3& s) {
  glm::dmat4 m(1.0);
  m[0][0] = s.x;
  m[1][1] = s.y;
  m[2][2] = s.z;
  return m;
}

// Sine of an angle in degrees, exact where OpenSCAD's sin_degrees is exact
// (multiples of 30 with a rational sine), so rotate(90) is an exact quarter turn.
double sin_deg(double degrees) {
  double x = std::fmod(degrees, 360.0);
  if (x < 0) x += 360.0;
  if (x == 0 || x == 180) return 0;
  if (x == 90) return 1;
  if (x == 270) return -1;
  if (x == 30 || x == 150) return 0.5;
  if (x == 210 || x == 330) return -0.5;
  return std::sin(x * std::numbers::pi / 180.0);
}

double cos_deg(double degrees) {
  double x = std::fmod(degrees, 360.0);
  if (x < 0) x += 360.0;
  if (x == 90 || x == 270) return 0;
  if (x == 0) return 1;
  if (x == 180) return -1;
  if (x == 60 || x == 300) return 0.5;
  if (x == 120 || x == 240) return -0.5;
  return std::cos(x * std::numbers::pi / 180.0);
}

// Rotation by `degrees` about the unit vector `k` (right-handed).
glm::dmat4 axis_rotation(double degrees, const glm::dvec3& k) {
  double c = cos_deg(degrees), s = sin_deg(degrees), t = 1 - c;
  return from_rows3({c + k.x * k.x * t, k.x * k.y * t - k.z * s, k.x * k.z * t + k.y * s},
                    {k.y * k.x * t + k.z * s, c + k.y * k.y * t, k.y * k.z * t - k.x * s},
                    {k.z * k.x * t - k.y * s, k.z * k.y * t + k.x * s, c + k.z * k.z * t});
}

// rotate([x, y, z]): about x first, then y, then z (M = Rz * Ry * Rx).
glm::dmat4 euler_rotation(const glm::dvec3& a) {
  double cx = cos_deg(a.x), sx = sin_deg(a.x);
  double cy = cos_deg(a.y), sy = sin_deg(a.y);
  double cz = cos_deg(a.z), sz = sin_deg(a.z);
  glm::dmat4 rx = from_rows3({1, 0, 0}, {0, cx, -sx}, {0, sx, cx});
  glm::dmat4 ry = from_rows3({cy, 0, sy}, {0, 1, 0}, {-sy, 0, cy});
  glm::dmat4 rz = from_rows3({cz, -sz, 0}, {sz, cz, 0}, {0, 0, 1});
  return rz * ry * rx;
}

// Of two given arguments, the one written later (where a conflict is noticed).
std::string_view later(const Args& args, std::string_view a, std::string_view b) {
  Loc la = args.name_loc(a), lb = args.name_loc(b);
  return (la.line > lb.line || (la.line == lb.line && la.col > lb.col)) ? a : b;
}

double non_negative(const Args& args, std::string_view name, double fallback) {
  double v = args.number(name, fallback);
  if (args.has(name) && v < 0) {
    args.fail_value(name, fmt::format("{} must not be negative, got {}", args.what(name), v));
  }
  return v;
}

double positive(const Args& args, std::string_view name, double fallback) {
  double v = args.number(name, fallback);
  if (args.has(name) && !(v > 0)) {
    args.fail_value(name, fmt::format("{} must be positive, got {}", args.what(name), v));
  }
  return v;
}

// A length given by argument `name` (value `v`, positive or, for a cone's
// radius, zero): refused outside [kMinLength, kMaxLength]. The message calls
// it `label`, or "argument 'NAME' of MODULE" when that is empty.
void check_length(const Args& args, std::string_view name, double v, std::string_view label = {}) {
  static_assert(kMinLength == 1e-30 && kMaxLength == 1e30, "the messages name the range");
  if (v <= kMaxLength && (v == 0 || v >= kMinLength)) return;
  const std::string what = label.empty() ? args.what(name) : std::string(label);
  args.fail_value(name, v > kMaxLength ? fmt::format("{} must be at most 1e30, the largest length "
                                                     "capsim traces, got {}",
                                                     what, v)
                                       : fmt::format("{} must be at least 1e-30, the smallest "
                                                     "length capsim traces, got {}",
                                                     what, v));
}

// A point given by argument `name`: refused beyond kMaxLength in any coordinate.
glm::dvec3 point(const Args& args, std::string_view name, glm::dvec3 fallback, std::string_view what) {
  glm::dvec3 v = args.vec3(name, fallback);
  if (!(std::abs(v.x) <= kMaxLength && std::abs(v.y) <= kMaxLength && std::abs(v.z) <= kMaxLength)) {
    args.fail_value(name, fmt::format("{} must lie within 1e30 of the origin in every "
                                      "coordinate, the farthest capsim traces, got {}",
                                      what, vec_str(v)));
  }
  return v;
}

// A weight (material term or light intensity): at most kMaxWeight.
double weight(const Args& args, std::string_view name, double v) {
  static_assert(kMaxWeight == 1e6, "the message names the limit");
  if (args.has(name) && v > kMaxWeight) {
    args.fail_value(name, fmt::format("{} must be at most 1e6, got {}", args.what(name), v));
  }
  return v;
}

Primitive read_sphere(const Call& call) {
  Args args(call, {"r"}, {"d"});
  if (args.has("r") && args.has("d")) {
    throw SceneError(args.name_loc(later(args, "r", "d")),
                     "sphere takes either r or d, not both (OpenSCAD would ignore r)");
  }
  const std::string_view given = args.has("d") ? "d" : "r";
  const double value = positive(args, given, given == "d" ? 2 : 1);
  check_length(args, given, value);
  double r = given == "d" ? value / 2 : value;
  Primitive p;
  p.kind = PrimitiveKind::Sphere;
  p.to_world = scaling(glm::dvec3(r));
  return p;
}

Primitive read_cube(const Call& call) {
  Args args(call, {"size", "center"});
  glm::dvec3 size = args.number_or_vec3("size", glm::dvec3(1));
  if (!(size.x > 0 && size.y > 0 && size.z > 0)) {
    args.fail_value("size", fmt::format("cube size must be positive in every dimension, got {}",
                                        args.value("size").kind == Value::Kind::Number
                                            ? fmt::format("{}", size.x)
                                            : vec_str(size)));
  }
  for (int i = 0; i < 3; ++i) check_length(args, "size", size[i], "cube size");
  bool center = args.boolean("center", false);
  Primitive p;
  p.kind = PrimitiveKind::Box;
  p.to_world = translation(center ? -size / 2.0 : glm::dvec3(0)) * scaling(size);
  return p;
}

// One end's radius: OpenSCAD takes the first given of (d1, d, r1, r) for the
// bottom and (d2, d, r2, r) for the top.
struct RadiusSource {
  std::string_view name;
  double radius;
};

std::optional<RadiusSource> first_given(const Args& args,
                                        std::initializer_list<std::string_view> names) {
  for (std::string_view n : names) {
    if (args.has(n)) {
      double v = non_negative(args, n, 0);
      check_length(args, n, v);
      return RadiusSource{n, n[0] == 'd' ? v / 2 : v};
    }
  }
  return std::nullopt;
}

Primitive read_cylinder(const Call& call) {
  Args args(call, {"h", "r1", "r2", "center"}, {"r", "d", "d1", "d2"});
  double h = positive(args, "h", 1);
  check_length(args, "h", h);
  auto bottom = first_given(args, {"d1", "d", "r1", "r"});
  auto top = first_given(args, {"d2", "d", "r2", "r"});
  // A radius argument that neither end uses would be silently ignored: refuse it.
  for (std::string_view n : {"r", "d", "r1", "r2", "d1", "d2"}) {
    if (!args.has(n)) continue;
    if ((bottom && bottom->name == n) || (top && top->name == n)) continue;
    throw SceneError(
        args.name_loc(n),
        fmt::format("cylinder argument '{}' has no effect: {} (give one radius per "
                    "end: r, d, r1/r2 or d1/d2)",
                    n,
                    bottom && top && bottom->name != top->name
                        ? fmt::format("'{}' and '{}' override it", bottom->name, top->name)
                        : fmt::format("'{}' overrides it", bottom ? bottom->name : top->name)));
  }
  double r1 = bottom ? bottom->radius : 1;
  double r2 = top ? top->radius : 1;
  if (r1 == 0 && r2 == 0) {
    std::string_view culprit = top ? top->name : bottom->name;
    args.fail_value(culprit, "cylinder radii r1 and r2 are both zero (nothing to render)");
  }
  bool center = args.boolean("center", false);
  double rmax = std::max(r1, r2);
  Primitive p;
  p.kind = PrimitiveKind::Cone;
  p.cone_r1 = r1 / rmax;
  p.cone_r2 = r2 / rmax;
  p.to_world = translation({0, 0, center ? -h / 2 : 0}) * scaling({rmax, rmax, h});
  return p;
}

glm::dmat4 read_multmatrix(const Call& call) {
  Args args(call, {"m"});
  if (!args.has("m")) return glm::dmat4(1.0);
  const Value& m = args.value("m");
  constexpr std::string_view kShape = "a 4x4 matrix (4 rows of 4 numbers, row-major)";
  if (m.kind != Value::Kind::Vector || (m.items.size() != 3 && m.items.size() != 4)) {
    args.fail_type("m", kShape);
  }
  double rows[4][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
  for (size_t r = 0; r < m.items.size(); ++r) {
    const Value& row = m.items[r];
    if (row.kind != Value::Kind::Vector || row.items.size() != 4) {
      throw SceneError(row.loc, fmt::format("{} must be {}, but row {} is {}", args.what("m"),
                                            kShape, r + 1, describe(row)));
    }
    for (size_t c = 0; c < 4; ++c) {
      const Value& e = row.items[c];
      if (e.kind != Value::Kind::Number) {
        throw SceneError(e.loc, fmt::format("{} must be {}, but element [{}][{}] is {}",
                                            args.what("m"), kShape, r, c, describe(e)));
      }
      rows[r][c] = e.number;
    }
  }
  if (m.items.size() == 4 &&
      !(rows[3][0] == 0 && rows[3][1] == 0 && rows[3][2] == 0 && rows[3][3] == 1)) {
    throw SceneError(m.items[3].loc,
                     fmt::format("the last row of multmatrix must be [0, 0, 0, 1] (projective "
                                 "transforms are not supported), got [{}, {}, {}, {}]",
                                 rows[3][0], rows[3][1], rows[3][2], rows[3][3]));
  }
  glm::dmat4 matrix = from_rows(rows);
  if (is_singular(matrix)) {
    args.fail_value("m",
                    "singular matrix: multmatrix flattens space (its 3x3 part has a zero or "
                    "near-zero determinant)");
  }
  return matrix;
}

glm::dmat4 read_rotate(const Call& call) {
  Args args(call, {"a", "v"});
  if (!args.has("a")) {
    if (args.has("v")) {
      throw SceneError(args.name_loc("v"),
                       "rotate: 'v' is the axis of a scalar angle 'a', but no 'a' is given");
    }
    return glm::dmat4(1.0);
  }
  const Value& a = args.value("a");
  if (a.kind == Value::Kind::Vector) {
    glm::dvec3 angles = args.vec2_or_3("a", glm::dvec3(0), 0);
    if (args.has("v")) {
      throw SceneError(args.name_loc("v"),
                       "rotate: 'v' (an axis) is used only with a scalar angle 'a', not with a "
                       "vector of angles");
    }
    return euler_rotation(angles);
  }
  if (a.kind != Value::Kind::Number) args.fail_type("a", "a number or a vector of 2 or 3 numbers");
  glm::dvec3 axis = args.vec3("v", {0, 0, 1});
  std::optional<glm::dvec3> k = unit_vector(axis);
  if (!k)
    args.fail_value(
        "v", fmt::format("rotate: the axis v must be a non-zero vector, got {}", vec_str(axis)));
  return axis_rotation(a.number, *k);
}

glm::dmat4 read_scale(const Call& call) {
  Args args(call, {"v"});
  glm::dvec3 s = args.number_or_vec2_or_3("v", glm::dvec3(1), 1);
  if (s.x == 0 || s.y == 0 || s.z == 0) {
    args.fail_value("v",
                    fmt::format("singular transform: scale {} flattens space (every factor must "
                                "be non-zero)",
                                vec_str(s)));
  }
  glm::dmat4 m = scaling(s);
  if (is_singular(m)) {
    args.fail_value("v", fmt::format("singular transform: scale {} is too flat (factors differ by "
                                     "too many orders of magnitude)",
                                     vec_str(s)));
  }
  return m;
}

glm::dmat4 read_mirror(const Call& call) {
  Args args(call, {"v"});
  glm::dvec3 v = args.vec2_or_3("v", {1, 0, 0}, 0);
  std::optional<glm::dvec3> unit = unit_vector(v);
  if (!unit) {
    args.fail_value("v", fmt::format("singular transform: mirror {} has no plane normal (the "
                                     "vector must be non-zero)",
                                     vec_str(v)));
  }
  glm::dvec3 n = *unit;
  return from_rows3({1 - 2 * n.x * n.x, -2 * n.x * n.y, -2 * n.x * n.z},
                    {-2 * n.y * n.x, 1 - 2 * n.y * n.y, -2 * n.y * n.z},
                    {-2 * n.z * n.x, -2 * n.z * n.y, 1 - 2 * n.z * n.z});
}

// A colour component or alpha in [0, 1].
double unit_component(const Value& item, const std::string& what) {
  if (item.kind != Value::Kind::Number) {
    throw SceneError(item.loc,
                     fmt::format("{} must be a number in [0, 1], got {}", what, describe(item)));
  }
  if (!(item.number >= 0 && item.number <= 1)) {
    throw SceneError(item.loc, fmt::format("{} must be in [0, 1], got {}", what, item.number));
  }
  return item.number;
}

std::string unknown_color_message(std::string_view text) {
  std::string guess = closest_name(text, color_names());
  return fmt::format(
      "unknown colour {}{}; use a CSS/SVG colour name (e.g. \"red\", "
      "\"steelblue\"), \"#rgb\", \"#rgba\", \"#rrggbb\", \"#rrggbbaa\" or a vector "
      "[r, g, b] / [r, g, b, a] of numbers in [0, 1]",
      quoted(text), guess.empty() ? "" : fmt::format(" (did you mean \"{}\"?)", guess));
}

}  // namespace

bool is_singular(const glm::dmat4& m) {
  // The largest entry sets the scale; dividing by it first keeps huge and tiny
  // factors from overflowing or underflowing the determinant.
  double scale = 0;
  for (int c = 0; c < 3; ++c) {
    for (int r = 0; r < 3; ++r) scale = std::max(scale, std::abs(m[c][r]));
  }
  if (!(scale > 0) || !std::isfinite(scale)) return true;
  glm::dmat3 unit = glm::dmat3(m) / scale;
  return !(std::abs(glm::determinant(unit)) >= kSingularRelativeDet);
}

Primitive read_primitive(const Call& call) {
  Primitive p = call.name == "sphere" ? read_sphere(call)
                : call.name == "cube" ? read_cube(call)
                                      : read_cylinder(call);
  p.loc = call.loc;
  return p;
}

glm::dmat4 read_transform(const Call& call) {
  if (call.name == "translate") {
    Args args(call, {"v"});
    return translation(args.vec2_or_3("v", glm::dvec3(0), 0));
  }
  if (call.name == "rotate") return read_rotate(call);
  if (call.name == "scale") return read_scale(call);
  if (call.name == "mirror") return read_mirror(call);
  return read_multmatrix(call);
}

ColorSetting read_color(const Call& call) {
  Args args(call, {"c", "alpha"});
  ColorSetting out;
  if (args.has("c")) {
    const Value& c = args.value("c");
    if (c.kind == Value::Kind::String) {
      auto rgba = lookup_color(c.string);
      if (!rgba) args.fail_value("c", unknown_color_message(c.string));
      out.linear_rgb = srgb_to_linear(glm::dvec3(*rgba));
      out.alpha = rgba->w;
    } else if (c.kind == Value::Kind::Vector && (c.items.size() == 3 || c.items.size() == 4)) {
      bool unset = true;  // OpenSCAD's [-1, -1, -1, a]: alpha only, colour inherited
      for (int i = 0; i < 3; ++i) {
        unset = unset && c.items[i].kind == Value::Kind::Number && c.items[i].number == -1;
      }
      if (!unset) {
        glm::dvec3 rgb;
        for (int i = 0; i < 3; ++i) {
          rgb[i] = unit_component(c.items[i],
                                  fmt::format("colour component {} of {}", i + 1, args.what("c")));
        }
        out.linear_rgb = srgb_to_linear(rgb);
      }
      if (c.items.size() == 4)
        out.alpha = unit_component(c.items[3], fmt::format("alpha of {}", args.what("c")));
    } else {
      args.fail_type("c", "a colour name, a \"#hex\" code or a vector [r, g, b] / [r, g, b, a]");
    }
  }
  if (args.has("alpha")) out.alpha = unit_component(args.value("alpha"), args.what("alpha"));
  return out;
}

Material read_material(const Call& call, const Material& enclosing) {
  Args args(call, {"diffuse", "specular", "shininess", "reflect", "transmit", "ior", "ambient"});
  Material m = enclosing;
  m.diffuse = weight(args, "diffuse", non_negative(args, "diffuse", m.diffuse));
  m.specular = weight(args, "specular", non_negative(args, "specular", m.specular));
  m.shininess = non_negative(args, "shininess", m.shininess);
  m.reflect = non_negative(args, "reflect", m.reflect);
  m.transmit = non_negative(args, "transmit", m.transmit);
  m.ior = positive(args, "ior", m.ior);
  static_assert(kMinIor == 1e-3 && kMaxIor == 1e3, "the message names the range");
  if (args.has("ior") && !(m.ior >= kMinIor && m.ior <= kMaxIor)) {
    args.fail_value("ior", fmt::format("argument 'ior' of material must be between 0.001 and "
                                       "1000, got {}",
                                       m.ior));
  }
  m.ambient = weight(args, "ambient", non_negative(args, "ambient", m.ambient));
  if (m.reflect + m.transmit > 1) {
    std::string_view culprit = args.has("reflect") && args.has("transmit")
                                   ? later(args, "reflect", "transmit")
                               : args.has("reflect") ? "reflect"
                                                     : "transmit";
    args.fail_value(culprit,
                    fmt::format("material reflect + transmit must not exceed 1, got {} + {} "
                                "(counting values inherited from an enclosing material)",
                                m.reflect, m.transmit));
  }
  return m;
}

void read_pass_through(const Call& call) {
  if (call.name == "render") {
    Args args(call, {"convexity"});
    args.number("convexity", 1);
  } else {
    Args args(call, {});
  }
}

void read_hull_arguments(const Call& call) {
  Args args(call, {}, {"convexity"});
  args.number("convexity", 1);
}

Camera read_camera(const Call& call) {
  Args args(call, {"eye", "center", "up", "fov", "size"});
  Camera cam;
  cam.eye = point(args, "eye", cam.eye, "camera eye");
  cam.center = point(args, "center", cam.center, "camera center");
  cam.loc = args.has("eye") ? args.value("eye").loc : call.loc;
  cam.up = args.vec3("up", cam.up);
  cam.fov_deg = args.number("fov", cam.fov_deg);
  if (args.has("fov") && !(cam.fov_deg > 0 && cam.fov_deg < 180)) {
    args.fail_value("fov",
                    fmt::format("camera fov must be between 0 and 180 degrees (exclusive), got {}",
                                cam.fov_deg));
  }
  if (args.has("size")) {
    const Value& size = args.value("size");
    if (size.kind != Value::Kind::Vector || size.items.size() != 2) {
      args.fail_type("size", "a vector [width, height] of pixel counts");
    }
    int wh[2];
    for (int i = 0; i < 2; ++i) {
      const Value& e = size.items[i];
      if (e.kind != Value::Kind::Number || !(e.number >= 1 && e.number <= 16384) ||
          e.number != std::floor(e.number)) {
        throw SceneError(
            e.loc,
            fmt::format("camera size must be two whole numbers of pixels in "
                        "1..16384, got {}",
                        e.kind == Value::Kind::Number ? fmt::format("{}", e.number) : describe(e)));
      }
      wh[i] = static_cast<int>(e.number);
    }
    cam.width = wh[0];
    cam.height = wh[1];
  }
  glm::dvec3 view = cam.center - cam.eye;
  std::optional<glm::dvec3> forward = unit_vector(view);
  if (!forward) {
    std::string_view culprit = args.has("center") ? "center" : "eye";
    args.fail_value(
        culprit, fmt::format("camera eye and center must differ (both are {})", vec_str(cam.eye)));
  }
  std::optional<glm::dvec3> up = unit_vector(cam.up);
  if (!up || !(glm::length(glm::cross(*forward, *up)) > 1e-9)) {
    std::string message = fmt::format(
        "camera up {} must be non-zero and not parallel to the view "
        "direction {}",
        vec_str(cam.up), vec_str(view));
    // Point at the argument that made the pair degenerate; none given means the
    // defaults themselves are.
    for (std::string_view culprit : {"up", "center", "eye"}) {
      if (args.has(culprit)) args.fail_value(culprit, message);
    }
    throw SceneError(call.loc, message);
  }
  return cam;
}

Light read_light(const Call& call) {
  Args args(call, {"position", "color"});
  if (!args.has("position")) throw SceneError(call.loc, "light() needs position=[x, y, z]");
  Light light;
  light.position = point(args, "position", light.position, "light position");
  light.color = args.vec3("color", light.color);
  if (!(light.color.x >= 0 && light.color.y >= 0 && light.color.z >= 0)) {
    args.fail_value("color",
                    fmt::format("light color must not be negative, got {}", vec_str(light.color)));
  }
  if (!(light.color.x <= kMaxWeight && light.color.y <= kMaxWeight && light.color.z <= kMaxWeight)) {
    args.fail_value("color", fmt::format("light color must be at most 1e6 in every component, got {}",
                                         vec_str(light.color)));
  }
  return light;
}

glm::dvec3 read_background(const Call& call) {
  Args args(call, {"color"});
  if (!args.has("color")) throw SceneError(call.loc, "background() needs color=[r, g, b]");
  const Value& c = args.value("color");
  if (c.kind == Value::Kind::String) {
    auto rgba = lookup_color(c.string);
    if (!rgba) args.fail_value("color", unknown_color_message(c.string));
    if (rgba->w != 1)
      args.fail_value("color", "background color has no alpha; give an opaque colour");
    return srgb_to_linear(glm::dvec3(*rgba));
  }
  if (c.kind != Value::Kind::Vector || c.items.size() != 3) {
    args.fail_type("color", "a vector [r, g, b] of numbers in [0, 1] or a colour name");
  }
  glm::dvec3 rgb;
  for (int i = 0; i < 3; ++i) {
    rgb[i] = unit_component(c.items[i],
                            fmt::format("colour component {} of {}", i + 1, args.what("color")));
  }
  return srgb_to_linear(rgb);
}

}  // namespace capsim::scene_file
