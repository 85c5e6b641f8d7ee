#pragma once
// A step of a process's program as a coroutine of its own: `co_await
// trace_corners(unit)` runs the step as part of the process that awaits it, so
// a long program reads as a few named steps, each a few lines.
//
// Awaiting a task and its end are direct jumps between the two coroutines
// (symmetric transfer), not events: a program split into tasks runs the same
// events, at the same cycles, in the same order, as the same program written in
// one body, and EventKernel::events_run() does not change. While the task waits
// (a delay, a message, the bus) the process waits with it; whatever the kernel
// resumes is the task, which continues its awaiting coroutine when it ends.
//
// An exception the task lets escape is rethrown at the `co_await` in the
// coroutine that awaited it, as if the step's body were written there.
//
// Preconditions: a task starts only when awaited, and is awaited once, by the
// coroutine that made it (as a temporary: `co_await step()`); it returns a T
// (or nothing, Task<>).

#include <coroutine>
#include <exception>
#include <optional>
#include <utility>

namespace capsim::sim {

template <class T = void>
class Task;

namespace detail {

struct TaskPromiseBase {
  std::coroutine_handle<> continuation;  // the coroutine that awaits the task
  std::exception_ptr failure;            // an exception the body let escape

  // Lazy: the body starts when the task is awaited.
  std::suspend_always initial_suspend() noexcept { return {}; }
  // At its end the task continues its awaiting coroutine directly, and stays
  // suspended until that coroutine has taken its result and destroyed it.
  struct FinalAwaiter {
    bool await_ready() const noexcept { return false; }
    template <class Promise>
    std::coroutine_handle<> await_suspend(std::coroutine_handle<Promise> self) noexcept {
      return self.promise().continuation;
    }
    void await_resume() const noexcept {}
  };
  FinalAwaiter final_suspend() noexcept { return {}; }
  void unhandled_exception() noexcept { failure = std::current_exception(); }
  void rethrow_failure() const {
    if (failure) std::rethrow_exception(failure);
  }
};

template <class T>
struct TaskPromise : TaskPromiseBase {
  std::optional<T> value;
  Task<T> get_return_object();
  template <class U>
  void return_value(U&& v) {
    value.emplace(std::forward<U>(v));
  }
  T result() {
    rethrow_failure();
    return std::move(*value);
  }
};

template <>
struct TaskPromise<void> : TaskPromiseBase {
  Task<void> get_return_object();
  void return_void() noexcept {}
  void result() const { rethrow_failure(); }
};

}  // namespace detail

template <class T>
class [[nodiscard]] Task {
 public:
  using promise_type = detail::TaskPromise<T>;
  using Handle = std::coroutine_handle<promise_type>;

  explicit Task(Handle h) : handle_(h) {}
  Task(Task&& o) noexcept : handle_(std::exchange(o.handle_, {})) {}
  Task& operator=(Task&&) = delete;
  Task(const Task&) = delete;
  Task& operator=(const Task&) = delete;
  ~Task() {
    if (handle_) handle_.destroy();
  }

  struct Awaiter {
    Handle task;
    bool await_ready() const noexcept { return false; }
    // Starts the task at once, in the awaiting coroutine's place.
    std::coroutine_handle<> await_suspend(std::coroutine_handle<> awaiting) noexcept {
      task.promise().continuation = awaiting;
      return task;
    }
    T await_resume() { return task.promise().result(); }
  };
  Awaiter operator co_await() && noexcept { return Awaiter{handle_}; }

 private:
  Handle handle_;
};

namespace detail {
template <class T>
Task<T> TaskPromise<T>::get_return_object() {
  return Task<T>(Task<T>::Handle::from_promise(*this));
}
inline Task<void> TaskPromise<void>::get_return_object() {
  return Task<void>(Task<void>::Handle::from_promise(*this));
}
}  // namespace detail

}  // namespace capsim::sim
