// Counters per connection and the table `arbc run` prints at the end.
#include <algorithm>
#include <cstdio>

#include "runtime/runtime_internal.h"

namespace arbc {

std::vector<ConnectionStats> Runtime::stats() const {
  std::vector<ConnectionStats> out;
  for (const auto& c : connections_) {
    out.push_back(c->stats);
    out.back().pending = c->queue.size();
  }
  return out;
}

std::vector<InputStats> Runtime::input_stats() const {
  std::vector<InputStats> out;
  for (const auto& in : in_ports_) {
    if (in->slot && !in->mediated) out.push_back(in->stats);
  }
  return out;
}

std::string Runtime::transport_name() const { return transport_ ? transport_->name() : "inproc"; }

std::string Runtime::transport_summary() const {
  return transport_ ? transport_->summary() : std::string();
}

TransportStatus Runtime::transport_status() const {
  return transport_ ? transport_->status() : TransportStatus{};
}

std::map<std::string, size_t> Runtime::monitor_memory() const {
  std::map<std::string, size_t> out;
  for (const auto& c : connections_) {
    if (c->monitor) out[c->name] = c->monitor->memory_used();
  }
  return out;
}

std::vector<PluginStats> Runtime::plugin_stats() const {
  std::vector<PluginStats> out;
  for (const auto& m : modules_) out.push_back({m->name, m->errors});
  if (environment_slot_) out.push_back({environment_slot_->name, environment_slot_->errors});
  return out;
}

// One row per hosted input that another process mediates: what arrived through the transport
// and what it lost on the way (only the transport's losses can happen before the module).
std::string Runtime::input_table() const {
  std::vector<InputStats> inputs = input_stats();
  if (inputs.empty()) return {};
  const DropReason kLosses[] = {DropReason::QueueFull, DropReason::BadType,
                                DropReason::LostInTransit};
  std::string title = "input (mediated elsewhere)";
  size_t width = title.size();
  for (const InputStats& s : inputs) width = std::max(width, s.port.size());
  char cell[160];
  std::snprintf(cell, sizeof cell, "%-*s  arrived delivered", static_cast<int>(width),
                title.c_str());
  std::string out = cell;
  for (DropReason r : kLosses) out += std::string(" ") + drop_reason_name(r);
  out += "\n";
  for (const InputStats& s : inputs) {
    std::snprintf(cell, sizeof cell, "%-*s %8llu %9llu", static_cast<int>(width), s.port.c_str(),
                  static_cast<unsigned long long>(s.arrived),
                  static_cast<unsigned long long>(s.delivered));
    out += cell;
    for (DropReason r : kLosses) {
      int w = static_cast<int>(std::string_view(drop_reason_name(r)).size());
      std::snprintf(cell, sizeof cell, " %*llu", w, static_cast<unsigned long long>(s.drops(r)));
      out += cell;
    }
    out += "\n";
  }
  return out;
}

std::string Runtime::stats_table() const {
  std::string out = connection_table();
  out += input_table();
  for (const PluginStats& p : plugin_stats()) {
    if (p.errors == 0) continue;
    out += p.name + ": " + std::to_string(p.errors) + " exception(s) caught, the run went on\n";
  }
  return out;
}

// One row per connection run here (none in a process that mediates nothing).
std::string Runtime::connection_table() const {
  if (connections_.empty()) return {};
  size_t width = 10;
  for (const auto& c : connections_) width = std::max(width, c->name.size());
  std::string out;
  char cell[64];
  std::snprintf(cell, sizeof cell, "%-*s", static_cast<int>(width), "connection");
  out += cell;
  // bad-value (a list longer than the proof covers) is rare: its column only when it happened.
  std::vector<DropReasonInfo> columns;
  for (const DropReasonInfo& r : kDropReasons)
    if (r.reason != DropReason::BadValue ||
        std::any_of(connections_.begin(), connections_.end(),
                    [](const auto& c) { return c->stats.drops(DropReason::BadValue) > 0; }))
      columns.push_back(r);
  out += "  arrived delivered";
  for (const DropReasonInfo& r : columns) {
    std::snprintf(cell, sizeof cell, " %s", r.name);
    out += cell;
  }
  out += " pending errors\n";
  for (const auto& c : connections_) {
    const ConnectionStats& s = c->stats;
    std::snprintf(cell, sizeof cell, "%-*s", static_cast<int>(width), s.name.c_str());
    out += cell;
    std::snprintf(cell, sizeof cell, " %8llu %9llu", static_cast<unsigned long long>(s.arrived),
                  static_cast<unsigned long long>(s.delivered));
    out += cell;
    for (const DropReasonInfo& r : columns) {
      int w = static_cast<int>(std::string_view(r.name).size());
      std::snprintf(cell, sizeof cell, " %*llu", w,
                    static_cast<unsigned long long>(s.drops(r.reason)));
      out += cell;
    }
    std::snprintf(cell, sizeof cell, " %7zu %6llu%s\n", c->queue.size(),
                  static_cast<unsigned long long>(s.errors), s.quarantined ? "  QUARANTINED" : "");
    out += cell;
  }
  return out;
}

}  // namespace arbc
