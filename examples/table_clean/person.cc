#include "examples/table_clean/person.h"

#include <cmath>

#include "examples/table_clean/world.h"

namespace arbc::table_clean {

void Person::hear(const std::string& text, double now) {
  if (!present_ || text.empty()) return;
  ++requests_heard_;
  if (helping_) return;
  helping_ = true;
  world_.schedule(now + uniform(world_.rng(), kMinHelpDelay, kMaxHelpDelay), [this] { help(); });
}

void Person::help() {
  helping_ = false;
  if (!present_) return;
  if (auto id = world_.nearest_on_table_in(Zone::Beyond)) move_into_hand_reach(*id);
}

void Person::move_into_hand_reach(int id) {
  TableObject& obj = world_.object(id);
  if (obj.place != Place::Table) return;
  obj.pos = world_.free_spot(Zone::Hand, std::atan2(obj.pos.y(), obj.pos.x()), id);
  ++objects_moved_;
}

}  // namespace arbc::table_clean
