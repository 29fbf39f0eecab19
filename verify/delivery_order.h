// Exclusivity over deliveries (docs/checks.md#exclusive): two rules that may both hold in one
// state are still never selected together when each one's delivery keeps the other out. A rule
// with `then set e` / `then unset e` changes the port's events in the task of its delivery,
// before any other decision (docs/language.md#events-set-on-delivery), so of two messages
// decided one after the other the second is judged in the state the first delivery left. The
// claim is then: after either delivers, the other is not selected, in whichever order they come.
// The runtime judges the same (runtime/decision_watch.cc reads the state a delivery leaves).
#pragma once

#include <span>
#include <string>

#include "core/app_model.h"
#include "core/constraint.h"
#include "verify/port_solver.h"

namespace arbc::verify {

// Whether `c` changes events as it delivers (`then set` / `then unset`).
bool has_delivery_effects(const model::Connection& c);

// `guard` read in the state a delivery of `deliverer` leaves: its `then set` events present,
// its `then unset` events absent where only deliveries set them (else left as they were), the
// others as before.
Constraint after_delivery(const Constraint& guard, const model::Connection& deliverer,
                          std::span<const model::Connection* const> into);

enum class DeliveryOrder { KeepsOut, Overlap, Unknown };

// Rules i and j of `scope` (which may hold in one state): KeepsOut when no state lets i be
// selected and then j in the state i's delivery leaves, nor j then i; `text` then says so.
DeliveryOrder delivery_order(PortSolver& solver, const PortScope& scope, int i, int j,
                             std::string* text);

}  // namespace arbc::verify
