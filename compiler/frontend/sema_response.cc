// Semantic checks of a response `after OTHER [stops], ANSWER within D [while C];`
// (docs/language.md#properties-over-time). ANSWER is a rule or an arbitrated port (any of its
// rules delivers); OTHER is a rule of the same port (its deliveries trigger the window) or an
// event of that port's container (its becoming present does). The model checker follows one
// port's messages, so both sides must be about one port.
#include <string>
#include <vector>

#include "compiler/frontend/sema_context.h"

namespace arbc::frontend {

using namespace ast;

namespace {

bool names_a_rule(const Spec& spec, const std::string& name) {
  for (const ArbitrateDecl& a : spec.arbitrations)
    for (const Rule& r : a.rules)
      if (r.name == name) return true;
  return false;
}

}  // namespace

bool Sema::names_port_event(const ArbitrateDecl& port, const std::string& name) const {
  if (events_.count(name)) return true;
  for (const std::string& act : activity_events(port))
    if (act == name) return true;
  return false;
}

// OTHER as an event: declared, or an activity event of the port; `stops` reads a rule's last
// delivery, which an event has no counterpart of.
void Sema::check_response_event(TemporalDecl& n, const ArbitrateDecl& port) {
  n.event = n.other;
  n.event_loc = n.other_loc;
  n.other.clear();
  if (n.stops)
    error(n.event_loc,
          "'" + n.event +
              "' is an event: `stops` follows a rule (the window starts at its last delivery); "
              "for an event, the window starts each time it becomes present in " +
              port.port.qualified() + ": write `after " + n.event + ", ...`",
          diag::TemporalPair);
}

// OTHER as a rule: another rule of ANSWER's port.
void Sema::check_response_rule(TemporalDecl& n, const ArbitrateDecl& port) {
  n.other_decl = unique_rule(n.other, n.other_loc, "an `after ... within` property");
  if (!n.other_decl) return;
  if (n.other_decl == n.rule_decl) {
    error(n.other_loc,
          "`after " + n.other + ", " + n.rule +
              " within ...` names one rule twice: name the rule that must respond",
          diag::TemporalPair);
  } else if (n.other_decl->port != &port && n.other_decl->port) {
    std::string answer = n.rule.empty() ? "the answer is " + port.port.qualified()
                                        : "'" + n.rule + "' into " + port.port.qualified();
    error(n.other_loc,
          "'" + n.other + "' goes into " + n.other_decl->port->port.qualified() + " but " + answer +
              "; the trigger rule of `after ..., ... within` must go into the port that answers "
              "(the model checker follows one port's messages)",
          diag::TemporalPair);
  } else {
    return;
  }
  n.rule_decl = n.other_decl = nullptr;  // reported: lowering skips it
}

void Sema::check_response(TemporalDecl& n) {
  check_duration(n.window, "the `within` window");
  const ArbitrateDecl* port = nullptr;
  if (n.rule.empty()) {
    n.port_decl = port = arbitrated_port(n.port, "a response answered by a port");
  } else if ((n.rule_decl = unique_rule(n.rule, n.rule_loc, "an `after ... within` property"))) {
    port = n.rule_decl->port;
  }
  if (n.condition) n.condition_sema = check_constraint(*n.condition, "a response's `while`", false);
  if (!port) return;  // reported (the answer, or its port)

  bool rule = names_a_rule(spec_, n.other), event = names_port_event(*port, n.other);
  if (rule && event) {
    error(
        n.other_loc,
        "'" + n.other + "' names both a rule and an event, so the trigger is ambiguous: rename one",
        diag::TemporalPair);
    n.rule_decl = nullptr;
    n.port_decl = nullptr;
  } else if (event) {
    check_response_event(n, *port);
  } else if (rule) {
    check_response_rule(n, *port);
  } else {
    std::vector<std::string> candidates = event_names_;
    for (const Rule& r : port->rules) candidates.push_back(r.name);
    for (const std::string& act : activity_events(*port)) candidates.push_back(act);
    unknown(n.other_loc,
            "no rule or event is named '" + n.other +
                "': a response starts at each delivery of a rule of " + port->port.qualified() +
                " or each time an event becomes present there",
            diag::UnknownRule, n.other, candidates);
    n.rule_decl = nullptr;
    n.port_decl = nullptr;
  }
}

}  // namespace arbc::frontend
