#include "capsim/system/host_threads.h"

#include <tbb/info.h>
#include <tbb/task_arena.h>

#include <algorithm>

namespace capsim {

int host_arena_concurrency(int threads) {
  if (threads <= 0) return tbb::task_arena::automatic;
  return std::min(threads, tbb::info::default_concurrency());
}

}  // namespace capsim
