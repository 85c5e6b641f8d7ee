// The discrete-event kernel: event order, processes, mailboxes, tasks.

#include "kernel/event_kernel.h"
#include "kernel/mailbox.h"
#include "kernel/task.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace capsim::sim {
namespace {

TEST(EventKernel, OrdersByCycleThenPriorityThenInsertion) {
  EventKernel k;
  std::vector<std::string> log;
  auto note = [&](std::string s) { return [&log, s] { log.push_back(s); }; };
  k.schedule(Cycles(5), EventPriority::Resume, note("5-resume-a"));
  k.schedule(Cycles(3), EventPriority::Arbitration, note("3-arbitration"));
  k.schedule(Cycles(5), EventPriority::Delivery, note("5-delivery"));
  k.schedule(Cycles(3), EventPriority::Resume, note("3-resume"));
  k.schedule(Cycles(5), EventPriority::Resume, note("5-resume-b"));
  k.schedule(Cycles(0), EventPriority::Arbitration, note("0-arbitration"));
  k.schedule(Cycles(5), EventPriority::Arbitration, note("5-arbitration"));
  k.schedule(Cycles(5), EventPriority::Resume, note("5-resume-c"));
  k.run();
  EXPECT_EQ(log, (std::vector<std::string>{"0-arbitration", "3-resume", "3-arbitration",
                                           "5-delivery", "5-resume-a", "5-resume-b",
                                           "5-resume-c", "5-arbitration"}));
  EXPECT_EQ(k.now(), Cycles(5));
  EXPECT_EQ(k.events_run(), 8u);
}

TEST(EventKernel, EventsScheduledDuringACycleKeepTheOrder) {
  EventKernel k;
  std::vector<std::string> log;
  k.schedule(Cycles(2), EventPriority::Resume, [&] {
    log.push_back("resume");
    // Same cycle, later priority: after the other resume already queued.
    k.schedule(Cycles(2), EventPriority::Arbitration, [&] { log.push_back("arbitration"); });
    // Same cycle, earlier priority than the one running: runs next, time stays.
    k.schedule(Cycles(2), EventPriority::Delivery, [&] { log.push_back("late delivery"); });
  });
  k.schedule(Cycles(2), EventPriority::Resume, [&] { log.push_back("second resume"); });
  k.run();
  EXPECT_EQ(log, (std::vector<std::string>{"resume", "late delivery", "second resume",
                                           "arbitration"}));
}

TEST(EventKernel, RefusesThePast) {
  EventKernel k;
  k.schedule(Cycles(10), EventPriority::Resume, [&] {
    EXPECT_THROW(k.schedule(Cycles(9), EventPriority::Resume, [] {}), std::logic_error);
  });
  k.run();
}

Process sleeper(EventKernel& k, std::vector<std::uint64_t>& times, std::uint64_t step, int n) {
  for (int i = 0; i < n; ++i) {
    co_await k.delay(Cycles(step));
    times.push_back(k.now().count());
  }
}

TEST(EventKernel, ProcessesAdvanceByTheirDelays) {
  EventKernel k;
  std::vector<std::uint64_t> a, b;
  k.spawn(sleeper(k, a, 3, 3));
  k.spawn(sleeper(k, b, 4, 2));
  k.run();
  EXPECT_EQ(a, (std::vector<std::uint64_t>{3, 6, 9}));
  EXPECT_EQ(b, (std::vector<std::uint64_t>{4, 8}));
  EXPECT_TRUE(k.all_processes_finished());
  EXPECT_EQ(k.now(), Cycles(9));
}

TEST(EventKernel, ProcessesOfEqualWakeTimeRunInSpawnOrder) {
  EventKernel k;
  std::vector<int> order;
  auto p = [&](int id) -> Process {
    co_await k.delay(Cycles(7));
    order.push_back(id);
  };
  for (int id : {2, 0, 1}) k.spawn(p(id));
  k.run();
  EXPECT_EQ(order, (std::vector<int>{2, 0, 1}));
}

Process producer(EventKernel& k, Mailbox<int>& box) {
  co_await k.delay(Cycles(5));
  box.deliver(1);
  box.deliver(2);
  co_await k.delay(Cycles(5));
  box.deliver(3);
}

Process consumer(EventKernel& k, Mailbox<int>& box, std::vector<std::pair<int, std::uint64_t>>& got) {
  for (int i = 0; i < 3; ++i) {
    const int m = co_await box.receive();
    got.emplace_back(m, k.now().count());
  }
}

TEST(Mailbox, ReceiverWaitsAndTakesMessagesInArrivalOrder) {
  EventKernel k;
  Mailbox<int> box(k);
  std::vector<std::pair<int, std::uint64_t>> got;
  k.spawn(consumer(k, box, got));
  k.spawn(producer(k, box));
  k.run();
  EXPECT_EQ(got, (std::vector<std::pair<int, std::uint64_t>>{{1, 5}, {2, 5}, {3, 10}}));
  EXPECT_TRUE(k.all_processes_finished());
}

TEST(EventKernel, ReportsAProcessThatNeverFinishes) {
  EventKernel k;
  Mailbox<int> box(k);
  std::vector<std::pair<int, std::uint64_t>> got;
  k.spawn(consumer(k, box, got));
  k.run();
  EXPECT_FALSE(k.all_processes_finished());
}

Process failing(EventKernel& k) {
  co_await k.delay(Cycles(1));
  throw std::runtime_error("cell program failed");
}

TEST(EventKernel, RethrowsWhatAProcessLetsEscape) {
  EventKernel k;
  k.spawn(failing(k));
  EXPECT_THROW(k.run(), std::runtime_error);
}

// A step of a program as a task: its delays are the process's.
Task<std::uint64_t> step(EventKernel& k, std::uint64_t cycles, std::vector<std::uint64_t>& times) {
  co_await k.delay(Cycles(cycles));
  times.push_back(k.now().count());
  co_return k.now().count();
}

Task<> two_steps(EventKernel& k, std::vector<std::uint64_t>& times) {
  co_await step(k, 2, times);
  co_await step(k, 3, times);
}

TEST(Task, RunsAsPartOfTheAwaitingProcessWithoutEventsOfItsOwn) {
  // The same delays written in one body and split into tasks, nested two deep:
  // the same cycles and the same number of events.
  EventKernel flat;
  std::vector<std::uint64_t> flat_times;
  flat.spawn([](EventKernel& k, std::vector<std::uint64_t>& times) -> Process {
    for (const std::uint64_t c : {2, 3, 4, 2, 3}) {
      co_await k.delay(Cycles(c));
      times.push_back(k.now().count());
    }
  }(flat, flat_times));
  flat.run();

  EventKernel k;
  std::vector<std::uint64_t> times;
  std::uint64_t returned = 0;
  k.spawn([](EventKernel& k, std::vector<std::uint64_t>& times, std::uint64_t& returned) -> Process {
    co_await two_steps(k, times);
    returned = co_await step(k, 4, times);
    co_await two_steps(k, times);
  }(k, times, returned));
  k.run();
  EXPECT_EQ(times, (std::vector<std::uint64_t>{2, 5, 9, 11, 14}));
  EXPECT_EQ(times, flat_times);
  EXPECT_EQ(returned, 9u);
  EXPECT_TRUE(k.all_processes_finished());
  // One event to start the process, one per delay.
  EXPECT_EQ(k.events_run(), 6u);
  EXPECT_EQ(k.events_run(), flat.events_run());
}

Task<int> receive_in_task(Mailbox<int>& box) {
  const int m = co_await box.receive();
  co_return m * 10;
}

TEST(Task, WaitsForAMessageInTheProcessesPlace) {
  EventKernel k;
  Mailbox<int> box(k);
  std::vector<std::pair<int, std::uint64_t>> got;
  k.spawn([](EventKernel& k, Mailbox<int>& box, std::vector<std::pair<int, std::uint64_t>>& got) -> Process {
    for (int i = 0; i < 3; ++i) got.emplace_back(co_await receive_in_task(box), k.now().count());
  }(k, box, got));
  k.spawn(producer(k, box));
  k.run();
  EXPECT_EQ(got, (std::vector<std::pair<int, std::uint64_t>>{{10, 5}, {20, 5}, {30, 10}}));
  EXPECT_TRUE(k.all_processes_finished());
}

Task<> failing_step(EventKernel& k) {
  co_await k.delay(Cycles(1));
  throw std::runtime_error("step failed");
}

TEST(Task, AnExceptionReachesTheAwaitingProcess) {
  EventKernel k;
  std::string caught;
  k.spawn([](EventKernel& k, std::string& caught) -> Process {
    try {
      co_await failing_step(k);
    } catch (const std::runtime_error& e) {
      caught = e.what();
    }
    co_await k.delay(Cycles(1));
  }(k, caught));
  k.run();
  EXPECT_EQ(caught, "step failed");
  EXPECT_EQ(k.now(), Cycles(2));
  EXPECT_TRUE(k.all_processes_finished());
}

TEST(Task, AnExceptionNoneCatchesLeavesTheRun) {
  EventKernel k;
  k.spawn([](EventKernel& k) -> Process { co_await failing_step(k); }(k));
  EXPECT_THROW(k.run(), std::runtime_error);
}

TEST(Task, AnOverflowInsideATaskReachesItsProcess) {
  EventKernel k;
  bool overflowed = false;
  k.spawn([](EventKernel& k, bool& overflowed) -> Process {
    co_await k.delay(Cycles(10));
    try {
      co_await [](EventKernel& k) -> Task<> { co_await k.delay(Cycles(Cycles::kMax)); }(k);
    } catch (const CycleOverflow&) {
      overflowed = true;
    }
  }(k, overflowed));
  k.run();
  EXPECT_TRUE(overflowed);
  EXPECT_TRUE(k.all_processes_finished());
}

}  // namespace
}  // namespace capsim::sim
