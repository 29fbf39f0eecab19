#include "core/app_model.h"

namespace arbc::model {

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
