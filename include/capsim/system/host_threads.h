#pragma once
// How many host threads a parallel loop runs on, and the loop over an image's
// rows that every tracing pass uses (voxel generation runs it over ranges of
// primitives, the mode benchmarks over the runs of one traced screen,
// zlib_compress_in_bands over a whole input's bands). The output never
// depends on them.

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

namespace capsim {

// The concurrency of a TBB arena for a request of `threads` host threads
// (0 = all hardware threads): never more than the hardware threads TBB sees
// (the process's CPU affinity), because TBB refuses more workers with a warning
// on stderr, and more threads than cores could not run at once anyway.
// Precondition: threads >= 0.
int host_arena_concurrency(int threads);

// Runs body(rows), rows a tbb::blocked_range<int>, over the rows [0, count) on
// `threads` host threads (0 = all). On one thread the rows go in order, one
// a call, on the calling thread, without TBB's scheduler: starting it costs a
// process some 0.3 ms (docs/performance.md), and a call a row keeps progress
// reports as frequent as the threads' are.
template <class Body>
void parallel_rows(int threads, int count, Body body) {
  if (threads == 1) {
    for (int row = 0; row < count; ++row) body(tbb::blocked_range<int>(row, row + 1));
    return;
  }
  tbb::task_arena arena(host_arena_concurrency(threads));
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<int>(0, count), [&](const tbb::blocked_range<int>& rows) { body(rows); });
  });
}

// parallel_rows with each thread's own workspace: body(rows, workspace), the
// workspace made by make() on the thread's first rows and kept for its
// others. On one thread it is a plain local: TBB's per-thread storage
// allocates through TBB's allocator, whose library TBB opens on that first
// use (docs/performance.md), and a run on one thread need not open it.
template <class Make, class Body>
void parallel_rows_with(int threads, int count, Make make, Body body) {
  if (threads == 1) {
    if (count <= 0) return;
    auto workspace = make();
    parallel_rows(1, count, [&](const tbb::blocked_range<int>& rows) { body(rows, workspace); });
    return;
  }
  tbb::enumerable_thread_specific<decltype(make())> workspaces(make);
  parallel_rows(threads, count, [&](const tbb::blocked_range<int>& rows) { body(rows, workspaces.local()); });
}

}  // namespace capsim
