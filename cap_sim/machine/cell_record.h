#pragma once
// What a cell counts about its run as it runs it; the run's report of a cell
// adds where it sits and its idle time (machine/statistics.h declares each
// counter the reports write).

#include "kernel/cycles.h"
#include "machine/parts/cell_grid.h"
#include "machine/parts/corner_exchange.h"
#include "machine/costs/cost_profile.h"

#include "capsim/trace/op_counts.h"

#include <cstdint>
#include <vector>

namespace capsim::sim {

// A tile a cell traced, balanced on demand (balance.h): which, and when.
struct TileRun {
  int frame = 0;
  int tile = 0;
  Cycles requested;  // its request left for the host
  Cycles granted;    // the grant was in the cell's memory
  Cycles start, end;  // the cell traced it
};

// Chunks a cell traced, stealing (balance.h): `chunks` chunks from
// first_chunk of the window of cell `owner` (its own, or a victim's) in frame
// `frame`, from start to end.
struct ChunkRun {
  int frame = 0;
  CellId owner = 0;
  int first_chunk = 0, chunks = 0;
  Cycles start, end;
};

// Chunks of a cell's window that another cell traced, stealing: when their
// pixels were in its video memory.
struct ReturnedChunks {
  int frame = 0;
  int first_chunk = 0, chunks = 0;
  Cycles arrived;
};

// What a cell measured about its run.
struct CellRecord {
  Cycles busy;    // tracing (corners, pixels, subdivision) and its voxel shares, all frames
  Cycles comm;    // receiving broadcasts, and sending (waiting for the bus or a link
                  // included)
  Cycles finish;  // its last "done" message reached the host
  // Antialiasing: the three phases, each from its start to its end, summed over
  // the run's distribution units.
  Cycles trace_corners, exchange, subdivide;
  std::uint64_t corners_received = 0;
  std::vector<CornerIndex> received_corners;  // ascending; only with MachineConfig::keep_received_corners
  std::uint64_t pixels = 0;  // over all frames
  std::uint64_t rays = 0;
  OpCounts ops;        // the operations its busy time paid for, all frames
  CostBreakdown work;  // busy, by Table 4-3's processes
  std::vector<Cycles> frame_busy;   // per frame: the cycles it worked on it
  std::vector<Cycles> unit_finish;  // per distribution unit: when its "done" reached the host
  // Per frame: when it began writing the frame's pixels into video memory, in
  // video-memory order (tracing them; antialiased, subdividing them in phase 3).
  std::vector<Cycles> frame_write_start;
  // Balanced on demand: the tiles it traced, in order; the requests it sent;
  // how often and how long it waited for an answer with nothing to trace
  // (the waits for a grant, and for the last answer, "no tile"); the
  // balancing bytes it sent (requests) and took in (grants, "no tile").
  std::vector<TileRun> tiles;
  std::uint64_t tile_requests = 0;
  std::uint64_t tile_waits = 0;
  Cycles tile_wait, longest_tile_wait;
  std::uint64_t balance_bytes_sent = 0, balance_bytes_received = 0;
  // Stealing: the chunks it traced, in order (its own, then the stolen); the
  // pixels others traced for it, as they came back; as a thief, the requests
  // it sent, those answered "no work", its waits for an answer and the chunks
  // it took; as a victim, the requests it answered and the chunks it gave.
  // Its balancing bytes are those over the links: requests, answers and
  // pixels, sent and taken in.
  std::vector<ChunkRun> chunk_runs;
  std::vector<ReturnedChunks> returned;
  std::uint64_t steal_requests = 0, steals_refused = 0, steal_waits = 0, chunks_stolen = 0;
  Cycles steal_wait;
  std::uint64_t requests_answered = 0, chunks_given = 0;
  // Voxel generation on the cells (voxel_shares.h): its shares' work,
  // placing and building, all frames; its waits for the other cells' shares
  // (and the transfers of theirs it took in then); the bytes of its own two
  // broadcasts a frame and of the others' it took in.
  Cycles voxel_generation, voxel_gather;
  std::uint64_t voxel_bytes_sent = 0, voxel_bytes_received = 0;
};

struct CellReport : CellRecord {
  CellId id = 0;
  CellPosition position;
  Cycles idle;  // finish - busy - comm
};

}  // namespace capsim::sim
