#include "runtime/trace.h"

#include <cerrno>
#include <cstring>

#include "core/json_text.h"

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

TraceRecord& Trace::record(double t, TraceKind kind) {
  records_->emplace_back();
  TraceRecord& r = records_->back();
  r.t = t;
  r.kind = kind;
  return r;
}

void Trace::begin(double t, const char* type) {
  line_.clear();
  line_ += "{\"t\":";
  append_json_double(line_, t);
  line_ += ",\"type\":\"";
  line_ += type;
  line_ += '"';
}

void Trace::field(const char* key, std::string_view value) {
  line_ += ",\"";
  line_ += key;
  line_ += "\":";
  append_json_string(line_, value);
}

void Trace::end() {
  line_ += "}\n";
  std::fwrite(line_.data(), 1, line_.size(), file_);
}

void Trace::publish(double t, std::string_view port, const Value& v) {
  if (records_) record(t, TraceKind::Publish).port = port;
  if (!file_) return;
  begin(t, "publish");
  field("port", port);
  line_ += ",\"value\":";
  line_ += v.to_json();
  end();
}

void Trace::delivery(double t, std::string_view connection, std::string_view port, const Value& v) {
  if (records_) {
    TraceRecord& r = record(t, TraceKind::Deliver);
    r.connection = connection;
    r.port = port;
  }
  if (!file_) return;
  begin(t, "deliver");
  field("connection", connection);
  field("port", port);
  line_ += ",\"value\":";
  line_ += v.to_json();
  end();
}

void Trace::drop(double t, std::string_view connection, DropReason reason,
                 std::string_view detail) {
  if (records_) {
    TraceRecord& r = record(t, TraceKind::Drop);
    r.connection = connection;
    r.reason = reason;
    r.text = detail;
  }
  if (!file_) return;
  begin(t, "drop");
  field("connection", connection);
  field("reason", drop_reason_name(reason));
  if (!detail.empty()) field("detail", detail);
  end();
}

void Trace::event(double t, std::string_view port, std::string_view kind, std::string_view event,
                  std::string_view owner, double expiry) {
  if (records_) {
    TraceRecord& r = record(t, TraceKind::Event);
    r.port = port;
    r.op = kind;
    r.event = event;
    r.owner = owner;
    r.expiry = expiry;
  }
  if (!file_) return;
  begin(t, "event");
  field("port", port);
  field("op", kind);
  field("event", event);
  field("owner", owner);
  if (expiry >= 0) {
    line_ += ",\"expiry\":";
    append_json_double(line_, expiry);
  }
  end();
}

void Trace::error(double t, std::string_view connection, std::string_view message) {
  if (records_) {
    TraceRecord& r = record(t, TraceKind::Error);
    r.connection = connection;
    r.text = message;
  }
  if (!file_) return;
  begin(t, "error");
  field("connection", connection);
  field("message", message);
  end();
}

void Trace::quarantine(double t, std::string_view connection, std::string_view why) {
  if (records_) {
    TraceRecord& r = record(t, TraceKind::Quarantine);
    r.connection = connection;
    r.text = why;
  }
  if (!file_) return;
  begin(t, "quarantine");
  field("connection", connection);
  field("message", why);
  end();
}

void Trace::log(double t, std::string_view who, std::string_view message) {
  if (records_) {
    TraceRecord& r = record(t, TraceKind::Log);
    r.connection = who;
    r.text = message;
  }
  if (!file_) return;
  begin(t, "log");
  field("from", who);
  field("message", message);
  end();
}

void Trace::publish_error(double t, std::string_view port, std::string_view message) {
  if (records_) {
    TraceRecord& r = record(t, TraceKind::PublishError);
    r.port = port;
    r.text = message;
  }
  if (!file_) return;
  begin(t, "publish-error");
  field("port", port);
  field("message", message);
  end();
}

void Trace::plugin_error(double t, std::string_view who, std::string_view callback,
                         std::string_view message) {
  if (records_) {
    TraceRecord& r = record(t, TraceKind::PluginError);
    r.connection = who;
    r.callback = callback;
    r.text = message;
  }
  if (!file_) return;
  begin(t, "plugin-error");
  field("from", who);
  field("callback", callback);
  field("message", message);
  end();
}

void Trace::pending(double t, std::string_view connection, size_t count) {
  if (records_) {
    TraceRecord& r = record(t, TraceKind::Pending);
    r.connection = connection;
    r.count = count;
  }
  if (!file_) return;
  begin(t, "pending");
  field("connection", connection);
  line_ += ",\"count\":" + std::to_string(count);
  end();
}

}  // namespace arbc
