// Every sample this process takes off DDS, in the order it was taken, across all topics.
//
// Why one queue and not one per topic: an arbc process reasons about the order in which a
// remote process published (docs/design.md#deliveries-not-yet-answered: a status published
// after a delivery answers it; an object list published after the status is judged on it).
// Samples of one process on two topics reach this one in the order they were written, as far
// as DDS keeps it; handing each topic's backlog over as a batch would undo that (an object
// list from late in a burst judged before the status written before it). So the executor
// takes samples off this queue in arrival order, in slices, letting the runtime's own tasks
// for one slice run before the next (the connections' queues stay short: nothing is dropped
// as queue-full because a burst arrived at once).
#pragma once

#include <deque>
#include <functional>
#include <mutex>

namespace arbc::dds {

template <class Entry>
class Inbox {
 public:
  // Any thread: queues `e`; true when the caller must post a drain (none is pending).
  bool push(Entry e) {
    std::lock_guard<std::mutex> lock(mutex_);
    entries_.push_back(std::move(e));
    if (drain_posted_) return false;
    drain_posted_ = true;
    return true;
  }

  // Executor thread: takes the oldest entry (the drain was posted, so there is one); `more`
  // tells whether entries remain (the caller then posts another drain, which stays pending).
  Entry take(bool* more) {
    std::lock_guard<std::mutex> lock(mutex_);
    Entry e = std::move(entries_.front());
    entries_.pop_front();
    *more = !entries_.empty();
    drain_posted_ = *more;
    return e;
  }

 private:
  std::mutex mutex_;
  std::deque<Entry> entries_;
  bool drain_posted_ = false;
};

}  // namespace arbc::dds
