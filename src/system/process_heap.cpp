#include "capsim/system/process_heap.h"

#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>

namespace capsim {

namespace {

// A block taken from the top of the heap and given back at
// once returns to the top, which is never trimmed (M_TRIM_THRESHOLD): the next
// allocations are carved from the pages populated here.
void populate_free_heap(std::size_t populated) {
  if (populated == 0) return;
  void* block = std::malloc(populated);
  if (block == nullptr) return;
  const auto page = static_cast<std::uintptr_t>(::sysconf(_SC_PAGESIZE));
  const auto start = reinterpret_cast<std::uintptr_t>(block);
  const std::uintptr_t first = (start + page - 1) / page * page;
  const std::uintptr_t end = (start + populated) / page * page;
  if (end > first) ::madvise(reinterpret_cast<void*>(first), end - first, MADV_POPULATE_WRITE);
  std::free(block);
}

}  // namespace

void set_up_process_heap(std::size_t populated) {
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
  populate_free_heap(populated);
}

}  // namespace capsim
