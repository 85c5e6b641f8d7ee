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
      bus_inbox_(wiring.kernel) {}

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

  // Trace the pixels this cell's window controller shows, in order, into video
  // memory: the clock advances by the cycles of every pixel's operations. The
  // host threads traced them ahead; nothing reaches a cell while it traces, so
  // its clock advances once by their sum (the same time as pixel by pixel,
  // without an event per pixel) and its video memory takes them all at the end.
  try {
    co_await wire_.kernel.delay(traced_.work.total());
  } catch (const CycleOverflow& e) {
    throw e.inside(fmt::format("{}'s tracing", wire_.timeline.tracks().at(track_)));
  }
  video_memory_ = std::move(traced_.samples);
  record_.work = traced_.work;
  record_.rays = traced_.rays;
  record_.pixels = static_cast<std::uint64_t>(window_.pixel_count());
  record_.busy = wire_.kernel.now() - idle_end;
  wire_.timeline.span(track_, fmt::format("trace {} pixels", record_.pixels), "compute", idle_end,
                      wire_.kernel.now());

  // Tell the host this cell is done.
  const BusTransfer done = co_await wire_.bus.transfer(id_, kHost, kDoneMessageBytes,
                                                       std::string(kDoneMessage));
  if (done.granted > done.requested)
    wire_.timeline.span(track_, "wait for bus", "wait", done.requested, done.granted);
  wire_.timeline.span(track_, "send done", "message", done.granted, done.delivered, done.bytes);
  record_.comm += done.delivered - done.requested;
  record_.finish = done.delivered;
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
