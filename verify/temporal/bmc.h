// The bounded search every property over time shares (docs/design.md#properties-over-time):
// one solver holds the unrolling of the property's port; for n = first, first+1, ..., bound
// messages it asks, inside a push/pop, for a violation whose last step is step n. The first n
// that is satisfiable gives a trace of the fewest messages.
#pragma once

#include <z3++.h>

#include <chrono>
#include <functional>
#include <optional>
#include <string>

#include "core/app_model.h"
#include "verify/data_query.h"
#include "verify/report.h"
#include "verify/temporal/unrolling.h"

namespace arbc::verify::temporal {

// Messages into the property's port explored by default (`arbc verify --temporal-bound`).
inline constexpr int kDefaultBound = 8;

// The property violated at the last of the first `n` steps of `u`.
using ViolationAt = std::function<z3::expr(const Unrolling& u, int n)>;

// Reads what a property needs from the model of a violation over `n` steps (the step that
// triggered it, for the explanation).
using Witness = std::function<void(const z3::model& m, int n)>;

// Violated (with the trace and, when `data` finds a message for every rule step, the test that
// replays it), HoldsToBound, or Unknown when the deadline passes or the solver gives up.
// `first` is the fewest messages a violation can take (2 for spacing).
TemporalResult bounded_search(const PortShape& shape, const model::TemporalProperty& p, int first,
                              int bound, const ViolationAt& violation, z3::context& ctx,
                              DataQuery* data, std::chrono::steady_clock::time_point deadline,
                              const Witness& witness = {});

// The shape of the property's port and the indices of the rules it names: `rule` (-1 for a
// stability, which names none) and `other` (-1 when it names none). nullopt and *err when the
// port is not arbitrated or has no such rule ("the property at line 7 names rule 'x', which P
// does not have": bad input, not a verdict).
struct PropertyShape {
  PortShape shape;
  int rule = -1;
  int other = -1;
};
// `faithful`: the shape's unrolling keeps to runs the replay can make (PortShape::faithful);
// `data` (may be null): what deliveries do to the port's own delivery events (port_shape).
std::optional<PropertyShape> property_shape(const model::App& app, const model::TemporalProperty& p,
                                            std::string* err, bool faithful = false,
                                            DataQuery* data = nullptr);

}  // namespace arbc::verify::temporal
