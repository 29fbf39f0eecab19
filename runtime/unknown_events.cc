// What a mediator does not know after it (re)starts
// (docs/design.md#unknown-events-after-a-start): an event a feed provides is unknown until that
// feed has delivered once since start. Time passing is no evidence: the feed's source may not be
// discovered yet while it reports the event present (a held bumper; issue 39). A rule whose
// constraint reads an unknown event is not selected: absence of knowledge is not absence. This only
// removes selections, so the proof (at most one selected connection per port) holds as before.
// Also: reporting events that lapse because their source is silent.
#include "core/duration_literal.h"
#include "runtime/runtime_internal.h"

namespace arbc {

void Runtime::collect_unknown_events() {
  for (auto& cp : connections_) {
    Connection& c = *cp;
    if (c.is_feed) continue;
    std::set<std::string> read;
    c.model->constraint.collect_events(read);
    for (const std::string& e : read) {
      const model::Event* event = app_.find_event(e);
      if (!event || event->source.empty()) continue;  // not provided by a feed
      for (Connection* feed : c.destination->feeds) {
        // What this process delivers is known from the start: none of it yet.
        if (feed->delivered_from) continue;
        const std::vector<std::string>& sets = feed->model->sets;
        if (std::find(sets.begin(), sets.end(), e) != sets.end())
          c.unknown.push_back({e, feed, event->fail_open_after});
      }
    }
  }
}

bool still_unknown(const Runtime::Connection::UnknownEvent& u, Nanos now, Nanos start) {
  if (u.feed->fed) return false;
  // `otherwise absent after D`: the spec lets this feed's silence count as absence.
  return !u.lifetime || now < later(start, *u.lifetime);
}

std::string unknown_text(const Runtime::Connection::UnknownEvent& u) {
  return "unknown since start: " + u.event + " (nothing from " + u.feed->model->source + " yet)";
}

bool Runtime::knows_events_of(Connection& c, std::string* why) {
  std::erase_if(c.unknown, [&](const Connection::UnknownEvent& u) {
    if (still_unknown(u, now(), start_time_)) return false;
    if (!u.feed->fed && failed_open_.insert(u.event).second)
      report("event " + u.event + " taken as absent at " + run_time_text(now()) +
             ": nothing from " + u.feed->model->source +
             " since the start, and the spec lets it fail open after " +
             duration_literal(*u.lifetime) + " (`otherwise absent after`)");
    return true;
  });
  if (c.unknown.empty()) return true;
  *why = unknown_text(c.unknown.front());
  return false;
}

void Runtime::lapsed(InPort& in, int event, int owner, Nanos expiry) {
  Connection& c = *connections_[static_cast<size_t>(owner)];
  const std::string& name = in.container.index().name(event);
  trace_.event(expiry, in.qualified, "expire", name, c.name, expiry);
  // A delivery event lapses when its port has delivered nothing for its lifetime, and a rule's
  // hold (its activity event) when the rule delivered nothing for the hold: the hold ended as
  // it should, no source is silent then (issue 39: "nothing from Joy.cmd_vel" after a joystick
  // let go).
  if (!options_.report_silent_lapses || c.delivered_from || c.model->set_on_delivery(name)) return;
  std::optional<Nanos> lifetime = declared_lifetime(name);
  // Silent for the whole lifetime before the expiry, or its source spoke and the entry just ended.
  if (!lifetime || c.last_arrival > expiry - *lifetime) return;
  if (!c.silence_reported.insert(name).second) return;
  // The lifetime as the spec declares it (`for 500ms`), not as a run's instants read.
  std::string lifetime_text = duration_literal(*lifetime);
  report("event " + name + " at " + in.qualified + " lapsed at " + run_time_text(expiry) +
         ": nothing from " + c.model->source + " for " + lifetime_text);
}

void Runtime::watch_lapses(Nanos period) {
  executor_->post(now() + period, [this, period] {
    for (auto& in : in_ports_) {
      if (in->mediated) in->container.present(now());
    }
    watch_lapses(period);
  });
}

}  // namespace arbc
