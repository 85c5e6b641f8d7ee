// `--aa` on the command line: depth 0 is the old output byte for byte; the
// simulated screen equals the antialiased render; the EXR's samples channel.

#include "support/cli_run.h"

#include <OpenImageIO/imageio.h>

#include <map>

using namespace capsim::testing;

namespace {

const std::string kBalls = scene_path("balls.csg");

// Every channel of an EXR, by name.
std::map<std::string, std::vector<float>> read_channels(const std::string& path) {
  auto in = OIIO::ImageInput::open(path);
  EXPECT_TRUE(in) << path;
  if (!in) return {};
  const OIIO::ImageSpec& spec = in->spec();
  std::vector<float> px(static_cast<std::size_t>(spec.width) * spec.height * spec.nchannels);
  EXPECT_TRUE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, px.data()));
  std::map<std::string, std::vector<float>> out;
  for (int c = 0; c < spec.nchannels; ++c) {
    std::vector<float>& v = out[spec.channel_name(c)];
    for (std::size_t k = c; k < px.size(); k += spec.nchannels) v.push_back(px[k]);
  }
  return out;
}

TEST(CliAntialias, DepthZeroIsTheDefaultByteForByte) {
  TempDir dir;
  for (const std::string ext : {"png", "exr"}) {
    for (const std::string cmd : {"render", "simulate"}) {
      const std::string base = cmd + " " + kBalls + " --size 40x30 -o ";
      ASSERT_EQ(run_capsim(base + (dir / ("a." + ext)), dir).status, 0);
      ASSERT_EQ(run_capsim(base + (dir / ("b." + ext)) + " --aa 0 --aa-threshold 0.7", dir).status, 0);
      EXPECT_EQ(read_file(dir / ("a." + ext)), read_file(dir / ("b." + ext))) << cmd << " " << ext;
    }
  }
  EXPECT_EQ(read_channels(dir / "b.exr").count("samples"), 0u);
}

TEST(CliAntialias, SimulatedScreenEqualsTheAntialiasedRenderInEveryMode) {
  TempDir dir;
  const std::string opts = " --size 48x40 --aa 2 --aa-threshold 0.2";
  ASSERT_EQ(run_capsim("render " + kBalls + " -o " + (dir / "r.png") + opts, dir).status, 0);
  ASSERT_EQ(run_capsim("render " + kBalls + " -o " + (dir / "r.exr") + opts, dir).status, 0);
  const std::string png = read_file(dir / "r.png");
  auto rendered = read_channels(dir / "r.exr");
  ASSERT_EQ(rendered.count("samples"), 1u);
  for (const std::string mode : {"dot", "line", "block"})
    for (const std::string threads : {"1", "2"}) {
      const std::string base = "simulate " + kBalls + opts + " --cells 4x4 --mode " + mode + " --threads " + threads;
      const RunResult r = run_capsim(base + " -o " + (dir / "s.png"), dir);
      ASSERT_EQ(r.status, 0) << r.err;
      EXPECT_EQ(read_file(dir / "s.png"), png) << mode << " threads " << threads;
      ASSERT_EQ(run_capsim(base + " -o " + (dir / "s.exr"), dir).status, 0);
      auto simulated = read_channels(dir / "s.exr");
      for (const std::string ch : {"R", "G", "B", "A", "Z", "id", "samples"})
        EXPECT_EQ(simulated[ch], rendered[ch]) << ch << " " << mode;
      EXPECT_EQ(simulated.count("cycles"), 1u);
    }
  // The report says what the exchange cost.
  ASSERT_EQ(run_capsim("simulate " + kBalls + opts + " --cells 4x4 -o " + (dir / "s.png"), dir).status, 0);
  const RunResult r = run_capsim("simulate " + kBalls + opts + " --cells 4x4 -o " + (dir / "s.png"), dir);
  EXPECT_NE(r.out.find("antialiasing: depth 2, threshold 0.2, links: mesh"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("link traffic: 32 messages"), std::string::npos) << r.out;
}

TEST(CliAntialias, SamplesChannelCountsThePrimaryRaysOfEachPixel) {
  TempDir dir;
  ASSERT_EQ(run_capsim("render " + kBalls + " -o " + (dir / "r.exr") + " --size 30x20 --aa 1", dir).status, 0);
  const auto ch = read_channels(dir / "r.exr");
  const std::vector<float>& samples = ch.at("samples");
  ASSERT_EQ(samples.size(), 600u);
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const int i = static_cast<int>(k % 30), j = static_cast<int>(k / 30);
    const int own = (1 + (i == 29)) * (1 + (j == 19));  // corners this pixel's owner traces
    EXPECT_TRUE(samples[k] == own || samples[k] == own + 5) << i << "," << j << ": " << samples[k];
  }
}

TEST(CliAntialias, RefusesDepthAndThresholdOutOfRange) {
  TempDir dir;
  for (const std::string bad : {"--aa 9", "--aa -1", "--aa-threshold 3.5", "--aa-threshold -0.1"}) {
    const RunResult r = run_capsim("render " + kBalls + " -o " + (dir / "x.png") + " " + bad, dir);
    EXPECT_NE(r.status, 0) << bad;
    EXPECT_NE(r.err.find(bad.substr(0, bad.find(' '))), std::string::npos) << bad << ": " << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "x.png")) << bad;
  }
}

}  // namespace
