#include "machine/parts/frame_protocol.h"

namespace capsim::sim {

std::vector<Broadcast> unit_broadcasts(bool first_unit, int first_frame, int frames, bool host_voxels) {
  std::vector<Broadcast> out;
  if (first_unit) out.push_back({BusMessage::Program});
  for (int f = first_frame; f < first_frame + frames; ++f) {
    out.push_back({BusMessage::Scene, f});
    if (host_voxels) out.push_back({BusMessage::VoxelData, f});
  }
  out.push_back({BusMessage::Start});
  return out;
}

}  // namespace capsim::sim
