// Executors: who decides what runs when (docs/design.md#runtime).
//
// Both run tasks one at a time on the thread that called run(), in order of (time, posting
// order), so everything the runtime and the modules do is serialised. The simulated executor
// jumps from task to task (as fast as the CPU allows; deterministic). The real-time executor
// sleeps until a task's wall-clock time; post() and cancel() may be called from any thread.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <thread>

#include "runtime/task_queue.h"

namespace arbc {

class Executor {
 public:
  using TaskId = TaskQueue::TaskId;
  virtual ~Executor() = default;
  virtual double now() const = 0;
  // Runs fn at time `at` (not before now()). Returns an id for cancel().
  virtual TaskId post(double at, Task task) = 0;
  // The same for a plain function that is never cancelled (no id): the cheaper way, for the
  // task the message path posts per message.
  virtual void post_plain(double at, void (*fn)(void*), void* argument) = 0;
  virtual void cancel(TaskId id) = 0;
  // Runs tasks until time `until` is reached or stop() is called; now() is then `until`
  // (or the time of the stop).
  virtual void run(double until) = 0;
  virtual void stop() = 0;
  // Is the caller on the thread inside run() (or is run() not active)?
  virtual bool on_executor_thread() const = 0;
  // Not null: run() returns before the next task once *flag is true (a signal handler sets it;
  // the real-time executor then sleeps in short slices so that it notices).
  void set_interrupt(const std::atomic<bool>* flag) { interrupt_ = flag; }

 protected:
  bool interrupted() const { return interrupt_ && interrupt_->load(std::memory_order_relaxed); }
  const std::atomic<bool>* interrupt_ = nullptr;
};

class SimulatedExecutor : public Executor {
 public:
  double now() const override { return now_; }
  TaskId post(double at, Task task) override;
  void post_plain(double at, void (*fn)(void*), void* argument) override;
  void cancel(TaskId id) override { queue_.cancel(id); }
  void run(double until) override;
  void stop() override { stopped_ = true; }
  bool on_executor_thread() const override { return true; }

 private:
  TaskQueue queue_;
  double now_ = 0;
  bool stopped_ = false;
};

// Time is the wall time since construction, times `scale` (a distributed run's --time-scale:
// every process of the run uses the same scale, so a simulated world can run faster than real
// time across processes).
class RealtimeExecutor : public Executor {
 public:
  explicit RealtimeExecutor(double scale = 1)
      : start_(std::chrono::steady_clock::now()), scale_(scale) {}
  double now() const override;
  TaskId post(double at, Task task) override;
  void post_plain(double at, void (*fn)(void*), void* argument) override;
  void cancel(TaskId id) override;
  void run(double until) override;
  void stop() override;
  bool on_executor_thread() const override;

 private:
  std::chrono::steady_clock::time_point start_;
  double scale_ = 1;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  TaskQueue queue_;
  bool stopped_ = false;
  std::thread::id runner_;
};

}  // namespace arbc
