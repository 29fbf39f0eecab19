#include "runtime/event_container.h"

#include <algorithm>

namespace arbc {

void EventContainer::set(int event, int owner, Nanos expiry) {
  if (static_cast<int>(entries_.size()) <= event) entries_.resize(static_cast<size_t>(event) + 1);
  std::vector<Entry>& list = entries_[static_cast<size_t>(event)];
  auto it =
      std::find_if(list.begin(), list.end(), [&](const Entry& e) { return e.owner == owner; });
  if (it == list.end()) {
    list.push_back({owner, expiry});
  } else {
    it->expiry = expiry;  // a refresh may shorten or lengthen the lifetime
  }
  present_.set(event);
  next_expiry_ = std::min(next_expiry_, expiry);
}

bool EventContainer::unset(int event, int owner) {
  if (event < 0 || static_cast<int>(entries_.size()) <= event) return false;
  std::vector<Entry>& list = entries_[static_cast<size_t>(event)];
  auto it =
      std::find_if(list.begin(), list.end(), [&](const Entry& e) { return e.owner == owner; });
  if (it == list.end()) return false;
  list.erase(it);
  if (list.empty()) present_.reset(event);
  return true;
}

bool EventContainer::has(std::string_view name, Nanos now) {
  int id = index_.find(name);
  return id >= 0 && has(id, now);
}

void EventContainer::for_each_entry(
    const std::function<void(int event, int owner, Nanos expiry)>& fn) const {
  for (size_t event = 0; event < entries_.size(); ++event)
    for (const Entry& e : entries_[event]) fn(static_cast<int>(event), e.owner, e.expiry);
}

void EventContainer::expire(Nanos now) {
  Nanos next = kNever;
  for (size_t event = 0; event < entries_.size(); ++event) {
    std::vector<Entry>& list = entries_[event];
    for (size_t i = 0; i < list.size();) {
      if (now >= list[i].expiry && list[i].expiry != kNever) {  // kNever: until unset
        Entry gone = list[i];
        list.erase(list.begin() + static_cast<long>(i));
        if (on_expiry_) on_expiry_(static_cast<int>(event), gone.owner, gone.expiry);
      } else {
        next = std::min(next, list[i].expiry);
        ++i;
      }
    }
    if (list.empty()) present_.reset(static_cast<int>(event));
  }
  next_expiry_ = next;
}

}  // namespace arbc
