#include "compiler/docs/port_summary.h"

#include <algorithm>
#include <set>

#include "core/event_facts.h"

namespace arbc::docs {

namespace {

bool reads_only(const Constraint& literal, const std::set<std::string>& events) {
  if (literal.op == Constraint::Op::Event) return events.count(literal.event) > 0;
  if (literal.op == Constraint::Op::Not) return reads_only(literal.args[0], events);
  return false;
}

// The constraint without its conjuncts `act_k` / `not act_k` over the port's activity events.
std::string when_text(const Constraint& c, const std::set<std::string>& activity) {
  if (activity.empty()) return c.to_string();
  if (reads_only(c, activity)) return "true";
  if (c.op != Constraint::Op::And) return c.to_string();
  std::vector<Constraint> kept;
  for (const Constraint& part : c.args)
    if (!reads_only(part, activity)) kept.push_back(part);
  return Constraint::conjunction(std::move(kept)).to_string();
}

}  // namespace

PortSummary summarize_port(const model::App& app, const model::ArbitratedPort& port,
                           std::span<const model::Connection* const> into) {
  PortSummary out;
  out.port = &port;
  // A `by priority` rule's activity event: the runtime sets it for the rule's hold (the
  // event's lifetime) on each delivery; the lower rules' constraints read `not act_k`.
  std::set<std::string> activity;
  for (const model::Connection* c : into)
    if (c->kind == model::ConnectionKind::Rule && !c->activity_event.empty())
      activity.insert(c->activity_event);
  for (const std::string& rule : port.rules) {
    for (const model::Connection* c : into) {
      if (c->name != rule || c->kind != model::ConnectionKind::Rule) continue;
      RuleSummary r{c, when_text(c->constraint, activity), std::nullopt, {}};
      if (!c->activity_event.empty()) {
        const model::Event* e = app.find_event(c->activity_event);
        if (e) r.hold = e->lifetime;
      }
      for (const std::string& e : c->must_set)
        if (!activity.count(e)) r.sets.push_back(e);
      out.rules.push_back(std::move(r));
    }
  }
  for (const model::Connection* c : into) {
    if (c->kind != model::ConnectionKind::Feed) continue;
    std::set<std::string> events(c->sets.begin(), c->sets.end());
    events.insert(c->unsets.begin(), c->unsets.end());
    out.feeds.push_back({c, std::vector<std::string>(events.begin(), events.end()),
                         model::is_delivery_feed(app, *c)});
  }
  return out;
}

}  // namespace arbc::docs
