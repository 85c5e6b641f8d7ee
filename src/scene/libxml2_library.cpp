#include "scene/libxml2_library.h"

#include "capsim/shared_library.h"

namespace capsim::scene_file {

namespace {

// CAPSIM_LIBXML2_SONAME is the soname of the libxml2 the build compiled
// against (CMakeLists.txt), so the functions loaded are the ones the header
// declares.
const SharedLibrary& library() {
  static const SharedLibrary lib(CAPSIM_LIBXML2_SONAME, "AMF and SVG import");
  return lib;
}

}  // namespace

#define CAPSIM_LIBXML2(name) name(library().function<decltype(&::name)>(#name))
Libxml2::Libxml2()
    : CAPSIM_LIBXML2(xmlReaderForMemory),
      CAPSIM_LIBXML2(xmlFreeTextReader),
      CAPSIM_LIBXML2(xmlTextReaderSetStructuredErrorHandler),
      CAPSIM_LIBXML2(xmlTextReaderRead),
      CAPSIM_LIBXML2(xmlTextReaderNodeType),
      CAPSIM_LIBXML2(xmlTextReaderIsEmptyElement),
      CAPSIM_LIBXML2(xmlTextReaderConstName),
      CAPSIM_LIBXML2(xmlTextReaderConstValue),
      CAPSIM_LIBXML2(xmlTextReaderValue),
      CAPSIM_LIBXML2(xmlTextReaderGetAttribute),
      CAPSIM_LIBXML2(xmlTextReaderMoveToNextAttribute),
      CAPSIM_LIBXML2(xmlTextReaderMoveToElement),
      CAPSIM_LIBXML2(xmlTextReaderCurrentNode),
      CAPSIM_LIBXML2(xmlTextReaderGetParserLineNumber),
      CAPSIM_LIBXML2(xmlGetLineNo),
      free_variable_(library().variable<xmlFreeFunc>("xmlFree")) {}
#undef CAPSIM_LIBXML2

void Libxml2::free(void* memory) const { (*free_variable_)(memory); }

const Libxml2& libxml2() {
  static const Libxml2 table;
  return table;
}

}  // namespace capsim::scene_file
