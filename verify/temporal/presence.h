// One event's entries in a port's container as a replay's records leave them
// (docs/design.md#events-and-lifetimes): owner -> expiry (-1: none). The event is present at t
// when an entry has no expiry or t has not reached its expiry (core/instant.h).
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
      // A lapse (it has its expiry) removes only the entry that lapsed, not a later refresh.
      if (it != entries_.end() && (r.expiry < 0 || it->second <= r.expiry)) entries_.erase(it);
    }
  }
  bool present(double t) const {
    for (const auto& [owner, expiry] : entries_)
      if (expiry < 0 || !reached(t, expiry)) return true;
    return false;
  }

 private:
  std::map<std::string, double> entries_;
};

}  // namespace arbc::verify::temporal
