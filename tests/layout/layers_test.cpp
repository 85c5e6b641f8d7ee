// The layers hold: every include of a project header names it by its path
// from a root ("machine/parts/cell.h", "capsim/trace/dda.h"), and no file includes a
// header of a layer above its own. The layers and what each links are the
// build's (CAPSIM_LAYERS, from capsim_layer() in CMakeLists.txt); a layer may
// include its own headers and those of the layers it links, directly or
// through others.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

struct Layer {
  std::string dir;                 // from the source root: "src/trace"
  std::vector<std::string> below;  // the layers it links directly
};

// "name=dir:below,below name=dir: ..." as the build writes it.
std::map<std::string, Layer> parse_layers(const std::string& text) {
  std::map<std::string, Layer> layers;
  std::istringstream words(text);
  for (std::string word; words >> word;) {
    const auto eq = word.find('='), colon = word.find(':');
    Layer l;
    l.dir = word.substr(eq + 1, colon - eq - 1);
    std::istringstream below(word.substr(colon + 1));
    for (std::string b; std::getline(below, b, ',');) l.below.push_back(b);
    layers[word.substr(0, eq)] = l;
  }
  return layers;
}

class LayerCheck {
 public:
  LayerCheck(fs::path root, std::map<std::string, Layer> layers) : root_(std::move(root)), layers_(std::move(layers)) {}

  // The layers a layer may include: itself and every layer below it.
  std::set<std::string> allowed(const std::string& layer) const {
    std::set<std::string> out{layer};
    for (const std::string& b : layers_.at(layer).below)
      for (const std::string& a : allowed(b)) out.insert(a);
    return out;
  }

  // The layer of a file, by its path from the root; nothing for files the
  // layers do not cover (shared test helpers, benchmarks).
  std::optional<std::string> layer_of(const std::string& path) const {
    const fs::path p(path);
    const std::string dir = p.parent_path().generic_string();
    for (const auto& [name, l] : layers_)
      if (dir == l.dir || dir.rfind(l.dir + "/", 0) == 0) return name;  // a layer's stage folders are its own
    // A public header sits in the folder of its layer: include/capsim/trace/dda.h.
    if (dir == "include/capsim" || dir.rfind("include/capsim/", 0) == 0) {
      const std::string sub = dir == "include/capsim" ? "" : dir.substr(15);
      if (layers_.count(sub)) return sub;
      return "?";  // a public header outside its layer's folder
    }
    // Tests sit in the layer they test; the oracle and the fuzz targets test the tracer.
    if (dir.rfind("tests/", 0) == 0) {
      const std::string sub = dir.substr(6);
      const std::string top = sub.substr(0, sub.find('/'));  // tests/cli/render: cli, in a stage folder
      if (layers_.count(top)) return top;
      if (sub == "oracle" || sub == "fuzz") return "trace";
    }
    return std::nullopt;
  }

  // Each problem with one file's text, as "path: message".
  std::vector<std::string> problems(const std::string& path, const std::string& text) const {
    std::vector<std::string> out;
    const std::optional<std::string> layer = layer_of(path);
    if (layer && *layer == "?") out.push_back(path + ": a public header outside include/capsim/LAYER/, LAYER a layer's name");
    static const std::regex include(R"re(^\s*#\s*include\s*"([^"]+)")re");
    std::istringstream lines(text);
    int n = 0;
    for (std::string line; std::getline(lines, line);) {
      ++n;
      std::smatch m;
      if (!std::regex_search(line, m, include)) continue;
      const std::string target = m[1];
      const std::string where = path + ":" + std::to_string(n) + ": \"" + target + "\"";
      const std::optional<std::string> file = resolve(target);
      if (!file) {
        out.push_back(where + " is not a header by its path from include/, src/, cap_sim/, tests/ or bench/");
        continue;
      }
      const std::optional<std::string> to = layer_of(*file);
      if (!to) {
        if (!layer || path.rfind("tests/", 0) == 0) continue;  // test helpers, from tests
        out.push_back(where + " is a test or benchmark helper, included by the product");
        continue;
      }
      if (!layer || *layer == "?" || *to == "?") continue;
      if (!allowed(*layer).count(*to))
        out.push_back(where + " runs back up: layer " + *layer + " includes layer " + *to);
    }
    return out;
  }

 private:
  // The file an include names, from the roots the build puts on the path
  // (bench/ for the benchmarks' code their tests share).
  std::optional<std::string> resolve(const std::string& target) const {
    for (const char* r : {"include", "src", "cap_sim", "tests", "bench"}) {
      const fs::path p = fs::path(r) / target;
      if (fs::is_regular_file(root_ / p)) return p.generic_string();
    }
    return std::nullopt;
  }

  fs::path root_;
  std::map<std::string, Layer> layers_;
};

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

LayerCheck project_check() { return LayerCheck(CAPSIM_SOURCE_DIR, parse_layers(CAPSIM_LAYERS)); }

TEST(Layers, TheBuildDeclaresEveryLayer) {
  const std::map<std::string, Layer> layers = parse_layers(CAPSIM_LAYERS);
  for (const char* name : {"system", "image", "scene", "trace", "kernel", "machine", "report", "paper", "cli"})
    EXPECT_TRUE(layers.count(name)) << name;
  // The order of docs/architecture.md: the machine needs the tracer, never
  // the reverse; the report needs the machine; the paper the report.
  const LayerCheck check = project_check();
  EXPECT_TRUE(check.allowed("machine").count("trace"));
  EXPECT_FALSE(check.allowed("trace").count("kernel"));
  EXPECT_FALSE(check.allowed("kernel").count("trace"));
  EXPECT_FALSE(check.allowed("machine").count("report"));
  EXPECT_TRUE(check.allowed("paper").count("report"));
  EXPECT_FALSE(check.allowed("scene").count("trace"));
}

TEST(Layers, NoIncludeRunsBackUp) {
  const fs::path root = CAPSIM_SOURCE_DIR;
  const LayerCheck check = project_check();
  int files = 0;
  std::vector<std::string> problems;
  for (const char* top : {"include", "src", "cap_sim", "tests", "bench"}) {
    for (const auto& e : fs::recursive_directory_iterator(root / top)) {
      const std::string ext = e.path().extension().string();
      if (!e.is_regular_file() || (ext != ".h" && ext != ".cpp")) continue;
      ++files;
      const std::string path = fs::relative(e.path(), root).generic_string();
      for (std::string& p : check.problems(path, read(e.path()))) problems.push_back(std::move(p));
    }
  }
  EXPECT_GT(files, 150);
  for (const std::string& p : problems) ADD_FAILURE() << p;
}

// The check itself finds what it is for, on made-up files of the real tree.
TEST(Layers, TheCheckFindsAnIncludeThatRunsBackUp) {
  const LayerCheck check = project_check();
  EXPECT_TRUE(check.problems("cap_sim/machine/parts/cell.cpp", "#include \"kernel/cycles.h\"\n").empty());
  EXPECT_TRUE(check.problems("cap_sim/machine/parts/cell.cpp", "#include \"capsim/trace/tracer.h\"\n").empty());
  const std::vector<std::string> up = check.problems("cap_sim/machine/parts/cell.cpp", "\n#include \"report/sim_report.h\"\n");
  ASSERT_EQ(up.size(), 1u);
  EXPECT_EQ(up[0], "cap_sim/machine/parts/cell.cpp:2: \"report/sim_report.h\" runs back up: layer machine includes layer report");
  EXPECT_EQ(check.problems("src/trace/dda.cpp", "#include \"machine/parts/cell.h\"\n").size(), 1u);
  EXPECT_EQ(check.problems("src/scene/reading/parser.cpp", "#include \"capsim/trace/tracer.h\"\n").size(), 1u);
  // A public header outside the folder of a layer belongs to none.
  EXPECT_EQ(check.problems("include/capsim/ray.h", "").size(), 1u);
  EXPECT_EQ(check.problems("include/capsim/shading/ray.h", "").size(), 1u);
  EXPECT_TRUE(check.problems("include/capsim/trace/ray.h", "#include \"capsim/scene/bounds.h\"\n").empty());
  EXPECT_EQ(check.problems("tests/machine/x_test.cpp", "#include \"report/heatmap.h\"\n").size(), 1u);
  // A header named by its bare file name does not build, and is refused here.
  EXPECT_EQ(check.problems("cap_sim/machine/parts/cell.cpp", "#include \"cycles.h\"\n").size(), 1u);
  // Test helpers belong to the tests only.
  EXPECT_TRUE(check.problems("tests/machine/x_test.cpp", "#include \"support/cli_run.h\"\n").empty());
  // A test in a stage folder of its layer's tests is held to that layer.
  EXPECT_TRUE(check.problems("tests/cli/render/x_test.cpp", "#include \"paper/experiment_run.h\"\n").empty());
  EXPECT_EQ(check.problems("tests/trace/stage/x_test.cpp", "#include \"machine/parts/cell.h\"\n").size(), 1u);
  EXPECT_EQ(check.problems("src/cli/main.cpp", "#include \"support/cli_run.h\"\n").size(), 1u);
}

}  // namespace
