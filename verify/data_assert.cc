#include "verify/data_assert.h"

#include <algorithm>

#include "core/join.h"
#include "verify/data_pair.h"

namespace arbc::verify {

namespace {

Finding assert_finding(const PortScope& scope, const model::Assertion& a) {
  Finding f;
  f.check = kCheckAssert;
  f.severity = Severity::Error;
  f.port = scope.port->port;
  f.rules = {a.rule};
  f.loc = a.loc;
  return f;
}

// Runs the witness message through the rule's monitor: it must accept, deliver what Z3 says it
// delivers, and the property must be false on that value; else `*why` (an internal error).
bool replay_violation(const model::Connection& c, const model::Assertion& a, const Type& type,
                      const DataWitness& w, DataQuery& data, const MonitorRunner* runner,
                      MessageExample& ex, std::string* why) {
  if (!replay_accepts(data.app(), runner, {&c}, w.messages, {0}, ex, why)) return false;
  MonitorRun run;
  std::string err;
  runner->run(c, w.messages[0], &run, &err);
  std::optional<bool> holds = data.holds(*a.emitted, run.delivered, type);
  if (!holds) {  // undecided (the deadline passed): neither confirms nor contradicts Z3
    why->clear();
    return false;
  }
  if (!*holds) {
    ex.replay.push_back("the property is false on what it delivers");
    return true;
  }
  *why = "Z3 says '" + c.name +
         "' delivers a value for which the assert over `emitted` is false, " +
         "but its Lua monitor delivers " + spec_value_text(run.delivered) +
         (holds ? ", for which it holds" : ", on which it cannot be decided");
  return false;
}

}  // namespace

DataAssertOutcome check_data_assert(const PortScope& scope, int rule_index,
                                    const model::Assertion& a, PortSolver& solver, DataQuery& data,
                                    const MonitorRunner* runner) {
  DataAssertOutcome out;
  const ScopedRule& rule = scope.rules[static_cast<size_t>(rule_index)];
  const model::Connection& c = *rule.connection;
  const std::string what = model::assertion_text(scope.port->port, a);
  // Where the rule is never selected it never delivers: the assert holds (the dead check says so).
  std::optional<std::vector<std::string>> present = solver.minimal_state({rule_index}, {});
  if (!present) {
    if (solver.last_answer() == Answer::Unknown) {
      out.unknown = "the assert on '" + a.rule + "'";
      out.unknown_reason = solver.unknown_reason();
    }
    return out;
  }
  std::string opaque = data.predicate_opaque_reason(c, *a.emitted);
  if (!opaque.empty()) {
    Finding f = assert_finding(scope, a);
    f.message = what + " is not proved: it is opaque for data (" + opaque + ")";
    f.notes.push_back({"arbc cannot show what it delivers; an unproved assert never passes", {}});
    out.finding = std::move(f);
    return out;
  }
  DataWitness w;
  Answer ans = data.ask({{&c, &*a.emitted, true}}, &w, nullptr);
  if (ans == Answer::Unknown) {
    out.unknown = "the assert on '" + a.rule + "'";
    out.unknown_reason = data.unknown_reason();
    return out;
  }
  if (ans == Answer::Unsat) return out;
  Finding f = assert_finding(scope, a);
  f.message =
      what + " can fail: '" + a.rule + "' can deliver a value for which the property is false";
  f.counterexample = state_of(scope, *present);
  f.notes.push_back({"in the event state (fewest events present): present: " +
                         (present->empty() ? std::string("none") : join(*present)),
                     {}});
  MessageExample ex;
  ex.source = c.source;
  ex.value = spec_value_text(w.messages[0], port_type_of(data.app(), c.source));
  f.notes.push_back({"the message: " + ex.source + " = " + ex.value, {}});
  f.notes.push_back({"'" + a.rule + "' is selected (`" + rule.effective_guard.to_string() +
                         "`) and delivers " + spec_value_text(w.emitted[0]),
                     c.loc});
  if (!w.assumed_state[0].empty()) {
    f.notes.push_back({"with monitor state " + join(w.assumed_state[0]) +
                           " (abstracted: any value earlier messages could leave), so not "
                           "replayed",
                       {}});
    f.not_replayable = "it needs monitor state that earlier messages would have to leave";
  } else if (runner) {
    std::string why;
    const model::Port* port = data.app().find_port(scope.port->port);
    bool replayed = port && replay_violation(c, a, *port->type, w, data, runner, ex, &why);
    if (!replayed && port && why.empty()) {  // the replayed value's verdict was not decided
      out.unknown = "the assert on '" + a.rule + "'";
      out.unknown_reason = "timeout";
      return out;
    }
    if (!replayed) {
      out.finding =
          internal_data_error(scope.port->port, a.loc, port ? why : "the port's type is unknown");
      return out;
    }
    f.notes.push_back({"replayed through the Lua monitors: " + join(ex.replay, "; "), {}});
    out.message = w.messages[0];
  } else {
    f.notes.push_back({"not replayed (no monitor runner)", {}});
    f.not_replayable = "it was not replayed";
  }
  f.messages.push_back(std::move(ex));
  f.notes.push_back(
      {"add an `accept` to '" + a.rule + "' that rules such messages out, or correct what it emits",
       {}});
  out.finding = std::move(f);
  return out;
}

}  // namespace arbc::verify
