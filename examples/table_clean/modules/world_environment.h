// The run's environment: owns the simulated World that the modules share. A module finds the
// world through its context (find_world); nothing else connects the modules to each other.
#pragma once

#include <memory>
#include <string>

#include "examples/table_clean/world.h"
#include "runtime/module.h"

namespace arbc::table_clean {

class WorldEnvironment : public arbc::Environment {
 public:
  World* world() { return world_.get(); }

 protected:
  // Creates the world, seeded from the run's generator, and lets the runtime's clock drive its
  // agenda so that scheduled happenings occur at their exact simulated instant.
  void create_world(arbc::EnvironmentContext& ctx);

  arbc::EnvironmentContext* ctx_ = nullptr;
  std::unique_ptr<World> world_;
  double end_time_ = 0;
};

// The world of the module's run, or nullptr (logged once) when the run has no such environment.
World* find_world(arbc::Module& module);

}  // namespace arbc::table_clean
