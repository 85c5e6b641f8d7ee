#pragma once
// The process's heap, set up for a run that allocates and frees megabytes.
//
// A page of memory costs a fault the first time it is touched. In a virtual
// machine a fault can cost 12 us, where asking the kernel to populate pages
// in one call costs about 1 us a page (docs/performance.md). Every run's own
// allocations (the command line's options, the scene, the tracer's
// workspaces, the PNG's bands and compressor) take one to two megabytes of
// the heap.

#include <cstddef>

namespace capsim {

// What the heap is populated with by default: the most the shipped scenes and
// the benchmarks' lattices use at 1024 x 1024 pixels.
inline constexpr std::size_t kRunHeapBytes = std::size_t{2} << 20;

// Sets glibc's malloc to keep freed memory: blocks up to 32 MiB come from the
// heap rather than from mappings of their own, and the heap is never trimmed.
// Parsing a large scene frees megabytes that voxel generation, the tracer and
// the image then reuse; given back to the system, every page of theirs would
// be faulted in again. Then has the kernel populate `populated` bytes of the
// heap's free memory in one call (madvise MADV_POPULATE_WRITE), so that the
// allocations after it take no faults there. A kernel older than 5.14
// refuses the call, and the pages then fault as before. Call it first in
// main, before any other thread exists.
void set_up_process_heap(std::size_t populated = kRunHeapBytes);

}  // namespace capsim
