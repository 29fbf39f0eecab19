// One line of the run's trace as a value, for consumers that read the trace in memory
// (`arbc run --report` builds its HTML report from these) instead of parsing the JSON lines.
// The fields mirror the JSON keys of docs/runtime.md, "Trace format"; a field a kind does not
// have stays empty (or 0, kNever).
#pragma once

#include <cstdint>
#include <string>

#include "core/instant.h"
#include "core/value.h"
#include "runtime/drop_reason.h"

namespace arbc {

enum class TraceKind {
  Deliver,
  Drop,
  Event,
  Error,
  Quarantine,
  Log,
  PublishError,
  PluginError,
  Pending,
  Publish,  // a value a module published on an out-port (what `arbc run --inputs` replays)
  Breach    // a runtime check found a claim or assumption of the proof broken (claim_watch.h)
};

struct TraceRecord {
  Nanos t{0};  // the runtime's instant (core/instant.h)
  TraceKind kind = TraceKind::Log;
  // Deliver, Drop, Error, Quarantine, Pending: the connection; Log: who logged ("from");
  // PluginError: the module or environment whose callback threw ("from").
  std::string connection;
  // Deliver: the destination port; Event: the port whose container changed; PublishError;
  // Publish: the out-port ("Module.port").
  std::string port;
  DropReason reason = DropReason::Rejected;  // Drop only
  std::string op;                            // Event: "set", "unset" or "expire"
  std::string event, owner;                  // Event: the event and the owning connection
  Nanos expiry = kNever;                     // Event: set/expire with a lifetime; kNever: none
  std::string text;      // Drop: detail; Error, Quarantine, Log, PluginError: message
  std::string callback;  // PluginError: the callback that threw, e.g. "tick"
  uint64_t count = 0;    // Pending: messages left queued
  // Deliver, Publish: the value, for the runtime checks' claims over delivered values while
  // they read the record (trace_line_of); null in the records a Trace keeps, since the value
  // lives only as long as its line.
  const Value* value = nullptr;
};

}  // namespace arbc
