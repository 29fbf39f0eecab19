// Whether a replayed run violates a response `after OTHER [stops], RULE within D [while C];`
// (docs/design.md#properties-over-time): some delivery of OTHER at t with no delivery of RULE
// in (t, t + D] (nor, with `stops`, of OTHER), while C was present at each time RULE decided
// in that window. The run goes on after the test's last message with nothing happening, so a
// window that reaches past it is silent there.
#pragma once

#include <string>
#include <vector>

#include "core/app_model.h"
#include "core/test_case.h"
#include "verify/verify.h"

namespace arbc::verify::temporal {

// True when violated; otherwise false and *seen says what the runtime did. The times RULE
// decided are the test's messages on `rule_source`.
bool response_violated(const model::TemporalProperty& p, const std::vector<ReplayRecord>& records,
                       const model::TestCase* test, const std::string& rule_source,
                       std::string* seen);

}  // namespace arbc::verify::temporal
