#include "kernel/event_kernel.h"

#include <fmt/core.h>

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace capsim::sim {

const char* to_string(EventPriority p) {
  switch (p) {
    case EventPriority::Delivery: return "delivery";
    case EventPriority::Resume: return "resume";
    case EventPriority::Arbitration: return "arbitration";
  }
  return "?";
}

bool EventKernel::runs_later(const Event& a, const Event& b) {
  if (a.at != b.at) return a.at > b.at;
  if (a.priority != b.priority) return a.priority > b.priority;
  return a.sequence > b.sequence;
}

Cycles EventKernel::after(Cycles delay) const {
  try {
    return now_ + delay;
  } catch (const CycleOverflow&) {
    throw CycleOverflow(fmt::format("an event {} cycles after cycle {}", delay.count(), now_.count()));
  }
}

void EventKernel::schedule(Cycles at, EventPriority priority, Action action) {
  if (at < now_) throw std::logic_error("event scheduled in the past");
  queue_.push_back(Event{at, priority, next_sequence_++, std::move(action)});
  std::push_heap(queue_.begin(), queue_.end(), runs_later);
}

void EventKernel::spawn(Process process) {
  const ProcessHandle h = process.handle();
  h.promise().escaped = &escaped_;
  processes_.push_back(std::move(process));
  resume_at(now_, h);
}

void EventKernel::resume_at(Cycles at, std::coroutine_handle<> process) {
  schedule(at, EventPriority::Resume, [process] { process.resume(); });
}

void EventKernel::run() {
  while (!queue_.empty()) {
    std::pop_heap(queue_.begin(), queue_.end(), runs_later);
    Event event = std::move(queue_.back());
    queue_.pop_back();
    now_ = event.at;
    ++events_run_;
    event.action();
    if (escaped_) std::rethrow_exception(std::exchange(escaped_, nullptr));
  }
}

bool EventKernel::all_processes_finished() const {
  return std::all_of(processes_.begin(), processes_.end(),
                     [](const Process& p) { return p.done(); });
}

}  // namespace capsim::sim
