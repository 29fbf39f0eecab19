#include "compiler/lower/test_cases.h"

#include "compiler/frontend/literal_value.h"
#include "compiler/lower/lower_body.h"
#include "compiler/lower/temporal.h"

namespace arbc {

namespace {

Value value_for(const ast::Expr& e, const ast::PortRef& port) {
  std::string unused;
  std::optional<Value> v = frontend::literal_value(e, *port.port_decl->type.resolved, &unused);
  return v ? *v : Value();  // sema checked it
}

model::TestStep lower_step(const ast::TestStep& s) {
  model::TestStep out;
  out.t = s.at.nanos;
  out.loc = s.loc;
  switch (s.kind) {
    case ast::TestStep::Kind::Input:
      out.kind = model::TestStep::Kind::Input;
      out.port = s.port.qualified();
      out.value = value_for(*s.value, s.port);
      break;
    case ast::TestStep::Kind::Set:
    case ast::TestStep::Kind::Unset:
      out.kind = s.kind == ast::TestStep::Kind::Set ? model::TestStep::Kind::Set
                                                    : model::TestStep::Kind::Unset;
      out.event = s.event;
      break;
  }
  return out;
}

model::Expectation lower_expect(const ast::TestExpect& e) {
  model::Expectation out;
  out.text = e.text;
  out.loc = e.loc;
  if (e.window.present) {
    out.from = e.window.from.nanos;
    out.to = e.window.to.expr ? e.window.to.nanos : out.from;
  }
  switch (e.kind) {
    case ast::TestExpect::Kind::Receives:
      out.kind = model::Expectation::Kind::Receives;
      out.port = e.port.qualified();
      if (e.value) out.value = value_for(*e.value, e.port);
      break;
    case ast::TestExpect::Kind::Nothing:
      out.kind = model::Expectation::Kind::Nothing;
      out.port = e.port.qualified();
      break;
    case ast::TestExpect::Kind::Drops:
      out.kind = model::Expectation::Kind::Drops;
      out.connection = e.rule;
      out.reason = e.reason;
      break;
    case ast::TestExpect::Kind::Delivers:
      out.kind = model::Expectation::Kind::Delivers;
      out.connection = e.rule;
      break;
    case ast::TestExpect::Kind::DeliversNothing:
      out.kind = model::Expectation::Kind::DeliversNothing;
      out.connection = e.rule;
      break;
    case ast::TestExpect::Kind::Property:
      out.kind = model::Expectation::Kind::Property;
      out.property = lower_temporal(*e.property);
      break;
    case ast::TestExpect::Kind::State:
      out.kind = model::Expectation::Kind::State;
      out.state = e.constraint;
      if (!e.port.module.empty()) out.port = e.port.qualified();
      break;
    case ast::TestExpect::Kind::Exclusive:
      out.kind = model::Expectation::Kind::Exclusive;
      out.port = e.port.qualified();
      break;
    case ast::TestExpect::Kind::Resource:
      out.kind = model::Expectation::Kind::Resource;
      out.resource = e.rule;
      break;
    case ast::TestExpect::Kind::Assert:
      out.kind = model::Expectation::Kind::Assert;
      out.port = e.assertion->port.qualified();
      out.assertion = lower::lower_assert(
          *e.assertion,
          e.assertion->port.port_decl ? e.assertion->port.port_decl->type.resolved : nullptr);
      break;
  }
  return out;
}

}  // namespace

std::vector<model::TestCase> lower_tests(const ast::Spec& spec) {
  std::vector<model::TestCase> out;
  for (const ast::TestDecl& t : spec.tests) {
    model::TestCase c;
    c.name = t.name;
    c.rule = t.on;
    c.loc = t.loc;
    for (const ast::TestStep& s : t.steps) c.steps.push_back(lower_step(s));
    for (const ast::TestExpect& e : t.expects) c.expectations.push_back(lower_expect(e));
    out.push_back(std::move(c));
  }
  return out;
}

}  // namespace arbc
