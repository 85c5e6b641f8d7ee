#include "cli/command_failure.h"

#include "capsim/scene/scene.h"
#include "cli/options/cli_usage.h"

#include <fmt/core.h>

#include <new>

namespace capsim::cli {

CommandFailure describe_failure(const std::exception_ptr& e, const std::string& command) {
  try {
    std::rethrow_exception(e);
  } catch (const UsageError& u) {
    return {2, fmt::format("{}: {}", command, u.what())};
  } catch (const SceneError& s) {
    return {1, s.what()};  // FILE:LINE:COL: message, as compilers print
  } catch (const std::bad_alloc&) {
    return {1, fmt::format("{}: out of memory", command)};
  } catch (const std::exception& x) {
    return {1, fmt::format("capsim: {}", x.what())};
  }
}

}  // namespace capsim::cli
