#include "runtime/executor.h"

#include <algorithm>

namespace arbc {

TaskQueue::TaskId TaskQueue::push(double at, std::function<void()> fn) {
  TaskId id = next_id_++;
  tasks_.emplace(std::make_pair(at, id), std::move(fn));
  time_of_.emplace(id, at);
  return id;
}

void TaskQueue::cancel(TaskId id) {
  auto it = time_of_.find(id);
  if (it == time_of_.end()) return;
  tasks_.erase({it->second, id});
  time_of_.erase(it);
}

std::function<void()> TaskQueue::pop() {
  auto it = tasks_.begin();
  std::function<void()> fn = std::move(it->second);
  time_of_.erase(it->first.second);
  tasks_.erase(it);
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
