#include "runtime/trace.h"

#include <cerrno>
#include <cstring>

#include "runtime/trace_format.h"

namespace arbc {

Trace::~Trace() { close(); }

bool Trace::open(const std::string& path, std::string* err) {
  close();
  file_ = std::fopen(path.c_str(), "w");
  if (file_) return true;
  *err = "cannot write trace file " + path + ": " + std::strerror(errno);
  return false;
}

void Trace::close() {
  if (file_) std::fclose(file_);
  file_ = nullptr;
}

// Every record goes through here: the line in memory for --report and --diff, and on file.
// The watch comes last, so that a breach line it writes follows the record that showed it.
void Trace::emit(const TraceLine& line) {
  if (file_) {
    line_.clear();
    append_trace_line(line_, line);
    std::fwrite(line_.data(), 1, line_.size(), file_);
  }
  if (records_) records_->push_back(to_trace_record(line));
  if (!watch_ || line.kind == TraceKind::Breach) return;
  // A feed's drop says only that the feed consumed its message (its event records say what it
  // did), and feeds are most of the records: the watch does without them.
  if (line.kind == TraceKind::Drop && line.reason == DropReason::Feed) return;
  watch_(line, *this);
}

void Trace::publish(Nanos t, std::string_view port, const Value& v) {
  TraceLine l{t, TraceKind::Publish};
  l.port = port;
  l.value = &v;
  emit(l);
}

void Trace::delivery(Nanos t, std::string_view connection, std::string_view port, const Value& v) {
  TraceLine l{t, TraceKind::Deliver};
  l.connection = connection;
  l.port = port;
  l.value = &v;
  emit(l);
}

void Trace::drop(Nanos t, std::string_view connection, DropReason reason, std::string_view detail) {
  TraceLine l{t, TraceKind::Drop};
  l.connection = connection;
  l.reason = reason;
  l.text = detail;
  emit(l);
}

void Trace::event(Nanos t, std::string_view port, std::string_view kind, std::string_view event,
                  std::string_view owner, Nanos expiry) {
  TraceLine l{t, TraceKind::Event};
  l.port = port;
  l.op = kind;
  l.event = event;
  l.owner = owner;
  l.expiry = expiry;
  emit(l);
}

void Trace::breach(Nanos t, std::string_view claim, std::string_view what) {
  TraceLine l{t, TraceKind::Breach};
  l.connection = claim;
  l.text = what;
  emit(l);
}

void Trace::error(Nanos t, std::string_view connection, std::string_view message) {
  TraceLine l{t, TraceKind::Error};
  l.connection = connection;
  l.text = message;
  emit(l);
}

void Trace::quarantine(Nanos t, std::string_view connection, std::string_view why) {
  TraceLine l{t, TraceKind::Quarantine};
  l.connection = connection;
  l.text = why;
  emit(l);
}

void Trace::log(Nanos t, std::string_view who, std::string_view message) {
  TraceLine l{t, TraceKind::Log};
  l.connection = who;
  l.text = message;
  emit(l);
}

void Trace::publish_error(Nanos t, std::string_view port, std::string_view message) {
  TraceLine l{t, TraceKind::PublishError};
  l.port = port;
  l.text = message;
  emit(l);
}

void Trace::plugin_error(Nanos t, std::string_view who, std::string_view callback,
                         std::string_view message) {
  TraceLine l{t, TraceKind::PluginError};
  l.connection = who;
  l.callback = callback;
  l.text = message;
  emit(l);
}

void Trace::pending(Nanos t, std::string_view connection, size_t count) {
  TraceLine l{t, TraceKind::Pending};
  l.connection = connection;
  l.count = count;
  emit(l);
}

}  // namespace arbc
