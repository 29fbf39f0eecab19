// An unbounded proof of a property over time by k-induction (docs/design.md#properties-over-time).
// The base case is the bounded search (verify/temporal/bmc.h): no run from the empty container
// violates the property within `bound` messages. The step case for k: no run of k messages into
// the port, starting from ANY state (container entries, each rule's last delivery time, the
// monitors of precedences and assumptions all free, constrained only by what every reachable
// state satisfies), in which the property holds at the first k-1 messages, violates it at the
// k-th. With both, by induction over the run's length, no run of any length violates it.
#pragma once

#include <z3++.h>

#include <chrono>

#include "verify/report.h"
#include "verify/temporal/bmc.h"
#include "verify/temporal/unrolling.h"

namespace arbc::verify::temporal {

// For a result that holds up to its bound: the smallest k <= bound for which the step case
// holds makes it Proved (result.induction_k = k, result.proof says so); otherwise (or when the
// deadline passes) it stays "holds up to the bound". `violation` as for bounded_search.
void try_induction(TemporalResult& result, const PortShape& shape, const ViolationAt& violation,
                   z3::context& ctx, std::chrono::steady_clock::time_point deadline);

}  // namespace arbc::verify::temporal
