#pragma once
// .scad scene files: OpenSCAD itself exports each to its CSG tree (what
// `openscad -o model.csg model.scad` writes), which capsim then reads. The
// exports live in a private temporary directory for as long as a ScadExports
// does, and are removed with it, or by the signal handler of
// temp_file_registry.h if a signal ends the process first.

#include <string>
#include <vector>

namespace capsim::cli {

// Whether `path` names an OpenSCAD program (ends in .scad, in any case).
bool is_scad_file(const std::string& path);

class ScadExports {
 public:
  // `defines`: OpenSCAD's -D assignments ("var=value"), passed to every run
  // verbatim.
  explicit ScadExports(std::vector<std::string> defines);
  ~ScadExports();
  ScadExports(const ScadExports&) = delete;
  ScadExports& operator=(const ScadExports&) = delete;

  // Has openscad (found on PATH, run without a shell) export `scad` as
  // `name`.csg, or with `animate_frames` > 0 as `openscad --animate K` does,
  // one file per frame; returns the exported files in frame order. Lines of
  // OpenSCAD's output that start with WARNING:, DEPRECATED: or ECHO: are
  // passed on to stderr, prefixed with "openscad: "; the rest (progress
  // notes) is dropped. Throws SceneError ("SCAD: message") when openscad is
  // not on PATH, cannot be started or fails, showing what it printed and its
  // exit status. Precondition: `name` is a plain file name, unique among the
  // exports of this object.
  std::vector<std::string> export_csg(const std::string& scad, const std::string& name, int animate_frames = 0);

 private:
  void add_file(const std::string& path);

  std::vector<std::string> defines_;
  std::string dir_;  // absolute; empty until the first export
  int dir_slot_ = -1;
  struct File {
    std::string path;
    int slot;
  };
  std::vector<File> files_;
};

}  // namespace capsim::cli
