#include <cctype>

#include "compiler/frontend/ast_builder_class.h"

namespace arbc::frontend {

using namespace ast;

// portRef : ID '.' ID ;
PortRef Builder::port_ref(ArbcParser::PortRefContext* ctx) {
  PortRef p;
  auto* module = child<antlr4::tree::TerminalNode>(ctx, 0);
  auto* port = child<antlr4::tree::TerminalNode>(ctx, 2);
  p.module = tx(module);
  p.port = tx(port);
  p.loc = loc(ctx);
  p.module_loc = loc(module);
  p.port_loc = loc(port);
  return p;
}

void Builder::add_decl(Spec& spec, ArbcParser::DeclContext* ctx) {
  reported_depth_ = false;
  if (auto* c = ctx->appDecl()) {
    add_app(spec, c);
  } else if (auto* c = ctx->useDecl()) {
    spec.uses.push_back(use_decl(c));
  } else if (auto* c = ctx->typeDecl()) {
    spec.types.push_back(type_decl(c));
  } else if (auto* c = ctx->constDecl()) {
    spec.consts.push_back(const_decl(c));
  } else if (auto* c = ctx->moduleDecl()) {
    spec.modules.push_back(module_decl(c));
  } else if (auto* c = ctx->eventDecl()) {
    spec.events.push_back(event_decl(c));
  } else if (auto* c = ctx->derivedEventDecl()) {
    spec.derived_events.push_back(derived_event_decl(c));
  } else if (auto* c = ctx->lockEventDecl()) {
    spec.locks.push_back(lock_event_decl(c));
  } else if (auto* c = ctx->statusEventsDecl()) {
    spec.status_events.push_back(status_events_decl(c));
  } else if (auto* c = ctx->exclusiveDecl()) {
    spec.exclusives.push_back(exclusive_decl(c));
  } else if (auto* c = ctx->invariantDecl()) {
    spec.invariants.push_back(invariant_decl(c));
  } else if (auto* c = ctx->arbitrateDecl()) {
    spec.arbitrations.push_back(arbitrate_decl(c));
  } else if (auto* c = ctx->connectDecl()) {
    spec.connects.push_back(connect_decl(c));
  } else if (auto* c = ctx->assertDecl()) {
    spec.asserts.push_back(assert_decl(c));
  } else if (auto* c = ctx->neverDecl()) {
    spec.temporal.push_back(never_decl(c));
  } else if (auto* c = ctx->onlyAfterDecl()) {
    spec.temporal.push_back(only_after_decl(c));
  } else if (auto* c = ctx->assumeDecl()) {
    spec.assumptions.push_back(assume_decl(c));
  } else if (auto* c = ctx->responseDecl()) {
    spec.temporal.push_back(response_decl(c));
  } else if (auto* c = ctx->stableDecl()) {
    spec.temporal.push_back(stable_decl(c));
  } else if (auto* c = ctx->givenDecl()) {
    spec.rates.push_back({port_ref(c->portRef()), duration(c->duration()), loc(c->getStart())});
  } else if (auto* c = ctx->resourceDecl()) {
    spec.resources.push_back(resource_decl(c));
  } else if (auto* c = ctx->testDecl()) {
    spec.tests.push_back(test_decl(c));
  } else if (auto* c = ctx->testsForDecl()) {
    add_tests_for(spec, c);
  }
}

// appDecl : 'app' ID STRING? ';' ;   at most one per spec
void Builder::add_app(Spec& spec, ArbcParser::AppDeclContext* c) {
  AppDecl app;
  app.name = tx(c->ID());
  if (c->STRING()) app.doc = decode_string(c->STRING());
  app.loc = loc(c->ID());
  if (spec.app) {
    error(app.loc,
          "the app is already declared as '" + spec.app->name + "' at line " +
              std::to_string(spec.app->loc.line) + ": a spec describes one app",
          diag::Duplicate);
    return;
  }
  spec.app = std::move(app);
}

// useDecl : 'use' ID msgName ';' ;   msgName : ID '/' ID ('/' ID)? ;
UseDecl Builder::use_decl(ArbcParser::UseDeclContext* c) {
  UseDecl u;
  u.system = tx(c->ID());
  u.system_loc = loc(c->ID());
  auto* name = c->msgName();
  u.loc = loc(name);
  std::vector<antlr4::tree::TerminalNode*> parts = name->ID();
  for (antlr4::tree::TerminalNode* part : parts)
    u.written += (u.written.empty() ? "" : "/") + tx(part);
  u.package = tx(parts.front());
  u.name = tx(parts.back());
  u.name_loc = loc(parts.back());
  return u;
}

// typeDecl : 'type' ID '=' typeExpr ';' ;
TypeDecl Builder::type_decl(ArbcParser::TypeDeclContext* c) {
  TypeDecl t;
  t.name = tx(c->ID());
  t.loc = loc(c->ID());
  t.type = type_expr(c->typeExpr());
  return t;
}

// constDecl : 'const' ID '=' expr ';' ;
ConstDecl Builder::const_decl(ArbcParser::ConstDeclContext* c) {
  ConstDecl k;
  k.name = tx(c->ID());
  k.loc = loc(c->ID());
  k.value = expr(c->expr(), 0);
  return k;
}

// moduleDecl : 'module' ID STRING? '{' portDecl* '}' ;
ModuleDecl Builder::module_decl(ArbcParser::ModuleDeclContext* c) {
  ModuleDecl m;
  m.name = tx(c->ID());
  m.loc = loc(c->ID());
  if (c->STRING()) m.doc = decode_string(c->STRING());
  for (ArbcParser::PortDeclContext* p : c->portDecl()) {
    PortDecl port;
    port.name = tx(p->ID());
    port.loc = loc(p->ID());
    port.direction = tx(p->direction) == "in" ? model::Direction::In : model::Direction::Out;
    port.type = type_expr(p->typeExpr());
    m.ports.push_back(std::move(port));
  }
  return m;
}

// eventDecl : 'event' ID (',' ID)* ('lifetime' duration)? ';' ;
EventDecl Builder::event_decl(ArbcParser::EventDeclContext* c) {
  EventDecl e;
  e.loc = loc(c);
  for (antlr4::tree::TerminalNode* id : c->ID()) e.names.push_back({tx(id), loc(id)});
  e.lifetime = optional_duration(c->duration());
  return e;
}

// resourceDecl : 'resource' ID '{' portRef (',' portRef)* ','? '}' ('when' expr)? ';' ;
ResourceDecl Builder::resource_decl(ArbcParser::ResourceDeclContext* c) {
  ResourceDecl r;
  r.name = tx(c->ID());
  r.loc = loc(c->ID());
  for (ArbcParser::PortRefContext* p : c->portRef()) r.ports.push_back(port_ref(p));
  if (c->expr()) r.uses = expr(c->expr(), 0);
  return r;
}

// derivedEventDecl : 'event' ID '=' portRef ':' expr ('for' duration)? failOpen? ';' ;
DerivedEventDecl Builder::derived_event_decl(ArbcParser::DerivedEventDeclContext* c) {
  DerivedEventDecl e;
  e.name = tx(c->ID());
  e.loc = loc(c->ID());
  e.source = port_ref(c->portRef());
  e.predicate = expr(c->expr(), 0);
  e.lifetime = optional_duration(c->duration());
  e.fail_open = fail_open(c->failOpen());
  return e;
}

// lockEventDecl : 'event' ID '=' ID portRef (':' expr)? (ID duration)? failOpen? ';' ;
// The second ID is the word `lock`, the third `timeout`.
LockDecl Builder::lock_event_decl(ArbcParser::LockEventDeclContext* c) {
  LockDecl l;
  l.name = tx(c->ID(0));
  l.loc = loc(c->ID(0));
  if (tx(c->ID(1)) != "lock")
    error(loc(c->ID(1)),
          "`event " + l.name + " = " + tx(c->ID(1)) +
              " ...`: after `=` comes a port (`event e = M.p : PREDICATE;`) or `lock` and a port "
              "(`event e = lock M.p;`, a lock: docs/language.md#locks)",
          diag::Lock);
  l.source = port_ref(c->portRef());
  if (c->expr()) l.predicate = expr(c->expr(), 0);
  if (c->ID().size() > 2) {
    if (tx(c->ID(2)) != "timeout")
      error(loc(c->ID(2)),
            "`" + tx(c->ID(2)) + "`: a lock's time is `timeout D` (engaged after D of silence), " +
                "or `otherwise open after D` (silence opens it)",
            diag::Lock);
    l.timeout = optional_duration(c->duration());
  }
  l.open_after = fail_open(c->failOpen());
  return l;
}

// failOpen : 'otherwise' ID 'after' duration ;
std::optional<FailOpen> Builder::fail_open(ArbcParser::FailOpenContext* c) {
  if (!c) return std::nullopt;
  return FailOpen{tx(c->ID()), loc(c->ID()), *optional_duration(c->duration())};
}

// statusEventsDecl : 'events' 'from' portRef '{' statusEntry (',' statusEntry)* '}'
//                    ('lifetime' duration)? failOpen? ';' ;
StatusEventDecl Builder::status_events_decl(ArbcParser::StatusEventsDeclContext* c) {
  StatusEventDecl e;
  e.loc = loc(c);
  e.source = port_ref(c->portRef());
  for (ArbcParser::StatusEntryContext* entry : c->statusEntry()) {
    StatusEventDecl::Entry x;
    x.event = tx(entry->ID());
    x.flag = entry->STRING() ? decode_string(entry->STRING()) : x.event;
    x.loc = loc(entry);
    e.entries.push_back(std::move(x));
  }
  e.lifetime = optional_duration(c->duration());
  e.fail_open = fail_open(c->failOpen());
  return e;
}

// exclusiveDecl : 'exclusive' '{' ID (',' ID)* '}' ';' ;
ExclusiveDecl Builder::exclusive_decl(ArbcParser::ExclusiveDeclContext* c) {
  ExclusiveDecl x;
  x.loc = loc(c);
  for (antlr4::tree::TerminalNode* id : c->ID()) x.events.push_back({tx(id), loc(id)});
  return x;
}

// invariantDecl : 'invariant' expr ';' ;
InvariantDecl Builder::invariant_decl(ArbcParser::InvariantDeclContext* c) {
  InvariantDecl inv;
  inv.loc = loc(c);
  inv.formula = expr(c->expr(), 0);
  return inv;
}

// arbitrateDecl : 'arbitrate' portRef ('by' 'priority')? 'complete'? '{' ruleDecl* '}' ;
ArbitrateDecl Builder::arbitrate_decl(ArbcParser::ArbitrateDeclContext* c) {
  ArbitrateDecl a;
  a.loc = loc(c->getStart());
  a.port = port_ref(c->portRef());
  a.by_priority = c->byPriority != nullptr;
  a.complete = c->isComplete != nullptr;
  std::vector<ArbcParser::RuleDeclContext*> rules = c->ruleDecl();
  a.rules.reserve(rules.size());  // a Rule is ~400 bytes: growing by doubling touches twice that
  for (ArbcParser::RuleDeclContext* r : rules) a.rules.push_back(rule(r));
  return a;
}

// connectDecl : 'connect' portRef '->' portRef (block | ';') ;
ConnectDecl Builder::connect_decl(ArbcParser::ConnectDeclContext* c) {
  ConnectDecl k;
  k.loc = loc(c->getStart());
  k.source = port_ref(c->portRef(0));
  k.destination = port_ref(c->portRef(1));
  if (c->block()) {
    k.has_body = true;
    k.body = block(c->block(), 0);
  }
  return k;
}

// assertDecl : 'assert' portRef ':' ID '->' expr ';' ;
AssertDecl Builder::assert_decl(ArbcParser::AssertDeclContext* c) {
  AssertDecl a;
  a.loc = loc(c->getStart());
  a.port = port_ref(c->portRef());
  a.rule = tx(c->ID());
  a.rule_loc = loc(c->ID());
  a.property = expr(c->expr(), 0);
  return a;
}

// neverDecl : 'never' ('two' ID 'within' duration
//                       | ID ('within' duration 'after' ID | 'while' ID)) ';' ;
TemporalDecl Builder::never_decl(ArbcParser::NeverDeclContext* c) {
  TemporalDecl n;
  n.loc = loc(c->getStart());
  n.rule = tx(c->ID(0));
  n.rule_loc = loc(c->ID(0));
  if (c->duration()) {
    n.kind = TemporalDecl::Kind::Spacing;
    n.window = duration(c->duration());
    if (c->ID().size() > 1) {  // `never RULE within D after OTHER;`
      n.other = tx(c->ID(1));
      n.other_loc = loc(c->ID(1));
    }
  } else {
    n.kind = TemporalDecl::Kind::Absence;
    n.event = tx(c->ID(1));
    n.event_loc = loc(c->ID(1));
  }
  return n;
}

// onlyAfterDecl : 'only' ID 'after' ID ';' ;
TemporalDecl Builder::only_after_decl(ArbcParser::OnlyAfterDeclContext* c) {
  TemporalDecl n;
  n.kind = TemporalDecl::Kind::Precedence;
  n.loc = loc(c->getStart());
  n.rule = tx(c->ID(0));
  n.rule_loc = loc(c->ID(0));
  n.other = tx(c->ID(1));
  n.other_loc = loc(c->ID(1));
  return n;
}

// assumeDecl : 'assume' (ID 'only' 'after' ID ('until' ID)?
//                        | 'not' ID 'for' duration 'after' ID) ';' ;
AssumeDecl Builder::assume_decl(ArbcParser::AssumeDeclContext* c) {
  AssumeDecl a;
  a.loc = loc(c->getStart());
  a.event = tx(c->ID(0));
  a.event_loc = loc(c->ID(0));
  a.after = tx(c->ID(1));
  a.after_loc = loc(c->ID(1));
  if (c->duration()) a.absent_for = duration(c->duration());
  if (c->ID().size() > 2) {
    a.until = tx(c->ID(2));
    a.until_loc = loc(c->ID(2));
  }
  return a;
}

// responseDecl : 'after' ID 'stops'? ',' (ID | portRef) 'within' duration ('while' expr)? ';' ;
// The trigger is a rule or an event: sema tells which (TemporalDecl::other).
TemporalDecl Builder::response_decl(ArbcParser::ResponseDeclContext* c) {
  TemporalDecl n;
  n.kind = TemporalDecl::Kind::Response;
  n.loc = loc(c->getStart());
  n.other = tx(c->ID(0));
  n.other_loc = loc(c->ID(0));
  n.stops = c->stops != nullptr;
  if (c->served) {
    n.port = port_ref(c->served);
  } else {
    n.rule = tx(c->ID(1));
    n.rule_loc = loc(c->ID(1));
  }
  n.window = duration(c->duration());
  if (c->expr()) n.condition = expr(c->expr(), 0);
  return n;
}

// stableDecl : 'stable' portRef 'for' duration ';' ;
TemporalDecl Builder::stable_decl(ArbcParser::StableDeclContext* c) {
  TemporalDecl n;
  n.kind = TemporalDecl::Kind::Stability;
  n.loc = loc(c->getStart());
  n.port = port_ref(c->portRef());
  n.window = duration(c->duration());
  return n;
}

// testsForDecl : 'tests' 'for' STRING ';' ;   at most one per file
void Builder::add_tests_for(Spec& spec, ArbcParser::TestsForDeclContext* c) {
  TestsFor f{decode_string(c->STRING()), loc(c->STRING())};
  if (spec.tests_for) {
    error(f.loc,
          "this file already names the app it tests (\"" + spec.tests_for->path + "\" at line " +
              std::to_string(spec.tests_for->loc.line) +
              "); a tests file tests one app: keep one `tests for`",
          diag::Duplicate);
    return;
  }
  spec.tests_for = std::move(f);
}

// testDecl : 'test' STRING ('on' ID)? '{' testStep* '}' ;
TestDecl Builder::test_decl(ArbcParser::TestDeclContext* c) {
  TestDecl t;
  t.name = decode_string(c->STRING());
  t.loc = loc(c->STRING());
  if (c->ID()) {
    t.on = tx(c->ID());
    t.on_loc = loc(c->ID());
  }
  for (ArbcParser::TestStepContext* step : c->testStep()) add_test_step(t, step);
  return t;
}

// testStep : 'at' duration portRef '<-' expr ';' | 'at' duration ('set'|'unset') ID ';'
//          | 'expect' ... ;   (the expectations of ast::TestExpect)
void Builder::add_test_step(TestDecl& t, ArbcParser::TestStepContext* step) {
  if (auto* c = as<ArbcParser::TestInputContext>(step)) {
    TestStep s;
    s.loc = loc(c);
    s.at = duration(c->duration());
    s.port = port_ref(c->portRef());
    s.value = expr(c->expr(), 0);
    t.steps.push_back(std::move(s));
  } else if (auto* c = as<ArbcParser::TestEventContext>(step)) {
    TestStep s;
    s.kind = tx(c->op) == "set" ? TestStep::Kind::Set : TestStep::Kind::Unset;
    s.loc = loc(c);
    s.at = duration(c->duration());
    s.event = tx(c->ID());
    s.event_loc = loc(c->ID());
    t.steps.push_back(std::move(s));
  } else {
    t.expects.push_back(test_expect(step));
  }
}

TestExpect Builder::test_expect(ArbcParser::TestStepContext* step) {
  TestExpect e;
  e.loc = loc(step);
  e.text = spaced_text(step);
  ArbcParser::TestWindowContext* window = nullptr;
  if (auto* c = as<ArbcParser::ExpectReceivesContext>(step)) {
    e.kind = c->nothing ? TestExpect::Kind::Nothing : TestExpect::Kind::Receives;
    e.port = port_ref(c->portRef());
    if (c->expr()) e.value = expr(c->expr(), 0);
    window = c->testWindow();
  } else if (auto* c = as<ArbcParser::ExpectDropsContext>(step)) {
    e.kind = TestExpect::Kind::Drops;
    e.rule = tx(c->ID());
    e.rule_loc = loc(c->ID());
    if (c->STRING()) {
      e.reason = decode_string(c->STRING());
      e.reason_loc = loc(c->STRING());
    }
    window = c->testWindow();
  } else if (auto* c = as<ArbcParser::ExpectDeliversContext>(step)) {
    e.kind = c->nothing ? TestExpect::Kind::DeliversNothing : TestExpect::Kind::Delivers;
    e.rule = tx(c->ID());
    e.rule_loc = loc(c->ID());
    window = c->testWindow();
  } else if (auto* c = as<ArbcParser::ExpectPropertyContext>(step)) {
    e.kind = TestExpect::Kind::Property;
    if (c->neverDecl()) e.property = std::make_shared<TemporalDecl>(never_decl(c->neverDecl()));
    if (c->onlyAfterDecl())
      e.property = std::make_shared<TemporalDecl>(only_after_decl(c->onlyAfterDecl()));
    if (c->responseDecl())
      e.property = std::make_shared<TemporalDecl>(response_decl(c->responseDecl()));
    if (c->stableDecl()) e.property = std::make_shared<TemporalDecl>(stable_decl(c->stableDecl()));
  } else if (auto* c = as<ArbcParser::ExpectExclusiveContext>(step)) {
    e.kind = TestExpect::Kind::Exclusive;
    e.port = port_ref(c->portRef());
  } else if (auto* c = as<ArbcParser::ExpectAssertContext>(step)) {
    e.kind = TestExpect::Kind::Assert;
    e.assertion = std::make_shared<AssertDecl>(assert_decl(c->assertDecl()));
  } else if (auto* c = as<ArbcParser::ExpectResourceContext>(step)) {
    e.kind = TestExpect::Kind::Resource;
    e.rule = tx(c->ID());
    e.rule_loc = loc(c->ID());
  } else if (auto* c = as<ArbcParser::ExpectStateContext>(step)) {
    e.kind = TestExpect::Kind::State;
    e.value = expr(c->expr(), 0);
    if (c->portRef()) e.port = port_ref(c->portRef());
    window = c->testWindow();
  }
  if (window) {
    e.window.present = true;
    e.window.loc = loc(window);
    e.window.from = duration(window->duration(0));
    if (window->duration().size() > 1) e.window.to = duration(window->duration(1));
  }
  return e;
}

// The text of an expectation as written, minus `expect` and `;`, tokens joined by single
// spaces except around `.`, `,`, brackets and `..`: for a test's failure message.
std::string Builder::spaced_text(antlr4::ParserRuleContext* ctx) {
  std::vector<antlr4::Token*> tokens;
  collect_tokens(ctx, tokens);
  std::string out;
  std::string previous;
  for (size_t i = 1; i + 1 < tokens.size(); ++i) {
    std::string text = tx(tokens[i]);
    bool glue = previous == "." || previous == "(" || previous == "[" || previous == ".." ||
                text == "." || text == "," || text == ")" || text == "]" || text == ".." ||
                text == ":" ||
                (text == "(" && !previous.empty() &&
                 std::isalnum(static_cast<unsigned char>(previous.back())));
    if (!out.empty() && !glue) out += ' ';
    out += text;
    previous = text;
  }
  return out;
}

void Builder::collect_tokens(antlr4::tree::ParseTree* node, std::vector<antlr4::Token*>& out) {
  if (auto* leaf = dynamic_cast<antlr4::tree::TerminalNode*>(node)) {
    out.push_back(leaf->getSymbol());
    return;
  }
  for (antlr4::tree::ParseTree* child : node->children) collect_tokens(child, out);
}

// ruleDecl : ID ':' 'from' portRef ('when' expr)? ('hold' duration)? onDelivery? (block | ';') ;
// The optional parts are found in one pass over the children, not by the generated accessors,
// each of which dynamic_casts every child: a spec's rules are most of its declarations.
Rule Builder::rule(ArbcParser::RuleDeclContext* c) {
  Rule r;
  auto* name = child<antlr4::tree::TerminalNode>(c, 0);
  r.name = tx(name);
  r.loc = loc(name);
  r.source = port_ref(child<ArbcParser::PortRefContext>(c, 3));
  for (size_t i = 4; i < c->children.size(); ++i) {
    auto* part = dynamic_cast<antlr4::ParserRuleContext*>(c->children[i]);
    if (!part) continue;  // 'when', 'hold', ';'
    switch (part->getRuleIndex()) {
      case ArbcParser::RuleExpr:
        r.when = expr(static_cast<ArbcParser::ExprContext*>(part), 0);
        break;
      case ArbcParser::RuleDuration:
        r.hold = duration(static_cast<ArbcParser::DurationContext*>(part));
        break;
      case ArbcParser::RuleOnDelivery:
        r.on_delivery = on_delivery(static_cast<ArbcParser::OnDeliveryContext*>(part));
        break;
      case ArbcParser::RuleBlock:
        r.has_body = true;
        r.body = block(static_cast<ArbcParser::BlockContext*>(part), 0);
        break;
      default:
        break;
    }
  }
  return r;
}

// onDelivery : 'then' deliveryEffect (',' deliveryEffect)* ;
// deliveryEffect : op=('set' | 'unset') ID ;
std::vector<DeliveryEffect> Builder::on_delivery(ArbcParser::OnDeliveryContext* c) {
  std::vector<DeliveryEffect> out;
  for (ArbcParser::DeliveryEffectContext* e : c->deliveryEffect()) {
    if (!e->ID() || !e->op) continue;  // a syntax error, reported by the parser
    out.push_back({e->op->getText() == "set", tx(e->ID()), loc(e->ID())});
  }
  return out;
}

}  // namespace arbc::frontend
