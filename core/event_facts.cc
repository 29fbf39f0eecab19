#include "core/event_facts.h"

#include <algorithm>
#include <set>

namespace arbc::model {

namespace {

bool lists(const std::vector<std::string>& v, std::string_view s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}

}  // namespace

std::vector<const Connection*> setters_into(const App& app, std::string_view port,
                                            std::string_view event) {
  std::vector<const Connection*> out;
  for (const Connection* c : app.connections_into(port)) {
    if (c->opaque || lists(c->sets, event) || c->activity_event == event) out.push_back(c);
  }
  return out;
}

bool is_delivery_feed(const App& app, const Connection& c) {
  if (c.kind != ConnectionKind::Feed) return false;
  const Port* p = app.find_port(c.source);
  return p && p->direction == Direction::In;
}

bool one_fact(const App& app, std::string_view event, std::string_view a, std::string_view b) {
  if (a == b) return true;
  std::set<std::string> from_a, from_b;
  for (const auto& [port, into] : {std::pair{a, &from_a}, std::pair{b, &from_b}}) {
    for (const Connection* c : setters_into(app, port, event)) {
      if (!is_delivery_feed(app, *c)) return false;
      into->insert(c->source);
    }
  }
  return !from_a.empty() && from_a == from_b;
}

std::vector<std::string> ports_holding(const App& app, std::string_view event) {
  std::vector<std::string> out;
  for (const ArbitratedPort& p : app.arbitrated_ports) {
    if (!setters_into(app, p.port, event).empty()) out.push_back(p.port);
  }
  return out;
}

}  // namespace arbc::model
