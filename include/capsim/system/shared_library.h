#pragma once
// A shared library opened the first time a command needs it, not at start-up.
//
// Each library the dynamic loader maps at start costs every run of capsim its
// loading and relocation, needed or not: lib3MF brought libzip and libcrypto,
// libxml2 brought ICU, and the font libraries brought GLib, to every run,
// though only import() of a .3mf, .amf or .svg file and text() call them.
// Such a library is named here by its soname and opened by dlopen on first
// use; its functions are found by name. Only libraries with a C interface can
// be reached this way (a function is found by its unmangled name).
// docs/performance.md gives what this saves.

#include <mutex>
#include <string>

namespace capsim {

class SharedLibrary {
 public:
  // `soname` as the loader finds it ("lib3MF.so.1"); `needed_for` ends the
  // message of a failure to open it: "... is needed for 3MF import".
  SharedLibrary(std::string soname, std::string needed_for);
  SharedLibrary(const SharedLibrary&) = delete;
  SharedLibrary& operator=(const SharedLibrary&) = delete;

  // The function `name` of the library, opening it on the first call (from any
  // thread). Throws std::runtime_error, saying which library and why, when the
  // library cannot be opened or has no such symbol.
  template <class Function>
  Function function(const char* name) const {
    return reinterpret_cast<Function>(symbol(name));
  }

  // The variable `name` of the library, as function() finds a function.
  template <class T>
  T* variable(const char* name) const {
    return static_cast<T*>(symbol(name));
  }

 private:
  void* symbol(const char* name) const;

  std::string soname_;
  std::string needed_for_;
  mutable std::once_flag opened_;
  mutable void* handle_ = nullptr;
  mutable std::string open_error_;
};

}  // namespace capsim
