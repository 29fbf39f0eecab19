#include "runtime/trace_container.h"

#include <limits>

#include "core/instant.h"

namespace arbc {

void TraceContainer::apply(const TraceRecord& r) {
  auto key = std::make_pair(r.event, r.owner);
  if (r.op == "set") {
    entries_[key] = r.expiry >= 0 ? r.expiry : std::numeric_limits<double>::infinity();
  } else if (r.op == "unset") {
    entries_.erase(key);
  }
}

std::set<std::string> TraceContainer::present(double t) const {
  std::set<std::string> out;
  for (const auto& [key, expiry] : entries_)
    if (!reached(t, expiry)) out.insert(key.first);
  return out;
}

}  // namespace arbc
