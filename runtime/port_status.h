// The live view of the arbitrated ports (issue 42, docs/runtime.md#live-status): which rule of
// each port is selected now and, for every other rule, why it is not, with the port's counters.
// The runtime fills it on its own thread (Runtime::port_status, runtime_status.cc); `arbc run
// --status` draws it on the terminal and a DDS mediator publishes it (status topics and
// /diagnostics). This file holds the values and the texts, so that every view says the same.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "core/constraint.h"
#include "core/instant.h"
#include "runtime/drop_reason.h"

namespace arbc {

// diagnostic_msgs/msg/DiagnosticStatus's levels (OK 0, WARN 1, ERROR 2), in that order.
enum class StatusLevel { Ok, Warn, Error };
const char* status_level_name(StatusLevel level);  // "OK", "WARN", "ERROR"

struct RuleStatus {
  std::string rule, source;  // "nav", "Nav.cmd_vel"
  bool selected = false;     // it delivered last on its port and may deliver now
  // Empty: nothing keeps it from delivering its source's next message. Else why it cannot, first
  // cause first: "quarantined", "unknown since start: e_ok (nothing from EStop.state yet)",
  // "held by dock's hold", "e_bumped present", "throttled for 20ms".
  std::string blocked;
  Nanos last_arrival = -kNever;  // its source's last message (-kNever: none yet)
  Nanos last_delivery = -kNever;
  uint64_t arrived = 0, delivered = 0;
  std::array<uint64_t, kDropReasonCount> dropped{};
};

struct PortStatus {
  std::string port;      // "Base.cmd_vel"
  std::string selected;  // the selected rule; empty: none
  StatusLevel level = StatusLevel::Ok;
  std::string message;  // one line: "nav selected", "no rule may deliver: ..."
  Nanos last_delivery = -kNever;
  std::string last_rule;                // the rule that delivered last (-kNever above: none yet)
  uint64_t arrived = 0, delivered = 0;  // over its rules (a message read by two rules: twice)
  std::array<uint64_t, kDropReasonCount> dropped{};
  std::vector<RuleStatus> rules;  // in spec order
};

// Why `c` is false over the events `present` says are present: the false parts, each as the
// event state that makes it false ("e_bumped present", "e_ok absent"); a conjunct `not ACT`
// where `hold_of(ACT)` names a rule reads "held by RULE's hold". Empty when `c` is true.
std::string why_false(const Constraint& c, const std::function<bool(const std::string&)>& present,
                      const std::function<std::string(const std::string&)>& hold_of);

// A rule's state in words at `now`: "selected, delivered 12ms ago", the reason it is blocked, or
// "may deliver; nothing from Joy.cmd_vel for 2s" (its source is silent).
std::string rule_state_text(const RuleStatus& r, Nanos now);

// Level and message of a port from its rules; `losses`: its connections lost messages since the
// last status (queue-full, bad-type, a monitor error, ...).
void summarize_port(PortStatus& p, bool losses);

// One line per port for a terminal: "Base.cmd_vel  OK  nav selected | joy: e_joy absent | ...".
std::string status_lines(const std::vector<PortStatus>& ports, Nanos now);

}  // namespace arbc
