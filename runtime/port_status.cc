#include "runtime/port_status.h"

#include "core/duration_literal.h"
#include "core/join.h"

namespace arbc {

namespace {

using Present = std::function<bool(const std::string&)>;
using HoldOf = std::function<std::string(const std::string&)>;

void false_parts(const Constraint& c, const Present& present, const HoldOf& hold_of,
                 std::vector<std::string>& out);

// The parts of a true `c` that make it true, each as the state that does: every conjunct of an
// `and`, the alternatives of an `or` that hold, an event's presence ("held by R's hold" for a
// priority's activity event). A lock's `not (L_engaged or not L_heard)` is false because
// "L_heard absent", not because "`L_engaged or not L_heard` holds".
void true_parts(const Constraint& c, const Present& present, const HoldOf& hold_of,
                std::vector<std::string>& out) {
  switch (c.op) {
    case Constraint::Op::True:
    case Constraint::Op::False:
      return;
    case Constraint::Op::Event: {
      std::string rule = hold_of(c.event);
      out.push_back(rule.empty() ? c.event + " present" : "held by " + rule + "'s hold");
      return;
    }
    case Constraint::Op::Not:
      false_parts(c.args[0], present, hold_of, out);
      return;
    case Constraint::Op::And:
    case Constraint::Op::Or:
      for (const Constraint& a : c.args)
        if (evaluate_with(a, present)) true_parts(a, present, hold_of, out);
      return;
  }
}

// The parts of a false `c` that make it false, each as the state that does: the conjuncts of an
// `and` that are false, every alternative of an `or` (all false), an event's presence.
void false_parts(const Constraint& c, const Present& present, const HoldOf& hold_of,
                 std::vector<std::string>& out) {
  switch (c.op) {
    case Constraint::Op::True:
      return;
    case Constraint::Op::False:
      out.push_back("its `when` is false");
      return;
    case Constraint::Op::Event:
      out.push_back(c.event + " absent");
      return;
    case Constraint::Op::Not:  // false: its argument holds, and says why
      true_parts(c.args[0], present, hold_of, out);
      return;
    case Constraint::Op::And:
    case Constraint::Op::Or:  // false: each alternative is, and each says why
      for (const Constraint& a : c.args)
        if (!evaluate_with(a, present)) false_parts(a, present, hold_of, out);
      return;
  }
}

}  // namespace

const char* status_level_name(StatusLevel level) {
  switch (level) {
    case StatusLevel::Ok:
      return "OK";
    case StatusLevel::Warn:
      return "WARN";
    case StatusLevel::Error:
      return "ERROR";
  }
  return "ERROR";
}

std::string why_false(const Constraint& c, const Present& present, const HoldOf& hold_of) {
  if (evaluate_with(c, present)) return "";
  std::vector<std::string> parts;
  false_parts(c, present, hold_of, parts);
  return join(parts, ", ");
}

std::string rule_state_text(const RuleStatus& r, Nanos now) {
  if (r.selected) return "selected, delivered " + age_literal(now - r.last_delivery) + " ago";
  if (!r.blocked.empty()) return r.blocked;
  if (r.last_arrival == -kNever) return "may deliver; nothing from " + r.source + " yet";
  return "may deliver; last message from " + r.source + " " + age_literal(now - r.last_arrival) +
         " ago";
}

void summarize_port(PortStatus& p, bool losses) {
  std::vector<std::string> quarantined, ready;
  for (const RuleStatus& r : p.rules) {
    if (r.blocked == "quarantined") quarantined.push_back(r.rule);
    if (r.blocked.empty()) ready.push_back(r.rule);
  }
  if (!quarantined.empty()) {
    p.level = StatusLevel::Error;
    p.message = join(quarantined, ", ", " and ") + " quarantined";
  } else if (!p.selected.empty()) {
    p.level = StatusLevel::Ok;
    p.message = p.selected + " selected";
  } else if (!ready.empty()) {
    p.level = StatusLevel::Ok;
    p.message = "none selected; " + join(ready, ", ", " or ") + " may deliver";
  } else {
    // Every rule blocked: the destination gets nothing (by design under an e-stop, but whoever
    // watches the robot should see it).
    p.level = StatusLevel::Warn;
    p.message = "no rule may deliver";
  }
  if (losses && p.level == StatusLevel::Ok) {
    p.level = StatusLevel::Warn;
    p.message += "; messages lost since the last status";
  }
}

std::string status_lines(const std::vector<PortStatus>& ports, Nanos now) {
  std::string out;
  for (const PortStatus& p : ports) {
    out += p.port + "  " + status_level_name(p.level) + "  " + p.message;
    for (const RuleStatus& r : p.rules) {
      if (r.selected) continue;  // the message names it
      out += " | " + r.rule + ": " + rule_state_text(r, now);
    }
    out +=
        "  [" + std::to_string(p.delivered) + " of " + std::to_string(p.arrived) + " delivered]\n";
  }
  return out;
}

}  // namespace arbc
