#include "capsim/system/shared_library.h"

#include <dlfcn.h>
#include <fmt/core.h>

#include <stdexcept>
#include <utility>

namespace capsim {

SharedLibrary::SharedLibrary(std::string soname, std::string needed_for)
    : soname_(std::move(soname)), needed_for_(std::move(needed_for)) {}

void* SharedLibrary::symbol(const char* name) const {
  std::call_once(opened_, [this] {
    // RTLD_LOCAL: the library's symbols serve the lookups below only, so they
    // cannot stand in for another library's of the same name.
    handle_ = dlopen(soname_.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle_) {
      const char* why = dlerror();
      open_error_ = why ? why : "dlopen failed";
    }
  });
  if (!handle_)
    throw std::runtime_error(
        fmt::format("{} cannot be loaded ({}); it is needed for {}", soname_, open_error_, needed_for_));
  dlerror();  // clear any earlier error, so that a null symbol is told from a failed lookup
  void* found = dlsym(handle_, name);
  if (const char* why = dlerror())
    throw std::runtime_error(fmt::format("{} has no symbol {} ({}); it is needed for {}", soname_, name, why,
                                         needed_for_));
  return found;
}

}  // namespace capsim
