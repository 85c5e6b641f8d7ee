// A library capsim opens on first use (capsim/system/shared_library.h) that cannot
// be loaded: the import or text() that needs it is refused at its place in the
// scene, naming the library, the loader's reason and what needs it (exit 1,
// nothing written), while a scene that needs none of them still renders. The
// library is hidden from one run only, by bind-mounting an empty file over it
// in a mount namespace of the run's own (unshare -m); where that cannot be
// done (not root, no unshare), the tests are skipped saying why.

#include "support/cli_run.h"

#include <dlfcn.h>
#include <link.h>

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

using namespace capsim::testing;

namespace {

// The file the loader opens for `soname`, or "" when it cannot.
std::string library_file(const char* soname) {
  void* handle = dlopen(soname, RTLD_LAZY | RTLD_LOCAL);
  if (!handle) return "";
  link_map* map = nullptr;
  const bool found = dlinfo(handle, RTLD_DI_LINKMAP, &map) == 0 && map && map->l_name;
  const std::string name = found ? std::filesystem::canonical(map->l_name).string() : "";
  dlclose(handle);
  return name;
}

class CliMissingLibrary : public ::testing::Test {
 protected:
  void SetUp() override {
    std::ofstream(dir_ / "empty.so");
    std::ofstream(dir_ / "ball.csg") << "sphere(r = 1);\n";
    if (std::system(("unshare -m sh -c 'mount --bind " + (dir_ / "empty.so") + " " + (dir_ / "ball.csg") +
                     "' >/dev/null 2>&1")
                        .c_str()) != 0)
      GTEST_SKIP() << "cannot bind-mount in a mount namespace of its own (unshare -m needs root)";
  }

  // Renders `scene` (text written to the test's directory) with the library of
  // `soname` hidden.
  RunResult render_without(const char* soname, const std::string& scene) {
    const std::string library = library_file(soname);
    EXPECT_FALSE(library.empty()) << soname;
    std::ofstream(dir_ / "scene.csg") << scene;
    const std::string hide =
        "unshare -m sh -c 'mount --bind " + (dir_ / "empty.so") + " " + library + " && exec \"$0\" \"$@\"'";
    return run_capsim("render " + (dir_ / "scene.csg") + " -o " + (dir_ / "out.png") + " --size 16x16 --quiet",
                      dir_, "", hide);
  }

  // A refusal at `where` of scene.csg holding `fragment`, in one line, nothing written.
  ::testing::AssertionResult refused(const RunResult& r, const std::string& where, const std::string& fragment) {
    const std::string prefix = (dir_ / "scene.csg") + ":" + where + ": ";
    if (r.status != 1 || r.err.rfind(prefix, 0) != 0 || r.err.find(fragment) == std::string::npos ||
        r.err.find('\n') != r.err.size() - 1 || std::filesystem::exists(dir_ / "out.png"))
      return ::testing::AssertionFailure() << "status " << r.status << ", stderr: " << r.err;
    return ::testing::AssertionSuccess();
  }

  TempDir dir_;
};

std::string data(const std::string& file) { return std::string(CAPSIM_SOURCE_DIR) + "/tests/data/" + file; }

}  // namespace

TEST_F(CliMissingLibrary, A3mfImportWithoutLib3mfIsRefusedAtTheImport) {
  const RunResult r = render_without(CAPSIM_LIB3MF_SONAME, "import(\"" + data("mesh_import/notch.3mf") + "\");\n");
  EXPECT_TRUE(refused(r, "1:8", std::string(CAPSIM_LIB3MF_SONAME) + " cannot be loaded ("));
  EXPECT_NE(r.err.find("); it is needed for 3MF import\n"), std::string::npos) << r.err;
}

TEST_F(CliMissingLibrary, AmfAndSvgImportsWithoutLibxml2AreRefusedAtTheImport) {
  const std::string needed = std::string(CAPSIM_LIBXML2_SONAME) + " cannot be loaded (";
  const RunResult amf = render_without(CAPSIM_LIBXML2_SONAME, "import(\"" + data("mesh_import/notch.amf") + "\");\n");
  EXPECT_TRUE(refused(amf, "1:8", needed));
  EXPECT_NE(amf.err.find("); it is needed for AMF and SVG import\n"), std::string::npos) << amf.err;
  const RunResult svg = render_without(
      CAPSIM_LIBXML2_SONAME, "linear_extrude(1) import(\"" + data("svg_import/page.svg") + "\");\n");
  EXPECT_TRUE(refused(svg, "1:26", needed));  // at its file argument, as other SVG refusals
}

TEST_F(CliMissingLibrary, TextWithoutItsFontLibrariesIsRefusedAtTheText) {
  for (const char* soname : {CAPSIM_FREETYPE_SONAME, CAPSIM_HARFBUZZ_SONAME, CAPSIM_FONTCONFIG_SONAME}) {
    const RunResult r = render_without(soname, "linear_extrude(1) text(\"capsim\");\n");
    EXPECT_TRUE(refused(r, "1:19", "); it is needed for text()")) << soname;
  }
}

TEST_F(CliMissingLibrary, ASceneThatNeedsNoneOfThemRendersWithoutThem) {
  for (const char* soname : {CAPSIM_LIB3MF_SONAME, CAPSIM_LIBXML2_SONAME, CAPSIM_FREETYPE_SONAME}) {
    const RunResult r = render_without(soname, "sphere(r = 1);\n");
    EXPECT_EQ(r.status, 0) << soname << ": " << r.err;
    EXPECT_TRUE(std::filesystem::exists(dir_ / "out.png")) << soname;
    std::filesystem::remove(dir_ / "out.png");
  }
}
