#pragma once
// How many host threads a parallel loop runs on. The output never depends on it.

namespace capsim {

// The concurrency of a TBB arena for a request of `threads` host threads
// (0 = all hardware threads): never more than the hardware threads TBB sees
// (the process's CPU affinity), because TBB refuses more workers with a warning
// on stderr, and more threads than cores could not run at once anyway.
// Precondition: threads >= 0.
int host_arena_concurrency(int threads);

}  // namespace capsim
