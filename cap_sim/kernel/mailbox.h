#pragma once
// A process's inbox: messages delivered by the bus or the links queue here in
// arrival order; `co_await inbox.receive()` takes the oldest, waiting for one if
// none has come yet. One process receives from a given mailbox.

#include "kernel/event_kernel.h"

#include <deque>
#include <stdexcept>

namespace capsim::sim {

template <class Message>
class Mailbox {
 public:
  explicit Mailbox(EventKernel& kernel) : kernel_(&kernel) {}

  // Queues a message; a process waiting on receive() continues in this cycle.
  void deliver(Message m) {
    messages_.push_back(std::move(m));
    if (waiter_) {
      kernel_->resume_at(kernel_->now(), waiter_);
      waiter_ = {};
    }
  }

  bool empty() const { return messages_.empty(); }
  std::size_t size() const { return messages_.size(); }

  struct ReceiveAwaiter {
    Mailbox& box;
    bool await_ready() const noexcept { return !box.messages_.empty(); }
    void await_suspend(std::coroutine_handle<> h) {
      if (box.waiter_) throw std::logic_error("two processes receive from one mailbox");
      box.waiter_ = h;
    }
    Message await_resume() {
      Message m = std::move(box.messages_.front());
      box.messages_.pop_front();
      return m;
    }
  };
  ReceiveAwaiter receive() { return {*this}; }

 private:
  EventKernel* kernel_;
  std::deque<Message> messages_;
  std::coroutine_handle<> waiter_{};
};

}  // namespace capsim::sim
