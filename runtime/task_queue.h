// The executors' queue of tasks, ordered by (time, posting order).
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <type_traits>
#include <vector>

#include "core/instant.h"

namespace arbc {

// What an executor runs: a plain function and its argument, or any callable. The message path
// posts a task per message (a connection's drain); as a function pointer and a pointer it costs
// two stores, where a std::function costs its type-erased construction, moves and destruction.
class Task {
 public:
  Task() = default;
  Task(void (*fn)(void*), void* argument) : plain_(fn), argument_(argument) {}
  template <class F, class = std::enable_if_t<!std::is_same_v<std::decay_t<F>, Task> &&
                                              std::is_invocable_r_v<void, F&>>>
  Task(F&& fn) : callable_(std::forward<F>(fn)) {}
  // Moves copy a plain task's two pointers and leave the std::function alone: the queue moves
  // every task in and out of its slot.
  Task(Task&& other) noexcept : plain_(other.plain_), argument_(other.argument_) {
    if (!plain_) callable_ = std::move(other.callable_);
  }
  Task& operator=(Task&& other) noexcept {
    plain_ = other.plain_;
    argument_ = other.argument_;
    if (!plain_) {
      callable_ = std::move(other.callable_);
    } else if (callable_) {
      callable_ = nullptr;
    }
    return *this;
  }
  Task(const Task&) = delete;
  Task& operator=(const Task&) = delete;
  // Releases what the task holds (a callable's captures).
  void clear() {
    plain_ = nullptr;
    if (callable_) callable_ = nullptr;
  }
  explicit operator bool() const { return plain_ || callable_; }
  void operator()() {
    if (plain_) {
      plain_(argument_);
    } else {
      callable_();
    }
  }

 private:
  void (*plain_)(void*) = nullptr;
  void* argument_ = nullptr;
  std::function<void()> callable_;
};

// Tasks ordered by (time, posting order): a binary heap over a vector, with each task in a
// reused slot, so that posting and running a task allocate nothing once the queue has grown to
// its working size (a map node per task cost two allocations and frees per message on the
// message path). A task id names its slot and the slot's generation, so a stale id (a task that
// ran or was cancelled) cancels nothing.
//
// A task that is never cancelled (push_plain: a connection's drain, one per message) needs no
// slot: its function and argument ride in the heap entry itself, which saves the slot's
// bookkeeping (free list, generation, moving the task in and out) on every message.
class TaskQueue {
 public:
  using TaskId = uint64_t;
  TaskId push(Nanos at, Task task);
  void push_plain(Nanos at, void (*fn)(void*), void* argument);
  void cancel(TaskId id);
  bool empty() const { return heap_.empty(); }
  Nanos next_time() const { return heap_.front().at; }
  Task pop();
  // Tasks waiting (cancelled ones no longer count).
  size_t size() const { return heap_.size() - dead_; }
  // Heap entries, cancelled ones not yet discarded included: bounded by about twice size().
  size_t entries() const { return heap_.size(); }

 private:
  struct Entry {
    // Built in place in the heap (emplace_back): an entry built on the stack and then copied was
    // written with 8-byte stores and read back with 16-byte loads, which the processor cannot
    // forward, a stall of a dozen cycles on every post.
    Entry(Nanos at, uint64_t seq, TaskId id, void (*plain)(void*), void* argument)
        : at(at), seq(seq), id(id), plain(plain), argument(argument) {}
    Nanos at;
    uint64_t seq;  // posting order, the tie-break between equal times
    TaskId id;     // its slot; 0 for a plain task, which is `plain` and `argument`
    void (*plain)(void*);
    void* argument;
  };
  struct Slot {
    uint32_t generation = 0;
    bool live = false;
    Task task;
  };
  // A function object rather than a function: the heap algorithms then inline it.
  struct Later {
    bool operator()(const Entry& a, const Entry& b) const {
      return a.at != b.at ? a.at > b.at : a.seq > b.seq;
    }
  };
  bool stale(const Entry& e) const;
  void add(Nanos at, TaskId id, void (*plain)(void*), void* argument);
  void release(uint32_t slot);
  void drop_dead_top();
  std::vector<Entry> heap_;
  std::vector<Slot> slots_;
  std::vector<uint32_t> free_;
  uint64_t next_seq_ = 0;
  size_t dead_ = 0;  // cancelled entries still in heap_
};

}  // namespace arbc
