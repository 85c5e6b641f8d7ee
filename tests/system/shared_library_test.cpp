// SharedLibrary: a library opened on first use gives its functions by name, and
// one that cannot be opened, or lacks the function, is refused with a message
// naming it and what needs it. capsim itself starts without the libraries it
// opens this way.

#include "capsim/system/shared_library.h"

#include "support/cli_run.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

using capsim::SharedLibrary;
using capsim::testing::run_capsim;
using capsim::testing::TempDir;

namespace {

std::string refusal(const SharedLibrary& lib, const char* function) {
  try {
    lib.function<void (*)()>(function);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(SharedLibrary, GivesAFunctionOfTheLibraryByName) {
  const SharedLibrary libm("libm.so.6", "the test");
  const auto floor = libm.function<double (*)(double)>("floor");
  EXPECT_EQ(floor(2.5), 2.0);
  EXPECT_EQ(libm.function<double (*)(double)>("floor"), floor);
}

TEST(SharedLibrary, RefusesALibraryThatCannotBeOpenedAtEachCall) {
  const SharedLibrary missing("libcapsim-no-such-library.so.0", "reading widgets");
  const std::string first = refusal(missing, "widget_open");
  EXPECT_NE(first.find("libcapsim-no-such-library.so.0 cannot be loaded ("), std::string::npos) << first;
  EXPECT_NE(first.find("); it is needed for reading widgets"), std::string::npos) << first;
  EXPECT_EQ(refusal(missing, "widget_open"), first);
}

// lgamma leaves the sign of the gamma function in libm's variable signgam.
TEST(SharedLibrary, GivesAVariableOfTheLibraryByName) {
  const SharedLibrary libm("libm.so.6", "the test");
  const auto lgamma = libm.function<double (*)(double)>("lgamma");
  int* const sign = libm.variable<int>("signgam");
  lgamma(-0.5);
  EXPECT_EQ(*sign, -1);
  lgamma(0.5);
  EXPECT_EQ(*sign, 1);
}

TEST(SharedLibrary, RefusesASymbolTheLibraryDoesNotHave) {
  const SharedLibrary libm("libm.so.6", "the test");
  const std::string message = refusal(libm, "capsim_no_such_function");
  EXPECT_NE(message.find("libm.so.6 has no symbol capsim_no_such_function ("), std::string::npos) << message;
  EXPECT_NE(message.find("); it is needed for the test"), std::string::npos) << message;
}

// The loader lists what it maps at start (LD_TRACE_LOADED_OBJECTS, as ldd
// does): lib3MF, libxml2, the font libraries, MPI's and OpenEXR's (which the
// EXR module brings) are not among them, nor libzip, libcrypto, ICU, GLib and
// Open MPI's runtime, which only they bring.
TEST(SharedLibrary, CapsimStartsWithoutTheLibrariesItOpensOnUse) {
  const TempDir dir;
  const auto r = run_capsim("--version", dir, "export LD_TRACE_LOADED_OBJECTS=1;");
  ASSERT_EQ(r.status, 0) << r.err;
  ASSERT_NE(r.out.find("libc.so.6"), std::string::npos) << r.out;
  for (const char* lib : {"lib3MF", "libzip", "libcrypto", "libxml2", "libicuuc", "libfreetype", "libharfbuzz",
                          "libfontconfig", "libglib", "libmpi", "libopen-pal", "libhwloc", "libevent", "libOpenEXR",
                          "libImath", "libIex", "libIlmThread", "libcapsim_exr"})
    EXPECT_EQ(r.out.find(lib), std::string::npos) << lib << " is loaded at start:\n" << r.out;
}
