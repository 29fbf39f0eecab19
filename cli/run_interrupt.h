// Ctrl-C and SIGTERM during `arbc run` (docs/reliability.md, "A stuck monitor").
//
// From construction to destruction both signals set flag() instead of ending the process: the
// runtime stops at its next check (the executor before its next task, a monitor callback within
// a few hundred instructions or a few thousand pattern steps) and `arbc run` prints the counters
// and writes the trace and report of an interrupted run. If the run has not returned `grace`
// seconds after the signal (a callback stuck where no check runs: plugin code, or a C function
// of a monitor the sandbox does not bound), a watchdog thread runs `give_up` (which names the
// stuck callback and writes what it can) and ends the process with exit code 3, so a signal
// always ends the run within about a second. A phase known to be slow but bounded (closing the
// DDS entities, longer on a loaded or sanitized machine) may ask for more time: `patience`.
#pragma once

#include <atomic>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <thread>

namespace arbc::cli {

class RunInterrupt {
 public:
  RunInterrupt();  // one at a time: the signal handlers are process-wide
  ~RunInterrupt();
  RunInterrupt(const RunInterrupt&) = delete;
  RunInterrupt& operator=(const RunInterrupt&) = delete;

  const std::atomic<bool>* flag() const;
  // "SIGINT" or "SIGTERM" once a signal came; "" before.
  const char* signal_name() const;
  // Starts the watchdog; `give_up(waited)` runs on its thread if the run outlives a signal by
  // `grace` plus what `patience()`, asked once the grace is over, allows (seconds; 0: none).
  void watch(double grace, std::function<double()> patience,
             std::function<void(double waited)> give_up);
  // The run returned: the watchdog stands down. False when it is already giving up: the caller
  // must then not touch the run (the process is about to exit) and should wait.
  bool run_returned();

 private:
  void watchdog(double grace);

  int pipe_[2] = {-1, -1};
  std::thread thread_;
  std::function<double()> patience_;
  std::function<void(double)> give_up_;
  std::mutex mutex_;
  std::condition_variable returned_cv_;
  bool returned_ = false, giving_up_ = false;
};

}  // namespace arbc::cli
