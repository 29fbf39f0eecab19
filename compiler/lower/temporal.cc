#include "compiler/lower/temporal.h"

namespace arbc {

std::optional<model::TemporalProperty> lower_temporal(const ast::TemporalDecl& n) {
  const ast::ArbitrateDecl* port = n.rule_decl ? n.rule_decl->port : n.port_decl;
  if (!port) return std::nullopt;
  model::TemporalProperty t;
  t.kind = static_cast<model::TemporalProperty::Kind>(n.kind);  // the same five, in order
  t.port = port->port.qualified();
  t.rule = n.rule;
  t.window = n.window.nanos;
  t.event = n.event;
  t.other = n.other;
  t.stops = n.stops;
  t.condition = n.condition_sema;
  t.loc = n.loc;
  return t;
}

}  // namespace arbc
