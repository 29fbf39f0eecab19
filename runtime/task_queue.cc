#include "runtime/task_queue.h"

#include <algorithm>

namespace arbc {

TaskQueue::TaskId TaskQueue::push(Nanos at, Task task) {
  uint32_t slot;
  if (free_.empty()) {
    slot = static_cast<uint32_t>(slots_.size());
    slots_.emplace_back();
  } else {
    slot = free_.back();
    free_.pop_back();
  }
  Slot& s = slots_[slot];
  if (++s.generation == 0) s.generation = 1;  // id 0 means "no task" to callers
  s.live = true;
  s.task = std::move(task);
  TaskId id = (TaskId{s.generation} << 32) | slot;
  add(at, id, nullptr, nullptr);
  return id;
}

void TaskQueue::push_plain(Nanos at, void (*fn)(void*), void* argument) {
  add(at, 0, fn, argument);
}

void TaskQueue::add(Nanos at, TaskId id, void (*plain)(void*), void* argument) {
  heap_.emplace_back(at, next_seq_++, id, plain, argument);
  // Most tasks are posted in time order (the message path's at the current time), and such a
  // task already sits where the heap wants it: no sift.
  size_t last = heap_.size() - 1;
  if (last > 0 && Later()(heap_[(last - 1) / 2], heap_[last])) {
    std::push_heap(heap_.begin(), heap_.end(), Later());
  }
}

bool TaskQueue::stale(const Entry& e) const {
  if (e.id == 0) return false;  // a plain task cannot be cancelled
  const Slot& s = slots_[static_cast<uint32_t>(e.id)];
  return !s.live || s.generation != static_cast<uint32_t>(e.id >> 32);
}

void TaskQueue::release(uint32_t slot) {
  slots_[slot].live = false;
  slots_[slot].task.clear();
  free_.push_back(slot);
}

// Keeps the invariant that the top of the heap is a live task.
void TaskQueue::drop_dead_top() {
  while (!heap_.empty() && stale(heap_.front())) {
    std::pop_heap(heap_.begin(), heap_.end(), Later());
    heap_.pop_back();
    --dead_;
  }
}

void TaskQueue::cancel(TaskId id) {
  auto slot = static_cast<uint32_t>(id);
  if (slot >= slots_.size()) return;
  const Slot& s = slots_[slot];
  if (!s.live || s.generation != static_cast<uint32_t>(id >> 32)) return;  // ran or cancelled
  release(slot);
  ++dead_;
  drop_dead_top();
  // Cancelled entries deep in the heap wait until they surface; when they outnumber the live
  // ones, sweep them so that a task re-posted and cancelled over and over keeps memory flat.
  if (dead_ > 16 && dead_ * 2 > heap_.size()) {
    heap_.erase(
        std::remove_if(heap_.begin(), heap_.end(), [this](const Entry& e) { return stale(e); }),
        heap_.end());
    std::make_heap(heap_.begin(), heap_.end(), Later());
    dead_ = 0;
  }
}

Task TaskQueue::pop() {
  std::pop_heap(heap_.begin(), heap_.end(), Later());
  Entry top = heap_.back();
  heap_.pop_back();
  if (top.id == 0) {
    drop_dead_top();
    return Task(top.plain, top.argument);
  }
  auto slot = static_cast<uint32_t>(top.id);
  Task task = std::move(slots_[slot].task);
  release(slot);
  drop_dead_top();
  return task;
}

}  // namespace arbc
