#include "import/twist_mux/twist_mux_spec.h"

#include <nlohmann/json.hpp>

#include "core/check_ids.h"
#include "core/duration_literal.h"
#include "core/instant.h"
#include "core/join.h"
#include "import/twist_mux/twist_mux_names.h"

namespace arbc::twist_mux {
namespace {

constexpr const char* kTwist =
    "{ linear: { x: 0.1, y: 0.0, z: 0.0 }, angular: { x: 0.0, y: 0.0, z: 0.1 } }";

std::string duration(double seconds) { return duration_literal(nanos_from_seconds(seconds)); }
std::string ms(int n) { return duration_literal(nanos_from_seconds(n / 1000.0)); }

std::string timeout_text(const MuxEntry& e) {
  return e.timeout > 0 ? "timeout " + duration(e.timeout) : "no timeout";
}

// A ROS 2 topic name as the deployment file writes it: relative names in the root namespace.
std::string topic_name(const std::string& t) { return t.empty() || t[0] == '/' ? t : "/" + t; }

class Writer {
 public:
  Writer(const MuxConfig& c, std::string source, std::string output)
      : config_(c), names_(name_mux(c)), source_(std::move(source)), output_(std::move(output)) {}

  MuxSpec write() {
    warn_choices();
    header();
    modules();
    events();
    arbitration();
    properties();
    tests();
    return {s_, deploy(), warnings_};
  }

 private:
  void warn(const model::SourceLocation& at, std::string message) {
    warnings_.push_back(
        make_diagnostic(Severity::Warning, at, std::move(message), diag::TwistMuxChoice.text()));
  }

  void warn_choices() {
    for (const MuxEntry& e : config_.inputs) {
      if (e.priority == 0)
        warn(e.priority_loc, "input '" + e.name +
                                 "' has priority 0, and twist_mux only publishes an input whose "
                                 "priority is above 0: it is left out of the spec");
    }
    const std::vector<Named>& in = names_.inputs;
    for (size_t i = 1; i < in.size(); ++i) {
      if (in[i].entry->priority != in[i - 1].entry->priority) continue;
      warn(in[i].entry->priority_loc,
           "inputs '" + in[i - 1].entry->name + "' (line " +
               std::to_string(in[i - 1].entry->loc.line) + ") and '" + in[i].entry->name +
               "' have the same priority, " + std::to_string(in[i].entry->priority) +
               ": while both are active twist_mux publishes the one it holds first in its list "
               "and drops the other's commands, an order the file does not show. The spec lets "
               "both deliver, so `arbc verify` refutes " +
               names_.base + ".cmd_vel until one of the priorities is changed");
    }
    for (const Named& above : in) {
      if (above.heard.empty()) continue;
      warn(above.entry->loc, "input '" + above.entry->name +
                                 "' never times out (timeout 0), so twist_mux counts it active "
                                 "from the start: the inputs below its priority never reach the "
                                 "base");
    }
    for (const MuxEntry& l : config_.locks) {
      bool kept = false;
      for (const Named& n : names_.locks) kept = kept || n.entry == &l;
      if (!kept)
        warn(l.priority_loc, "lock '" + l.name + "' (priority " + std::to_string(l.priority) +
                                 ") blocks no input: twist_mux masks the inputs whose priority is "
                                 "below a lock's; it is left out of the spec");
    }
  }

  void header() {
    s_ += "// Written by `arbc import twist_mux` (docs/twist_mux.md) from\n//   " + source_ + "\n";
    s_ +=
        "// Each input is active for its timeout after each of its messages; the active input\n"
        "// of highest priority drives the base. A lock engaged (its last message true, or\n"
        "// silent for its timeout) blocks the inputs below its priority.\n";
    s_ +=
        "app twist_mux \"The active input of highest priority drives the base; an engaged lock "
        "blocks the inputs below it.\";\n\n";
    s_ += "use ros2 geometry_msgs/msg/Twist;\n";
    if (!names_.locks.empty()) s_ += "use ros2 std_msgs/msg/Bool;\n";
    s_ += "\n";
  }

  void modules() {
    for (const Named& n : names_.inputs)
      s_ += "module " + n.module + " \"input " + n.entry->name + ": topic " + n.entry->topic +
            ", priority " + std::to_string(n.entry->priority) + ", " + timeout_text(*n.entry) +
            "\" { out cmd_vel: Twist; }\n";
    for (const Named& n : names_.locks)
      s_ += "module " + n.module + " \"lock " + n.entry->name + ": topic " + n.entry->topic +
            ", priority " + std::to_string(n.entry->priority) + ", " + timeout_text(*n.entry) +
            "\" { out lock: Bool; }\n";
    s_ += "module " + names_.base + " \"the base: what twist_mux publishes on " + output_ +
          "\" { in cmd_vel: Twist; }\n\n";
  }

  void events() {
    s_ +=
        "// An input is active for its timeout after each of its messages, selected or not (its\n"
        "// rule's body sets it, as twist_mux stamps a message on arrival); absent before.\n";
    std::vector<std::string> active;
    for (const Named& n : names_.inputs) active.push_back(n.event);
    s_ += "event " + join(active) + ";\n";
    for (const Named& n : names_.inputs) {
      if (n.heard.empty()) continue;
      s_ += "// Input " + n.entry->name +
            " never times out: twist_mux counts it active from the start, so the\n"
            "// rules below it stay closed before it speaks (unknown) and after (present).\n";
      s_ += "event " + n.heard + " = " + n.module + ".cmd_vel : true;\n";
    }
    if (names_.locks.empty()) return s_.append("\n"), void();
    s_ +=
        "// A lock is engaged while its last message said true (its `data`); one with a timeout\n"
        "// also while it has been silent that long, and until it first speaks (fail closed).\n";
    for (const Named& n : names_.locks) {
      s_ += "event " + n.event + " = lock " + n.module + ".lock";
      s_ += n.heard.empty() ? " otherwise open after 1ms;\n"
                            : " timeout " + duration(n.entry->timeout) + ";\n";
    }
    s_ += "\n";
  }

  void arbitration() {
    s_ += "arbitrate " + names_.base + ".cmd_vel {\n";
    for (const Named& n : names_.inputs) {
      std::vector<std::string> terms = blocking_terms(names_, n);
      // Its own activity, set by the body of this very message before the decision: a rule is
      // selected only while it is the active input, so no two are selected in one state.
      terms.insert(terms.begin(), n.event);
      s_ += "  " + n.rule + ": from " + n.module + ".cmd_vel\n      when " +
            join(terms, "\n       and ") + " {\n    set " + n.event;
      s_ += n.entry->timeout > 0 ? " for " + duration(n.entry->timeout) + ";\n  }\n" : ";\n  }\n";
    }
    s_ += "}\n\n";
  }

  void properties() {
    s_ +=
        "// What a twist_mux user relies on, proved by `arbc verify`: an active input above a\n"
        "// rule's keeps it out, and so does an engaged lock above it.\n";
    for (const Named& n : names_.inputs) {
      for (const Named& above : names_.inputs)
        if (above.entry->priority > n.entry->priority)
          s_ += "never " + n.rule + " while " + (above.heard.empty() ? above.event : above.heard) +
                ";\n";
      for (const Named& lock : names_.locks)
        if (blocks(lock, n)) s_ += "never " + n.rule + " while " + lock.event + ";\n";
    }
    s_ += "\n";
  }

  // The lock messages that keep every lock but `except` released and heard at `t`.
  std::string release_locks(const std::string& t, const Named* except) const {
    std::string out;
    for (const Named& l : names_.locks)
      if (&l != except) out += "  at " + t + " " + l.module + ".lock <- { data: false };\n";
    return out;
  }
  std::string send(const std::string& t, const Named& in) const {
    return "  at " + t + " " + in.module + ".cmd_vel <- " + kTwist + ";\n";
  }

  void tests() {
    for (const Named& n : names_.inputs) input_test(n);
    for (const Named& l : names_.locks) lock_test(l);
  }

  // An input above `n` that never times out, which twist_mux counts active from the start
  // (arbc in a DDS run: from the start, as unknown; in a test, from its first message).
  const Named* never_expiring_above(const Named& n) const {
    for (const Named& above : names_.inputs)
      if (above.entry->priority > n.entry->priority && !above.heard.empty()) return &above;
    return nullptr;
  }

  void input_test(const Named& n) {
    const Named* blocker = never_expiring_above(n);
    s_ += "test \"input " + n.entry->name + (blocker ? " is kept out" : " alone drives the base") +
          "\" {\n";
    s_ += release_locks(ms(100), nullptr);
    if (blocker) s_ += send(ms(100), *blocker);
    s_ += send(ms(100), n);
    s_ += blocker ? "  expect " + n.rule + " drops \"not-selected\" at 100ms;\n"
                  : "  expect " + names_.base + ".cmd_vel receives " + kTwist + " at 100ms;\n";
    s_ += "}\n\n";
  }

  // The lock engaged keeps out the highest input below it; released, that input drives.
  void lock_test(const Named& l) {
    const Named* below = nullptr;
    for (const Named& n : names_.inputs)
      if (!below && blocks(l, n)) below = &n;
    bool never = never_expiring_above(*below) != nullptr;
    s_ += "test \"lock " + l.entry->name + " blocks input " + below->entry->name + "\" {\n";
    s_ += release_locks(ms(100), &l) + "  at 100ms " + l.module + ".lock <- { data: true };\n";
    s_ += send(ms(100), *below);
    s_ += "  expect " + below->rule + " drops \"not-selected\" at 100ms;\n";
    if (!never) {
      s_ += release_locks(ms(200), nullptr) + send(ms(200), *below);
      s_ += "  expect " + below->rule + " delivers at 200ms;\n";
    }
    if (!l.heard.empty() && !never) {
      std::string t = duration(0.2 + l.entry->timeout + 0.1);
      s_ += release_locks(t, &l) + send(t, *below);
      s_ += "  expect " + below->rule + " drops \"not-selected\" at " + t +
            ";  // the lock is silent\n";
    }
    s_ += "}\n\n";
  }

  std::string deploy() const {
    nlohmann::ordered_json topics;
    for (const Named& n : names_.inputs) topics[n.module + ".cmd_vel"] = topic_name(n.entry->topic);
    for (const Named& n : names_.locks) topics[n.module + ".lock"] = topic_name(n.entry->topic);
    topics[names_.base + ".cmd_vel"] = topic_name(output_);
    nlohmann::ordered_json d{{"ros2", true}, {"topics", topics}};
    return d.dump(2) + "\n";
  }

  const MuxConfig& config_;
  MuxNames names_;
  std::string source_, output_;
  std::string s_;
  std::vector<Diagnostic> warnings_;
};

}  // namespace

MuxSpec write_mux_spec(const MuxConfig& config, const std::string& source_name,
                       const std::string& output_topic) {
  return Writer(config, source_name, output_topic).write();
}

}  // namespace arbc::twist_mux
