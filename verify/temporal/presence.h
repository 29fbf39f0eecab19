// One event's entries in a port's container as a replay's records leave them
// (docs/design.md#events-and-lifetimes): owner -> expiry (kNever: none). The event is present at
// t when some entry has t < expiry, exactly, as in the runtime (core/instant.h).
#pragma once

#include <map>
#include <string>

#include "core/instant.h"
#include "verify/verify.h"

namespace arbc::verify::temporal {

class Presence {
 public:
  void apply(const ReplayRecord& r) {
    if (r.kind == ReplayRecord::Kind::Set) {
      entries_[r.connection] = r.expiry;
    } else if (r.kind == ReplayRecord::Kind::Remove) {
      auto it = entries_.find(r.connection);
      // A lapse (it has its expiry) removes only the entry that lapsed, not a later refresh; an
      // unset (expiry kNever) removes whatever is there.
      if (it != entries_.end() && it->second <= r.expiry) entries_.erase(it);
    }
  }
  bool present(Nanos t) const {
    for (const auto& [owner, expiry] : entries_)
      if (t < expiry) return true;
    return false;
  }

 private:
  std::map<std::string, Nanos> entries_;
};

}  // namespace arbc::verify::temporal
