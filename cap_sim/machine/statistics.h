#pragma once
// The statistics a run keeps of each cell and each link direction, each
// declared once: its name, its unit, what it measures, and the headings of
// the text and HTML tables. The text report, the JSON report and the HTML
// page write every statistic of a table from these declarations, in their
// order; adding one is a row here (and the counter it reads).

#include "machine/parts/balance.h"
#include "machine/cell_record.h"
#include "machine/parts/neighbour_links.h"

#include <array>
#include <cstdint>
#include <string>

namespace capsim::sim {

enum class StatisticUnit {
  Count,   // written as is
  Bytes,   // written as is
  Cycles,  // of the profile's clock; JSON "<name>_cycles"; seconds where a table says so
};

// When a statistic is kept: always, only when the run antialiases, only when
// it is balanced on demand, only when it steals, or only when the cells
// generate the voxel grids.
enum class StatisticScope { Always, Antialiased, Demand, Steal, CellVoxels };

constexpr bool statistic_kept(StatisticScope scope, bool antialiased, BalanceScheme balance,
                              bool cells_generate_voxels = false) {
  return scope == StatisticScope::Always || (scope == StatisticScope::Antialiased && antialiased) ||
         (scope == StatisticScope::Demand && balance == BalanceScheme::Demand) ||
         (scope == StatisticScope::Steal && balance == BalanceScheme::Steal) ||
         (scope == StatisticScope::CellVoxels && cells_generate_voxels);
}

template <class Part>
struct Statistic {
  const char* name;     // "busy"; its JSON key is json_key()
  StatisticUnit unit;
  StatisticScope scope;
  const char* meaning;  // one line, for the documentation and the page's captions
  const char* heading;  // the text table's column: "busy cyc"
  int width;            // and its width
  const char* title;    // the HTML table's column: "Busy" (with " s" for cycles, shown in seconds)
  std::uint64_t (*value)(const Part& part);

  std::string json_key() const { return unit == StatisticUnit::Cycles ? std::string(name) + "_cycles" : name; }
};

inline constexpr std::array<Statistic<CellReport>, 27> kCellStatistics = {{
    {"pixels", StatisticUnit::Count, StatisticScope::Always, "pixels it traced, all frames", "pixels", 8,
     "Pixels", [](const CellReport& c) { return c.pixels; }},
    {"rays", StatisticUnit::Count, StatisticScope::Always, "rays it traced, every kind", "rays", 9, "Rays",
     [](const CellReport& c) { return c.rays; }},
    {"busy", StatisticUnit::Cycles, StatisticScope::Always, "tracing (and its voxel shares, when the cells generate them): its operations' costs", "busy cyc", 14,
     "Busy", [](const CellReport& c) { return c.busy.count(); }},
    {"idle", StatisticUnit::Cycles, StatisticScope::Always, "finish - busy - comm: waiting", "idle cyc", 14,
     "Idle", [](const CellReport& c) { return c.idle.count(); }},
    {"comm", StatisticUnit::Cycles, StatisticScope::Always,
     "receiving broadcasts and sending, waits for the bus or a link included", "comm cyc", 12, "Comm",
     [](const CellReport& c) { return c.comm.count(); }},
    {"finish", StatisticUnit::Cycles, StatisticScope::Always, "when its last \"done\" reached the host",
     "finish cyc", 14, "Finish", [](const CellReport& c) { return c.finish.count(); }},
    {"trace_corners", StatisticUnit::Cycles, StatisticScope::Antialiased,
     "phase 1, tracing the corners it owns, start to end", "trace corners", 16, "Trace corners",
     [](const CellReport& c) { return c.trace_corners.count(); }},
    {"exchange", StatisticUnit::Cycles, StatisticScope::Antialiased,
     "phase 2, the corner exchange, start to end, waits included", "exchange", 14, "Exchange",
     [](const CellReport& c) { return c.exchange.count(); }},
    {"subdivide", StatisticUnit::Cycles, StatisticScope::Antialiased, "phase 3, subdividing its pixels",
     "subdivide", 14, "Subdivide", [](const CellReport& c) { return c.subdivide.count(); }},
    {"corners_received", StatisticUnit::Count, StatisticScope::Antialiased,
     "corner samples it took in over the links", "corners in", 9, "Corners in",
     [](const CellReport& c) { return c.corners_received; }},
    {"tiles", StatisticUnit::Count, StatisticScope::Demand, "tiles it was granted and traced", "tiles", 7, "Tiles",
     [](const CellReport& c) { return static_cast<std::uint64_t>(c.tiles.size()); }},
    {"requests", StatisticUnit::Count, StatisticScope::Demand, "requests for a tile it sent the host", "requests", 9,
     "Requests", [](const CellReport& c) { return c.tile_requests; }},
    {"waits", StatisticUnit::Count, StatisticScope::Demand, "times it waited for the host's answer with nothing to trace",
     "tile waits", 10, "Waits", [](const CellReport& c) { return c.tile_waits; }},
    {"tile_wait", StatisticUnit::Cycles, StatisticScope::Demand, "those waits, summed", "tile wait cyc", 14,
     "Tile wait", [](const CellReport& c) { return c.tile_wait.count(); }},
    {"longest_tile_wait", StatisticUnit::Cycles, StatisticScope::Demand, "the longest of those waits",
     "max tile wait cyc", 17, "Longest tile wait", [](const CellReport& c) { return c.longest_tile_wait.count(); }},
    {"balance_bytes", StatisticUnit::Bytes, StatisticScope::Demand,
     "balancing bytes on the bus: its requests sent, the grants and \"no tile\" it took in", "balance B", 10,
     "Balance bytes", [](const CellReport& c) { return c.balance_bytes_sent + c.balance_bytes_received; }},
    {"chunks", StatisticUnit::Count, StatisticScope::Steal, "chunks it traced, its own and stolen", "chunks", 8,
     "Chunks", [](const CellReport& c) {
       std::uint64_t n = 0;
       for (const ChunkRun& r : c.chunk_runs) n += static_cast<std::uint64_t>(r.chunks);
       return n;
     }},
    {"chunks_stolen", StatisticUnit::Count, StatisticScope::Steal, "chunks it took from its neighbours",
     "stolen", 8, "Stolen", [](const CellReport& c) { return c.chunks_stolen; }},
    {"chunks_given", StatisticUnit::Count, StatisticScope::Steal, "chunks of its window its neighbours took",
     "given", 8, "Given", [](const CellReport& c) { return c.chunks_given; }},
    {"steal_requests", StatisticUnit::Count, StatisticScope::Steal, "requests for work it sent its neighbours",
     "asked", 7, "Requests", [](const CellReport& c) { return c.steal_requests; }},
    {"steals_refused", StatisticUnit::Count, StatisticScope::Steal, "of those, answered \"no work\"", "refused", 8,
     "Refused", [](const CellReport& c) { return c.steals_refused; }},
    {"steal_wait", StatisticUnit::Cycles, StatisticScope::Steal,
     "its waits for an answer to a request, summed", "steal wait cyc", 14, "Steal wait",
     [](const CellReport& c) { return c.steal_wait.count(); }},
    {"steal_bytes", StatisticUnit::Bytes, StatisticScope::Steal,
     "balancing bytes over the links: requests, answers and pixels it sent and took in", "steal B", 10,
     "Steal bytes", [](const CellReport& c) { return c.balance_bytes_sent + c.balance_bytes_received; }},
    {"voxel_generation", StatisticUnit::Cycles, StatisticScope::CellVoxels,
     "its shares of the voxel grids: placing its primitives and building its voxels' lists", "voxel gen cyc", 14,
     "Voxel generation", [](const CellReport& c) { return c.voxel_generation.count(); }},
    {"voxel_gather", StatisticUnit::Cycles, StatisticScope::CellVoxels,
     "its waits for the other cells' shares, their transfers included", "voxel gather cyc", 16, "Voxel gather",
     [](const CellReport& c) { return c.voxel_gather.count(); }},
    {"voxel_bytes_sent", StatisticUnit::Bytes, StatisticScope::CellVoxels,
     "its broadcasts of entries and rows on the bus", "voxel B out", 11, "Voxel bytes out",
     [](const CellReport& c) { return c.voxel_bytes_sent; }},
    {"voxel_bytes_received", StatisticUnit::Bytes, StatisticScope::CellVoxels,
     "the other cells' entries and rows it took in", "voxel B in", 11, "Voxel bytes in",
     [](const CellReport& c) { return c.voxel_bytes_received; }},
}};

inline constexpr std::array<Statistic<LinkTraffic>, 4> kLinkStatistics = {{
    {"messages", StatisticUnit::Count, StatisticScope::Antialiased, "messages it carried", "messages", 9,
     "Messages", [](const LinkTraffic& l) { return l.messages; }},
    {"bytes", StatisticUnit::Bytes, StatisticScope::Antialiased, "bytes it carried", "bytes", 12, "Bytes",
     [](const LinkTraffic& l) { return l.bytes; }},
    {"busy", StatisticUnit::Cycles, StatisticScope::Antialiased, "cycles bits were on it", "busy cyc", 12,
     "Busy cycles", [](const LinkTraffic& l) { return l.busy.count(); }},
    {"max_wait", StatisticUnit::Cycles, StatisticScope::Antialiased,
     "the longest a message waited for it to be free", "max wait cyc", 12, "Longest wait",
     [](const LinkTraffic& l) { return l.max_wait.count(); }},
}};

}  // namespace capsim::sim
