#pragma once
// One cell of CAP: its ID, its window controller, its video memory, and the
// program it runs (paper §3.3), frame after frame.

#include "kernel/event_kernel.h"
#include "kernel/mailbox.h"
#include "kernel/task.h"
#include "kernel/timeline.h"
#include "machine/cell_record.h"
#include "machine/parts/command_bus.h"
#include "machine/parts/corner_exchange.h"
#include "machine/frame_work.h"
#include "machine/parts/neighbour_links.h"
#include "machine/parts/program_clock.h"
#include "machine/traced_cells.h"
#include "machine/parts/window_controller.h"

#include "capsim/trace/render.h"

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace capsim::sim {

class Cell {
 public:
  struct Wiring {
    EventKernel& kernel;
    CommandBus& bus;
    NeighbourLinks& links;
    const CellGrid& grid;
    Timeline& timeline;
    std::vector<FrameWork>& frames;
    const std::vector<DistributionUnit>& units;
    bool antialiased;
    bool keep_received_corners;  // MachineConfig::keep_received_corners
    // Balanced on demand: each frame's work is its tiles (frames[f].cells[t],
    // laid out by frames[f].layout), traced as the host grants them.
    bool on_demand = false;
    // Stealing (balance.h): the windows are cut into chunks of chunk_pixels
    // pixels; video_of(cell, frame) is that cell's traced window, which a
    // thief reads the chunks it took from.
    int chunk_pixels = 0;
    std::function<const TracedCell&(CellId, int)> video_of;
    // The cells generate the voxel grids (voxel_shares.h): each unit begins
    // with this cell's share of each frame's grid (frames[f].voxel_shares).
    bool generate_voxels = false;
  };

  // Takes this cell's traced work out of every frame of wiring.frames.
  Cell(CellId id, int timeline_track, const Wiring& wiring);

  // The program every cell runs (§3.3), for each distribution unit of the run
  // in turn: receive, (generate its voxel shares,) trace, report done; antialiased: receive, trace
  // corners, exchange corners, subdivide, report done; balanced on demand:
  // receive, trace tiles as granted, report done. Precondition: the host
  // broadcasts what unit_broadcasts() lists and collects a "done" from every
  // cell before the next unit's broadcasts.
  Process run();

  Mailbox<BusTransfer>& bus_inbox() { return bus_inbox_; }
  // A message the links delivered to this cell: the corner exchange's go to
  // its program; stealing, a request is answered at once by the cell's link
  // interface (answer_steal_request), and answers and returned pixels go to
  // its program.
  void deliver_link(const LinkMessage& m);
  const CellRecord& record() const { return record_; }
  CellId id() const { return id_; }
  // Its video memory of a frame, once traced: the samples, in its window's
  // order, with their cycles and, antialiased, their primary samples.
  const TracedCell& video_memory(int frame) const { return video_[frame]; }

 private:
  // The phases of run(), each for one distribution unit (receive: by its
  // index, the first unit's broadcasts beginning with the program).
  Task<> receive(std::size_t u);
  // Voxel generation on the cells: for each frame, place its primitives,
  // broadcast their entries, gather the others'; build its voxels' lists,
  // broadcast them, gather the others' (cell_voxel_share.cpp).
  Task<> generate_voxel_shares(const DistributionUnit& unit);
  Task<> broadcast_share(BusMessage message, int frame, std::uint64_t bytes);
  Task<> gather_shares(BusMessage message, int frame);
  Task<> trace(const DistributionUnit& unit);
  Task<> trace_corners(const DistributionUnit& unit);
  Task<> exchange_corners(const CornerExchange& exchange);
  Task<> subdivide(const DistributionUnit& unit);
  Task<> report_done();
  // Balanced on demand: ask the host for a tile (now, or from the cell's bus
  // interface while it traces), and take in its answer; trace the tiles it
  // grants.
  Task<> trace_tiles(const DistributionUnit& unit);
  Task<> request_tile();
  Process request_tile_after(Cycles delay);
  Task<BusTransfer> take_answer();
  Task<> trace_tile(int frame, const BusTransfer& grant, Cycles requested);
  // Stealing (balance.h): trace its own chunks from the front while
  // neighbours may take them from the back, then take chunks from its
  // neighbours, then wait for the pixels of those it gave away.
  Task<> trace_stealing(const DistributionUnit& unit);
  Task<> trace_own_chunks(int frame);
  Task<> steal_from_neighbours(int frame);
  Task<> trace_stolen(const LinkMessage& work);
  Task<> collect_returned_pixels(int frame);
  void answer_steal_request(const LinkMessage& request);
  // A message its link interface sends while the program goes on.
  Process send_from_link_interface(CellId to, std::uint64_t bytes, LinkPacket packet);
  // The work a chunk moves and what it counts, added to this cell's record.
  void count_chunk(const TracedCell& window, int frame, int chunk, int window_pixels);
  // The two halves of each step of exchange_corners.
  Task<> send_corners(const CornerExchange& exchange, ExchangeStep step);
  Task<> receive_corners(const CornerExchange& exchange, ExchangeStep step);

  // A broadcast taken in; throws std::logic_error if it is not the one expected.
  void take_in(const BusTransfer& t, BusMessage expected);
  // The antialiasing exchange's bookkeeping: a message's corners taken in; a
  // message to relay holds only corners this cell has; every corner its pixels
  // need has come (each throws std::logic_error if not).
  void take_in(const LinkMessage& m, const CornerExchange& exchange);
  void check_holds(const CornerMessage& m, const CornerExchange& exchange);
  void check_has_every_corner(const CornerExchange& exchange);
  // The unit's exchange is over: the corners it took in, counted (and kept if
  // asked), and forgotten.
  void count_received_corners();
  // Every pixel of frame f is in video memory: what the cell spent on them.
  void count_frame(int f);
  std::string cell_name(CellId id) const;
  std::string frame_name(std::string_view what, int frame) const;
  std::string pixels_name(std::string_view verb, int frame) const;  // "<verb> N pixels"

  CellId id_;
  Wiring wire_;
  CellRecord record_;
  ProgramClock clock_;  // counts its busy cycles in record_.busy
  Mailbox<BusTransfer> bus_inbox_;
  Mailbox<LinkMessage> link_inbox_;
  std::vector<LinkMessage> early_;  // horizontal messages that came before the vertical ones
  std::vector<BusTransfer> early_shares_;  // other cells' voxel shares of a later step or frame
  std::vector<CornerIndex> unit_received_;  // corners taken in during this unit's exchange, ascending
  std::vector<TracedCell> video_;   // per frame: traced ahead, its video memory once traced (static)
  Cycles last_request_;  // on demand: when its latest request left
  // Stealing: its unstarted chunks of the frame it works on are front to
  // back - 1 (it traces from the front, thieves take from the back); requests
  // for a frame it has not opened wait in deferred_.
  struct StealQueue {
    int frame = -1;
    int front = 0, back = 0;
  };
  StealQueue queue_;
  std::vector<LinkMessage> deferred_;
  int grants_out_ = 0;  // chunks runs it gave away this frame
  Mailbox<LinkMessage> steal_inbox_;    // answers to its requests
  Mailbox<LinkMessage> returns_inbox_;  // pixels others traced for it
  std::vector<CellId> neighbours_;      // distinct, N, E, S, W
};

}  // namespace capsim::sim
