// A run whose image buffers would not fit in memory is refused before any work,
// with the estimate and the limit; --max-memory sets the limit.

#include "support/cli_run.h"

using namespace capsim::testing;

namespace {

const std::string kBalls = scene_path("balls.csg");

struct MemoryCase {
  std::string name;
  std::string args;     // OUT stands for the output's path without its extension
  std::string message;  // after "capsim "
};
void PrintTo(const MemoryCase& c, std::ostream* os) { *os << c.args; }

class CliMemoryRefused : public ::testing::TestWithParam<MemoryCase> {};

TEST_P(CliMemoryRefused, WithTheEstimateAndTheLimitAndNothingWritten) {
  TempDir dir;
  std::string args = GetParam().args;
  args.replace(args.find("OUT"), 3, dir / "out");
  const RunResult r = run_capsim(args, dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "capsim " + GetParam().message + "\n");
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 0);
}

// 16384 x 16384 pixels: simulate to EXR holds 61 bytes a pixel; simulate to
// PNG 9 and a little while it writes (the 8-bit screen, filtered rows and the
// compressed data's bound), as render to PNG does; render to EXR 48 (the
// framebuffer and its planar copy).
INSTANTIATE_TEST_SUITE_P(
    Commands, CliMemoryRefused,
    ::testing::Values(
        MemoryCase{"SimulatePng", "simulate " + kBalls + " -o OUT.png --size 16384x16384 --max-memory 2G",
                   "simulate: a 16384x16384 image needs about 2.3 GiB of image buffers, more than the 2.0 GiB set "
                   "by --max-memory; give a smaller --size or a larger --max-memory"},
        MemoryCase{"SimulateExr", "simulate " + kBalls + " -o OUT.exr --size 16384x16384 --max-memory 15G",
                   "simulate: a 16384x16384 image needs about 15.2 GiB of image buffers, more than the 15.0 GiB set "
                   "by --max-memory; give a smaller --size or a larger --max-memory"},
        MemoryCase{"RenderExr", "render " + kBalls + " -o OUT.exr --size 16384x16384 --max-memory 11g",
                   "render: a 16384x16384 image needs about 12.0 GiB of image buffers, more than the 11.0 GiB set "
                   "by --max-memory; give a smaller --size or a larger --max-memory"},
        MemoryCase{"RenderPng", "render " + kBalls + " -o OUT.png --size 16384x16384 --max-memory 1024M",
                   "render: a 16384x16384 image needs about 1.5 GiB of image buffers, more than the 1.0 GiB set "
                   "by --max-memory; give a smaller --size or a larger --max-memory"}),
    [](const ::testing::TestParamInfo<MemoryCase>& info) { return info.param.name; });

TEST(CliMemory, TheSizeOfTheSceneCameraIsCheckedToo) {
  TempDir dir;
  std::ofstream(dir / "big.csg") << "camera(eye = [10, -10, 10], center = [0, 0, 0], size = [16384, 16384]);\n"
                                    "sphere(1);\n";
  const RunResult r = run_capsim("render " + (dir / "big.csg") + " -o " + (dir / "out.exr") + " --max-memory 1G", dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "capsim render: a 16384x16384 image needs about 12.0 GiB of image buffers, more than the 1.0 GiB "
                   "set by --max-memory; give a smaller --size or a larger --max-memory\n");
  EXPECT_FALSE(std::filesystem::exists(dir / "out.exr"));
}

TEST(CliMemory, ARunThatFitsTheLimitExactlyGoesAhead) {
  // 64 x 64 pixels to EXR at 61 bytes: 249856 bytes.
  TempDir dir;
  const std::string base = "simulate " + kBalls + " -o " + (dir / "s.exr") + " --size 64x64 --max-memory ";
  RunResult r = run_capsim(base + "249856", dir);
  EXPECT_EQ(r.status, 0) << r.err;
  r = run_capsim(base + "249855", dir);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "capsim simulate: a 64x64 image needs about 244.0 KiB of image buffers, more than the 244.0 KiB set "
                   "by --max-memory; give a smaller --size or a larger --max-memory\n");
}

TEST(CliMemory, MaxMemoryTakesASizeWithAnOptionalUnit) {
  TempDir dir;
  const std::string base = "render " + kBalls + " -o " + (dir / "b.png") + " --size 8x8 --max-memory ";
  const std::string range = "(accepted: a whole number of bytes, or of K, M, G or T (powers of 1024), e.g. 8G)";
  for (const std::string ok : {"1G", "1g", "300k", "2T", "1000000"}) EXPECT_EQ(run_capsim(base + ok, dir).status, 0) << ok;
  const std::pair<std::string, std::string> bad[] = {{"8GB", "is not a size"}, {"G", "is not a size"},
                                                     {"-1", "is not a size"}, {"0", "is out of range"},
                                                     {"99999999999T", "is out of range"}};
  for (const auto& [value, problem] : bad) {
    const RunResult r = run_capsim(base + value, dir);
    EXPECT_EQ(r.status, 2) << value;
    EXPECT_EQ(r.err, "capsim render: --max-memory " + value + " " + problem + " " + range + "\n");
  }
}

}  // namespace
