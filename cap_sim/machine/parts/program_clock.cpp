#include "machine/parts/program_clock.h"

#include <fmt/core.h>

#include <utility>

namespace capsim::sim {

ProgramClock::ProgramClock(EventKernel& kernel, Timeline& timeline, int track, std::string who, Cycles& busy)
    : kernel_(&kernel), timeline_(&timeline), track_(track), who_(std::move(who)), busy_(&busy) {}

void ProgramClock::resume_after(Cycles work, std::string_view activity, std::coroutine_handle<> program) {
  try {
    kernel_->resume_at(kernel_->after(work), program);
  } catch (const CycleOverflow& e) {
    if (activity.empty()) throw;
    throw e.inside(fmt::format("{}'s {}", who_, activity));
  }
}

void ProgramClock::worked(std::string label, SpanCategory category, Cycles begin, Cycles work) {
  timeline_->span(track_, std::move(label), category, begin, now());
  *busy_ += work;
}

void ProgramClock::span(std::string name, SpanCategory category, Cycles begin, Cycles end, std::uint64_t bytes) {
  timeline_->span(track_, std::move(name), category, begin, end, bytes);
}

void ProgramClock::wait(std::string name, Cycles since, Cycles until) {
  if (until > since) span(std::move(name), SpanCategory::Wait, since, until);
}

}  // namespace capsim::sim
