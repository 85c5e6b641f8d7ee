#include "machine/frame_work.h"

#include <fmt/core.h>

namespace capsim::sim {

std::string frame_span_name(std::string_view what, int frame, std::size_t frame_count) {
  return frame_count == 1 ? std::string(what) : fmt::format("{}, frame {}", what, frame);
}

}  // namespace capsim::sim
