#pragma once
// One cell of CAP: its ID, its window controller, its video memory, and the
// program it runs for a frame (paper §3.3).

#include "command_bus.h"
#include "event_kernel.h"
#include "mailbox.h"
#include "timeline.h"
#include "traced_screen.h"
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
    const TracedScreen& screen;  // the work of every pixel, traced ahead
  };

  Cell(CellId id, const CellWindow& window, int timeline_track, const Wiring& wiring);

  // The program every cell runs for one frame.
  Process run_frame();

  Mailbox<BusTransfer>& bus_inbox() { return bus_inbox_; }
  const Framebuffer& video_memory() const { return video_memory_; }
  const CellWindow& window() const { return window_; }
  const CellRecord& record() const { return record_; }
  CellId id() const { return id_; }

 private:
  void take_in(const BusTransfer& t, std::string_view expected);
  void write_video_memory(int k, ScreenPixel p);

  CellId id_;
  CellWindow window_;
  int track_;
  Wiring wire_;
  Mailbox<BusTransfer> bus_inbox_;
  Framebuffer video_memory_;  // pixel k of the window at (k, 0)
  CellRecord record_;
};

}  // namespace capsim::sim
