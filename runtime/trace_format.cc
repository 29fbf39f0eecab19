#include "runtime/trace_format.h"

#include <array>

#include "core/json_text.h"

namespace arbc {

namespace {

// Where a key's value lives in a line.
enum class Slot {
  Connection,
  Port,
  Reason,
  Op,
  Event,
  Owner,
  Expiry,
  Text,
  Callback,
  Count,
  Value
};

struct Key {
  const char* name;
  Slot slot;
  bool optional = false;  // written only when set (a drop's detail, an event's expiry)
};

struct KindFormat {
  TraceKind kind;
  const char* name;
  std::array<Key, 5> keys;  // in order; unused entries have a null name
};

// The format: every kind, its name, its keys. Log and PluginError name who is speaking under
// "from"; a drop's detail and a quarantine's reason are "detail" and "message".
constexpr KindFormat kFormats[] = {
    {TraceKind::Deliver,
     "deliver",
     {{{"connection", Slot::Connection}, {"port", Slot::Port}, {"value", Slot::Value}}}},
    {TraceKind::Drop,
     "drop",
     {{{"connection", Slot::Connection}, {"reason", Slot::Reason}, {"detail", Slot::Text, true}}}},
    {TraceKind::Event,
     "event",
     {{{"port", Slot::Port},
       {"op", Slot::Op},
       {"event", Slot::Event},
       {"owner", Slot::Owner},
       {"expiry", Slot::Expiry, true}}}},
    {TraceKind::Error, "error", {{{"connection", Slot::Connection}, {"message", Slot::Text}}}},
    {TraceKind::Quarantine,
     "quarantine",
     {{{"connection", Slot::Connection}, {"message", Slot::Text}}}},
    {TraceKind::Log, "log", {{{"from", Slot::Connection}, {"message", Slot::Text}}}},
    {TraceKind::PublishError, "publish-error", {{{"port", Slot::Port}, {"message", Slot::Text}}}},
    {TraceKind::PluginError,
     "plugin-error",
     {{{"from", Slot::Connection}, {"callback", Slot::Callback}, {"message", Slot::Text}}}},
    {TraceKind::Pending, "pending", {{{"connection", Slot::Connection}, {"count", Slot::Count}}}},
    {TraceKind::Publish, "publish", {{{"port", Slot::Port}, {"value", Slot::Value}}}},
    {TraceKind::Breach, "breach", {{{"claim", Slot::Connection}, {"message", Slot::Text}}}},
};

const KindFormat& format_of(TraceKind kind) {
  for (const KindFormat& f : kFormats)
    if (f.kind == kind) return f;
  return kFormats[0];  // unreachable: every kind is in the table (trace_format_test)
}

std::string_view text_slot(const TraceLine& l, Slot s) {
  switch (s) {
    case Slot::Connection:
      return l.connection;
    case Slot::Port:
      return l.port;
    case Slot::Reason:
      return drop_reason_name(l.reason);
    case Slot::Op:
      return l.op;
    case Slot::Event:
      return l.event;
    case Slot::Owner:
      return l.owner;
    case Slot::Text:
      return l.text;
    case Slot::Callback:
      return l.callback;
    default:
      return {};
  }
}

std::string* record_slot(TraceRecord* r, Slot s) {
  switch (s) {
    case Slot::Connection:
      return &r->connection;
    case Slot::Port:
      return &r->port;
    case Slot::Op:
      return &r->op;
    case Slot::Event:
      return &r->event;
    case Slot::Owner:
      return &r->owner;
    case Slot::Text:
      return &r->text;
    case Slot::Callback:
      return &r->callback;
    default:
      return nullptr;
  }
}

bool reason_named(const std::string& name, DropReason* r) {
  for (int i = 0; i < kDropReasonCount; ++i) {
    if (name == drop_reason_name(static_cast<DropReason>(i))) {
      *r = static_cast<DropReason>(i);
      return true;
    }
  }
  return false;
}

// One key of a parsed line into the record; false when it is missing or of the wrong kind.
bool read_key(const nlohmann::json& j, const Key& key, TraceRecord* r, nlohmann::json* value) {
  auto it = j.find(key.name);
  if (it == j.end()) return key.optional || key.slot == Slot::Value;
  switch (key.slot) {
    case Slot::Expiry:
      if (!it->is_number()) return false;
      r->expiry = nanos_from_seconds(it->get<double>());  // as written, to the nanosecond
      return true;
    case Slot::Count:
      if (!it->is_number_unsigned()) return false;
      r->count = it->get<uint64_t>();
      return true;
    case Slot::Value:
      if (value) *value = *it;
      return true;
    case Slot::Reason:
      return it->is_string() && reason_named(it->get<std::string>(), &r->reason);
    default:
      if (!it->is_string()) return false;
      *record_slot(r, key.slot) = it->get<std::string>();
      return true;
  }
}

}  // namespace

const char* trace_kind_name(TraceKind kind) { return format_of(kind).name; }

std::optional<TraceKind> trace_kind_named(std::string_view name) {
  for (const KindFormat& f : kFormats)
    if (name == f.name) return f.kind;
  return std::nullopt;
}

void append_trace_line(std::string& out, const TraceLine& line) {
  const KindFormat& f = format_of(line.kind);
  out += "{\"t\":";
  append_json_seconds(out, line.t);
  out += ",\"type\":\"";
  out += f.name;
  out += '"';
  for (const Key& key : f.keys) {
    if (!key.name) break;
    if (key.optional && key.slot == Slot::Expiry && line.expiry == kNever) continue;
    if (key.optional && key.slot == Slot::Text && line.text.empty()) continue;
    out += ",\"";
    out += key.name;
    out += "\":";
    if (key.slot == Slot::Expiry) {
      append_json_seconds(out, line.expiry);
    } else if (key.slot == Slot::Count) {
      out += std::to_string(line.count);
    } else if (key.slot == Slot::Value) {
      out += line.value ? line.value->to_json() : "null";
    } else {
      append_json_string(out, text_slot(line, key.slot));
    }
  }
  out += "}\n";
}

void fill_trace_record(const TraceLine& line, TraceRecord* r) {
  r->t = line.t;
  r->kind = line.kind;
  r->connection.assign(line.connection);
  r->port.assign(line.port);
  r->reason = line.reason;
  r->op.assign(line.op);
  r->event.assign(line.event);
  r->owner.assign(line.owner);
  r->expiry = line.expiry;
  r->text.assign(line.text);
  r->callback.assign(line.callback);
  r->count = line.count;
  r->value = line.value;
}

TraceRecord to_trace_record(const TraceLine& line) {
  TraceRecord r;
  fill_trace_record(line, &r);
  r.value = nullptr;  // the line's value lives only as long as the line
  return r;
}

TraceLine trace_line_of(const TraceRecord& r) {
  TraceLine l{r.t, r.kind};
  l.connection = r.connection, l.port = r.port, l.op = r.op, l.event = r.event;
  l.owner = r.owner, l.text = r.text, l.callback = r.callback;
  l.reason = r.reason, l.expiry = r.expiry, l.count = r.count, l.value = r.value;
  return l;
}

bool read_trace_line(const nlohmann::json& j, TraceRecord* record, nlohmann::json* value) {
  if (!j.is_object() || !j.contains("t") || !j["t"].is_number()) return false;
  auto type = j.find("type");
  if (type == j.end() || !type->is_string()) return false;
  std::optional<TraceKind> kind = trace_kind_named(type->get<std::string>());
  if (!kind) return false;
  TraceRecord r;
  r.t = nanos_from_seconds(j["t"].get<double>());  // as the runtime wrote it, to the nanosecond
  r.kind = *kind;
  if (value) *value = nullptr;
  for (const Key& key : format_of(*kind).keys) {
    if (key.name && !read_key(j, key, &r, value)) return false;
  }
  *record = std::move(r);
  return true;
}

}  // namespace arbc
