// One port's event container as its trace records show it: (event, owner) entries set, unset
// and lapsing at their expiry. The checks that read a run's trace (runtime/property_watch.h,
// runtime/claim_watch.h) judge a decision by the state of its port's own container, as the
// proof does (docs/design.md#events-and-lifetimes).
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <set>
#include <string>

#include "core/instant.h"
#include "runtime/trace_format.h"
#include "runtime/trace_record.h"

namespace arbc {

class TraceContainer {
 public:
  // An event record ("set", "unset"; an "expire" record comes late, when the runtime next reads
  // the container, so presence is judged by the expiry instants themselves).
  void apply(const TraceLine& r);
  void apply(const TraceRecord& r) { apply(trace_line_of(r)); }
  // The events present at t; valid until the next apply() or present() call.
  const std::set<std::string>& present(Nanos t) const;
  // Which answer present() last gave: another number whenever the set may differ, so that a
  // check that only reads the set may keep its verdict while the number stays (a port decides
  // many times between two changes of its events). Never 0.
  uint64_t version() const { return version_; }
  // Whether `event` alone is present at t (no set built: cheap on every record).
  bool present_at(std::string_view event, Nanos t) const;

 private:
  using Owners = std::map<std::string, Nanos, std::less<>>;  // owner -> expiry (kNever: none)
  std::map<std::string, Owners, std::less<>> entries_;       // event -> its entries
  // The last answer of present(), still right for any t before the next expiry after it, as
  // long as nothing was applied: a port decides many times between two changes.
  mutable std::set<std::string> present_;
  mutable bool cached_ = false;
  mutable Nanos cached_from_{0}, cached_until_{0};
  mutable uint64_t version_ = 1;
};

}  // namespace arbc
