#include "runtime/trace_container.h"

namespace arbc {

void TraceContainer::apply(const TraceLine& r) {
  if (r.op == "set") {
    auto event = entries_.find(r.event);
    if (event == entries_.end()) event = entries_.emplace(r.event, Owners{}).first;
    auto owner = event->second.find(r.owner);
    if (owner == event->second.end())
      event->second.emplace(r.owner, r.expiry);
    else
      owner->second = r.expiry;
  } else if (r.op == "unset") {
    auto event = entries_.find(r.event);
    if (event == entries_.end()) return;
    auto owner = event->second.find(r.owner);
    if (owner == event->second.end()) return;
    event->second.erase(owner);
  } else {
    return;  // "expire" changes nothing: the expiry instant already did
  }
  cached_ = false;
}

bool TraceContainer::present_at(std::string_view event, Nanos t) const {
  auto it = entries_.find(event);
  if (it == entries_.end()) return false;
  for (const auto& [owner, expiry] : it->second)
    if (t < expiry) return true;
  return false;
}

const std::set<std::string>& TraceContainer::present(Nanos t) const {
  if (cached_ && t >= cached_from_ && t < cached_until_) return present_;
  ++version_;
  present_.clear();
  cached_from_ = t;
  cached_until_ = kNever;
  for (const auto& [event, owners] : entries_) {
    for (const auto& [owner, expiry] : owners) {
      // Exact, as the runtime compares (core/instant.h); the answer changes at the next expiry.
      if (t < expiry) {
        present_.insert(event);
        if (expiry < cached_until_) cached_until_ = expiry;
      }
    }
  }
  cached_ = true;
  return present_;
}

}  // namespace arbc
