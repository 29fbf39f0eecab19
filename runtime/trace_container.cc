#include "runtime/trace_container.h"

#include "core/instant.h"

namespace arbc {

void TraceContainer::apply(const TraceRecord& r) {
  auto key = std::make_pair(r.event, r.owner);
  if (r.op == "set") {
    entries_[key] = r.expiry;  // kNever: no lifetime
  } else if (r.op == "unset") {
    entries_.erase(key);
  }
}

std::set<std::string> TraceContainer::present(Nanos t) const {
  std::set<std::string> out;
  for (const auto& [key, expiry] : entries_)
    if (t < expiry) out.insert(key.first);  // exact, as the runtime compares (core/instant.h)
  return out;
}

}  // namespace arbc
