#pragma once
// One cell of CAP: its ID, its window controller, its video memory, and the
// program it runs for a frame (paper §3.3).

#include "command_bus.h"
#include "corner_exchange.h"
#include "event_kernel.h"
#include "mailbox.h"
#include "neighbour_links.h"
#include "timeline.h"
#include "traced_cells.h"
#include "window_controller.h"

#include "capsim/render.h"

namespace capsim::sim {

// What a cell measured about its frame.
struct CellRecord {
  Cycles busy;    // tracing its pixels
  Cycles comm;    // receiving broadcasts, and sending (waiting for the bus or a link
                  // included)
  Cycles finish;  // its "done" message reached the host
  // Antialiasing: the three phases of the frame, each from its start to its end.
  Cycles trace_corners, exchange, subdivide;
  std::vector<CornerIndex> corners_received;  // ascending
  std::uint64_t pixels = 0;
  std::uint64_t rays = 0;
  CostBreakdown work;  // busy, by Table 4-3's processes
};

class Cell {
 public:
  struct Wiring {
    EventKernel& kernel;
    CommandBus& bus;
    NeighbourLinks& links;
    const CellGrid& grid;
    Timeline& timeline;
    const CornerExchange* exchange;  // null: the frame is not antialiased
  };

  // traced: this cell's pixels, traced ahead by the host threads.
  Cell(CellId id, const CellWindow& window, TracedCell traced, int timeline_track,
       const Wiring& wiring);

  // The program every cell runs for one frame.
  Process run_frame();

  Mailbox<BusTransfer>& bus_inbox() { return bus_inbox_; }
  Mailbox<LinkMessage>& link_inbox() { return link_inbox_; }
  const Framebuffer& video_memory() const { return video_memory_; }
  const std::vector<unsigned char>& video_memory_srgb8() const { return video_srgb8_; }
  const CellWindow& window() const { return window_; }
  const CellRecord& record() const { return record_; }
  // The cycles each of its pixels cost, in video-memory order.
  const std::vector<std::uint64_t>& pixel_cycles() const { return traced_.pixel_cycles; }
  // Antialiased: the primary samples traced for each of its pixels.
  const std::vector<std::uint32_t>& pixel_samples() const { return traced_.pixel_samples; }
  CellId id() const { return id_; }

 private:
  void take_in(const BusTransfer& t, std::string_view expected);
  // The antialiasing exchange's bookkeeping: a message's corners taken in; a
  // message to relay holds only corners this cell has; every corner its pixels
  // need has come (each throws std::logic_error if not).
  void take_in(const LinkMessage& m);
  void check_holds(const CornerMessage& m);
  void check_has_every_corner();
  std::string cell_name(CellId id) const;

  CellId id_;
  CellWindow window_;
  TracedCell traced_;
  int track_;
  Wiring wire_;
  Mailbox<BusTransfer> bus_inbox_;
  Mailbox<LinkMessage> link_inbox_;
  std::vector<LinkMessage> early_;  // horizontal messages that came before the vertical ones
  Framebuffer video_memory_;  // pixel k of the window at (k, 0); filled by the frame
  std::vector<unsigned char> video_srgb8_;  // or, for an 8-bit screen, at bytes 3k..3k+2
  CellRecord record_;
};

}  // namespace capsim::sim
