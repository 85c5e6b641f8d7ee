#include "capsim/trace/openscad_camera.h"

#include <fmt/format.h>

#include <cmath>

namespace capsim {

namespace {

constexpr double kPi = 3.14159265358979323846;
double radians(double degrees) { return degrees * kPi / 180; }
double degrees(double radians) { return radians * 180 / kPi; }

// OpenSCAD's gimbal camera (Camera.h): the model is translated by `trans`,
// then turned by rot.x about x, rot.y about y and rot.z about z (glRotated,
// applied to the model in the reverse order), and looked at from (0, -distance,
// 0) towards the origin with z up (GLView::setupCamera).
struct Gimbal {
  glm::dvec3 trans{0};
  glm::dvec3 rot{0};
  double distance = 140;  // Camera.cc DEFAULT_DISTANCE
};

glm::dmat3 rotation(double deg, int axis) {
  const double c = std::cos(radians(deg)), s = std::sin(radians(deg));
  glm::dmat3 m(1.0);  // column-major: m[column][row]
  const int a = (axis + 1) % 3, b = (axis + 2) % 3;
  m[a][a] = c;
  m[a][b] = s;
  m[b][a] = -s;
  m[b][b] = c;
  return m;
}

double wrap(double angle) { return std::fmod(360.0 + angle, 360.0); }

// Camera::setVpr: $vpr in the user's units to the gimbal's angles.
glm::dvec3 from_vpr(const glm::dvec3& vpr) { return {wrap(90 - vpr.x), wrap(-vpr.y), wrap(-vpr.z)}; }

// Camera::setup with 6 numbers.
Gimbal from_vector(const glm::dvec3& eye, const glm::dvec3& center) {
  Gimbal g;
  g.trans = -center;
  const glm::dvec3 dir = center - eye;
  g.distance = glm::length(dir);
  g.rot.z = (dir.y == 0 && dir.x == 0) ? (dir.z < 0 ? 0 : 180) : -degrees(std::atan2(dir.y, dir.x)) + 90;
  g.rot.y = 0;
  g.rot.x = -degrees(std::atan2(dir.z, std::hypot(dir.x, dir.y)));
  return g;
}

}  // namespace

Camera openscad_camera(const OpenScadCameraOptions& o, const Aabb& bounds, int width, int height) {
  Gimbal g;
  bool viewall = o.viewall, autocenter = o.autocenter;
  if (o.camera.size() == 7) {
    g.trans = -glm::dvec3(o.camera[0], o.camera[1], o.camera[2]);
    g.rot = from_vpr({o.camera[3], o.camera[4], o.camera[5]});
    g.distance = o.camera[6];
  } else if (o.camera.size() == 6) {
    g = from_vector({o.camera[0], o.camera[1], o.camera[2]}, {o.camera[3], o.camera[4], o.camera[5]});
  } else {
    // Camera::resetView, and openscad.cc's get_camera without --camera.
    g.rot = from_vpr({55, 0, 25});
    viewall = autocenter = true;
  }
  if (viewall && !bounds.empty()) {
    // Camera::viewAll.
    if (autocenter) g.trans = -bounds.center();
    const double radius = glm::length(bounds.center() + g.trans) + 0.5 * glm::length(bounds.extent());
    g.distance = radius / std::sin(radians(kOpenScadFov / 2));
  }
  // World to view is R (p + trans) with R = Rx Ry Rz; the view's eye, forward
  // and up are (0, -distance, 0), y and z, so in the world they are turned by
  // R's transpose.
  const glm::dmat3 r = rotation(g.rot.x, 0) * rotation(g.rot.y, 1) * rotation(g.rot.z, 2);
  const glm::dmat3 to_world = glm::transpose(r);
  Camera c;
  c.center = -g.trans;
  c.eye = c.center + to_world * glm::dvec3(0, -g.distance, 0);
  c.up = to_world * glm::dvec3(0, 0, 1);
  c.fov_deg = kOpenScadFov;
  c.projection = o.projection;
  c.width = width;
  c.height = height;
  return c;
}

bool expressible_as_openscad(const Camera& c) {
  if (c.fov_deg != kOpenScadFov) return false;
  const glm::dvec3 forward = glm::normalize(c.center - c.eye);
  const glm::dvec3 right = glm::cross(forward, c.up);
  const glm::dvec3 z{0, 0, 1};
  // The gimbal's up is z made perpendicular to the view: right is horizontal
  // and the image's up points upwards (for a view straight up or down, any).
  if (std::abs(glm::dot(forward, z)) > 1 - 1e-12) return true;
  return std::abs(right.z) <= 1e-9 * glm::length(right) && glm::dot(glm::cross(right, forward), z) > 0;
}

// "{}" prints a double's shortest form that reads back as the same double, so
// that a pasted camera gives the very same rays.
std::string camera_arguments(const Camera& c) {
  return fmt::format("--camera={},{},{},{},{},{} --projection={}", c.eye.x, c.eye.y,
                     c.eye.z, c.center.x, c.center.y, c.center.z, to_string(c.projection));
}

std::string camera_statement(const Camera& c) {
  return fmt::format("camera(eye = [{}, {}, {}], center = [{}, {}, {}], up = [{}, {}, {}], fov = {});", c.eye.x,
                     c.eye.y, c.eye.z, c.center.x, c.center.y, c.center.z, c.up.x, c.up.y, c.up.z, c.fov_deg);
}

}  // namespace capsim
