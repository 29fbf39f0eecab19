// The parts of yarp_import.h that read the whole application: exclusive groups derived from
// selector scripts, and the YARP-specific hazards (docs/yarp.md#diagnostics).
#pragma once

#include "import/yarp/yarp_import.h"

namespace arbc::yarp {

// Does some name YARP looks up in the constraint occur inside another looked-up name or inside
// and/or/not/true/false? (Then YARP's substring substitution may corrupt it.)
bool names_collide(const ConstraintMeaning& m);

// `exclusive { a, b }` for each pair a script never leaves both set, when no other monitor can
// set a or b (events are per process in YARP, and a monitor unsets only its own).
void derive_exclusive_groups(YarpImport& im);

// Appends the yarp-* hazard diagnostics to im.diagnostics.
void add_hazards(YarpImport& im);

}  // namespace arbc::yarp
