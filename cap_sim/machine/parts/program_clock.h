#pragma once
// The time of a program the machine runs (the host's, a cell's) as its
// timeline track shows it. The program's own work is one awaitable,
// compute(): its clock advances by the work's cycles, a span on its track
// covers them, they count as busy, and a run whose time no longer fits 64 bits
// fails naming who was doing what. Its waits and transfers are spans too.

#include "kernel/event_kernel.h"
#include "kernel/timeline.h"

#include <coroutine>
#include <cstdint>
#include <string>
#include <string_view>

namespace capsim::sim {

class ProgramClock {
 public:
  // `who` names the program in overflow messages ("cell[0,3]"); its busy
  // cycles add up in `busy`, which must outlive the clock.
  ProgramClock(EventKernel& kernel, Timeline& timeline, int track, std::string who, Cycles& busy);

  Cycles now() const { return kernel_->now(); }

  // co_await compute(work, label, activity): the program works `work` cycles
  // on its own (nothing it waits for can come meanwhile) and continues that
  // much later, in one kernel event however long the work; the span `label`
  // of `category` covers the work, which adds to the busy cycles. If the
  // run's time would pass 2^64 - 1 cycles, throws CycleOverflow located in
  // "<who>'s <activity>" (an empty activity leaves the kernel's message as it
  // is).
  struct ComputeAwaiter {
    ProgramClock& clock;
    Cycles work;
    std::string label;
    std::string_view activity;
    SpanCategory category;
    Cycles begin;
    bool await_ready() const noexcept { return false; }
    void await_suspend(std::coroutine_handle<> program) {
      begin = clock.now();
      clock.resume_after(work, activity, program);
    }
    void await_resume() { clock.worked(std::move(label), category, begin, work); }
  };
  // Precondition: `activity` outlives the co_await (a literal does).
  ComputeAwaiter compute(Cycles work, std::string label, std::string_view activity = {},
                         SpanCategory category = SpanCategory::Compute) {
    return {*this, work, std::move(label), activity, category, Cycles()};
  }

  // A span on the program's track.
  void span(std::string name, SpanCategory category, Cycles begin, Cycles end, std::uint64_t bytes = 0);
  // A wait from `since` to `until`: a span only if it lasted.
  void wait(std::string name, Cycles since, Cycles until);

 private:
  void resume_after(Cycles work, std::string_view activity, std::coroutine_handle<> program);
  void worked(std::string label, SpanCategory category, Cycles begin, Cycles work);

  EventKernel* kernel_;
  Timeline* timeline_;
  int track_;
  std::string who_;
  Cycles* busy_;
};

}  // namespace capsim::sim
