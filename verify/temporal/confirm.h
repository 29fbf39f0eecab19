// A violation the model checker found is reported only once the runtime shows it
// (docs/design.md#properties-over-time): its test runs in simulated time and the property is
// checked on what the runtime did at the port (verify/temporal/judge.h).
#pragma once

#include <vector>

#include "verify/report.h"
#include "verify/verify.h"

namespace arbc::verify::temporal {

enum class Confirmation {
  Shown,        // r.replayed: the runtime shows the violation
  NotShown,     // the replay ran and does not show it, or breaks an assumption: *seen says how
  NotReplayed,  // r is Unknown, saying why (no test, no replayer, or the replay could not run)
};

// Replays `r`'s test when r is Violated (Shown for anything else, which needs no replay). A
// replay that could not run is an `internal` error in `findings`. NotShown leaves r as it is:
// the caller searches again for a run the replay can make (PortShape::faithful) and otherwise
// makes r Unknown, never a verdict.
Confirmation confirm_violation(const TestReplayer* replayer, TemporalResult& r,
                               std::vector<Finding>& findings, std::string* seen);

}  // namespace arbc::verify::temporal
