// Executors: who decides what runs when (docs/design.md#runtime).
//
// Both run tasks one at a time on the thread that called run(), in order of (time, posting
// order), so everything the runtime and the modules do is serialised. Times are whole
// nanoseconds since the executor's start (core/instant.h): two tasks are at one instant exactly
// when their times are equal. The simulated executor
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
  virtual Nanos now() const = 0;
  // What now() is as ROS 2 time (age(), MonitorHost::stamp_now): stamp_origin() + now(). A
  // simulated clock is its own ROS 2 time (0: a test gives stamps as instants of the run).
  virtual Nanos stamp_origin() const { return Nanos{0}; }
  // Runs fn at time `at` (not before now()). Returns an id for cancel().
  virtual TaskId post(Nanos at, Task task) = 0;
  // The same for a plain function that is never cancelled (no id): the cheaper way, for the
  // task the message path posts per message.
  virtual void post_plain(Nanos at, void (*fn)(void*), void* argument) = 0;
  virtual void cancel(TaskId id) = 0;
  // Runs the tasks at times up to `until`, or until stop() is called; now() is then `until`
  // (or the time of the stop).
  virtual void run(Nanos until) = 0;
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
  Nanos now() const override { return now_; }
  TaskId post(Nanos at, Task task) override;
  void post_plain(Nanos at, void (*fn)(void*), void* argument) override;
  void cancel(TaskId id) override { queue_.cancel(id); }
  void run(Nanos until) override;
  void stop() override { stopped_ = true; }
  bool on_executor_thread() const override { return true; }

 private:
  TaskQueue queue_;
  Nanos now_{0};
  bool stopped_ = false;
};

// Time is the wall time since construction, times `scale` (a distributed run's --time-scale:
// every process of the run uses the same scale, so a simulated world can run faster than real
// time across processes), to the nanosecond of the steady clock.
class RealtimeExecutor : public Executor {
 public:
  explicit RealtimeExecutor(double scale = 1)
      : start_(std::chrono::steady_clock::now()),
        epoch_at_start_(
            std::chrono::duration_cast<Nanos>(std::chrono::system_clock::now().time_since_epoch())),
        scale_(scale) {}
  Nanos now() const override;
  // The wall clock at construction, since the epoch: a ROS 2 node's stamps are read against it.
  Nanos stamp_origin() const override { return epoch_at_start_; }
  TaskId post(Nanos at, Task task) override;
  void post_plain(Nanos at, void (*fn)(void*), void* argument) override;
  void cancel(TaskId id) override;
  void run(Nanos until) override;
  void stop() override;
  bool on_executor_thread() const override;

 private:
  std::chrono::steady_clock::time_point start_;
  Nanos epoch_at_start_;
  double scale_ = 1;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  TaskQueue queue_;
  bool stopped_ = false;
  std::thread::id runner_;
};

}  // namespace arbc
