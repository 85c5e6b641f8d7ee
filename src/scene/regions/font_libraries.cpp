#include "scene/regions/font_libraries.h"

namespace capsim {

const SharedLibrary& fontconfig_library() {
  static const SharedLibrary lib(CAPSIM_FONTCONFIG_SONAME, "text()");
  return lib;
}

const SharedLibrary& freetype_library() {
  static const SharedLibrary lib(CAPSIM_FREETYPE_SONAME, "text()");
  return lib;
}

const SharedLibrary& harfbuzz_library() {
  static const SharedLibrary lib(CAPSIM_HARFBUZZ_SONAME, "text()");
  return lib;
}

const FontLibraries& font_libraries() {
  static const FontLibraries table;
  return table;
}

}  // namespace capsim
