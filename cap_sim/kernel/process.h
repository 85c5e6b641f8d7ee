#pragma once
// A simulated process: a C++20 coroutine that the event kernel resumes. Its body
// reads as the sequential program a host or a cell runs; every `co_await` is a
// point where simulated time may pass (a delay, a message, a bus transfer), or
// a step of the program written as a Task (kernel/task.h).
//
// What the kernel and the machine's parts resume is a std::coroutine_handle<>:
// the process itself, or the task it is running when it waits.

#include <coroutine>
#include <exception>
#include <utility>

namespace capsim::sim {

class Process {
 public:
  struct promise_type {
    // Where an exception the body lets escape goes: EventKernel::spawn points
    // it at the kernel's, which run() rethrows after the event in which the
    // body failed. The body may be resumed through a task it awaits, so the
    // kernel cannot look for the failure in the handle it resumed.
    std::exception_ptr* escaped = nullptr;

    Process get_return_object() {
      return Process(std::coroutine_handle<promise_type>::from_promise(*this));
    }
    // A process starts only when the kernel resumes it (EventKernel::spawn).
    std::suspend_always initial_suspend() noexcept { return {}; }
    // Stays suspended at the end so the kernel can see done().
    std::suspend_always final_suspend() noexcept { return {}; }
    void return_void() {}
    // Precondition: spawned (escaped set); a process resumed by hand lets the
    // exception out of resume().
    void unhandled_exception() {
      if (!escaped) throw;
      *escaped = std::current_exception();
    }
  };
  using Handle = std::coroutine_handle<promise_type>;

  Process() = default;
  explicit Process(Handle h) : handle_(h) {}
  Process(Process&& o) noexcept : handle_(std::exchange(o.handle_, {})) {}
  Process& operator=(Process&& o) noexcept {
    if (this != &o) {
      if (handle_) handle_.destroy();
      handle_ = std::exchange(o.handle_, {});
    }
    return *this;
  }
  Process(const Process&) = delete;
  Process& operator=(const Process&) = delete;
  ~Process() {
    if (handle_) handle_.destroy();
  }

  Handle handle() const { return handle_; }
  bool done() const { return handle_ && handle_.done(); }

 private:
  Handle handle_;
};

using ProcessHandle = Process::Handle;

}  // namespace capsim::sim
