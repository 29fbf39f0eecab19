#include "runtime/executor.h"

#include <algorithm>

namespace arbc {

TaskQueue::TaskId TaskQueue::push(double at, std::function<void()> fn) {
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
  s.fn = std::move(fn);
  TaskId id = (TaskId{s.generation} << 32) | slot;
  heap_.push_back({at, next_seq_++, id});
  std::push_heap(heap_.begin(), heap_.end(), later);
  return id;
}

bool TaskQueue::stale(const Entry& e) const {
  const Slot& s = slots_[static_cast<uint32_t>(e.id)];
  return !s.live || s.generation != static_cast<uint32_t>(e.id >> 32);
}

void TaskQueue::release(uint32_t slot) {
  slots_[slot].live = false;
  slots_[slot].fn = nullptr;
  free_.push_back(slot);
}

// Keeps the invariant that the top of the heap is a live task.
void TaskQueue::drop_dead_top() {
  while (!heap_.empty() && stale(heap_.front())) {
    std::pop_heap(heap_.begin(), heap_.end(), later);
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
    std::make_heap(heap_.begin(), heap_.end(), later);
    dead_ = 0;
  }
}

std::function<void()> TaskQueue::pop() {
  std::pop_heap(heap_.begin(), heap_.end(), later);
  auto slot = static_cast<uint32_t>(heap_.back().id);
  heap_.pop_back();
  std::function<void()> fn = std::move(slots_[slot].fn);
  release(slot);
  drop_dead_top();
  return fn;
}

Executor::TaskId SimulatedExecutor::post(double at, std::function<void()> fn) {
  return queue_.push(std::max(at, now_), std::move(fn));
}

void SimulatedExecutor::run(double until) {
  stopped_ = false;
  while (!stopped_ && !interrupted() && !queue_.empty() && queue_.next_time() <= until) {
    now_ = queue_.next_time();
    std::function<void()> fn = queue_.pop();
    fn();
  }
  if (!stopped_ && !interrupted()) now_ = std::max(now_, until);
}

double RealtimeExecutor::now() const {
  return scale_ * std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

Executor::TaskId RealtimeExecutor::post(double at, std::function<void()> fn) {
  std::lock_guard<std::mutex> lock(mutex_);
  TaskId id = queue_.push(at, std::move(fn));
  wake_.notify_all();
  return id;
}

void RealtimeExecutor::cancel(TaskId id) {
  std::lock_guard<std::mutex> lock(mutex_);
  queue_.cancel(id);
}

void RealtimeExecutor::stop() {
  std::lock_guard<std::mutex> lock(mutex_);
  stopped_ = true;
  wake_.notify_all();
}

bool RealtimeExecutor::on_executor_thread() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return runner_ == std::thread::id() || runner_ == std::this_thread::get_id();
}

void RealtimeExecutor::run(double until) {
  std::unique_lock<std::mutex> lock(mutex_);
  runner_ = std::this_thread::get_id();
  stopped_ = false;
  auto deadline_of = [&](double t) {
    return start_ + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                        std::chrono::duration<double>(t / scale_));
  };
  while (!stopped_ && !interrupted()) {
    double t = now();
    if (t >= until) break;
    if (!queue_.empty() && queue_.next_time() <= t) {
      std::function<void()> fn = queue_.pop();
      lock.unlock();
      fn();
      lock.lock();
      continue;
    }
    double wake_at = queue_.empty() ? until : std::min(until, queue_.next_time());
    if (interrupt_) wake_at = std::min(wake_at, t + 0.02);  // a signal cannot notify wake_
    wake_.wait_until(lock, deadline_of(wake_at));
  }
  runner_ = std::thread::id();
}

}  // namespace arbc
