// The run's result as `arbc run` prints it: objects cleaned, simulated time, what the actors
// did and the conflicts by kind; success means a clean table and no conflict.
#pragma once

#include <string>

#include "examples/table_clean/world.h"

namespace arbc::table_clean {

bool run_succeeded(const World& world);

// Multi-line text, e.g.
//   scenario mixed, seed 7
//   objects cleaned: 10/10
//   simulated time: 71.40 s
//   ...
//   conflicts: 0
//   result: table clean, no conflict
std::string summarize(World& world, const std::string& scenario, uint64_t seed, double now);

}  // namespace arbc::table_clean
