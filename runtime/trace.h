// The run's trace: one JSON object per line, for every delivery, drop, event change and
// error (docs/runtime.md, "Trace format", whose keys runtime/trace_format.h defines). Keys come
// in a fixed order and numbers print deterministically, so the same seed gives a byte-identical
// trace. Times are the runtime's whole nanoseconds (core/instant.h), written as exact decimals of
// seconds.
#pragma once

#include <cstdio>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "core/value.h"
#include "runtime/drop_reason.h"
#include "runtime/trace_format.h"
#include "runtime/trace_record.h"

namespace arbc {

class Trace {
 public:
  Trace() = default;
  ~Trace();
  // Opens path for writing; false and *err when it cannot.
  bool open(const std::string& path, std::string* err);
  // Also appends every record to *records (nullptr: stop); independent of the file.
  // The caller keeps *records alive while the trace is written.
  void record_to(std::vector<TraceRecord>* records) { records_ = records; }
  // Also gives every record but a feed's drop, once written, to `watch` (the runtime checks,
  // runtime/claim_watch.h), which may write breach lines in turn; empty: stop. The watch sees
  // the line itself, its fields valid only during the call: it runs on every message, and
  // copying the fields into a TraceRecord cost more than the checks' own work
  // (bench/figures/runtime_checks.sh).
  using Watch = std::function<void(const TraceLine&, Trace&)>;
  void watch_with(Watch watch) { watch_ = std::move(watch); }
  bool enabled() const { return file_ != nullptr || records_ != nullptr || watch_ != nullptr; }

  // A module published v on its out-port `port` ("Module.port"); written before the message
  // enters the connections from the port, so a replay of the trace can publish it again.
  void publish(Nanos t, std::string_view port, const Value& v);
  void delivery(Nanos t, std::string_view connection, std::string_view port, const Value& v);
  void drop(Nanos t, std::string_view connection, DropReason reason, std::string_view detail);
  // kind: "set", "unset" or "expire"; expiry kNever means none.
  void event(Nanos t, std::string_view port, std::string_view kind, std::string_view event,
             std::string_view owner, Nanos expiry);
  void error(Nanos t, std::string_view connection, std::string_view message);
  void quarantine(Nanos t, std::string_view connection, std::string_view why);
  void log(Nanos t, std::string_view who, std::string_view message);
  void publish_error(Nanos t, std::string_view port, std::string_view message);
  // An exception escaped plugin code: `who` is a module's name or "environment".
  void plugin_error(Nanos t, std::string_view who, std::string_view callback,
                    std::string_view message);
  // A runtime check found `claim` broken (at the instant of the record that showed it; `what`
  // says when it broke and how).
  void breach(Nanos t, std::string_view claim, std::string_view what);
  // Messages still queued on a connection when the run ended.
  void pending(Nanos t, std::string_view connection, size_t count);
  void close();

 private:
  void emit(const TraceLine& line);
  std::FILE* file_ = nullptr;
  std::vector<TraceRecord>* records_ = nullptr;
  Watch watch_;
  std::string line_;
};

}  // namespace arbc
