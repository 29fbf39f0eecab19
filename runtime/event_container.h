// The event container of one input port (docs/design.md#events-and-lifetimes): entries (event,
// owner connection, expiry). An event is present at time t iff some owner's entry has t < expiry,
// both whole nanoseconds (core/instant.h): at the expiry instant itself it is absent.
//
// Presence is kept as a bit mask so that a compiled constraint decides in nanoseconds; the
// earliest expiry is kept too, so that checking for lapsed entries costs one comparison
// while nothing has expired.
#pragma once

#include <functional>
#include <string_view>
#include <vector>

#include "core/compiled_constraint.h"
#include "core/instant.h"

namespace arbc {

class EventContainer {
 public:
  // Called for each entry that lapses: (event id, owner, expiry time).
  using ExpiryObserver = std::function<void(int event, int owner, Nanos expiry)>;

  EventIndex& index() { return index_; }
  const EventIndex& index() const { return index_; }
  void on_expiry(ExpiryObserver observer) { on_expiry_ = std::move(observer); }

  // Inserts or refreshes owner's entry for event; expiry kNever: until unset.
  void set(int event, int owner, Nanos expiry);
  // Removes owner's own entry for event; returns whether there was one. Other owners'
  // entries stay, so the event may still be present.
  bool unset(int event, int owner);

  // The present events at time now (drops lapsed entries first). `now` must not go back.
  const EventMask& present(Nanos now) {
    if (now >= next_expiry_) expire(now);
    return present_;
  }
  bool has(int event, Nanos now) { return present(now).test(event); }
  bool has(std::string_view name, Nanos now);
  // Each entry (event id, owner, expiry), lapsed ones included until present() drops them.
  void for_each_entry(const std::function<void(int event, int owner, Nanos expiry)>& fn) const;

 private:
  struct Entry {
    int owner;
    Nanos expiry;
  };
  void expire(Nanos now);

  EventIndex index_;
  std::vector<std::vector<Entry>> entries_;  // by event id
  EventMask present_;
  Nanos next_expiry_ = kNever;
  ExpiryObserver on_expiry_;
};

}  // namespace arbc
