#include "compiler/docs/event_lifetimes.h"

#include <algorithm>
#include <map>
#include <set>

#include "core/duration_literal.h"
#include "core/join.h"

namespace arbc::docs {

namespace {

// As the spec writes the lifetime (`set e for 1s`).
std::string seconds_text(Nanos d) { return duration_literal(d); }

// The lifetime of each `set EVENT` in `body`, nested blocks included.
void collect_sets(const model::Body& body, const std::string& event, const std::string& fallback,
                  std::set<std::string>& out) {
  for (const model::BodyStmt& s : body) {
    if (s.kind == model::BodyStmt::Kind::Set && s.name == event)
      out.insert(s.lifetime ? seconds_text(*s.lifetime) : fallback);
    collect_sets(s.then_body, event, fallback, out);
    collect_sets(s.else_body, event, fallback, out);
  }
}

}  // namespace

std::string event_lifetime_cell(const model::Event& event, const model::App& app) {
  const std::string declared = event.lifetime ? seconds_text(*event.lifetime) : "until unset";
  // A fed event (a stream, a status flag, a rule's hold) is set by the runtime, with the
  // declared lifetime.
  if (!event.source.empty()) return declared;
  std::map<std::string, std::vector<std::string>> by_lifetime;  // lifetime -> connections
  for (const model::Connection& c : app.connections) {
    if (std::find(c.sets.begin(), c.sets.end(), event.name) == c.sets.end()) continue;
    std::set<std::string> lifetimes;
    if (c.activity_event == event.name)
      lifetimes.insert(declared);
    else if (!c.body)
      lifetimes.insert("as its script sets it");
    else
      collect_sets(*c.body, event.name, declared, lifetimes);
    for (const std::string& l : lifetimes) by_lifetime[l].push_back(c.name);
  }
  if (by_lifetime.empty()) return declared;  // set by no connection (a test, or nobody)
  if (by_lifetime.size() == 1 && by_lifetime.begin()->first != "as its script sets it")
    return by_lifetime.begin()->first;
  std::vector<std::string> parts;
  for (const auto& [lifetime, connections] : by_lifetime)
    parts.push_back(lifetime + " (" + join(connections) + ")");
  return join(parts, "; ");
}

}  // namespace arbc::docs
