#include "verify/replay.h"

#include <algorithm>
#include <set>

#include "core/compiled_constraint.h"

namespace arbc::verify {

bool runtime_holds(const Constraint& c, const std::vector<std::string>& present) {
  EventIndex index;
  EventMask mask;
  for (const std::string& e : present) mask.set(index.intern(e));
  CompiledConstraint compiled = CompiledConstraint::compile(c, index);
  return compiled.evaluate(mask);
}

std::string describe_state(const Constraint& c, const std::vector<std::string>& present) {
  std::set<std::string> events;
  c.collect_events(events);
  std::string out;
  for (const std::string& e : events) {
    if (!out.empty()) out += ", ";
    bool here = std::find(present.begin(), present.end(), e) != present.end();
    out += e + (here ? " present" : " absent");
  }
  return out.empty() ? "no events" : out;
}

}  // namespace arbc::verify
