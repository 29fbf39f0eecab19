// The trace's JSON lines (docs/runtime.md#trace-format), defined once: which kinds there are,
// what each is called, and which keys each line has in which order. runtime/trace.cc writes
// lines through it; `arbc run --diff` and `--inputs TRACE` read them back through it, so the
// writer and the readers cannot drift apart.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>

#include "core/instant.h"
#include "core/value.h"
#include "runtime/trace_record.h"

namespace arbc {

// "deliver", "drop", ..., "publish"; and back (nothing for an unknown name).
const char* trace_kind_name(TraceKind kind);
std::optional<TraceKind> trace_kind_named(std::string_view name);

// One line's fields without owning them: what Trace fills on the message path (no allocation)
// and writes. A field the kind does not have is left empty.
struct TraceLine {
  TraceLine(Nanos time, TraceKind what) : t(time), kind(what) {}
  Nanos t{0};  // the runtime's instant (core/instant.h)
  TraceKind kind = TraceKind::Log;
  std::string_view connection, port, op, event, owner, text, callback;
  DropReason reason = DropReason::Rejected;
  Nanos expiry = kNever;  // Event: kNever when the entry has no lifetime
  uint64_t count = 0;
  const Value* value = nullptr;  // Deliver, Publish
};

// The line as JSON text, ending in a newline, appended to `out`: keys in the fixed order of the
// kind, numbers printed round-trip exact.
void append_trace_line(std::string& out, const TraceLine& line);

// The line as a record (what --report and --diff keep in memory).
TraceRecord to_trace_record(const TraceLine& line);
// A record seen as a line (its fields viewed, not copied; valid while `r` lives): what the
// runtime checks read, from the runtime (Trace::Watch) or from records kept in memory.
TraceLine trace_line_of(const TraceRecord& r);
// The same into *r, reusing its strings' storage.
void fill_trace_record(const TraceLine& line, TraceRecord* r);

// A parsed line as a record; false when it is not a trace line of a known kind with the keys
// that kind must have. `value` (may be null) is set to the line's "value" for Deliver and
// Publish (null JSON otherwise): the caller knows the port's type to read it with.
bool read_trace_line(const nlohmann::json& j, TraceRecord* record, nlohmann::json* value);

}  // namespace arbc
