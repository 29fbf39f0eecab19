#include "runtime/executor.h"

#include <algorithm>

namespace arbc {

Executor::TaskId SimulatedExecutor::post(Nanos at, Task task) {
  return queue_.push(std::max(at, now_), std::move(task));
}

void SimulatedExecutor::post_plain(Nanos at, void (*fn)(void*), void* argument) {
  queue_.push_plain(std::max(at, now_), fn, argument);
}

void SimulatedExecutor::run(Nanos until) {
  stopped_ = false;
  while (!stopped_ && !interrupted() && !queue_.empty() && queue_.next_time() <= until) {
    now_ = queue_.next_time();
    Task task = queue_.pop();
    task();
  }
  if (!stopped_ && !interrupted()) now_ = std::max(now_, until);
}

Nanos RealtimeExecutor::now() const {
  Nanos wall = std::chrono::duration_cast<Nanos>(std::chrono::steady_clock::now() - start_);
  if (scale_ == 1) return wall;
  return nanos_from_seconds(scale_ * seconds_of(wall));
}

Executor::TaskId RealtimeExecutor::post(Nanos at, Task task) {
  std::lock_guard<std::mutex> lock(mutex_);
  TaskId id = queue_.push(at, std::move(task));
  wake_.notify_all();
  return id;
}

void RealtimeExecutor::post_plain(Nanos at, void (*fn)(void*), void* argument) {
  std::lock_guard<std::mutex> lock(mutex_);
  queue_.push_plain(at, fn, argument);
  wake_.notify_all();
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

void RealtimeExecutor::run(Nanos until) {
  std::unique_lock<std::mutex> lock(mutex_);
  runner_ = std::this_thread::get_id();
  stopped_ = false;
  auto deadline_of = [&](Nanos t) {
    // In wall time; a deadline past the clock's range (a task at kNever) is capped a year out.
    double wall = std::min(seconds_of(t) / scale_, 3.2e7);
    return start_ + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                        std::chrono::duration<double>(wall));
  };
  while (!stopped_ && !interrupted()) {
    Nanos t = now();
    if (t >= until) break;
    if (!queue_.empty() && queue_.next_time() <= t) {
      Task task = queue_.pop();
      lock.unlock();
      task();
      lock.lock();
      continue;
    }
    Nanos wake_at = queue_.empty() ? until : std::min(until, queue_.next_time());
    if (interrupt_)
      wake_at = std::min(wake_at,
                         later(t, std::chrono::milliseconds(20)));  // a signal cannot notify wake_
    wake_.wait_until(lock, deadline_of(wake_at));
  }
  runner_ = std::thread::id();
}

}  // namespace arbc
