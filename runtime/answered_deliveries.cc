// Deliveries not yet answered (docs/design.md#deliveries-not-yet-answered): when a connection
// mediated here delivers into a module hosted in another process, what this process knows of
// that module's state (the events its outputs feed) predates the delivery until the module
// answers: a message from it published after it received the delivery. Until then a rule
// whose constraint reads such an event is not selected (absence of an answer is not knowledge
// that nothing changed), or until the event's lifetime has passed since the delivery and since
// the feed's last message (every message the feed took meanwhile was published before the
// module had the delivery: stale news that sets entries again, for a lifetime from then; once
// that has passed, no entry from before the delivery is left). In one process a
// module sees a delivery before any later message is processed, so the rule never applies
// there. Like the unknown-after-start rule it only removes selections: the proof holds.
#include "runtime/runtime_internal.h"

namespace arbc {

void Runtime::collect_feedback_events() {
  for (auto& cp : connections_) {
    Connection& c = *cp;
    if (c.is_feed) continue;
    std::set<std::string> read;
    c.model->constraint.collect_events(read);
    for (const std::string& e : read) {
      for (Connection* feed : c.destination->feeds) {
        // Hosted here, or this process's own deliveries: it answers at once.
        if (!feed->source || !feed->source->remote) continue;
        const std::vector<std::string>& sets = feed->model->sets;
        if (std::find(sets.begin(), sets.end(), e) == sets.end()) continue;
        c.feedback.push_back({e, feed, declared_lifetime(e)});
        std::vector<const Connection*>& known = feed->source->remote->feeds;
        if (std::find(known.begin(), known.end(), feed) == known.end()) known.push_back(feed);
      }
    }
  }
}

bool Runtime::answered_events_of(Connection& c, Nanos t, std::string* why) {
  for (const Connection::UnknownEvent& u : c.feedback) {
    // Answered: the feed processed a message published after the delivery was received, or
    // the message judged now was published after that (its process had it by then).
    uint64_t answered = std::max(u.feed->answered, c.incoming_answered);
    for (const RemoteModule::Sent& s : u.feed->source->remote->recent) {
      if (s.number <= answered) continue;
      // A delivery made for this very message does not hide what the message is judged on:
      // in one process, too, every connection from a source judges a message on one state.
      if (s.message == c.message) continue;
      if (u.lifetime && t >= std::max(s.time, u.feed->last_fed_at) + *u.lifetime) continue;
      *why = "not answered: " + u.event + " (" + u.feed->model->source +
             " has not spoken since the delivery at " + run_time_text(s.time) + ")";
      return false;
    }
  }
  return true;
}

// Whether delivery `s` can no longer hide anything at `t`: every feed has answered it, or has
// been silent for longer than any lifetime since it (see answered_events_of).
static bool settled(const Runtime::RemoteModule::Sent& s, const Runtime::RemoteModule& m,
                    Nanos longest_lifetime, Nanos t) {
  for (const Runtime::Connection* feed : m.feeds) {
    if (s.number > feed->answered && std::max(s.time, feed->last_fed_at) + longest_lifetime >= t)
      return false;
  }
  return true;
}

void Runtime::delivered_to_remote(RemoteModule& m, Nanos t, uint64_t message) {
  m.recent.push_back({++remote_sent_, t, message});
  while (!m.recent.empty() && settled(m.recent.front(), m, longest_lifetime_, t))
    m.recent.pop_front();
}

}  // namespace arbc
