#include "examples/table_clean/modules/world_environment.h"

#include <algorithm>

namespace arbc::table_clean {

void WorldEnvironment::create_world(arbc::EnvironmentContext& ctx) {
  ctx_ = &ctx;
  world_ = std::make_unique<World>(ctx.rng()());
  World* world = world_.get();
  world->set_agenda_listener([world, &ctx](double at) {
    ctx.schedule(std::max(0.0, at - ctx.now()),
                 [world, &ctx, at] { world->advance_to(std::max(ctx.now(), at)); });
  });
}

World* find_world(arbc::Module& module) {
  auto* env = dynamic_cast<WorldEnvironment*>(module.context().environment());
  if (env && env->world()) return env->world();
  module.context().log(
      "no simulated world in this run: load the table_clean plugin and run an app it knows "
      "(table_clean or search_and_track); this module stays inactive");
  return nullptr;
}

}  // namespace arbc::table_clean
