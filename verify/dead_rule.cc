#include "verify/dead_rule.h"

#include <algorithm>

#include "core/join.h"

namespace arbc::verify {

namespace {

bool contains(const std::vector<std::string>& v, const std::string& x) {
  return std::find(v.begin(), v.end(), x) != v.end();
}

}  // namespace

std::vector<std::string> self_excluded(const ScopedRule& r) {
  const Constraint& when = r.connection->constraint;
  std::vector<const Constraint*> conjuncts;
  if (when.op == Constraint::Op::And) {
    for (const Constraint& c : when.args) conjuncts.push_back(&c);
  } else {
    conjuncts.push_back(&when);
  }
  std::vector<std::string> out;
  for (const Constraint* c : conjuncts) {
    if (c->op == Constraint::Op::Not && c->args[0].op == Constraint::Op::Event &&
        contains(r.forced_present, c->args[0].event))
      out.push_back("sets " + c->args[0].event);
    if (c->op == Constraint::Op::Event && contains(r.forced_absent, c->event))
      out.push_back("unsets " + c->event);
  }
  return out;
}

Finding dead_rule_finding(const ScopedRule& r, const std::string& port, bool under_domain,
                          bool strict) {
  Finding f;
  f.check = kCheckDead;
  f.severity = strict ? Severity::Error : Severity::Warning;
  f.strict = strict;
  f.port = port;
  f.rules = {r.connection->name};
  f.loc = r.connection->loc;
  const std::string rule = "'" + r.connection->name + "'";
  std::vector<std::string> own = self_excluded(r);
  if (own.empty()) {
    f.message = "rule " + rule + " of " + port + " can never be selected: its effective guard `" +
                r.effective_guard.to_string() + "` is unsatisfiable" +
                (under_domain ? " under the declared invariants and exclusive groups" : "");
    f.notes.push_back({"fix the `when` of " + rule + ", or remove the rule", {}});
    return f;
  }
  // The trap of issue 42: `when not e_busy { set e_busy; }` reads as "take the lock when free",
  // but the body runs when the message is accepted, before the rules are chosen.
  f.message = "rule " + rule + " of " + port + " can never be selected: its body " +
              join(own, " and ") +
              " when it accepts a message, before the rules are chosen, and its own `when` (`" +
              r.connection->constraint.to_string() + "`) excludes that";
  f.notes.push_back(
      {"a body's `set` and `unset` take effect when the monitor accepts the message, before "
       "selection (docs/design.md#effective-guards), as a YARP monitor's do",
       {}});
  f.notes.push_back({"to take an event only when " + rule +
                         " delivers, drop the `set` and write it after the `when`: `... then "
                         "set E { ... }` (docs/language.md#events-set-on-delivery)",
                     {}});
  return f;
}

std::optional<Finding> dead_port_finding(const PortScope& scope,
                                         const std::vector<std::string>& dead,
                                         size_t delivering_rules, bool strict) {
  // One rule: its own warning already says the port gets nothing.
  if (delivering_rules < 2 || dead.size() < delivering_rules) return std::nullopt;
  Finding f;
  f.check = kCheckDead;
  f.severity = strict ? Severity::Error : Severity::Warning;
  f.strict = strict;
  f.port = scope.port->port;
  f.rules = dead;
  f.loc = scope.port->loc;
  f.message = "no rule of " + scope.port->port + " can ever be selected (all " +
              std::to_string(dead.size()) +
              " of its rules are dead): the port never receives "
              "anything";
  f.notes.push_back({"`arbc build` still writes the app; fix the rules above first", {}});
  return f;
}

}  // namespace arbc::verify
