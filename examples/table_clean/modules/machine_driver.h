// Drives a timed state machine (the arm, the rake) from a module: publishes the machine's
// status flags on every change and on every heartbeat (10 Hz), and wakes the machine exactly
// when its next step is due, so that a status change is published at the simulated instant it
// happens (examples/table_clean/README.md#the-modules-modules).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "runtime/module.h"

namespace arbc::table_clean {

struct TimedMachine {
  std::function<void(double now)> update;
  std::function<std::optional<double>()> next_deadline;
  std::function<std::vector<std::string>()> status;
};

class MachineDriver {
 public:
  MachineDriver(arbc::Module& module, std::string status_port, TimedMachine machine)
      : module_(module), port_(std::move(status_port)), machine_(std::move(machine)) {}

  // After anything that may have changed the machine: publish a changed status, re-arm the
  // wake-up for the next step.
  void sync();
  // The periodic report: brings the machine up to date and publishes its status.
  void heartbeat();

 private:
  void publish(const std::vector<std::string>& flags);
  void wake(double due);

  arbc::Module& module_;
  std::string port_;
  TimedMachine machine_;
  std::optional<std::vector<std::string>> last_;
  std::optional<double> wake_due_;
  arbc::TimerId wake_timer_ = 0;
};

}  // namespace arbc::table_clean
