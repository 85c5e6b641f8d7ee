// The provenance's forms (report/provenance.h): its JSON, the command line a
// shell reads back word for word, the options' line and the text block; and
// what the HTML page calls a run (run_name).

#include "report/html_report.h"
#include "report/provenance.h"

#include <gtest/gtest.h>

namespace capsim::sim {
namespace {

Provenance example() {
  Provenance p;
  p.argv = {"capsim", "simulate", "a b.csg", "-o", "it's.png", "--cells", "2x2"};
  p.version = "9.8.7";
  p.scenes = {{"a b.csg", std::string(64, 'a')}};
  p.profile = "my.json";
  p.profile_name = "mine";
  p.profile_sha256 = std::string(64, 'f');
  p.options = {{"cells", "2x2"}, {"scenes", {"a b.csg"}}, {"html", nullptr}, {"aa", 0}, {"primary_only", true}};
  return p;
}

TEST(Provenance, JsonHoldsEveryPart) {
  const nlohmann::json j = provenance_json(example());
  EXPECT_EQ(j["capsim_version"], "9.8.7");
  EXPECT_EQ(j["argv"].size(), 7u);
  EXPECT_EQ(j["argv"][4], "it's.png");
  EXPECT_EQ(j["scenes"], nlohmann::json::parse(R"([{"path": "a b.csg", "sha256": ")" + std::string(64, 'a') +
                                                  R"("}])"));
  EXPECT_EQ(j["profile"]["given"], "my.json");
  EXPECT_EQ(j["profile"]["name"], "mine");
  EXPECT_EQ(j["profile"]["sha256"], std::string(64, 'f'));
  EXPECT_EQ(j["options"], example().options);
}

TEST(Provenance, CommandLineQuotesWhatAShellWouldSplitOrExpand) {
  EXPECT_EQ(shell_line(example().argv), "capsim simulate 'a b.csg' -o 'it'\\''s.png' --cells 2x2");
  EXPECT_EQ(shell_line({"capsim", "", "$HOME", "*.csg", "a/b-c_d.e=f:g,h+i@j%k"}),
            "capsim '' '$HOME' '*.csg' a/b-c_d.e=f:g,h+i@j%k");
}

TEST(Provenance, OptionsLineGivesEveryOptionInKeyOrder) {
  EXPECT_EQ(options_line(example().options), "aa 0, cells 2x2, html none, primary_only true, scenes a b.csg");
}

TEST(Provenance, TextBlockGivesVersionCommandInputsAndOptions) {
  EXPECT_EQ(provenance_text(example()),
            "\nprovenance: capsim 9.8.7\n"
            "  command  capsim simulate 'a b.csg' -o 'it'\\''s.png' --cells 2x2\n"
            "  scene    a b.csg sha256 " + std::string(64, 'a') + "\n"
            "  profile  my.json (name mine) sha256 " + std::string(64, 'f') + "\n"
            "  options  aa 0, cells 2x2, html none, primary_only true, scenes a b.csg\n");
}

TEST(RunName, NamesTheFileTheAnimationOrTheSequence) {
  EXPECT_EQ(run_name({"scenes/balls.csg"}, 1), "balls.csg");
  EXPECT_EQ(run_name({"anim/model.scad"}, 3), "model.scad (3 frames)");
  EXPECT_EQ(run_name({"d/f00000.csg", "d/f00001.csg"}, 2), "f00000.csg and f00001.csg (2 frames)");
  EXPECT_EQ(run_name({"d/f00000.csg", "d/f00001.csg", "d/f00002.csg", "d/f00003.csg"}, 4),
            "f00000.csg ... f00003.csg (4 frames)");
}

}  // namespace
}  // namespace capsim::sim
