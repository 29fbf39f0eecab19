// Environment assumptions (docs/design.md#properties-over-time,
// docs/language.md#environment-assumptions): `assume EVENT only after AFTER [until UNTIL];`
// restricts what the feeds report. At every decision of a message into the port, EVENT is present
// in the port's container only while the monitor "armed by a delivery of AFTER, disarmed by one of
// UNTIL" is armed; `assume not EVENT for D after AFTER;` keeps it absent at every decision less
// than D after a delivery of AFTER. The unrolling adds this at each step
// (Unrolling::add_assumptions), so every verdict about the port is under it, and every report
// prints it.
#pragma once

#include <string>
#include <vector>

#include "core/app_model.h"

namespace arbc::verify::temporal {

// The assumptions of `app` about `port`, in spec order.
std::vector<model::Assumption> assumptions_about(const model::App& app, const std::string& port);

}  // namespace arbc::verify::temporal
