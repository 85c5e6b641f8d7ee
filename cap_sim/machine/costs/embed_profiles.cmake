# Writes a C++ source holding the JSON text of every cost profile in PROFILE_DIR,
# so the capsim binary needs no data files at run time.
#   cmake -DPROFILE_DIR=<dir> -DOUTPUT=<file.cpp> -P embed_profiles.cmake
file(GLOB profiles "${PROFILE_DIR}/*.json")
list(SORT profiles)
set(entries "")
foreach(profile ${profiles})
  get_filename_component(name "${profile}" NAME_WE)
  file(READ "${profile}" text)
  string(FIND "${text}" ")capsim_json\"" clash)
  if(NOT clash EQUAL -1)
    message(FATAL_ERROR "${profile} contains the raw-string delimiter )capsim_json\"")
  endif()
  string(APPEND entries "    {\"${name}\", R\"capsim_json(${text})capsim_json\"},\n")
endforeach()
set(source "// Generated from cap_sim/profiles/*.json by cap_sim/machine/costs/embed_profiles.cmake.
#include \"machine/costs/builtin_profiles.h\"

namespace capsim::sim {

std::span<const BuiltinProfile> builtin_profiles() {
  static constexpr BuiltinProfile kProfiles[] = {
${entries}  };
  return kProfiles;
}

}  // namespace capsim::sim
")
file(WRITE "${OUTPUT}.tmp" "${source}")
execute_process(COMMAND ${CMAKE_COMMAND} -E copy_if_different "${OUTPUT}.tmp" "${OUTPUT}")
file(REMOVE "${OUTPUT}.tmp")
