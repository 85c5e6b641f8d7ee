// capsim's view against OpenSCAD's own: OpenSCAD's example models exported to
// CSG, drawn by `openscad -o ref.png` (under xvfb-run) and by `capsim render`
// with the same view options; the pixels each covers must agree (intersection
// over union of the object masks at least 0.95). Skipped when openscad,
// xvfb-run or OpenSCAD's examples are not installed.

#include "support/cli_run.h"

#include <OpenImageIO/imageio.h>
#include <fmt/core.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

using namespace capsim::testing;

namespace {

constexpr int kWidth = 320, kHeight = 240;

// The directory a program on PATH is in, if it is there.
std::optional<std::filesystem::path> on_path(const std::string& program) {
  const char* path = std::getenv("PATH");
  if (!path) return std::nullopt;
  const std::string dirs = path;
  std::size_t start = 0;
  for (;;) {
    const std::size_t colon = dirs.find(':', start);
    const std::filesystem::path dir = dirs.substr(start, colon - start);
    std::error_code ec;
    if (!dir.empty() && std::filesystem::is_regular_file(dir / program, ec)) return dir;
    if (colon == std::string::npos) return std::nullopt;
    start = colon + 1;
  }
}

struct Model {
  std::string name;  // the example's path under OpenSCAD's examples directory, without .scad
  double scale;      // a length about half the model's reach, for the hand-set cameras
};

// Example models capsim draws (spheres, cubes, cylinders) whose CSG holds
// differences and intersections.
const std::vector<Model> kModels = {
    {"Basics/CSG", 90}, {"Basics/CSG-modules", 100}, {"Old/example001", 105}, {"Old/example002", 115},
    {"Old/example003", 85}};

// The views compared, as OpenSCAD's options; the two --camera forms are set
// from the model's scale, off its centre and from other sides than the default.
std::vector<std::pair<std::string, std::string>> views(const Model& m) {
  const double s = m.scale;
  return {{"viewall, perspective", "--viewall --autocenter --projection=p"},
          {"viewall, ortho", "--viewall --autocenter --projection=o"},
          {"vector camera, perspective",
           fmt::format("--camera={:g},{:g},{:g},{:g},0,0 --projection=perspective", -0.9 * s, -1.6 * s, s, 0.05 * s)},
          {"gimbal camera, ortho", fmt::format("--camera=0,{:g},0,70,0,300,{:g} --projection=ortho", 0.05 * s, 2.2 * s)}};
}

// The pixels of an image of kWidth x kHeight that `covered` marks.
std::vector<bool> mask(const std::string& file, const std::string& what) {
  auto in = OIIO::ImageInput::open(file);
  if (!in) {
    ADD_FAILURE() << what << ": cannot read " << file;
    return {};
  }
  const OIIO::ImageSpec& spec = in->spec();
  EXPECT_EQ(spec.width, kWidth) << what;
  EXPECT_EQ(spec.height, kHeight) << what;
  std::vector<bool> covered(static_cast<std::size_t>(kWidth) * kHeight);
  if (spec.width != kWidth || spec.height != kHeight) return covered;
  const int id = spec.channelindex("id");
  if (id >= 0) {
    // capsim's EXR: the id of the primitive each pixel's primary ray hit, -1 for none.
    std::vector<float> ids(covered.size());
    EXPECT_TRUE(in->read_image(0, 0, id, id + 1, OIIO::TypeDesc::FLOAT, ids.data())) << what;
    for (std::size_t k = 0; k < ids.size(); ++k) covered[k] = ids[k] >= 0;
  } else {
    // OpenSCAD's PNG: anything but the Cornfield scheme's background, RGB 255, 255, 229.
    std::vector<unsigned char> rgb(covered.size() * 3);
    EXPECT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, rgb.data())) << what;
    for (std::size_t k = 0; k < covered.size(); ++k)
      covered[k] = rgb[3 * k] != 255 || rgb[3 * k + 1] != 255 || rgb[3 * k + 2] != 229;
  }
  return covered;
}

double intersection_over_union(const std::vector<bool>& a, const std::vector<bool>& b) {
  std::size_t both = 0, either = 0;
  for (std::size_t k = 0; k < a.size() && k < b.size(); ++k) {
    both += a[k] && b[k];
    either += a[k] || b[k];
  }
  return either == 0 ? 0 : static_cast<double>(both) / static_cast<double>(either);
}

TEST(OpenScadView, ObjectMasksMatchOpenScads) {
  const std::optional<std::filesystem::path> openscad = on_path("openscad");
  const std::optional<std::filesystem::path> xvfb = on_path("xvfb-run");
  if (!openscad || !xvfb) GTEST_SKIP() << "needs openscad and xvfb-run on PATH (Debian: openscad, xvfb)";
  const std::filesystem::path examples = *openscad / ".." / "share" / "openscad" / "examples";
  if (!std::filesystem::is_directory(examples)) GTEST_SKIP() << "OpenSCAD's examples are not at " << examples;
  TempDir dir;

  // Every OpenSCAD run in one script under one X server: its start is most of
  // an openscad run's time.
  std::ofstream script(dir / "openscad.sh");
  script << "set -e\n";
  for (std::size_t m = 0; m < kModels.size(); ++m) {
    const std::string scad = (examples / (kModels[m].name + ".scad")).string();
    script << fmt::format("openscad -o '{}' '{}' 2>/dev/null\n", dir / fmt::format("m{}.csg", m), scad);
    const auto model_views = views(kModels[m]);
    for (std::size_t v = 0; v < model_views.size(); ++v)
      script << fmt::format("openscad -o '{}' --imgsize={},{} {} '{}' 2>/dev/null\n",
                            dir / fmt::format("m{}v{}.png", m, v), kWidth, kHeight, model_views[v].second, scad);
  }
  script.close();
  const std::string run = fmt::format("xvfb-run -a sh '{}' >'{}' 2>&1", dir / "openscad.sh", dir / "openscad.log");
  ASSERT_EQ(std::system(run.c_str()), 0) << read_file(dir / "openscad.log");

  std::string table;
  for (std::size_t m = 0; m < kModels.size(); ++m) {
    const auto model_views = views(kModels[m]);
    for (std::size_t v = 0; v < model_views.size(); ++v) {
      const std::string what = kModels[m].name + ", " + model_views[v].first;
      const std::string exr = dir / fmt::format("m{}v{}.exr", m, v);
      const RunResult r = run_capsim(fmt::format("render '{}' -o '{}' --imgsize={},{} {}",
                                                 dir / fmt::format("m{}.csg", m), exr, kWidth, kHeight,
                                                 model_views[v].second),
                                     dir);
      ASSERT_EQ(r.status, 0) << what << ": " << r.err;
      const double iou = intersection_over_union(mask(dir / fmt::format("m{}v{}.png", m, v), what), mask(exr, what));
      table += fmt::format("{:<20} {:<28} {:.3f}\n", kModels[m].name, model_views[v].first, iou);
      EXPECT_GE(iou, 0.95) << what;
    }
  }
  std::cout << table;
}

}  // namespace
