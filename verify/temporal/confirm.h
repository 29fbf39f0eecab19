// A violation the model checker found is reported only once the runtime shows it
// (docs/design.md#properties-over-time): its test runs in simulated time and the property is
// checked on what the runtime did at the port (verify/temporal/judge.h).
#pragma once

#include <vector>

#include "verify/report.h"
#include "verify/verify.h"

namespace arbc::verify::temporal {

// Replays `r`'s test when r is Violated. Confirmed: r.replayed. No test or no replayer: r
// becomes Unknown, saying why. A replay that does not show the violation: an `internal` error
// in `findings` and r Unknown, never a verdict.
void confirm_violation(const TestReplayer* replayer, TemporalResult& r,
                       std::vector<Finding>& findings);

}  // namespace arbc::verify::temporal
