// The experiment's scenarios (issue 6): where the objects start and which of the paper's
// uncertainties happen.
//   reachable  3-5 objects within hand reach
//   tool       3 objects within tool reach
//   human      2 objects beyond tool reach (the person helps)
//   mixed      10 objects: 4 within hand reach, 3 within tool reach, 3 beyond
//   perturbed  2 + 2 + 1 objects; the first object put slips from the hand back onto the table,
//              and the person moves the first raked object into reach while the rake reaches
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "examples/table_clean/world.h"

namespace arbc::table_clean {

// The scenario names, in the order above.
const std::vector<std::string>& scenario_names();

// Places the objects of scenario `name` in `world` (using the world's generator) and enables
// its perturbations. Returns an empty string, or what is wrong (an unknown name, listing the
// known ones).
std::string setup_scenario(std::string_view name, World& world);

}  // namespace arbc::table_clean
