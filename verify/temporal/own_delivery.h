// The port's own delivery events in the temporal model (docs/design.md#properties-over-time):
// `event e = P : PRED [for D];` read by rules of P itself is set (for D from the delivery) or,
// without `for`, unset by the runtime in the task of each delivery into P, after the decision
// (Runtime::deliver), on the value delivered. So the unrolling changes such an entry only at a
// delivery step of P, in that step, as the delivered value allows; the environment never does.
#pragma once

#include <optional>

#include "core/app_model.h"
#include "verify/data_query.h"
#include "verify/temporal/unrolling.h"

namespace arbc::verify::temporal {

// Marks the shape's own delivery entries (Entry::on_delivery) with what a delivery of each
// rule can do to them: the delivered value's constants decide when every `emit` agrees, else
// the data encoding where it is exact (`data` null: neither), else anything.
void add_own_deliveries(const model::App& app, PortShape& shape, DataQuery* data);

// Whether connection c is the feed of the port's own delivery events: it runs only inside a
// delivery of the port, never as a step of its own.
bool own_delivery_feed(const PortShape& shape, int c);

// What `predicate` is on every value `rule` delivers, from constants alone: each `emit` of the
// body (on every path: a path without one delivers the message) is a record whose fields the
// predicate reads are literals, compared with `==`, `!=`, `and`, `or`, `not`; or the predicate
// reads nothing of the value (`false`). nullopt otherwise.
std::optional<bool> constant_outcome(const model::Connection& rule,
                                     const model::BodyExpr& predicate);

}  // namespace arbc::verify::temporal
