// `capsim render` end to end: outputs, option errors, and the invariances the
// tracer promises (grid size and thread count never change the image).

#include "support/cli_run.h"

#include <OpenImageIO/imageio.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <regex>

using namespace capsim::testing;

namespace {

std::vector<std::string> shipped_scenes() {
  std::vector<std::string> out;
  for (const auto& e : std::filesystem::directory_iterator(std::string(CAPSIM_SOURCE_DIR) + "/scenes"))
    if (e.path().extension() == ".csg") out.push_back(e.path().string());
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

TEST(CliRender, WritesAPng) {
  TempDir dir;
  const RunResult r = run_capsim("render " + scene_path("balls.csg") + " -o " + (dir / "b.png") + " --size 64x48", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  auto in = OIIO::ImageInput::open(dir / "b.png");
  ASSERT_TRUE(in);
  EXPECT_EQ(in->spec().width, 64);
  EXPECT_EQ(in->spec().height, 48);
  EXPECT_EQ(in->spec().nchannels, 3);
  // Nothing but the image is left in the directory.
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 1);
}

TEST(CliRender, ExrCarriesDepthAndPrimitiveIds) {
  TempDir dir;
  const RunResult r = run_capsim("render " + scene_path("balls.csg") + " -o " + (dir / "b.exr") + " --size 96x96", dir);
  ASSERT_EQ(r.status, 0) << r.err;
  auto in = OIIO::ImageInput::open(dir / "b.exr");
  ASSERT_TRUE(in);
  const OIIO::ImageSpec& spec = in->spec();
  std::vector<std::string> names(spec.channelnames.begin(), spec.channelnames.end());
  for (const char* want : {"R", "G", "B", "A", "Z", "id"})
    ASSERT_NE(std::find(names.begin(), names.end(), want), names.end()) << want;
  std::vector<float> px(static_cast<std::size_t>(spec.width) * spec.height * spec.nchannels);
  ASSERT_TRUE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, px.data()));
  const auto ch = [&](const char* n) { return std::find(names.begin(), names.end(), n) - names.begin(); };
  int hits = 0, misses = 0;
  for (int k = 0; k < spec.width * spec.height; ++k) {
    const float* p = &px[static_cast<std::size_t>(k) * spec.nchannels];
    const float id = p[ch("id")], z = p[ch("Z")], a = p[ch("A")];
    if (id < 0) {
      ++misses;
      EXPECT_EQ(id, -1.0f);
      EXPECT_TRUE(std::isinf(z));
      EXPECT_EQ(a, 0.0f);
    } else {
      ++hits;
      EXPECT_EQ(id, std::floor(id));
      EXPECT_LT(id, 125.0f);
      EXPECT_GT(z, 0.0f);
      EXPECT_TRUE(std::isfinite(z));
      EXPECT_EQ(a, 1.0f);
    }
  }
  EXPECT_GT(hits, 0);
  EXPECT_GT(misses, 0);
}

TEST(CliRender, GridSizeNeverChangesThePixels) {
  TempDir dir;
  for (const std::string& scene : shipped_scenes()) {
    std::string reference;
    for (const char* grid : {"1", "auto", "2", "7", "33"}) {
      const std::string out = dir / (std::string("g") + grid + ".exr");
      const RunResult r = run_capsim("render " + scene + " -o " + out + " --grid " + grid, dir);
      ASSERT_EQ(r.status, 0) << scene << " --grid " << grid << ": " << r.err;
      const std::string bytes = read_file(out);
      if (reference.empty()) {
        reference = bytes;
      } else {
        EXPECT_TRUE(bytes == reference) << scene << " differs at --grid " << grid;
      }
    }
  }
}

TEST(CliRender, ThreadCountNeverChangesTheBytes) {
  TempDir dir;
  const std::string scene = scene_path("balls.csg");
  ASSERT_EQ(run_capsim("render " + scene + " -o " + (dir / "t1.png") + " --threads 1", dir).status, 0);
  ASSERT_EQ(run_capsim("render " + scene + " -o " + (dir / "t2.png") + " --threads 2", dir).status, 0);
  ASSERT_EQ(run_capsim("render " + scene + " -o " + (dir / "t0.png"), dir).status, 0);
  EXPECT_TRUE(read_file(dir / "t1.png") == read_file(dir / "t2.png"));
  EXPECT_TRUE(read_file(dir / "t1.png") == read_file(dir / "t0.png"));
}

// --timings: one line on stderr at the end, each stage once in the order it
// ran (a sequence's frames add to their stages), and the same image.
TEST(CliRender, TimingsNameEachStageOnceAndChangeNoByte) {
  TempDir dir;
  const std::string scene = scene_path("balls.csg");
  const std::regex line(
      R"(timings \(wall clock\): read \d+\.\d ms, prepare \d+\.\d ms, trace \d+\.\d ms, write \d+\.\d ms; )"
      R"(\d+\.\d ms in all\n)");
  for (const char* extra : {"", " --quiet", " --frames 2", " --aa 1 --quiet"}) {
    const std::string ext = std::string(extra).find("--aa") != std::string::npos ? ".exr" : ".png";
    const RunResult plain =
        run_capsim("render " + scene + " -o " + (dir / ("a" + ext)) + " --size 24x16" + extra, dir);
    ASSERT_EQ(plain.status, 0) << plain.err;
    EXPECT_EQ(plain.err.find("timings"), std::string::npos) << extra;
    const RunResult timed =
        run_capsim("render " + scene + " -o " + (dir / ("b" + ext)) + " --size 24x16 --timings" + extra, dir);
    ASSERT_EQ(timed.status, 0) << timed.err;
    std::smatch m;
    ASSERT_TRUE(std::regex_search(timed.err, m, line)) << extra << ": " << timed.err;
    EXPECT_EQ(m.suffix().str(), "") << "the line ends the run's output";
    if (std::string(extra) == " --frames 2") {
      EXPECT_TRUE(read_file(dir / "a00000.png") == read_file(dir / "b00000.png"));
      EXPECT_TRUE(read_file(dir / "a00001.png") == read_file(dir / "b00001.png"));
    } else {
      EXPECT_TRUE(read_file(dir / ("a" + ext)) == read_file(dir / ("b" + ext))) << extra;
    }
  }
}

// A render to PNG on one thread runs without TBB's scheduler, and without
// its per-thread storage, which has TBB open its allocator library on first
// use (docs/performance.md): the loader's log never has it open that
// library. On two threads it does, so the check sees it. (The log names the
// library, not always its caller: a sanitizer's build opens it through its
// own dlopen.)
TEST(CliRender, OnOneThreadTbbNeverOpensItsAllocator) {
  TempDir dir;
  const std::string scene = scene_path("balls.csg");
  const std::regex opened_by_tbb(R"(file=\S*libtbbmalloc\.so\S* \[\d+\];\s+dynamically loaded by)");
  for (const char* extra : {"", " --aa 1"}) {
    const RunResult one = run_capsim("render " + scene + " -o " + (dir / "one.png") + " --size 24x16 --threads 1" + extra,
                                     dir, "export LD_DEBUG=files;");
    ASSERT_EQ(one.status, 0) << one.err;
    EXPECT_FALSE(std::regex_search(one.err, opened_by_tbb)) << extra << ": " << one.err;
    const RunResult two = run_capsim("render " + scene + " -o " + (dir / "two.png") + " --size 24x16 --threads 2" + extra,
                                     dir, "export LD_DEBUG=files;");
    ASSERT_EQ(two.status, 0) << two.err;
    EXPECT_TRUE(std::regex_search(two.err, opened_by_tbb)) << extra << ": " << two.err;
    EXPECT_TRUE(read_file(dir / "one.png") == read_file(dir / "two.png")) << extra;
  }
}

TEST(CliRender, PrimaryOnlyDropsShadowsAndSecondaryRays) {
  TempDir dir;
  const std::string scene = scene_path("balls.csg");
  ASSERT_EQ(run_capsim("render " + scene + " -o " + (dir / "full.png") + " --size 64x64", dir).status, 0);
  ASSERT_EQ(run_capsim("render " + scene + " -o " + (dir / "primary.png") + " --size 64x64 --primary-only", dir).status, 0);
  EXPECT_FALSE(read_file(dir / "full.png") == read_file(dir / "primary.png"));
}

struct BadOption {
  std::string args;
  std::string message;
};
void PrintTo(const BadOption& b, std::ostream* os) { *os << b.args; }

class CliRenderRefuses : public ::testing::TestWithParam<BadOption> {};

TEST_P(CliRenderRefuses, WithAMessageAndNoOutput) {
  TempDir dir;
  const std::string out = dir / "out.png";
  const RunResult r = run_capsim("render " + scene_path("balls.csg") + " -o " + out + " " + GetParam().args, dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find(GetParam().message), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out));
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 0);
}

INSTANTIATE_TEST_SUITE_P(
    Options, CliRenderRefuses,
    ::testing::Values(BadOption{"--size 0x10", "--size 0x10 is out of range"},
                      BadOption{"--size 100", "--size 100 is not WxH"},
                      BadOption{"--size 20000x10", "out of range"},
                      BadOption{"--grid 0", "--grid 0 is out of range"},
                      BadOption{"--grid 300", "--grid 300 is out of range"},
                      BadOption{"--grid many", "--grid many is not a whole number"},
                      BadOption{"--threads -1", "--threads"}),
    [](const ::testing::TestParamInfo<BadOption>& info) {
      std::string name;
      for (char c : info.param.args) name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
      return name;
    });

TEST(CliRender, RefusesAnUnknownImageType) {
  TempDir dir;
  const RunResult r = run_capsim("render " + scene_path("balls.csg") + " -o " + (dir / "out.jpg"), dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("has an unsupported image type (accepted: a path ending in .png or .exr)"), std::string::npos)
      << r.err;
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 0);
}

TEST(CliRender, SceneErrorsPointIntoTheFileAndWriteNothing) {
  TempDir dir;
  {
    std::ofstream f(dir / "bad.csg");
    f << "sphere(r=1);\ncube(size=[1, 2]);\n";
  }
  const std::string out = dir / "out.png";
  const RunResult r = run_capsim("render " + (dir / "bad.csg") + " -o " + out, dir);
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err.rfind(dir / "bad.csg:2:", 0), 0u) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out));
}

// A scene whose every object is dropped is refused, saying why, as
// docs/scene-format.md states; nothing is written.
TEST(CliRender, AllObjectsDroppedIsRefused) {
  TempDir dir;
  std::ofstream(dir / "dropped.csg") << "camera(eye = [5, 5, 5]);\n*sphere(1);\n%cube(2);\n";
  const RunResult r = run_capsim("render " + (dir / "dropped.csg") + " -o " + (dir / "out.png"), dir);
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err.rfind(dir / "dropped.csg:", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("the scene has no objects to draw: every object in it is dropped by '%' or '*'"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "out.png"));
}

TEST(CliRender, HelpDescribesEveryOption) {
  TempDir dir;
  const RunResult r = run_capsim("render --help", dir);
  EXPECT_EQ(r.status, 0);
  for (const char* opt : {"--output", "--size", "--grid", "--threads", "--primary-only", "--timings"})
    EXPECT_NE(r.out.find(opt), std::string::npos) << opt;
}
