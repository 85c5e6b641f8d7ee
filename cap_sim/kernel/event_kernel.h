#pragma once
// The discrete-event kernel: one clock, one queue of events, processes as
// coroutines.
//
// Total order of events (documented in docs/simulation.md and tested):
//   1. cycle, earliest first;
//   2. EventPriority within a cycle, lowest value first;
//   3. insertion sequence: among events of equal cycle and priority, the one
//      scheduled first runs first (FIFO).
// An event scheduled for the current cycle with a priority whose turn has
// already passed runs next: time never goes backwards.

#include "kernel/cycles.h"
#include "kernel/process.h"

#include <coroutine>
#include <cstdint>
#include <exception>
#include <functional>
#include <string>
#include <vector>

namespace capsim::sim {

enum class EventPriority : std::uint8_t {
  // A transfer or message lands in its receiver's memory. First, so that every
  // process running in the same cycle sees the data.
  Delivery = 0,
  // A process continues after a delay or after being woken.
  Resume = 1,
  // The command bus chooses its next grant. Last, so that every request made in
  // this cycle by any process competes in the same arbitration.
  Arbitration = 2,
};

const char* to_string(EventPriority p);

class EventKernel {
 public:
  using Action = std::function<void()>;

  Cycles now() const { return now_; }

  // Precondition: at >= now().
  void schedule(Cycles at, EventPriority priority, Action action);
  void schedule_after(Cycles delay, EventPriority priority, Action action) {
    schedule(after(delay), priority, std::move(action));
  }
  // The cycle `delay` after now(). Throws CycleOverflow naming both beyond 2^64 - 1.
  Cycles after(Cycles delay) const;

  // Takes ownership of a process and starts it at the current cycle
  // (priority Resume).
  void spawn(Process process);

  // Resumes a suspended process, or the task it waits in, at the given cycle
  // (priority Resume).
  void resume_at(Cycles at, std::coroutine_handle<> process);

  // Runs events in order until none is left. Rethrows the first exception a
  // process body lets escape.
  void run();

  // True when every spawned process has run to its end (false after a run means
  // some process still waits for something that never came: a deadlock).
  bool all_processes_finished() const;
  std::uint64_t events_run() const { return events_run_; }

  // co_await kernel.delay(c): the process continues c cycles later.
  struct DelayAwaiter {
    EventKernel& kernel;
    Cycles duration;
    bool await_ready() const noexcept { return false; }
    void await_suspend(std::coroutine_handle<> h) const { kernel.resume_at(kernel.after(duration), h); }
    void await_resume() const noexcept {}
  };
  DelayAwaiter delay(Cycles duration) { return {*this, duration}; }

 private:
  struct Event {
    Cycles at;
    EventPriority priority;
    std::uint64_t sequence;
    Action action;
  };
  // Heap order: the event that must run next compares greatest.
  static bool runs_later(const Event& a, const Event& b);

  Cycles now_{0};
  std::uint64_t next_sequence_ = 0;
  std::uint64_t events_run_ = 0;
  std::vector<Event> queue_;  // a binary heap under runs_later
  std::vector<Process> processes_;
  std::exception_ptr escaped_;  // what a process body let escape (Process::promise_type::escaped)
};

}  // namespace capsim::sim
