#include "examples/table_clean/scenario.h"

namespace arbc::table_clean {
namespace {

// Puts `count` objects at random free spots of `zone` across the table.
void place(World& world, Zone zone, int count) {
  for (int i = 0; i < count; ++i)
    world.add_object(world.free_spot(zone, uniform(world.rng(), -0.8, 0.8)));
}

}  // namespace

const std::vector<std::string>& scenario_names() {
  static const std::vector<std::string> names = {"reachable", "tool", "human", "mixed",
                                                 "perturbed"};
  return names;
}

std::string setup_scenario(std::string_view name, World& world) {
  if (name == "reachable") {
    place(world, Zone::Hand, std::uniform_int_distribution<int>(3, 5)(world.rng()));
  } else if (name == "tool") {
    place(world, Zone::Tool, 3);
  } else if (name == "human") {
    place(world, Zone::Beyond, 2);
  } else if (name == "mixed") {
    place(world, Zone::Hand, 4);
    place(world, Zone::Tool, 3);
    place(world, Zone::Beyond, 3);
  } else if (name == "perturbed") {
    place(world, Zone::Hand, 2);
    place(world, Zone::Tool, 2);
    place(world, Zone::Beyond, 1);
    world.perturbations().slip_first_put = true;
    world.perturbations().person_moves_first_rake_target = true;
  } else {
    std::string known;
    for (const std::string& n : scenario_names()) known += (known.empty() ? "" : ", ") + n;
    return "unknown scenario '" + std::string(name) + "' (known: " + known + ")";
  }
  return {};
}

}  // namespace arbc::table_clean
