#include "examples/table_clean/summary.h"

#include <cstdio>

namespace arbc::table_clean {

bool run_succeeded(const World& world) {
  return world.table_clean() && world.conflicts().total() == 0;
}

std::string summarize(World& world, const std::string& scenario, uint64_t seed, double now) {
  char line[160];
  std::string out;
  auto add = [&](const char* fmt, auto... args) {
    std::snprintf(line, sizeof line, fmt, args...);
    out += line;
    out += '\n';
  };
  add("scenario %s, seed %llu", scenario.c_str(), static_cast<unsigned long long>(seed));
  add("objects cleaned: %d/%d", world.objects_in_bucket(), world.objects_total());
  add("simulated time: %.2f s", now);
  add("arm: %d takes, %d failed takes, %d slips", world.arm().takes_completed(),
      world.arm().failed_takes(), world.arm().slips());
  add("rake: %d objects pulled, %d redundant pulls ignored, %d cancels honoured, %d ignored",
      world.rake().objects_pulled(), world.rake().redundant_pulls(),
      world.rake().cancels_honoured(), world.rake().cancels_ignored());
  add("person: %d requests heard, %d objects moved", world.person().requests_heard(),
      world.person().objects_moved());
  add("head: %d face targets, %d search targets", world.referee().face_targets(),
      world.referee().search_targets());
  add("conflicts: %d", world.conflicts().total());
  for (const auto& [name, count] : world.conflicts().by_name())
    add("  %s: %d", name.c_str(), count);
  if (run_succeeded(world)) {
    add("result: %s", "table clean, no conflict");
  } else if (!world.table_clean()) {
    add("result: FAILED, %d object(s) left", world.objects_total() - world.objects_in_bucket());
  } else {
    add("result: %s", "FAILED, table clean but with conflicts");
  }
  return out;
}

}  // namespace arbc::table_clean
