#pragma once
// The functions of libxml2's text reader that the AMF and SVG imports call,
// from the library opened on the first import rather than at every start
// (capsim/system/shared_library.h): libxml2 brings ICU, which every run would
// otherwise load and relocate.

#include "capsim/system/shared_library.h"

#include <libxml/xmlreader.h>

namespace capsim::scene_file {

// libxml2 itself, of the soname the build compiled against (CMakeLists.txt),
// so the functions loaded are the ones the header declares.
const SharedLibrary& libxml2_shared_library();

// Making the table opens the library; it throws std::runtime_error when the
// library cannot be opened, naming it and why.
struct Libxml2 {
#define CAPSIM_LIBXML2(name) decltype(&::name) name = libxml2_shared_library().function<decltype(&::name)>(#name)
  CAPSIM_LIBXML2(xmlReaderForMemory);
  CAPSIM_LIBXML2(xmlFreeTextReader);
  CAPSIM_LIBXML2(xmlTextReaderSetStructuredErrorHandler);
  CAPSIM_LIBXML2(xmlTextReaderRead);
  CAPSIM_LIBXML2(xmlTextReaderNodeType);
  CAPSIM_LIBXML2(xmlTextReaderIsEmptyElement);
  CAPSIM_LIBXML2(xmlTextReaderConstName);
  CAPSIM_LIBXML2(xmlTextReaderConstValue);
  CAPSIM_LIBXML2(xmlTextReaderValue);
  CAPSIM_LIBXML2(xmlTextReaderGetAttribute);
  CAPSIM_LIBXML2(xmlTextReaderMoveToNextAttribute);
  CAPSIM_LIBXML2(xmlTextReaderMoveToElement);
  CAPSIM_LIBXML2(xmlTextReaderCurrentNode);
  CAPSIM_LIBXML2(xmlTextReaderGetParserLineNumber);
  CAPSIM_LIBXML2(xmlGetLineNo);
#undef CAPSIM_LIBXML2

  // xmlFree: libxml2's deallocator for the strings it returns. The library
  // exports it as a variable (an application may replace it), read at each
  // call.
  void free(void* memory) const;

 private:
  xmlFreeFunc* free_variable_ = libxml2_shared_library().variable<xmlFreeFunc>("xmlFree");
};

// The table, opened once for the process (from any thread). A library that
// cannot be loaded is refused at each call with std::runtime_error.
const Libxml2& libxml2();

}  // namespace capsim::scene_file
