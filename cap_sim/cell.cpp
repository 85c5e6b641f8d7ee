#include "cell.h"

#include "frame_protocol.h"

#include <fmt/core.h>

#include <algorithm>
#include <stdexcept>

namespace capsim::sim {

Cell::Cell(CellId id, const CellWindow& window, TracedCell traced, int timeline_track,
           const Wiring& wiring)
    : id_(id),
      window_(window),
      traced_(std::move(traced)),
      track_(timeline_track),
      wire_(wiring),
      bus_inbox_(wiring.kernel),
      link_inbox_(wiring.kernel) {}

namespace {

const char* exchange_label(ExchangeStep step) {
  return step == ExchangeStep::Vertical ? "corners (vertical step)" : "corners (horizontal step)";
}

// A link message's payload names the step and the message's place among its
// sender's sends of that step.
std::uint64_t exchange_payload(ExchangeStep step, std::size_t index) {
  return index * 2 + (step == ExchangeStep::Horizontal ? 1 : 0);
}
ExchangeStep payload_step(std::uint64_t payload) {
  return payload % 2 ? ExchangeStep::Horizontal : ExchangeStep::Vertical;
}

}  // namespace

Process Cell::run_frame() {
  // Every cell holds the same program and the same data (§3.3): take in what the
  // host broadcasts, then wait for its start command.
  Cycles waiting_since = wire_.kernel.now();
  for (std::string_view expected : kFrameBroadcasts) {
    const BusTransfer t = co_await bus_inbox_.receive();
    if (t.granted > waiting_since)
      wire_.timeline.span(track_, "wait for host", "wait", waiting_since, t.granted);
    take_in(t, expected);
    waiting_since = wire_.kernel.now();
  }
  const Cycles idle_end = wire_.kernel.now();

  if (!wire_.exchange) {
    // Trace the pixels this cell's window controller shows, in order, into video
    // memory: the clock advances by the cycles of every pixel's operations. The
    // host threads traced them ahead; nothing reaches a cell while it traces, so
    // its clock advances once by their sum (the same time as pixel by pixel,
    // without an event per pixel) and its video memory takes them all at the end.
    co_await wire_.kernel.delay(traced_.work.total());
    wire_.timeline.span(track_, fmt::format("trace {} pixels", window_.pixel_count()), "compute",
                        idle_end, wire_.kernel.now());
  } else {
    const CornerExchange& exchange = *wire_.exchange;

    // Antialiasing, phase 1: trace the corner samples this cell owns (each of
    // its pixels' top-left corner, and the screen's extra right column and
    // bottom row where its pixels border them) into video memory.
    co_await wire_.kernel.delay(traced_.corner_work.total());
    record_.trace_corners = wire_.kernel.now() - idle_end;
    wire_.timeline.span(track_, "trace corners", "compute", idle_end, wire_.kernel.now());

    // Phase 2: exchange corners with the neighbours, a vertical step and then a
    // horizontal one (corner_exchange.h): send this step's messages, then take
    // in this step's. A horizontal message that arrives during the vertical
    // step waits in memory for its turn.
    const Cycles exchange_start = wire_.kernel.now();
    for (const ExchangeStep step : {ExchangeStep::Vertical, ExchangeStep::Horizontal}) {
      const auto& sends = exchange.sends(id_, step);
      for (std::size_t i = 0; i < sends.size(); ++i) {
        const CornerMessage& m = sends[i];
        if (step == ExchangeStep::Horizontal) check_holds(m);
        const Cycles begin = wire_.kernel.now();
        co_await wire_.links.send(id_, m.to, m.corners.size() * kScreenSampleBytes,
                                  std::string(exchange_label(step)), exchange_payload(step, i));
        record_.comm += wire_.kernel.now() - begin;
        wire_.timeline.span(track_, fmt::format("send corners to {}", cell_name(m.to)), "message",
                            begin, wire_.kernel.now(), m.corners.size() * kScreenSampleBytes);
      }
      const Cycles waiting = wire_.kernel.now();
      int received = 0;
      if (step == ExchangeStep::Horizontal) {
        for (const LinkMessage& m : early_) take_in(m);
        received = static_cast<int>(early_.size());
        early_.clear();
      }
      while (received < exchange.receives(id_, step)) {
        LinkMessage m = co_await link_inbox_.receive();
        if (payload_step(m.payload) != step) {
          early_.push_back(std::move(m));
          continue;
        }
        take_in(m);
        ++received;
      }
      if (wire_.kernel.now() > waiting)
        wire_.timeline.span(track_, "wait for corners", "wait", waiting, wire_.kernel.now());
    }
    check_has_every_corner();
    record_.exchange = wire_.kernel.now() - exchange_start;

    // Phase 3: subdivide its own pixels where their corners differ by the
    // threshold or more, tracing the extra samples on its own clock.
    const Cycles subdivide_start = wire_.kernel.now();
    co_await wire_.kernel.delay(traced_.subdivision_work.total());
    record_.subdivide = wire_.kernel.now() - subdivide_start;
    wire_.timeline.span(track_, fmt::format("subdivide {} pixels", window_.pixel_count()), "compute",
                        subdivide_start, wire_.kernel.now());
  }
  video_memory_ = std::move(traced_.samples);
  video_srgb8_ = std::move(traced_.srgb8);
  record_.work = traced_.work;
  record_.rays = traced_.rays;
  record_.pixels = static_cast<std::uint64_t>(window_.pixel_count());
  record_.busy = traced_.work.total();

  // Tell the host this cell is done.
  const BusTransfer done = co_await wire_.bus.transfer(id_, kHost, kDoneMessageBytes,
                                                       std::string(kDoneMessage));
  if (done.granted > done.requested)
    wire_.timeline.span(track_, "wait for bus", "wait", done.requested, done.granted);
  wire_.timeline.span(track_, "send done", "message", done.granted, done.delivered, done.bytes);
  record_.comm += done.delivered - done.requested;
  record_.finish = done.delivered;
}


std::string Cell::cell_name(CellId id) const {
  const CellPosition p = wire_.grid.position(id);
  return fmt::format("cell[{},{}]", p.row, p.col);
}

void Cell::take_in(const LinkMessage& m) {
  const ExchangeStep step = payload_step(m.payload);
  const CornerMessage& sent = wire_.exchange->sends(m.from, step).at(m.payload / 2);
  if (sent.to != id_)
    throw std::logic_error(fmt::format("{} took in corners sent to {}", cell_name(id_), cell_name(sent.to)));
  record_.corners_received.insert(record_.corners_received.end(), sent.corners.begin(), sent.corners.end());
}

void Cell::check_holds(const CornerMessage& m) {
  // What it relays must have reached it: its own corners, or ones taken in.
  std::sort(record_.corners_received.begin(), record_.corners_received.end());
  for (const CornerIndex c : m.corners) {
    const int x = static_cast<int>(c % (wire_.exchange->width() + 1));
    const int y = static_cast<int>(c / (wire_.exchange->width() + 1));
    if (wire_.exchange->owner(x, y) != id_ &&
        !std::binary_search(record_.corners_received.begin(), record_.corners_received.end(), c))
      throw std::logic_error(fmt::format("{} relays corner ({}, {}) before it came", cell_name(id_), x, y));
  }
}

void Cell::check_has_every_corner() {
  std::vector<CornerIndex>& got = record_.corners_received;
  std::sort(got.begin(), got.end());
  const std::vector<CornerIndex>& needs = wire_.exchange->needs(id_);
  if (!std::includes(got.begin(), got.end(), needs.begin(), needs.end()))
    throw std::logic_error(fmt::format("{} lacks corners it needs after the exchange", cell_name(id_)));
}

void Cell::take_in(const BusTransfer& t, std::string_view expected) {
  if (t.label != expected)
    throw std::logic_error(fmt::format("cell {} expected \"{}\" from the host, got \"{}\"", id_,
                                       expected, t.label));
  record_.comm += t.delivered - t.granted;
  wire_.timeline.span(track_, fmt::format("receive {}", t.label), "receive", t.granted, t.delivered,
                      t.bytes);
}

}  // namespace capsim::sim
