// Whether a replayed run violates a response `after OTHER [stops], RULE within D [while C];`
// (docs/design.md#properties-over-time): some delivery of OTHER (or onset of the trigger event)
// at t, and after it, up to t + D, no delivery of RULE (of any rule, when the port answers)
// nor, with `stops`, of OTHER, while C was present whenever RULE decided on a message. The
// run goes on after the test's last message with nothing happening, so a window that reaches
// past it is silent there.
#pragma once

#include <string>
#include <vector>

#include "core/app_model.h"
#include "verify/verify.h"

namespace arbc::verify::temporal {

// True when violated; otherwise false and *seen says what the runtime did.
bool response_violated(const model::TemporalProperty& p, const std::vector<ReplayRecord>& records,
                       std::string* seen);

}  // namespace arbc::verify::temporal
