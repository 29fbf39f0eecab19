#include "dds/status_types.h"

#include <array>

#include "core/duration_literal.h"

namespace arbc::dds {

namespace {

TypePtr named(StatusTypes& s, const std::string& name, const std::string& ros2,
              std::vector<Field> fields) {
  TypePtr t = Type::record(std::move(fields));
  s.named.push_back({.name = name, .type = t, .loc = {}, .ros2 = ros2});
  return t;
}

StatusTypes make_status_types() {
  StatusTypes s;
  TypePtr text = Type::scalar(Type::Kind::String);
  TypePtr time = named(s, "Time", "builtin_interfaces/msg/Time",
                       {{"sec", Type::number("int32")}, {"nanosec", Type::number("uint32")}});
  TypePtr header = named(s, "Header", "std_msgs/msg/Header", {{"stamp", time}, {"frame_id", text}});
  TypePtr key_value =
      named(s, "KeyValue", "diagnostic_msgs/msg/KeyValue", {{"key", text}, {"value", text}});
  s.status = named(s, "DiagnosticStatus", "diagnostic_msgs/msg/DiagnosticStatus",
                   {{"level", Type::number("byte")},
                    {"name", text},
                    {"message", text},
                    {"hardware_id", text},
                    {"values", Type::list(key_value)}});
  s.array = named(s, "DiagnosticArray", "diagnostic_msgs/msg/DiagnosticArray",
                  {{"header", header}, {"status", Type::list(s.status)}});
  return s;
}

// diagnostic_msgs/msg/DiagnosticStatus's level constants, by value.
const std::array<const char*, 4> kLevelNames = {"OK", "WARN", "ERROR", "STALE"};

Value key_value(std::string key, std::string value) {
  return Value::record({{"key", std::move(key)}, {"value", std::move(value)}});
}

// The state of a rule in words that do not change with time alone (no ages).
std::string steady_state(const RuleStatus& r) {
  if (r.selected) return "selected";
  return r.blocked.empty() ? "may deliver" : r.blocked;
}

Value status_value(const PortStatus& p, const std::string& app, ValueList values) {
  return Value::record({{"level", int64_t{static_cast<int>(p.level)}},
                        {"name", app + ": " + p.port},
                        {"message", p.message},
                        {"hardware_id", app},
                        {"values", Value(std::move(values))}});
}

ValueList rule_values(const PortStatus& p) {
  ValueList values{key_value("selected", p.selected)};
  for (const RuleStatus& r : p.rules)
    values.push_back(key_value("rule " + r.rule, steady_state(r)));
  return values;
}

}  // namespace

const StatusTypes& status_types() {
  static const StatusTypes types = make_status_types();
  return types;
}

std::string status_wire_topic(const std::string& written) {
  return "rt/" + (!written.empty() && written.front() == '/' ? written.substr(1) : written);
}

std::string default_status_topic(const std::string& app, const std::string& port) {
  std::string topic = "/arbc/" + app + "/status/" + port;
  topic[topic.rfind('.')] = '/';
  return topic;
}

Value latched_status_value(const PortStatus& p, const std::string& app) {
  return status_value(p, app, rule_values(p));
}

Value diagnostic_array_value(const std::vector<PortStatus>& ports, const std::string& app, Nanos t,
                             Nanos stamp) {
  ValueList statuses;
  for (const PortStatus& p : ports) {
    ValueList values = rule_values(p);
    values.push_back(key_value("arrived", std::to_string(p.arrived)));
    values.push_back(key_value("delivered", std::to_string(p.delivered)));
    for (const DropReasonInfo& info : kDropReasons) {
      uint64_t n = p.dropped[static_cast<int>(info.reason)];
      if (n > 0)
        values.push_back(key_value(std::string("dropped ") + info.name, std::to_string(n)));
    }
    values.push_back(key_value("last delivery",
                               p.last_delivery == -kNever
                                   ? "none yet"
                                   : age_literal(t - p.last_delivery) + " ago by " + p.last_rule));
    statuses.push_back(status_value(p, app, std::move(values)));
  }
  // builtin_interfaces/msg/Time: whole seconds (rounded down) and the nanoseconds past them.
  int64_t ns = stamp.count();
  int64_t sec = ns >= 0 ? ns / 1000000000 : -((-ns + 999999999) / 1000000000);
  Value time = Value::record({{"sec", sec}, {"nanosec", ns - sec * 1000000000}});
  return Value::record({{"header", Value::record({{"stamp", time}, {"frame_id", ""}})},
                        {"status", Value(std::move(statuses))}});
}

std::string status_line(const Value& status) {
  int64_t level = status["level"].as_int();
  std::string line = status["name"].as_string() + "  " +
                     (level >= 0 && level < 4 ? kLevelNames[static_cast<size_t>(level)] : "?") +
                     "  " + status["message"].as_string();
  std::string counters;
  std::string arrived, delivered;
  for (const Value& kv : status["values"].as_list()) {
    const std::string& key = kv["key"].as_string();
    const std::string& value = kv["value"].as_string();
    if (key.starts_with("rule ")) {
      if (value != "selected") line += " | " + key.substr(5) + ": " + value;
    } else if (key == "arrived") {
      arrived = value;
    } else if (key == "delivered") {
      delivered = value;
    } else if (key != "selected") {
      counters += "; " + key + " " + value;
    }
  }
  return line + "  [" + delivered + " of " + arrived + " delivered" + counters + "]";
}

}  // namespace arbc::dds
