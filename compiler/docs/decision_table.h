// Decision tables for arbitrated ports: which rule an event state selects (arbc docs). Rules are
// compared by their effective guards (docs/design.md#effective-guards), as the proof does.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "core/app_model.h"

namespace arbc::docs {

// Ports with at most this many events get a full table; larger ones get their guards in
// disjunctive normal form instead (2^6 = 64 rows is about what a reader will scan).
inline constexpr int kMaxTableEvents = 6;

struct DecisionRow {
  std::vector<bool> present;          // one per DecisionTable::events
  std::vector<std::string> selected;  // rules whose effective guard holds; empty: none
};

struct RuleGuard {
  std::string rule;
  std::string guard;  // effective guard, as constraint text
  std::string dnf;    // the same in disjunctive normal form ("a and not b or c")
};

struct DecisionTable {
  std::string port;
  std::vector<std::string> events;  // sorted; the columns
  std::vector<RuleGuard> rules;     // in spec order
  bool tabulated = false;           // events.size() <= kMaxTableEvents
  std::vector<DecisionRow> rows;    // when tabulated: every state, in binary counting order
};

DecisionTable decision_table(const model::App& app, const model::ArbitratedPort& port);
// The same, given every connection into the port (App::connections_into, or an index of them
// when tabulating many ports).
DecisionTable decision_table(const model::ArbitratedPort& port,
                             std::span<const model::Connection* const> into);

// Disjunctive normal form of a constraint, as text; contradictory cubes are dropped and the
// expansion stops at `max_cubes` (then the text ends with " or ..."), so it always terminates
// quickly.
std::string dnf_text(const Constraint& c, size_t max_cubes = 64);

}  // namespace arbc::docs
