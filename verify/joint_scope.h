// The scope of two ports of a resource, over one event state of both containers
// (docs/checks.md#resource). Each port's container holds its own facts: an event both read is
// one variable only where core/event_facts.h says it is one fact (delivery events fed into
// both by one port's deliveries); elsewhere each port's copy is its own variable, named
// "PORT:event", so a rule of one port cannot be kept out by an event of the same name that only
// the other port's container holds.
#pragma once

#include <functional>
#include <map>
#include <string>

#include "core/app_model.h"
#include "verify/port_scope.h"

namespace arbc::verify {

struct JointScope {
  PortScope scope;      // rules: the first port's, then the second's
  int first_rules = 0;  // how many rules the first port has
  // Each port's event names to their joint variables.
  std::map<std::string, std::string> names_a, names_b;
};

JointScope make_joint_scope(const model::App& app, const PortScope& a, const PortScope& b);

// The name a joint variable shows in a report: "e" (one fact) or "e in M.p".
std::string joint_event_text(const std::string& variable);

// `c` with each event replaced by what `f` gives for its name.
Constraint map_events(const Constraint& c, const std::function<Constraint(const std::string&)>& f);

}  // namespace arbc::verify
