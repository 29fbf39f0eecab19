// What happened when, per connection and per event, reconstructed from the run's trace
// records: the data behind the run report's timelines (run_report.h draws it).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "runtime/drop_reason.h"
#include "runtime/trace_record.h"

namespace arbc::report {

// A half-open time span [begin, end), as an event is present at t iff t < its expiry.
struct Interval {
  double begin = 0, end = 0;
};

struct TimedDrop {
  double t = 0;
  DropReason reason = DropReason::Rejected;
};

struct ConnectionLane {
  std::string name;
  std::vector<double> deliveries;  // delivery instants, in trace order
  std::vector<TimedDrop> drops;
  std::optional<double> quarantined_at;
};

// One event in one port's container (each arbitrated port has its own container, so the
// same event name can have one lane per port).
struct EventLane {
  std::string port, event;
  std::vector<Interval> present;  // sorted, disjoint, non-empty
};

// A claim or assumption of the proof a runtime check found broken (a trace `breach` line).
struct Breach {
  double t = 0;  // when the run showed it
  std::string claim, what;
};

struct RunTimeline {
  double end = 0;  // the run's last instant (the simulated or wall time it stopped at)
  std::vector<ConnectionLane> connections;
  std::vector<EventLane> events;  // sorted by port, then event
  std::vector<Breach> breaches;   // in trace order
};

// Builds the timeline of a run that ended at `end`: one lane per name in `connections`, in that
// order (records naming another connection get a lane appended after them), and one lane per (port,
// event) ever set. Presence is rebuilt from the set/unset records per owner (an event is present
// while any owner's entry is: docs/design.md#events-and-lifetimes); `expire` records only confirm
// what the expiry times already say, so they are not needed.
RunTimeline build_run_timeline(const std::vector<std::string>& connections,
                               const std::vector<TraceRecord>& records, double end);

}  // namespace arbc::report
