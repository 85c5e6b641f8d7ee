// parallel_rows: every row once, whatever the threads; on one thread, in order
// on the calling thread, outside any TBB arena (the scheduler not started).
// parallel_rows_with: the same, each thread with a workspace of its own.

#include "capsim/system/host_threads.h"

#include <gtest/gtest.h>

#include <atomic>
#include <mutex>
#include <set>
#include <thread>
#include <vector>

using capsim::parallel_rows;
using capsim::parallel_rows_with;

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

// A workspace that counts the rows given to it, and knows the thread that
// made it.
struct Workspace {
  std::thread::id maker = std::this_thread::get_id();
  int rows = 0;
};

TEST(HostThreads, EachThreadKeepsOneWorkspaceForAllItsRows) {
  for (const int threads : {1, 2, 3, 8}) {
    for (const int count : {1, 7, 1000}) {
      std::vector<std::atomic<int>> seen(static_cast<std::size_t>(count));
      std::atomic<int> made{0}, foreign{0};
      std::mutex m;
      std::set<Workspace*> used;
      parallel_rows_with(
          threads, count,
          [&] {
            ++made;
            return Workspace{};
          },
          [&](const tbb::blocked_range<int>& rows, Workspace& w) {
            foreign += w.maker != std::this_thread::get_id();
            w.rows += static_cast<int>(rows.size());
            for (int r = rows.begin(); r != rows.end(); ++r) ++seen[static_cast<std::size_t>(r)];
            const std::lock_guard lock(m);
            used.insert(&w);
          });
      for (int r = 0; r < count; ++r) EXPECT_EQ(seen[static_cast<std::size_t>(r)], 1) << threads << " " << count;
      EXPECT_EQ(foreign, 0) << threads << " " << count;  // a thread's own, made on it
      EXPECT_EQ(static_cast<std::size_t>(made.load()), used.size()) << threads << " " << count;
      EXPECT_LE(made, threads) << threads << " " << count;
      if (threads == 1) {
        EXPECT_EQ(made, 1) << count;
      }
    }
  }
}

TEST(HostThreads, OneThreadMakesOneWorkspaceAndNoneForNoRows) {
  std::vector<int> order;
  int made = 0;
  parallel_rows_with(
      1, 50,
      [&] {
        ++made;
        return Workspace{};
      },
      [&](const tbb::blocked_range<int>& rows, Workspace& w) {
        w.rows += static_cast<int>(rows.size());
        for (int r = rows.begin(); r != rows.end(); ++r) order.push_back(r);
      });
  EXPECT_EQ(made, 1);
  ASSERT_EQ(order.size(), 50u);
  for (int r = 0; r < 50; ++r) EXPECT_EQ(order[static_cast<std::size_t>(r)], r);
  parallel_rows_with(
      1, 0,
      [&] {
        ++made;
        return Workspace{};
      },
      [](const tbb::blocked_range<int>&, Workspace&) { ADD_FAILURE() << "a row of none"; });
  EXPECT_EQ(made, 1);
}
