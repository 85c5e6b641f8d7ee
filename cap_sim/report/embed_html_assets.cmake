# Writes a C++ source holding the HTML pages' own files (cap_sim/report/html/: the
# page template, the run report's styles and script, and the mode-comparison
# page's additions), so the capsim binary needs no data
# files at run time and the page nothing beside it.
#   cmake -DASSET_DIR=<dir> -DOUTPUT=<file.cpp> -P embed_html_assets.cmake
# The files go inside <style> and <script> elements: the build fails if one
# could end its element early.
set(members "")
foreach(pair "page;report.html" "style;report.css" "script;report.js" "modes_style;modes.css"
             "modes_script;modes.js")
  list(GET pair 0 member)
  list(GET pair 1 name)
  file(READ "${ASSET_DIR}/${name}" text)
  string(FIND "${text}" ")capsim_html\"" clash)
  if(NOT clash EQUAL -1)
    message(FATAL_ERROR "${name} contains the raw-string delimiter )capsim_html\"")
  endif()
  string(TOLOWER "${text}" lower)
  foreach(closing "</script" "</style" "<!--")
    if(NOT name STREQUAL "report.html")
      string(FIND "${lower}" "${closing}" early)
      if(NOT early EQUAL -1)
        message(FATAL_ERROR "${name} contains ${closing}, which would end or upset its element")
      endif()
    endif()
  endforeach()
  string(APPEND members "    R\"capsim_html(${text})capsim_html\",\n")
endforeach()
set(source "// Generated from cap_sim/report/html/ by cap_sim/report/embed_html_assets.cmake.
#include \"report/html_assets.h\"

namespace capsim::sim {

const HtmlAssets& html_assets() {
  static constexpr HtmlAssets kAssets{
${members}  };
  return kAssets;
}

}  // namespace capsim::sim
")
file(WRITE "${OUTPUT}.tmp" "${source}")
execute_process(COMMAND ${CMAKE_COMMAND} -E copy_if_different "${OUTPUT}.tmp" "${OUTPUT}")
file(REMOVE "${OUTPUT}.tmp")
