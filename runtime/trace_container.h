// One port's event container as its trace records show it: (event, owner) entries set, unset
// and lapsing at their expiry. The checks that read a run's trace (runtime/property_watch.h,
// runtime/claim_watch.h) judge a decision by the state of its port's own container, as the
// proof does (docs/design.md#events-and-lifetimes).
#pragma once

#include <map>
#include <set>
#include <string>
#include <utility>

#include "core/instant.h"
#include "runtime/trace_record.h"

namespace arbc {

class TraceContainer {
 public:
  // An event record ("set", "unset"; an "expire" record comes late, when the runtime next reads
  // the container, so presence is judged by the expiry instants themselves).
  void apply(const TraceRecord& r);
  // The events present at t.
  std::set<std::string> present(Nanos t) const;

 private:
  std::map<std::pair<std::string, std::string>, Nanos> entries_;  // (event, owner) -> expiry
};

}  // namespace arbc
