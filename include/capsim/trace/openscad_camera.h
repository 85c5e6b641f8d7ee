#pragma once
// OpenSCAD 2021.01's command-line camera (--camera, --viewall, --autocenter,
// --projection) turned into capsim's Camera, so that the same options give the
// view `openscad -o out.png` gives (docs/openscad.md).

#include "capsim/scene/scene.h"

#include <string>
#include <vector>

namespace capsim {

// OpenSCAD's fixed field of view, vertical, in degrees (Camera.cc DEFAULT_FOV).
inline constexpr double kOpenScadFov = 22.5;

struct OpenScadCameraOptions {
  // --camera: empty (not given), 6 numbers (eye, centre: the vector form) or 7
  // (translation, rotation in degrees, distance: the gimbal form, as $vpt,
  // $vpr and $vpd).
  std::vector<double> camera;
  bool viewall = false;     // --viewall: move back until the box fits
  bool autocenter = false;  // --autocenter: with viewall, look at the box's centre
  Projection projection = Projection::Perspective;
};

// The camera OpenSCAD sets up for these options and a model whose preview
// frames `bounds` (openscad_preview_bounds), as openscad.cc, Camera.cc,
// export_png.cc and GLView.cc do it: without --camera, the gimbal rotation
// [55, 0, 25] with viewall and autocenter; the vector form becomes a gimbal
// camera without roll; viewall sets the distance to the box's reach from the
// centre over sin(fov / 2); autocenter acts only with viewall; up is the
// gimbal's, z turned with the view.
Camera openscad_camera(const OpenScadCameraOptions& options, const Aabb& bounds, int width, int height);

// The camera as OpenSCAD options that give its view:
// "--camera=EYE_X,EYE_Y,EYE_Z,CENTER_X,CENTER_Y,CENTER_Z --projection=P".
std::string camera_arguments(const Camera& camera);

// The perspective camera as a scene file's camera statement that gives its
// view exactly: "camera(eye = [...], center = [...], up = [...], fov = F);".
std::string camera_statement(const Camera& camera);

// Whether camera_arguments gives this camera exactly: OpenSCAD's field of view
// and its up vector (z turned into the view plane).
bool expressible_as_openscad(const Camera& camera);

}  // namespace capsim
