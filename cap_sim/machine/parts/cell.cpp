#include "machine/parts/cell.h"

#include "machine/parts/balance.h"
#include "machine/parts/frame_protocol.h"
#include "machine/unit_memory.h"

#include "capsim/trace/antialias.h"

#include <fmt/core.h>

#include <algorithm>
#include <stdexcept>

namespace capsim::sim {

Cell::Cell(CellId id, int timeline_track, const Wiring& wiring)
    : id_(id),
      wire_(wiring),
      clock_(wiring.kernel, wiring.timeline, timeline_track, cell_name(id), record_.busy),
      bus_inbox_(wiring.kernel),
      link_inbox_(wiring.kernel),
      steal_inbox_(wiring.kernel),
      returns_inbox_(wiring.kernel) {
  video_.reserve(wiring.frames.size());
  if (wiring.chunk_pixels > 0)
    for (const Direction d : {Direction::North, Direction::East, Direction::South, Direction::West})
      if (const auto n = wiring.grid.neighbour(id, d))
        if (std::find(neighbours_.begin(), neighbours_.end(), *n) == neighbours_.end()) neighbours_.push_back(*n);
  // On demand the tiles stay with the frame: any cell may trace any of them.
  if (!wiring.on_demand)
    for (FrameWork& f : wiring.frames) video_.push_back(std::move(f.cells.at(id)));
  record_.frame_busy.resize(wiring.frames.size());
  record_.frame_write_start.resize(wiring.frames.size());
}

Process Cell::run() {
  for (std::size_t u = 0; u < wire_.units.size(); ++u) {
    const DistributionUnit& unit = wire_.units[u];
    co_await receive(u);
    if (wire_.generate_voxels) co_await generate_voxel_shares(unit);
    if (wire_.on_demand) {
      co_await trace_tiles(unit);
    } else if (wire_.chunk_pixels > 0) {
      co_await trace_stealing(unit);
    } else if (!wire_.antialiased) {
      co_await trace(unit);
    } else {
      co_await trace_corners(unit);
      co_await exchange_corners(*unit.exchange);
      co_await subdivide(unit);
    }
    co_await report_done();
  }
}

// Every cell holds the same program and the same data (§3.3): it takes in what
// the host broadcasts for the unit's frames, then waits for its start command.
Task<> Cell::receive(std::size_t u) {
  const DistributionUnit& unit = wire_.units[u];
  Cycles waiting_since = clock_.now();
  for (const Broadcast expected : unit_broadcasts(u == 0, unit.first_frame, unit.frames, !wire_.generate_voxels)) {
    const BusTransfer t = co_await bus_inbox_.receive();
    clock_.wait("wait for host", waiting_since, t.granted);
    take_in(t, expected.message);
    waiting_since = clock_.now();
  }
}

// Trace the pixels this cell's window controller shows, frame after frame, in
// order, into video memory: the clock advances by the cycles of every pixel's
// operations. The host threads traced them ahead; nothing reaches a cell while
// it traces, so its clock advances once per frame by their sum (the same time
// as pixel by pixel, without an event per pixel).
Task<> Cell::trace(const DistributionUnit& unit) {
  for (const int f : unit.frame_numbers()) {
    record_.frame_write_start[f] = clock_.now();
    co_await clock_.compute(video_[f].work.total(), pixels_name("trace", f), "tracing");
    count_frame(f);
  }
}

// Antialiasing, phase 1: trace the corner samples this cell owns in each of
// the unit's frames (each of its pixels' top-left corner, and the screen's
// extra right column and bottom row where its pixels border them) into video
// memory.
Task<> Cell::trace_corners(const DistributionUnit& unit) {
  const Cycles start = clock_.now();
  for (const int f : unit.frame_numbers())
    co_await clock_.compute(video_[f].corner_work.total(), frame_name("trace corners", f), "corner tracing");
  record_.trace_corners += clock_.now() - start;
}

// Phase 2: exchange corners with the neighbours, a vertical step and then a
// horizontal one (corner_exchange.h): in each, send this step's messages, then
// take in this step's. Afterwards every corner its pixels need is here.
Task<> Cell::exchange_corners(const CornerExchange& exchange) {
  const Cycles start = clock_.now();
  for (const ExchangeStep step : {ExchangeStep::Vertical, ExchangeStep::Horizontal}) {
    co_await send_corners(exchange, step);
    co_await receive_corners(exchange, step);
  }
  check_has_every_corner(exchange);
  count_received_corners();
  record_.exchange += clock_.now() - start;
}

// Phase 3: subdivide its own pixels where their corners differ by the
// threshold or more, tracing the extra samples on its own clock.
Task<> Cell::subdivide(const DistributionUnit& unit) {
  const Cycles start = clock_.now();
  for (const int f : unit.frame_numbers()) {
    record_.frame_write_start[f] = clock_.now();
    co_await clock_.compute(video_[f].subdivision_work.total(), pixels_name("subdivide", f), "subdivision",
                            SpanCategory::Subdivide);
    count_frame(f);
  }
  record_.subdivide += clock_.now() - start;
}

// Tell the host this cell is done with the unit: every pixel of its frames is
// in video memory.
Task<> Cell::report_done() {
  const BusTransfer done = co_await wire_.bus.transfer(id_, kHost, kDoneMessageBytes, BusMessage::Done);
  clock_.wait("wait for bus", done.requested, done.granted);
  clock_.span("send done", SpanCategory::Message, done.granted, done.delivered, done.bytes);
  record_.comm += done.delivered - done.requested;
  record_.finish = done.delivered;
  record_.unit_finish.push_back(done.delivered);
}

// Balanced on demand (balance.h): one request is outstanding at a time. The
// first goes as the unit starts; then, while tracing a tile, the cell's bus
// interface sends the next one when the tile has an uncontended round trip
// (request and grant) left, so that the grant arrives as the tile ends: the
// cell waits only when the bus or the host is slower than that, and holds no
// tile it has not started for longer. The unit's tiles are of its one frame.
Task<> Cell::trace_tiles(const DistributionUnit& unit) {
  if (unit.frames != 1) throw std::logic_error("tiles are handed out one frame at a time");
  const int f = unit.first_frame;
  record_.frame_write_start[f] = clock_.now();
  const Cycles sending = clock_.now();
  co_await request_tile();
  record_.comm += clock_.now() - sending;
  for (BusTransfer answer = co_await take_answer(); answer.message == BusMessage::Grant;
       answer = co_await take_answer())
    co_await trace_tile(f, answer, last_request_);
}

Task<> Cell::request_tile() {
  const BusTransfer r = co_await wire_.bus.transfer(id_, kHost, kTileRequestBytes, BusMessage::Request);
  clock_.span("request tile", SpanCategory::Message, r.granted, r.delivered, r.bytes);
  ++record_.tile_requests;
  record_.balance_bytes_sent += r.bytes;
  last_request_ = r.requested;
}

Process Cell::request_tile_after(Cycles delay) {
  co_await wire_.kernel.delay(delay);
  co_await request_tile();
}

// The host's answer to its request: a grant or "no tile". Waiting for it with
// nothing to trace is counted.
Task<BusTransfer> Cell::take_answer() {
  const Cycles waiting = clock_.now();
  BusTransfer t = co_await bus_inbox_.receive();
  if (t.message != BusMessage::Grant && t.message != BusMessage::NoTile)
    throw std::logic_error(fmt::format("{} expected a grant or \"no tile\" from the host, got \"{}\"",
                                       cell_name(id_), to_string(t.message)));
  record_.balance_bytes_received += t.bytes;
  const Cycles waited = clock_.now() - waiting;
  if (waited > Cycles()) {
    ++record_.tile_waits;
    record_.tile_wait += waited;
    record_.longest_tile_wait = std::max(record_.longest_tile_wait, waited);
    clock_.wait("wait for tile", waiting, clock_.now());
  }
  co_return t;
}

// Trace a granted tile into video memory: its window controller shows the
// tile where the grant says (balance.h). Antialiased, the tile traces every
// corner of its pixels, those on its border again where a neighbouring tile
// traces them too, then subdivides its pixels.
Task<> Cell::trace_tile(int f, const BusTransfer& grant, Cycles requested) {
  const TracedCell& tile = wire_.frames[f].cells.at(grant.tile);
  const int pixels = wire_.frames[f].layout.window(grant.tile).pixel_count();
  const Cycles start = clock_.now();
  const Cycles work = tile.work.total();
  const Cycles round_trip = wire_.bus.transfer_cycles(kTileRequestBytes) + wire_.bus.transfer_cycles(kTileGrantBytes);
  wire_.kernel.spawn(request_tile_after(work > round_trip ? work - round_trip : Cycles()));
  const std::string what = fmt::format("tile {} ({} pixel{})", grant.tile, pixels, pixels == 1 ? "" : "s");
  if (!wire_.antialiased) {
    co_await clock_.compute(work, frame_name("trace " + what, f), "tracing");
  } else {
    // Every corner of its pixels, then their subdivision: a tile has no
    // neighbour to take corners from (balance.h).
    co_await clock_.compute(tile.corner_work.total(), frame_name("trace corners of " + what, f), "corner tracing");
    record_.trace_corners += tile.corner_work.total();
    co_await clock_.compute(tile.subdivision_work.total(), frame_name("subdivide " + what, f), "subdivision",
                            SpanCategory::Subdivide);
    record_.subdivide += tile.subdivision_work.total();
  }
  record_.tiles.push_back(TileRun{f, grant.tile, requested, grant.delivered, start, clock_.now()});
  record_.frame_busy[f] += tile.work.total();
  record_.work += tile.work;
  record_.rays += tile.rays;
  record_.ops += tile.ops;
  record_.pixels += static_cast<std::uint64_t>(pixels);
}

void Cell::deliver_link(const LinkMessage& m) {
  switch (m.packet.kind) {
    case LinkKind::Corners:
      link_inbox_.deliver(m);
      return;
    case LinkKind::StealRequest:
      record_.balance_bytes_received += m.bytes;
      answer_steal_request(m);
      return;
    case LinkKind::Work:
    case LinkKind::NoWork:
      steal_inbox_.deliver(m);
      return;
    case LinkKind::Pixels:
      returns_inbox_.deliver(m);
      return;
  }
}

// Stealing (balance.h). Plain, the chunks are of its tracing; antialiased, the
// corners are traced and exchanged as statically (the exchange needs every
// owner's corners) and the chunks are of phase 3, the subdivision. The unit is
// one frame.
Task<> Cell::trace_stealing(const DistributionUnit& unit) {
  if (unit.frames != 1) throw std::logic_error("chunks are stolen one frame at a time");
  const int f = unit.first_frame;
  if (wire_.antialiased) {
    co_await trace_corners(unit);
    co_await exchange_corners(*unit.exchange);
    record_.work += video_[f].corner_work;
    record_.ops += video_[f].corner_ops;
    record_.rays += video_[f].corner_ops.rays;
    record_.frame_busy[f] += video_[f].corner_work.total();
  }
  const Cycles start = clock_.now();
  record_.frame_write_start[f] = start;
  co_await trace_own_chunks(f);
  co_await steal_from_neighbours(f);
  co_await collect_returned_pixels(f);
  if (wire_.antialiased) record_.subdivide += clock_.now() - start;
}

// Its own chunks, front to back, while thieves take from the back; requests
// that came before it opened the frame are answered as it does.
Task<> Cell::trace_own_chunks(int f) {
  const TracedCell& own = video_[f];
  const int pixels = wire_.frames[f].layout.window(id_).pixel_count();
  queue_ = {f, 0, static_cast<int>(own.chunk_work.size())};
  std::vector<LinkMessage> waiting;
  waiting.swap(deferred_);
  for (const LinkMessage& m : waiting) answer_steal_request(m);
  while (queue_.front < queue_.back) {
    const int k = queue_.front++;
    const Cycles begin = clock_.now();
    co_await clock_.compute(own.chunk_work[k].total(), frame_name(fmt::format("trace chunk {}", k), f),
                            wire_.antialiased ? "subdivision" : "tracing",
                            wire_.antialiased ? SpanCategory::Subdivide : SpanCategory::Compute);
    count_chunk(own, f, k, pixels);
    record_.chunk_runs.push_back({f, id_, k, 1, begin, clock_.now()});
  }
}

// Asks its neighbours in turn for work; a neighbour that gives is asked again
// first; it stops when every neighbour has answered "no work" in a row.
Task<> Cell::steal_from_neighbours(int f) {
  std::size_t refused = 0, next = 0;
  while (!neighbours_.empty() && refused < neighbours_.size()) {
    const CellId victim = neighbours_[next % neighbours_.size()];
    LinkPacket request{LinkKind::StealRequest};
    request.frame = f;
    const Cycles asking = clock_.now();
    co_await wire_.links.send(id_, victim, kStealRequestBytes, request);
    record_.comm += clock_.now() - asking;
    clock_.span(fmt::format("steal request to {}", cell_name(victim)), SpanCategory::Message, asking, clock_.now(),
                kStealRequestBytes);
    ++record_.steal_requests;
    record_.balance_bytes_sent += kStealRequestBytes;
    const Cycles waiting = clock_.now();
    const LinkMessage answer = co_await steal_inbox_.receive();
    record_.balance_bytes_received += answer.bytes;
    if (clock_.now() > waiting) {
      ++record_.steal_waits;
      record_.steal_wait += clock_.now() - waiting;
      clock_.wait("wait for work", waiting, clock_.now());
    }
    if (answer.packet.kind == LinkKind::NoWork) {
      ++record_.steals_refused;
      ++refused;
      ++next;
      continue;
    }
    refused = 0;
    co_await trace_stolen(answer);
  }
}

// The chunks a victim gave, traced from its window; their pixels go back to
// its video memory over the links.
Task<> Cell::trace_stolen(const LinkMessage& work) {
  const LinkPacket& p = work.packet;
  const TracedCell& window = wire_.video_of(p.owner, p.frame);
  const int pixels = wire_.frames[p.frame].layout.window(p.owner).pixel_count();
  const Cycles begin = clock_.now();
  int traced = 0;
  for (int k = p.first_chunk; k < p.first_chunk + p.chunks; ++k) {
    co_await clock_.compute(window.chunk_work[k].total(),
                            frame_name(fmt::format("trace chunk {} of {}", k, cell_name(p.owner)), p.frame),
                            wire_.antialiased ? "subdivision" : "tracing",
                            wire_.antialiased ? SpanCategory::Subdivide : SpanCategory::Compute);
    count_chunk(window, p.frame, k, pixels);
    traced += chunk_range(k, pixels, wire_.chunk_pixels).pixels;
  }
  record_.chunk_runs.push_back({p.frame, p.owner, p.first_chunk, p.chunks, begin, clock_.now()});
  record_.chunks_stolen += static_cast<std::uint64_t>(p.chunks);
  const std::uint64_t bytes = kStolenWorkHeaderBytes + static_cast<std::uint64_t>(traced) * kVideoPixelBytes;
  LinkPacket back = p;
  back.kind = LinkKind::Pixels;
  const Cycles sending = clock_.now();
  co_await wire_.links.send(id_, p.owner, bytes, back);
  record_.comm += clock_.now() - sending;
  clock_.span(fmt::format("send pixels to {}", cell_name(p.owner)), SpanCategory::Message, sending, clock_.now(),
              bytes);
  record_.balance_bytes_sent += bytes;
}

// Every chunk it gave away is back in its video memory. It gives none once its
// own are all started, so the count is final here.
Task<> Cell::collect_returned_pixels(int f) {
  const Cycles waiting = clock_.now();
  for (; grants_out_ > 0; --grants_out_) {
    const LinkMessage m = co_await returns_inbox_.receive();
    if (m.packet.frame != f || m.packet.owner != id_)
      throw std::logic_error(fmt::format("{} took in pixels of another window or frame", cell_name(id_)));
    record_.balance_bytes_received += m.bytes;
    record_.returned.push_back({f, m.packet.first_chunk, m.packet.chunks, m.arrived});
  }
  clock_.wait("wait for pixels", waiting, clock_.now());
}

// The cell's link interface answers at once, without the program: half of its
// unstarted chunks (rounded down) from the back, or "no work". A request for
// a frame it has not opened yet waits until it does.
void Cell::answer_steal_request(const LinkMessage& request) {
  if (request.packet.frame != queue_.frame) {
    deferred_.push_back(request);
    return;
  }
  ++record_.requests_answered;
  const int give = (queue_.back - queue_.front) / 2;
  if (give == 0) {
    LinkPacket no{LinkKind::NoWork};
    no.frame = queue_.frame;
    record_.balance_bytes_sent += kNoWorkBytes;
    wire_.kernel.spawn(send_from_link_interface(request.from, kNoWorkBytes, no));
    return;
  }
  queue_.back -= give;
  record_.chunks_given += static_cast<std::uint64_t>(give);
  ++grants_out_;
  LinkPacket work{LinkKind::Work};
  work.frame = queue_.frame;
  work.owner = id_;
  work.first_chunk = queue_.back;
  work.chunks = give;
  std::uint64_t bytes = kStolenWorkHeaderBytes;
  if (wire_.antialiased) {
    // The thief subdivides from every corner of each pixel, which this cell
    // holds after the exchange.
    const int pixels = wire_.frames[queue_.frame].layout.window(id_).pixel_count();
    std::uint64_t given = 0;
    for (int k = work.first_chunk; k < work.first_chunk + give; ++k)
      given += static_cast<std::uint64_t>(chunk_range(k, pixels, wire_.chunk_pixels).pixels);
    bytes += given * 4 * kScreenSampleBytes;
  }
  record_.balance_bytes_sent += bytes;
  wire_.kernel.spawn(send_from_link_interface(request.from, bytes, work));
}

Process Cell::send_from_link_interface(CellId to, std::uint64_t bytes, LinkPacket packet) {
  co_await wire_.links.send(id_, to, bytes, packet);
}

void Cell::count_chunk(const TracedCell& window, int f, int k, int window_pixels) {
  record_.frame_busy[f] += window.chunk_work[k].total();
  record_.work += window.chunk_work[k];
  record_.ops += window.chunk_ops[k];
  record_.rays += window.chunk_ops[k].rays;
  record_.pixels += static_cast<std::uint64_t>(chunk_range(k, window_pixels, wire_.chunk_pixels).pixels);
}

// A step's messages, in order; the sender continues as each has left it. What
// the horizontal step relays must have come in the vertical one.
Task<> Cell::send_corners(const CornerExchange& exchange, ExchangeStep step) {
  const std::vector<CornerMessage>& sends = exchange.sends(id_, step);
  for (std::size_t i = 0; i < sends.size(); ++i) {
    const CornerMessage& m = sends[i];
    if (step == ExchangeStep::Horizontal) check_holds(m, exchange);
    const std::uint64_t bytes = m.corners.size() * kScreenSampleBytes;
    const Cycles begin = clock_.now();
    co_await wire_.links.send(id_, m.to, bytes, LinkPacket{LinkKind::Corners, step, i});
    record_.comm += clock_.now() - begin;
    clock_.span(fmt::format("send corners to {}", cell_name(m.to)), SpanCategory::Message, begin, clock_.now(),
                bytes);
  }
}

// Takes in every message of the step. A horizontal message that comes during
// the vertical step waits in memory for its turn.
Task<> Cell::receive_corners(const CornerExchange& exchange, ExchangeStep step) {
  const Cycles waiting = clock_.now();
  int received = 0;
  if (step == ExchangeStep::Horizontal) {
    for (const LinkMessage& m : early_) take_in(m, exchange);
    received = static_cast<int>(early_.size());
    early_.clear();
  }
  while (received < exchange.receives(id_, step)) {
    LinkMessage m = co_await link_inbox_.receive();
    if (m.packet.step != step) {
      early_.push_back(std::move(m));
      continue;
    }
    take_in(m, exchange);
    ++received;
  }
  clock_.wait("wait for corners", waiting, clock_.now());
}

void Cell::count_frame(int f) {
  const TracedCell& v = video_[f];
  record_.frame_busy[f] = v.work.total();
  record_.work += v.work;
  record_.rays += v.rays;
  record_.ops += v.ops;
  record_.pixels += static_cast<std::uint64_t>(wire_.frames[f].layout.window(id_).pixel_count());
}

void Cell::count_received_corners() {
  record_.corners_received += unit_received_.size();
  // A later unit's corners are of later frames, so the list stays ascending.
  if (wire_.keep_received_corners)
    record_.received_corners.insert(record_.received_corners.end(), unit_received_.begin(), unit_received_.end());
  unit_received_.clear();
}

std::string Cell::frame_name(std::string_view what, int frame) const {
  return frame_span_name(what, frame, wire_.frames.size());
}

std::string Cell::pixels_name(std::string_view verb, int frame) const {
  return frame_name(fmt::format("{} {} pixels", verb, wire_.frames[frame].layout.window(id_).pixel_count()), frame);
}

std::string Cell::cell_name(CellId id) const {
  const CellPosition p = wire_.grid.position(id);
  return fmt::format("cell[{},{}]", p.row, p.col);
}

void Cell::take_in(const LinkMessage& m, const CornerExchange& exchange) {
  const CornerMessage& sent = exchange.sends(m.from, m.packet.step).at(m.packet.index);
  if (sent.to != id_)
    throw std::logic_error(fmt::format("{} took in corners sent to {}", cell_name(id_), cell_name(sent.to)));
  // Kept ascending: a message's corners are in ascending order already (the
  // exchange plans them so), merged in at a cost linear in what is held.
  const auto middle = unit_received_.insert(unit_received_.end(), sent.corners.begin(), sent.corners.end());
  if (!std::is_sorted(middle, unit_received_.end())) std::sort(middle, unit_received_.end());
  std::inplace_merge(unit_received_.begin(), middle, unit_received_.end());
}

void Cell::check_holds(const CornerMessage& m, const CornerExchange& exchange) {
  // What it relays must have reached it: ones taken in, or its own corners.
  // Both lists ascend, so each search starts where the last one ended.
  auto from = unit_received_.begin();
  for (const CornerIndex c : m.corners) {
    from = std::lower_bound(from, unit_received_.end(), c);
    if ((from == unit_received_.end() || *from != c) && exchange.owner(c) != id_)
      throw std::logic_error(fmt::format("{} relays corner {} before it came", cell_name(id_), c));
  }
}

void Cell::check_has_every_corner(const CornerExchange& exchange) {
  const std::vector<CornerIndex>& got = unit_received_;
  const std::vector<CornerIndex>& needs = exchange.needs(id_);
  if (!std::includes(got.begin(), got.end(), needs.begin(), needs.end()))
    throw std::logic_error(fmt::format("{} lacks corners it needs after the exchange", cell_name(id_)));
}

void Cell::take_in(const BusTransfer& t, BusMessage expected) {
  if (t.message != expected)
    throw std::logic_error(fmt::format("cell {} expected \"{}\" from the host, got \"{}\"", id_,
                                       to_string(expected), to_string(t.message)));
  record_.comm += t.delivered - t.granted;
  clock_.span(fmt::format("receive {}", to_string(t.message)), SpanCategory::Receive, t.granted, t.delivered,
              t.bytes);
}

}  // namespace capsim::sim
