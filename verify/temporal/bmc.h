// The bounded search every property over time shares (docs/design.md#properties-over-time):
// one solver holds the unrolling of the property's port; for n = first, first+1, ..., bound
// messages it asks, inside a push/pop, for a violation whose last step is step n. The first n
// that is satisfiable gives a trace of the fewest messages.
#pragma once

#include <z3++.h>

#include <chrono>
#include <functional>

#include "core/app_model.h"
#include "verify/data_query.h"
#include "verify/report.h"
#include "verify/temporal/unrolling.h"

namespace arbc::verify::temporal {

// Messages into the property's port explored by default (`arbc verify --temporal-bound`).
inline constexpr int kDefaultBound = 8;

// The property violated at the last of the first `n` steps of `u`.
using ViolationAt = std::function<z3::expr(const Unrolling& u, int n)>;

// Violated (with the trace and, when `data` finds a message for every rule step, the test that
// replays it), HoldsToBound, or Unknown when the deadline passes or the solver gives up.
// `first` is the fewest messages a violation can take (2 for spacing).
TemporalResult bounded_search(const PortShape& shape, const model::TemporalProperty& p, int first,
                              int bound, const ViolationAt& violation, z3::context& ctx,
                              DataQuery* data, std::chrono::steady_clock::time_point deadline);

// The index of `rule` in `shape`; -1 and *err ("the property at line 7 names rule 'x', which
// P does not have": bad input, not a verdict) when the port has no such rule.
int property_rule(const PortShape& shape, const model::TemporalProperty& p, const std::string& rule,
                  std::string* err);

}  // namespace arbc::verify::temporal
