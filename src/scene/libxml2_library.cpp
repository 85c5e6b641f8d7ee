#include "scene/libxml2_library.h"

namespace capsim::scene_file {

const SharedLibrary& libxml2_shared_library() {
  static const SharedLibrary lib(CAPSIM_LIBXML2_SONAME, "AMF and SVG import");
  return lib;
}

void Libxml2::free(void* memory) const { (*free_variable_)(memory); }

const Libxml2& libxml2() {
  static const Libxml2 table;
  return table;
}

}  // namespace capsim::scene_file
