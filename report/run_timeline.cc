#include "report/run_timeline.h"

#include <algorithm>
#include <limits>
#include <map>
#include <utility>

namespace arbc::report {

namespace {

constexpr double kNever = std::numeric_limits<double>::infinity();

// One owner's entry for one event: at most one open span at a time.
struct Entry {
  bool open = false;
  double begin = 0, expiry = 0;
};

// The presence spans of one (port, event), collected over all its owners.
struct EventHistory {
  std::map<std::string, Entry> entries;  // by owner connection
  std::vector<Interval> spans;

  void close(Entry& e, double at) {
    if (at > e.begin) spans.push_back({e.begin, at});
    e.open = false;
  }
  // setEvent: starts an entry or refreshes (or shortens) a live one.
  void set(const std::string& owner, double t, double expiry) {
    Entry& e = entries[owner];
    if (e.open && e.expiry <= t) close(e, e.expiry);  // it lapsed before this refresh
    if (e.open) {
      if (expiry > t) {
        e.expiry = expiry;
      } else {
        close(e, t);
      }
    } else if (expiry > t) {
      e = {true, t, expiry};
    }
  }
  // unsetEvent: removes only this owner's entry.
  void unset(const std::string& owner, double t) {
    auto it = entries.find(owner);
    if (it != entries.end() && it->second.open) close(it->second, std::min(t, it->second.expiry));
  }
  // The union of every owner's spans, closing the open ones at the end of the run.
  std::vector<Interval> presence(double end) {
    for (auto& [owner, e] : entries) {
      if (e.open) close(e, std::min(end, e.expiry));
    }
    std::sort(spans.begin(), spans.end(),
              [](const Interval& a, const Interval& b) { return a.begin < b.begin; });
    std::vector<Interval> merged;
    for (const Interval& s : spans) {
      if (!merged.empty() && s.begin <= merged.back().end) {
        merged.back().end = std::max(merged.back().end, s.end);
      } else {
        merged.push_back(s);
      }
    }
    return merged;
  }
};

}  // namespace

RunTimeline build_run_timeline(const std::vector<std::string>& connections,
                               const std::vector<TraceRecord>& records, double end) {
  RunTimeline timeline;
  timeline.end = end;
  std::map<std::string, size_t> lane_of;
  auto lane = [&](const std::string& name) -> ConnectionLane& {
    auto [it, added] = lane_of.emplace(name, timeline.connections.size());
    if (added) timeline.connections.push_back({name, {}, {}, std::nullopt});
    return timeline.connections[it->second];
  };
  for (const std::string& name : connections) lane(name);

  std::map<std::pair<std::string, std::string>, EventHistory> histories;
  for (const TraceRecord& r : records) {
    // The runtime's nanoseconds as the seconds the timelines are drawn in: the nearest doubles,
    // which keep the order and the equalities of instants under 2^22 s.
    double t = seconds_of(r.t);
    switch (r.kind) {
      case TraceKind::Deliver:
        lane(r.connection).deliveries.push_back(t);
        break;
      case TraceKind::Drop:
        lane(r.connection).drops.push_back({t, r.reason});
        break;
      case TraceKind::Quarantine: {
        ConnectionLane& l = lane(r.connection);
        if (!l.quarantined_at) l.quarantined_at = t;
        break;
      }
      case TraceKind::Breach:
        timeline.breaches.push_back({t, r.connection, r.text});
        break;
      case TraceKind::Event: {
        EventHistory& h = histories[{r.port, r.event}];
        if (r.op == "set")
          h.set(r.owner, t, r.expiry == arbc::kNever ? kNever : seconds_of(r.expiry));
        if (r.op == "unset") h.unset(r.owner, t);
        break;
      }
      default:
        break;
    }
  }
  for (auto& [key, history] : histories) {
    timeline.events.push_back({key.first, key.second, history.presence(end)});
  }
  return timeline;
}

}  // namespace arbc::report
