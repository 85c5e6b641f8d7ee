#include "machine/cell.h"

#include "machine/frame_protocol.h"

#include <fmt/core.h>

#include <algorithm>
#include <stdexcept>

namespace capsim::sim {

Cell::Cell(CellId id, int timeline_track, const Wiring& wiring)
    : id_(id),
      track_(timeline_track),
      wire_(wiring),
      bus_inbox_(wiring.kernel),
      link_inbox_(wiring.kernel) {
  video_.reserve(wiring.frames.size());
  for (FrameWork& f : wiring.frames) video_.push_back(std::move(f.cells.at(id)));
  record_.frame_busy.resize(wiring.frames.size());
  record_.frame_write_start.resize(wiring.frames.size());
}

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

Process Cell::run() {
  for (std::size_t u = 0; u < wire_.units.size(); ++u) {
    const DistributionUnit& unit = wire_.units[u];
    const int first = unit.first_frame, end = unit.first_frame + unit.frames;

    // Every cell holds the same program and the same data (§3.3): take in what
    // the host broadcasts for the unit's frames, then wait for its start command.
    Cycles waiting_since = wire_.kernel.now();
    for (const std::string_view expected : unit_broadcasts(u == 0, unit.frames)) {
      const BusTransfer t = co_await bus_inbox_.receive();
      if (t.granted > waiting_since)
        wire_.timeline.span(track_, "wait for host", SpanCategory::Wait, waiting_since, t.granted);
      take_in(t, expected);
      waiting_since = wire_.kernel.now();
    }
    const Cycles started = wire_.kernel.now();

    if (!wire_.antialiased) {
      // Trace the pixels this cell's window controller shows, frame after frame,
      // in order, into video memory: the clock advances by the cycles of every
      // pixel's operations. The host threads traced them ahead; nothing reaches
      // a cell while it traces, so its clock advances once per frame by their sum
      // (the same time as pixel by pixel, without an event per pixel).
      for (int f = first; f < end; ++f) {
        const Cycles begin = wire_.kernel.now();
        record_.frame_write_start[f] = begin;
        try {
          co_await wire_.kernel.delay(video_[f].work.total());
        } catch (const CycleOverflow& e) {
          throw e.inside(fmt::format("{}'s tracing", cell_name(id_)));
        }
        record_.frame_busy[f] = video_[f].work.total();
        wire_.timeline.span(
            track_, frame_name(fmt::format("trace {} pixels", wire_.frames[f].layout.window(id_).pixel_count()), f),
            SpanCategory::Compute, begin, wire_.kernel.now());
      }
    } else {
      const CornerExchange& exchange = *unit.exchange;

      // Antialiasing, phase 1: trace the corner samples this cell owns in each
      // of the unit's frames (each of its pixels' top-left corner, and the
      // screen's extra right column and bottom row where its pixels border them)
      // into video memory.
      for (int f = first; f < end; ++f) {
        const Cycles begin = wire_.kernel.now();
        try {
          co_await wire_.kernel.delay(video_[f].corner_work.total());
        } catch (const CycleOverflow& e) {
          throw e.inside(fmt::format("{}'s corner tracing", cell_name(id_)));
        }
        wire_.timeline.span(track_, frame_name("trace corners", f), SpanCategory::Compute, begin, wire_.kernel.now());
      }
      record_.trace_corners += wire_.kernel.now() - started;

      // Phase 2: exchange corners with the neighbours, a vertical step and then a
      // horizontal one (corner_exchange.h): send this step's messages, then take
      // in this step's. A horizontal message that arrives during the vertical
      // step waits in memory for its turn.
      const Cycles exchange_start = wire_.kernel.now();
      for (const ExchangeStep step : {ExchangeStep::Vertical, ExchangeStep::Horizontal}) {
        const auto& sends = exchange.sends(id_, step);
        for (std::size_t i = 0; i < sends.size(); ++i) {
          const CornerMessage& m = sends[i];
          if (step == ExchangeStep::Horizontal) check_holds(m, exchange);
          const Cycles begin = wire_.kernel.now();
          co_await wire_.links.send(id_, m.to, m.corners.size() * kScreenSampleBytes,
                                    std::string(exchange_label(step)), exchange_payload(step, i));
          record_.comm += wire_.kernel.now() - begin;
          wire_.timeline.span(track_, fmt::format("send corners to {}", cell_name(m.to)), SpanCategory::Message, begin,
                              wire_.kernel.now(), m.corners.size() * kScreenSampleBytes);
        }
        const Cycles waiting = wire_.kernel.now();
        int received = 0;
        if (step == ExchangeStep::Horizontal) {
          for (const LinkMessage& m : early_) take_in(m, exchange);
          received = static_cast<int>(early_.size());
          early_.clear();
        }
        while (received < exchange.receives(id_, step)) {
          LinkMessage m = co_await link_inbox_.receive();
          if (payload_step(m.payload) != step) {
            early_.push_back(std::move(m));
            continue;
          }
          take_in(m, exchange);
          ++received;
        }
        if (wire_.kernel.now() > waiting)
          wire_.timeline.span(track_, "wait for corners", SpanCategory::Wait, waiting, wire_.kernel.now());
      }
      check_has_every_corner(exchange);
      record_.corners_received += unit_received_.size();
      // A later unit's corners are of later frames, so the list stays ascending.
      if (wire_.keep_received_corners)
        record_.received_corners.insert(record_.received_corners.end(), unit_received_.begin(), unit_received_.end());
      unit_received_.clear();
      record_.exchange += wire_.kernel.now() - exchange_start;

      // Phase 3: subdivide its own pixels where their corners differ by the
      // threshold or more, tracing the extra samples on its own clock.
      const Cycles subdivide_start = wire_.kernel.now();
      for (int f = first; f < end; ++f) {
        const Cycles begin = wire_.kernel.now();
        record_.frame_write_start[f] = begin;
        try {
          co_await wire_.kernel.delay(video_[f].subdivision_work.total());
        } catch (const CycleOverflow& e) {
          throw e.inside(fmt::format("{}'s subdivision", cell_name(id_)));
        }
        record_.frame_busy[f] = video_[f].work.total();
        wire_.timeline.span(
            track_,
            frame_name(fmt::format("subdivide {} pixels", wire_.frames[f].layout.window(id_).pixel_count()), f),
            SpanCategory::Compute, begin, wire_.kernel.now());
      }
      record_.subdivide += wire_.kernel.now() - subdivide_start;
    }
    for (int f = first; f < end; ++f) {
      record_.work += video_[f].work;
      record_.busy += video_[f].work.total();
      record_.rays += video_[f].rays;
      record_.ops += video_[f].ops;
      record_.pixels += static_cast<std::uint64_t>(wire_.frames[f].layout.window(id_).pixel_count());
    }

    // Tell the host this cell is done with the unit.
    const BusTransfer done =
        co_await wire_.bus.transfer(id_, kHost, kDoneMessageBytes, std::string(kDoneMessage));
    if (done.granted > done.requested)
      wire_.timeline.span(track_, "wait for bus", SpanCategory::Wait, done.requested, done.granted);
    wire_.timeline.span(track_, "send done", SpanCategory::Message, done.granted, done.delivered, done.bytes);
    record_.comm += done.delivered - done.requested;
    record_.finish = done.delivered;
    record_.unit_finish.push_back(done.delivered);
  }
}

std::string Cell::frame_name(const std::string& what, int frame) const {
  return wire_.frames.size() == 1 ? what : fmt::format("{}, frame {}", what, frame);
}

std::string Cell::cell_name(CellId id) const {
  const CellPosition p = wire_.grid.position(id);
  return fmt::format("cell[{},{}]", p.row, p.col);
}

void Cell::take_in(const LinkMessage& m, const CornerExchange& exchange) {
  const ExchangeStep step = payload_step(m.payload);
  const CornerMessage& sent = exchange.sends(m.from, step).at(m.payload / 2);
  if (sent.to != id_)
    throw std::logic_error(fmt::format("{} took in corners sent to {}", cell_name(id_), cell_name(sent.to)));
  unit_received_.insert(unit_received_.end(), sent.corners.begin(), sent.corners.end());
}

void Cell::check_holds(const CornerMessage& m, const CornerExchange& exchange) {
  // What it relays must have reached it: its own corners, or ones taken in.
  std::sort(unit_received_.begin(), unit_received_.end());
  for (const CornerIndex c : m.corners)
    if (exchange.owner(c) != id_ &&
        !std::binary_search(unit_received_.begin(), unit_received_.end(), c))
      throw std::logic_error(fmt::format("{} relays corner {} before it came", cell_name(id_), c));
}

void Cell::check_has_every_corner(const CornerExchange& exchange) {
  std::vector<CornerIndex>& got = unit_received_;
  std::sort(got.begin(), got.end());
  const std::vector<CornerIndex>& needs = exchange.needs(id_);
  if (!std::includes(got.begin(), got.end(), needs.begin(), needs.end()))
    throw std::logic_error(fmt::format("{} lacks corners it needs after the exchange", cell_name(id_)));
}

void Cell::take_in(const BusTransfer& t, std::string_view expected) {
  if (t.label != expected)
    throw std::logic_error(fmt::format("cell {} expected \"{}\" from the host, got \"{}\"", id_,
                                       expected, t.label));
  record_.comm += t.delivered - t.granted;
  wire_.timeline.span(track_, fmt::format("receive {}", t.label), SpanCategory::Receive, t.granted, t.delivered,
                      t.bytes);
}

}  // namespace capsim::sim
