#pragma once
// One cell of CAP: its ID, its window controller, its video memory, and the
// program it runs for a frame (paper §3.3).

#include "command_bus.h"
#include "event_kernel.h"
#include "mailbox.h"
#include "timeline.h"
#include "traced_cells.h"
#include "window_controller.h"

#include "capsim/render.h"

namespace capsim::sim {

// What a cell measured about its frame.
struct CellRecord {
  Cycles busy;    // tracing its pixels
  Cycles comm;    // receiving broadcasts, and sending (waiting for the bus included)
  Cycles finish;  // its "done" message reached the host
  std::uint64_t pixels = 0;
  std::uint64_t rays = 0;
  CostBreakdown work;  // busy, by Table 4-3's processes
};

class Cell {
 public:
  struct Wiring {
    EventKernel& kernel;
    CommandBus& bus;
    Timeline& timeline;
  };

  // traced: this cell's pixels, traced ahead by the host threads.
  Cell(CellId id, const CellWindow& window, TracedCell traced, int timeline_track,
       const Wiring& wiring);

  // The program every cell runs for one frame.
  Process run_frame();

  Mailbox<BusTransfer>& bus_inbox() { return bus_inbox_; }
  const Framebuffer& video_memory() const { return video_memory_; }
  const CellWindow& window() const { return window_; }
  const CellRecord& record() const { return record_; }
  // The cycles each of its pixels cost, in video-memory order.
  const std::vector<std::uint64_t>& pixel_cycles() const { return traced_.pixel_cycles; }
  CellId id() const { return id_; }

 private:
  void take_in(const BusTransfer& t, std::string_view expected);

  CellId id_;
  CellWindow window_;
  TracedCell traced_;
  int track_;
  Wiring wire_;
  Mailbox<BusTransfer> bus_inbox_;
  Framebuffer video_memory_;  // pixel k of the window at (k, 0); filled by the frame
  CellRecord record_;
};

}  // namespace capsim::sim
