// Counters per connection and the table `arbc run` prints at the end.
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

std::string Runtime::stats_table() const {
  static const DropReason kColumns[] = {
      DropReason::Rejected,    DropReason::NoValue,   DropReason::NotSelected,
      DropReason::Throttled,   DropReason::Feed,      DropReason::MonitorError,
      DropReason::Quarantined, DropReason::QueueFull, DropReason::BadType,
  };
  size_t width = 10;
  for (const auto& c : connections_) width = std::max(width, c->name.size());
  std::string out;
  char cell[64];
  std::snprintf(cell, sizeof cell, "%-*s", static_cast<int>(width), "connection");
  out += cell;
  out += "  arrived delivered";
  for (DropReason r : kColumns) {
    std::snprintf(cell, sizeof cell, " %s", drop_reason_name(r));
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
    for (DropReason r : kColumns) {
      int w = static_cast<int>(std::string_view(drop_reason_name(r)).size());
      std::snprintf(cell, sizeof cell, " %*llu", w, static_cast<unsigned long long>(s.drops(r)));
      out += cell;
    }
    std::snprintf(cell, sizeof cell, " %7zu %6llu%s\n", c->queue.size(),
                  static_cast<unsigned long long>(s.errors), s.quarantined ? "  QUARANTINED" : "");
    out += cell;
  }
  for (const PluginStats& p : plugin_stats()) {
    if (p.errors == 0) continue;
    out += p.name + ": " + std::to_string(p.errors) + " exception(s) caught, the run went on\n";
  }
  return out;
}

}  // namespace arbc
