// parallel_rows: every row once, whatever the threads; on one thread, in order
// on the calling thread, outside any TBB arena (the scheduler not started).

#include "capsim/system/host_threads.h"

#include <gtest/gtest.h>

#include <atomic>
#include <thread>
#include <vector>

using capsim::parallel_rows;

TEST(HostThreads, EveryRowOnceOnAnyNumberOfThreads) {
  for (const int threads : {0, 1, 2, 3, 8}) {
    for (const int count : {0, 1, 7, 1000}) {
      std::vector<std::atomic<int>> seen(static_cast<std::size_t>(count));
      parallel_rows(threads, count, [&](const tbb::blocked_range<int>& rows) {
        for (int r = rows.begin(); r != rows.end(); ++r) ++seen[static_cast<std::size_t>(r)];
      });
      for (int r = 0; r < count; ++r) EXPECT_EQ(seen[static_cast<std::size_t>(r)], 1) << threads << " " << count << " " << r;
    }
  }
}

TEST(HostThreads, OneThreadTakesTheRowsInOrderOnTheCallingThreadOutsideTbb) {
  // A thread of its own, which no TBB arena has ever had as a worker: one
  // that has stays attached to TBB's default arena.
  std::vector<int> order;
  std::vector<int> arena_index;
  bool on_caller = true;
  std::thread([&] {
    const std::thread::id caller = std::this_thread::get_id();
    parallel_rows(1, 50, [&](const tbb::blocked_range<int>& rows) {
      on_caller = on_caller && std::this_thread::get_id() == caller;
      arena_index.push_back(tbb::this_task_arena::current_thread_index());
      for (int r = rows.begin(); r != rows.end(); ++r) order.push_back(r);
    });
  }).join();
  EXPECT_TRUE(on_caller);
  ASSERT_EQ(order.size(), 50u);
  for (int r = 0; r < 50; ++r) EXPECT_EQ(order[static_cast<std::size_t>(r)], r);
  const int outside_any_arena = tbb::task_arena::not_initialized;  // a copy: the constant has no definition to bind to
  for (const int index : arena_index) EXPECT_EQ(index, outside_any_arena);
}
