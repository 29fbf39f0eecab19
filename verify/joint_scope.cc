#include "verify/joint_scope.h"

#include <algorithm>
#include <set>

#include "core/event_facts.h"

namespace arbc::verify {

namespace {

// Each event of `s` keeps its name when it is one fact in both ports, else "PORT:event".
std::map<std::string, std::string> joint_names(const model::App& app, const PortScope& s,
                                               const std::string& other_port) {
  std::map<std::string, std::string> names;
  for (const std::string& e : s.events) {
    bool shared = model::one_fact(app, e, s.port->port, other_port);
    names[e] = shared ? e : s.port->port + ":" + e;
  }
  return names;
}

Constraint renamed(const Constraint& c, const std::map<std::string, std::string>& names) {
  return map_events(c, [&](const std::string& e) {
    auto it = names.find(e);
    return Constraint::event_ref(it == names.end() ? e : it->second);
  });
}

std::vector<std::string> renamed(const std::vector<std::string>& events,
                                 const std::map<std::string, std::string>& names) {
  std::vector<std::string> out;
  for (const std::string& e : events) out.push_back(names.count(e) ? names.at(e) : e);
  return out;
}

// The port's rules and domain constraints over its joint variables.
void add_port(const PortScope& s, const std::map<std::string, std::string>& names, PortScope& j) {
  for (const ScopedRule& r : s.rules) {
    ScopedRule copy = r;
    copy.effective_guard = renamed(r.effective_guard, names);
    copy.forced_present = renamed(r.forced_present, names);
    copy.forced_absent = renamed(r.forced_absent, names);
    j.rules.push_back(std::move(copy));
  }
  // An exclusive group or invariant holds in every container, so in each port's copy of it.
  for (const DomainConstraint& d : s.domain) {
    DomainConstraint copy = d;
    copy.formula = renamed(d.formula, names);
    copy.group = renamed(d.group, names);
    bool known = std::any_of(j.domain.begin(), j.domain.end(),
                             [&](const DomainConstraint& e) { return e.formula == copy.formula; });
    if (!known) j.domain.push_back(std::move(copy));
  }
  for (const auto& [event, variable] : names) j.events.push_back(variable);
}

}  // namespace

Constraint map_events(const Constraint& c, const std::function<Constraint(const std::string&)>& f) {
  switch (c.op) {
    case Constraint::Op::True:
    case Constraint::Op::False:
      return c;
    case Constraint::Op::Event:
      return f(c.event);
    case Constraint::Op::Not:
      return Constraint::negate(map_events(c.args[0], f));
    case Constraint::Op::And:
    case Constraint::Op::Or: {
      std::vector<Constraint> args;
      for (const Constraint& a : c.args) args.push_back(map_events(a, f));
      return c.op == Constraint::Op::And ? Constraint::conjunction(std::move(args))
                                         : Constraint::disjunction(std::move(args));
    }
  }
  return c;
}

JointScope make_joint_scope(const model::App& app, const PortScope& a, const PortScope& b) {
  JointScope j;
  j.names_a = joint_names(app, a, b.port->port);
  j.names_b = joint_names(app, b, a.port->port);
  j.scope.port = a.port;
  add_port(a, j.names_a, j.scope);
  j.first_rules = static_cast<int>(a.rules.size());
  add_port(b, j.names_b, j.scope);
  std::sort(j.scope.events.begin(), j.scope.events.end());
  j.scope.events.erase(std::unique(j.scope.events.begin(), j.scope.events.end()),
                       j.scope.events.end());
  return j;
}

std::string joint_event_text(const std::string& variable) {
  size_t colon = variable.rfind(':');
  if (colon == std::string::npos) return variable;
  return variable.substr(colon + 1) + " in " + variable.substr(0, colon);
}

}  // namespace arbc::verify
