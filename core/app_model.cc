#include "core/app_model.h"

#include "core/body_spec_text.h"
#include "core/duration_literal.h"

namespace arbc::model {

std::string assumption_text(const Assumption& a) {
  if (a.absent_for)
    return "assume not " + a.event + " for " + duration_literal(*a.absent_for) + " after " +
           a.after;
  return "assume " + a.event + " only after " + a.after +
         (a.until.empty() ? "" : " until " + a.until);
}

std::string assertion_text(const std::string& port, const Assertion& a) {
  return "assert " + port + ": " + a.rule + " -> " +
         (a.emitted ? body_expr_spec_text(*a.emitted, "emitted") : a.property.to_string());
}

std::string temporal_property_text(const TemporalProperty& p) {
  switch (p.kind) {
    case TemporalProperty::Kind::Spacing:
      if (!p.other.empty())
        return "never " + p.rule + " within " + duration_literal(p.window) + " after " + p.other;
      return "never two " + p.rule + " within " + duration_literal(p.window);
    case TemporalProperty::Kind::Absence:
      return "never " + p.rule + " while " + p.event;
    case TemporalProperty::Kind::Precedence:
      return "only " + p.rule + " after " + p.other;
    case TemporalProperty::Kind::Response: {
      std::string words = "after " + (p.event.empty() ? p.other : p.event) +
                          (p.stops ? " stops, " : ", ") + (p.rule.empty() ? p.port : p.rule) +
                          " within " + duration_literal(p.window);
      if (p.condition.op != Constraint::Op::True) words += " while " + p.condition.to_string();
      return words;
    }
    case TemporalProperty::Kind::Stability:
      return "stable " + p.port + " for " + duration_literal(p.window);
  }
  return p.rule;
}

const char* temporal_kind_name(TemporalProperty::Kind k) {
  switch (k) {
    case TemporalProperty::Kind::Spacing:
      return "spacing";
    case TemporalProperty::Kind::Absence:
      return "absence";
    case TemporalProperty::Kind::Precedence:
      return "precedence";
    case TemporalProperty::Kind::Response:
      return "response";
    case TemporalProperty::Kind::Stability:
      return "stability";
  }
  return "spacing";
}

const Module* App::find_module(std::string_view name) const {
  for (const Module& m : modules)
    if (m.name == name) return &m;
  return nullptr;
}

const Port* App::find_port(std::string_view qualified) const {
  size_t dot = qualified.find('.');
  if (dot == std::string_view::npos) return nullptr;
  const Module* m = find_module(qualified.substr(0, dot));
  if (!m) return nullptr;
  std::string_view port = qualified.substr(dot + 1);
  for (const Port& p : m->ports)
    if (p.name == port) return &p;
  return nullptr;
}

const Event* App::find_event(std::string_view name) const {
  for (const Event& e : events)
    if (e.name == name) return &e;
  return nullptr;
}

const ArbitratedPort* App::find_arbitrated(std::string_view port) const {
  for (const ArbitratedPort& a : arbitrated_ports)
    if (a.port == port) return &a;
  return nullptr;
}

std::vector<const Connection*> App::connections_into(std::string_view port) const {
  std::vector<const Connection*> out;
  for (const Connection& c : connections)
    if (c.destination == port) out.push_back(&c);
  return out;
}

}  // namespace arbc::model

namespace arbc::model {

const SourceRate* App::find_rate(std::string_view port) const {
  for (const SourceRate& r : rates)
    if (r.port == port) return &r;
  return nullptr;
}

}  // namespace arbc::model
