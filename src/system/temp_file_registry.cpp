#include "capsim/system/temp_file_registry.h"

#include <limits.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>

namespace capsim {

namespace {

// A command has at most four outputs; in-process users (tests) a few more.
constexpr int kSlots = 1024;  // a sequence stages one output per frame

enum SlotState : int { kFree, kFilling, kArmed };

// The states apart from the paths, and zero (kFree) by constant
// initialization: nothing touches the 4 MiB of paths at start-up, so a
// command does not fault in a page per slot before it begins.
static_assert(kFree == 0, "the states start free without a constructor running");
std::atomic<int> slot_states[kSlots];
char slot_paths[kSlots][PATH_MAX];
static_assert(std::atomic<int>::is_always_lock_free, "the signal handler reads the slot states");

// Not SIGPIPE: capsim ignores it and handles EPIPE where it writes.
constexpr int kSignals[] = {SIGHUP, SIGINT, SIGQUIT, SIGTERM, SIGXCPU, SIGXFSZ};

// A slot is rewritten only after it went back to kFree, so a handler that sees
// kArmed reads a complete path. (A slot freed and filled again, on another
// thread, while the handler runs could still be read mid-change; the window is
// a few instructions, and its worst outcome is a failed unlink.)
extern "C" void remove_temp_files_and_reraise(int signal_number) {
  const int saved_errno = errno;
  for (int i = 0; i < kSlots; ++i)
    if (slot_states[i].load(std::memory_order_acquire) == kArmed) ::unlink(slot_paths[i]);
  // Directories go once the files in them are gone; rmdir fails harmlessly on
  // the paths the first pass removed.
  for (int i = 0; i < kSlots; ++i)
    if (slot_states[i].load(std::memory_order_acquire) == kArmed) ::rmdir(slot_paths[i]);
  errno = saved_errno;
  // SA_RESETHAND restored the default action on entry; the signal, blocked
  // while this handler runs, is delivered again when it returns.
  ::raise(signal_number);
}

}  // namespace

int register_temp_file(const std::string& path) {
  if (path.size() >= PATH_MAX) return -1;
  for (int i = 0; i < kSlots; ++i) {
    int expected = kFree;
    if (slot_states[i].compare_exchange_strong(expected, kFilling, std::memory_order_acquire)) {
      std::memcpy(slot_paths[i], path.c_str(), path.size() + 1);
      slot_states[i].store(kArmed, std::memory_order_release);
      return i;
    }
  }
  return -1;
}

void unregister_temp_file(int slot) {
  if (slot >= 0 && slot < kSlots) slot_states[slot].store(kFree, std::memory_order_release);
}

void remove_temp_files_on_signals() {
  struct sigaction action {};
  action.sa_handler = remove_temp_files_and_reraise;
  action.sa_flags = SA_RESETHAND;
  sigemptyset(&action.sa_mask);
  // One handler at a time: a second signal waits until the first has done.
  for (const int s : kSignals) sigaddset(&action.sa_mask, s);
  for (const int s : kSignals) {
    struct sigaction current {};
    if (sigaction(s, nullptr, &current) != 0 || current.sa_handler == SIG_IGN) continue;
    sigaction(s, &action, nullptr);
  }
}

}  // namespace capsim
