// Checks that need no solver: who sets, unsets and reads which event (docs/checks.md).
//   unfed      a constraint or assert of a port reads an event no connection into it sets
//              (not reported for a port with a `script` rule: its code may set anything)
//   unused     a connection sets an event its destination never reads
//   ownership  a monitor unsets an event it never sets (an unset removes only its own entry)
#pragma once

#include <vector>

#include "core/app_model.h"
#include "verify/report.h"

namespace arbc::verify {

// Appends the findings of the three checks; `strict` makes `unused` an error.
void run_structural_checks(const model::App& app, bool strict, std::vector<Finding>& out);

}  // namespace arbc::verify
