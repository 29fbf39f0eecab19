#include "compiler/docs/monitor_summary.h"

#include <sstream>

#include "core/join.h"

namespace arbc::docs {

std::string monitor_summary(const model::Connection& c) {
  std::vector<std::string> parts;
  if (c.kind == model::ConnectionKind::Feed) {
    parts.push_back("feeds " + join(c.sets) + " into the container; never delivers");
  } else {
    if (c.opaque) parts.push_back("hand-written script");
    if (!c.sets.empty()) parts.push_back("sets " + join(c.sets));
    if (!c.unsets.empty()) parts.push_back("unsets " + join(c.unsets));
    if (c.throttle) {
      std::ostringstream s;
      s << "at most one delivery per " << *c.throttle << " s";
      parts.push_back(s.str());
    }
    if (c.trig_interval) {
      std::ostringstream s;
      s << "runs every " << *c.trig_interval << " s";
      parts.push_back(s.str());
    }
  }
  if (parts.empty()) parts.push_back(c.monitor.empty() ? "none" : "filters and transforms");
  return join(parts);
}

}  // namespace arbc::docs
