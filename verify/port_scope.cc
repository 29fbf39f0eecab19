#include "verify/port_scope.h"

#include <algorithm>
#include <set>

#include "core/effective_guard.h"
#include "core/join.h"

namespace arbc::verify {

Constraint at_most_one(const std::vector<std::string>& events) {
  std::vector<Constraint> clauses;
  for (size_t i = 0; i < events.size(); ++i) {
    for (size_t j = i + 1; j < events.size(); ++j) {
      clauses.push_back(Constraint::negate(Constraint::conjunction(
          {Constraint::event_ref(events[i]), Constraint::event_ref(events[j])})));
    }
  }
  return Constraint::conjunction(std::move(clauses));
}

namespace {

bool contains(const std::vector<std::string>& v, const std::string& s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}

// Does some connection into the port other than `self` set `event`? A `script` rule may set
// any event (core/effective_guard.h).
bool set_by_other(const std::vector<const model::Connection*>& into, const model::Connection* self,
                  const std::string& event) {
  for (const model::Connection* c : into) {
    if (c != self && (c->opaque || contains(c->sets, event))) return true;
  }
  return false;
}

std::string group_text(const std::vector<std::string>& events) {
  return "exclusive { " + join(events) + " }";
}

}  // namespace

std::optional<PortScope> build_port_scope(const model::App& app, const model::ArbitratedPort& port,
                                          std::string* err) {
  PortScope scope;
  scope.port = &port;
  std::vector<const model::Connection*> into = app.connections_into(port.port);
  std::set<std::string> events;
  for (const std::string& name : port.rules) {
    const model::Connection* conn = nullptr;
    for (const model::Connection* c : into) {
      if (c->name == name && c->kind == model::ConnectionKind::Rule) conn = c;
    }
    if (!conn) {
      *err = "arbitrated port " + port.port + " names rule '" + name +
             "', but no rule connection of that name goes into it";
      return std::nullopt;
    }
    ScopedRule rule;
    rule.connection = conn;
    // The one definition of E_c, shared with the docs' decision tables.
    rule.effective_guard = model::effective_guard(into, *conn);
    rule.activity = conn->activity_event;
    if (!conn->opaque) {
      // The same parts again, named, to explain a counterexample ("its monitor sets ...").
      for (const std::string& e : conn->must_set) {
        if (!contains(rule.forced_present, e)) rule.forced_present.push_back(e);
      }
      for (const std::string& e : conn->must_unset) {
        if (!contains(rule.forced_absent, e) && !set_by_other(into, conn, e)) {
          rule.forced_absent.push_back(e);
        }
      }
    }
    rule.effective_guard.collect_events(events);
    scope.rules.push_back(std::move(rule));
  }
  for (const model::Assertion& a : port.asserts) {
    if (!contains(port.rules, a.rule)) {
      *err = "an assert on " + port.port + " names rule '" + a.rule +
             "', which the port does not have";
      return std::nullopt;
    }
    a.property.collect_events(events);
  }

  // Domain constraints that mention the scope, closed transitively.
  std::vector<DomainConstraint> all;
  for (const model::ExclusiveGroup& g : app.exclusive_groups) {
    all.push_back({at_most_one(g.events), false, g.events, group_text(g.events), g.loc});
  }
  for (const model::Invariant& inv : app.invariants) {
    all.push_back({inv.formula, true, {}, inv.formula.to_string(), inv.loc});
  }
  std::vector<bool> used(all.size(), false);
  for (bool grew = true; grew;) {
    grew = false;
    for (size_t i = 0; i < all.size(); ++i) {
      if (used[i]) continue;
      std::set<std::string> mentioned;
      all[i].formula.collect_events(mentioned);
      bool touches = std::any_of(mentioned.begin(), mentioned.end(),
                                 [&](const std::string& e) { return events.count(e) > 0; });
      if (!touches) continue;
      used[i] = grew = true;
      events.insert(mentioned.begin(), mentioned.end());
    }
  }
  for (size_t i = 0; i < all.size(); ++i) {
    if (used[i]) scope.domain.push_back(std::move(all[i]));
  }
  scope.events.assign(events.begin(), events.end());
  return scope;
}

EventState state_of(const PortScope& scope, const std::vector<std::string>& present) {
  EventState s;
  s.present = present;
  for (const std::string& e : scope.events)
    if (!std::binary_search(present.begin(), present.end(), e)) s.absent.push_back(e);
  return s;
}

}  // namespace arbc::verify
