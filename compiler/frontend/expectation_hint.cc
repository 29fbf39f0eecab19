#include "compiler/frontend/expectation_hint.h"

#include "core/duration_literal.h"

namespace arbc::frontend {

namespace {

// The destination a message from `source` reaches: the rule's own port in a test `on RULE`,
// else the port of the first rule that reads `source`; null when none does.
const ast::PortRef* destination_of(const ast::PortRef& source, const ast::TestDecl& test,
                                   const ast::Spec& spec) {
  if (test.on_rule) return test.on_rule->port ? &test.on_rule->port->port : nullptr;
  for (const ast::ArbitrateDecl& a : spec.arbitrations) {
    for (const ast::Rule& r : a.rules) {
      if (r.source.qualified() == source.qualified()) return &a.port;
    }
  }
  return nullptr;
}

}  // namespace

std::string expectation_hint(const ast::TestDecl& test, const ast::Spec& spec) {
  for (auto s = test.steps.rbegin(); s != test.steps.rend(); ++s) {
    if (s->kind != ast::TestStep::Kind::Input) continue;
    if (const ast::PortRef* to = destination_of(s->port, test, spec))
      return "expect " + to->qualified() + " receives at " + duration_literal(s->at.nanos) + ";";
  }
  return "";
}

}  // namespace arbc::frontend
