// The proof obligation of one arbitrated port, before any solver sees it
// (docs/design.md#the-proof).
//
// For each rule c the effective guard (core/effective_guard.h) is
//   E_c = G_c and (events c sets on every accepting path)
//             and not (events c unsets on every accepting path that no other connection
//                      of the port sets)
//             and act_c (`by priority`: the activity event the runtime sets as c delivers),
// because at the decision (step 2 of a delivery) c's own accept has already run, and c's
// delivery sets act_c in the same step. A `script` rule is opaque: E_c = G_c and act_c. Every event
// in the port's scope is a free boolean, restricted only by the exclusive groups and invariants
// that mention the scope (closed transitively, so an invariant linking a scope event to another
// event brings that event's constraints in too).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/app_model.h"
#include "verify/report.h"

namespace arbc::verify {

struct ScopedRule {
  const model::Connection* connection = nullptr;
  Constraint effective_guard;
  std::vector<std::string> forced_present;  // must_set events that enter the guard
  std::vector<std::string> forced_absent;   // must_unset events that enter the guard
  std::string activity;                     // the activity event set on delivery, if any
};

// A domain constraint: an exclusive group or an invariant, as a formula over events.
struct DomainConstraint {
  Constraint formula;
  bool is_invariant = false;       // else an exclusive group
  std::vector<std::string> group;  // the group's events (solvers use a cardinality constraint)
  std::string text;                // the invariant's text or "exclusive { a, b }"
  model::SourceLocation loc;
};

struct PortScope {
  const model::ArbitratedPort* port = nullptr;
  std::vector<ScopedRule> rules;         // in the port's rule order
  std::vector<std::string> events;       // sorted, unique
  std::vector<DomainConstraint> domain;  // in model order
};

// The scope of `port`; nullopt (and `err`) when a rule named by the port is not a rule
// connection into it, or an assert names a rule the port does not have.
std::optional<PortScope> build_port_scope(const model::App& app, const model::ArbitratedPort& port,
                                          std::string* err);

// The state with `present` (sorted) present and the scope's other events absent.
EventState state_of(const PortScope& scope, const std::vector<std::string>& present);

// "at most one of the events" as a formula: pairwise "not (a and b)".
Constraint at_most_one(const std::vector<std::string>& events);

}  // namespace arbc::verify
