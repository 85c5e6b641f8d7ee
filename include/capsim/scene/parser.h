#pragma once
// Reads a scene file: OpenSCAD's CSG tree (what `openscad -o model.csg` writes)
// plus camera(), light(), material() and background() statements in the same
// grammar. docs/scene-format.md gives the grammar and the list of refusals.

#include "capsim/scene/scene.h"

#include <cstddef>
#include <string>
#include <string_view>

namespace capsim {

// How large a scene the parser takes on. Its memory grows with both: up to
// about 100 bytes per byte of file while reading (a token, and a value or a
// call, for every few bytes), and about 1.7 KB per primitive through
// preparation (docs/scene-format.md gives the measurements).
inline constexpr std::size_t kMaxListedSceneErrors = 50;

struct ParseLimits {
  std::size_t max_file_bytes = std::size_t{32} << 20;  // 32 MiB
  std::size_t max_primitives = 1'000'000;              // dropped ones ('%', '*') included
};

// Throws SceneError ("FILE:LINE:COL: message") on any input outside the supported
// subset and on every bad value; never returns a partial scene. Modules outside
// the subset are all reported at once, in file order, up to
// kMaxListedSceneErrors of them: the error is the first's, and its message
// goes on with a line "FILE:LINE:COL: message" for each other (then "and N
// more errors"), ending with the first other error if one follows them.
// Any other error is reported alone. A file past the
// size limit is refused as a whole ("FILE: message") before it is parsed, a
// primitive past the limit where it stands.
// `t` is the value of OpenSCAD's $t in the scene's expressions (the
// animation time, 0 <= t < 1 in an animation; docs/animation.md).
// import() reads a relative path in `import_dir`, by default the directory
// of file_name (OpenSCAD's rule: beside the file that names it), then in the
// current directory; each imported file is held to limits.max_file_bytes.
Scene parse_scene(std::string_view text, const std::string& file_name,
                  const ParseLimits& limits = {}, double t = 0, const std::string& import_dir = {});
Scene parse_scene_file(const std::string& path, const ParseLimits& limits = {}, double t = 0,
                       const std::string& import_dir = {});

// The text of a scene file, for parse_scene; throws SceneError ("FILE:
// message") where parse_scene_file would: a file that cannot be read or is
// past the size limit. An animation reads its file once and parses the text
// once per frame.
std::string read_scene_file(const std::string& path, const ParseLimits& limits = {});

}  // namespace capsim
