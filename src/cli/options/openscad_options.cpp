#include "cli/options/openscad_options.h"

#include "capsim/trace/prepared_scene.h"
#include "cli/options/cli_options.h"
#include "cli/options/cli_usage.h"

#include <fmt/core.h>

#include <charconv>
#include <cmath>
#include <string>
#include <vector>

namespace capsim::cli {

namespace {

std::vector<std::string> split_commas(const std::string& text) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = text.find(',', start);
    parts.push_back(text.substr(start, comma - start));
    if (comma == std::string::npos) return parts;
    start = comma + 1;
  }
}

// The numbers of a --camera value, or nothing if one is not a finite decimal.
std::optional<std::vector<double>> camera_numbers(const std::string& text) {
  std::vector<double> numbers;
  for (const std::string& part : split_commas(text)) {
    double v = 0;
    const auto [end, ec] = std::from_chars(part.data(), part.data() + part.size(), v);
    if (part.empty() || end != part.data() + part.size() || ec != std::errc() || !std::isfinite(v))
      return std::nullopt;
    numbers.push_back(v);
  }
  return numbers;
}

std::string camera_problem(const std::string& text) {
  const std::optional<std::vector<double>> n = camera_numbers(text);
  if (!n) return "is not a list of numbers";
  if (n->size() == 6) {
    if ((*n)[0] == (*n)[3] && (*n)[1] == (*n)[4] && (*n)[2] == (*n)[5]) return "has the eye at the centre";
    return "";
  }
  if (n->size() == 7) return (*n)[6] > 0 ? "" : "has a distance that is not above 0";
  return "does not have 6 or 7 numbers";
}

std::optional<Projection> parse_projection(const std::string& text) {
  if (text == "p" || text == "perspective") return Projection::Perspective;
  if (text == "o" || text == "ortho" || text == "orthogonal") return Projection::Orthographic;
  return std::nullopt;
}

std::string imgsize_problem(const std::string& text) {
  const std::vector<std::string> sides = split_commas(text);
  if (sides.size() != 2) return "is not W,H";
  const CLI::Validator side = whole_number(1, kMaxImageSide);
  for (std::string s : sides)
    if (!side(s).empty()) return side(s) == "is out of range" ? "is out of range" : "is not W,H";
  return "";
}

}  // namespace

void add_openscad_options(CLI::App& cmd, OpenScadOptions& o) {
  add_option(cmd, "--camera", o.camera,
             "OpenSCAD's camera: =EYE_X,EYE_Y,EYE_Z,CENTER_X,CENTER_Y,CENTER_Z or =TRANS_X,TRANS_Y,TRANS_Z,ROT_X,"
             "ROT_Y,ROT_Z,DIST ($vpt, $vpr, $vpd); with it or any other OpenSCAD view option the view is "
             "OpenSCAD's, over the scene's camera statement (docs/openscad.md)",
             CLI::Validator([](std::string& value) { return camera_problem(value); },
                            "6 numbers (eye, centre) or 7 (translation, rotation in degrees, distance above 0), "
                            "separated by commas"));
  accepts(cmd.add_flag("--viewall", o.viewall, "As OpenSCAD's --viewall: move the camera back until the model fits"),
          flag_values());
  accepts(cmd.add_flag("--autocenter", o.autocenter,
                       "As OpenSCAD's --autocenter: with --viewall, look at the model's centre"),
          flag_values());
  add_option(cmd, "--projection", o.projection, "As OpenSCAD's --projection: perspective (p) or ortho (o)",
             satisfying([](const std::string& v) { return parse_projection(v).has_value(); },
                        "is not a projection")
                 .description("perspective, p, ortho, o or orthogonal"));
  add_option(cmd, "--imgsize", o.imgsize,
             fmt::format("As OpenSCAD's --imgsize: image size W,H, each 1 to {} (the same as --size WxH)",
                         kMaxImageSide),
             CLI::Validator([](std::string& value) { return imgsize_problem(value); },
                            fmt::format("W,H, W and H whole numbers from 1 to {}, e.g. 640,480", kMaxImageSide)));
}

std::optional<OpenScadCameraOptions> check_openscad_camera(const OpenScadOptions& o) {
  if (o.camera.text.empty() && o.projection.text.empty() && !o.viewall && !o.autocenter) return std::nullopt;
  OpenScadCameraOptions c;
  if (!o.camera.text.empty()) c.camera = *camera_numbers(checked(o.camera));
  c.viewall = o.viewall;
  c.autocenter = o.autocenter;
  if (!o.projection.text.empty()) c.projection = *parse_projection(checked(o.projection));
  return c;
}

std::optional<std::pair<int, int>> check_imgsize(const OpenScadOptions& o) {
  if (o.imgsize.text.empty()) return std::nullopt;
  const std::vector<std::string> sides = split_commas(checked(o.imgsize));
  return std::pair{whole_value(sides[0]), whole_value(sides[1])};
}

}  // namespace capsim::cli
