// `arbc run --report FILE.html`: one self-contained HTML page about a run (issue 7). No
// network, no external script, style or font: the timelines are inline SVG drawn here, so the
// page reads the same with scripts off; a few lines of inline script only add a time cursor.
//
// Sections: header (app, scenario, seed, the proof, time run, outcome, the environment's
// summary), the transport (when the run had one), totals, the delivery/drop timeline per
// connection, event presence per port and event, drops by reason, the counters per connection with
// a totals row, errors and quarantines, and the run's log.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "runtime/runtime.h"
#include "runtime/trace_record.h"

namespace arbc::report {

struct RunHeader {
  std::string app, description, scenario;
  uint64_t seed = 1;
  bool realtime = false;
  double requested = 0;     // --duration, seconds
  double end = 0;           // the time the run stopped at
  std::string stop_reason;  // why it stopped early; empty: it ran the whole duration
  bool success = false;
  std::string verdict;      // e.g. "success" or "failure (no environment; ...)"
  std::string environment;  // the environment's summary text, shown as is
  // What `arbc run` said about the proof: "verified: ..." or "not verified (--no-verify)".
  std::string proof;
};

struct ConnectionRow {
  ConnectionStats stats;  // the runtime's counters (Runtime::stats())
  bool feed = false;      // a generated event feed: never delivers
  std::string constraint;
};

// A run over a transport between processes (DDS): where the modules ran and were mediated,
// and per topic whether a peer was ever heard and what was received, lost and written, so
// that a page read later still says why a timeline is empty. Both empty in-process: then the
// page has no transport section.
struct TransportSection {
  std::string placement;   // "dds (domain 7, ...)" (cli/run_transport.h)
  TransportStatus status;  // the transport's own counters (Transport::status)
};

// One claim or assumption of the proof the run watched (runtime/claim_watch.h), as a violation
// names it, and whether the run broke it.
struct CheckRow {
  std::string claim;
  bool broken = false;
  double at = 0;     // s: the instant the run broke it
  std::string what;  // what the run did
};

struct RunReportInput {
  RunHeader header;
  // The runtime checks; `checks_watched` false: the run watched none (--runtime-checks off).
  bool checks_watched = false;
  std::vector<CheckRow> checks;
  TransportSection transport;
  std::vector<ConnectionRow> connections;             // in the app's order
  const std::vector<TraceRecord>* records = nullptr;  // the whole trace, in order
};

// The report as one HTML document. Every name and message is HTML-escaped.
std::string render_run_report(const RunReportInput& input);

}  // namespace arbc::report
