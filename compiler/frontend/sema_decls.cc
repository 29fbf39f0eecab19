// Semantic analysis of declarations: duplicates, types, constants, modules and ports, events,
// arbitrated ports and their rules, connects and assertions (docs/language.md#declarations).
#include <set>

#include "compiler/frontend/field_mismatch.h"
#include "compiler/frontend/lapsing_permission.h"
#include "compiler/frontend/sema.h"
#include "compiler/frontend/sema_context.h"
#include "compiler/frontend/stray_field.h"
#include "compiler/frontend/type_rules.h"
#include "core/join.h"
#include "core/suggest.h"

namespace arbc::frontend {

using namespace ast;

namespace {

TypePtr port_type(const PortRef& ref) {
  return ref.port_decl ? ref.port_decl->type.resolved : nullptr;
}

}  // namespace

// ---- the passes ---------------------------------------------------------------------------

void Sema::run() {
  check_app_declared();
  declare_types();
  declare_consts();
  declare_modules();
  declare_events();
  check_derived_predicates();
  check_domain();
  for (ArbitrateDecl& a : spec_.arbitrations) check_arbitration(a);
  for (ConnectDecl& c : spec_.connects) check_connect(c);
  check_delivery_effects();  // sema_delivery.cc
  for (AssertDecl& a : spec_.asserts) check_assert(a);
  for (TemporalDecl& n : spec_.temporal) check_temporal(n);
  for (AssumeDecl& a : spec_.assumptions) check_assume(a);
  check_rates();  // sema_rates.cc
  check_resources();
  check_tests();  // sema_test.cc
}

void Sema::check_app_declared() {
  if (spec_.app) return;
  Loc start;
  start.file = spec_.file;
  start.line = 1;
  start.column = 1;
  error(start, "the spec has no app declaration: start it with `app NAME \"what it does\";`",
        diag::MissingApp);
}

// ---- types, constants, modules --------------------------------------------------------------

void Sema::declare_types() {
  for (TypeDecl& t : spec_.types) {
    if (types_.count(t.name) || t.name == "bool" || Type::number(t.name) || t.name == "string" ||
        t.name == "vec3" || t.name == "list") {
      if (types_.count(t.name)) {
        error(t.loc,
              "type '" + t.name + "' is already defined at " + where_defined(types_[t.name]->loc) +
                  kRenameOne,
              diag::Duplicate);
      } else {
        error(t.loc, "'" + t.name + "' is a built-in type and cannot be redefined",
              diag::Duplicate);
      }
      continue;
    }
    types_[t.name] = &t;
  }
  for (TypeDecl& t : spec_.types) resolve_type_decl(t);
}

void Sema::declare_consts() {
  const_state_.assign(spec_.consts.size(), 0);
  for (size_t i = 0; i < spec_.consts.size(); ++i) {
    ConstDecl& c = spec_.consts[i];
    if (consts_.count(c.name)) {
      error(c.loc,
            "constant '" + c.name + "' is already defined at " +
                where_defined(spec_.consts[consts_[c.name]].loc) + kRenameOne,
            diag::Duplicate);
      const_state_[i] = 2;
      continue;
    }
    consts_[c.name] = i;
  }
  for (size_t i = 0; i < spec_.consts.size(); ++i) check_const(i);
}

void Sema::declare_modules() {
  for (ModuleDecl& m : spec_.modules) {
    if (modules_.count(m.name)) {
      error(m.loc,
            "module '" + m.name + "' is already defined at " +
                where_defined(modules_[m.name]->loc) + kRenameOne,
            diag::Duplicate);
    } else {
      modules_[m.name] = &m;
    }
    std::map<std::string, const PortDecl*> ports;
    for (PortDecl& p : m.ports) {
      if (ports.count(p.name)) {
        error(p.loc,
              "module '" + m.name + "' already has a port '" + p.name + "' (" +
                  where_defined(ports[p.name]->loc) + ")" + kRenameOne,
              diag::Duplicate);
      }
      ports[p.name] = &p;
      resolve_type(p.type);
    }
  }
}

// ---- events -------------------------------------------------------------------------------

void Sema::declare_events() {
  for (EventDecl& e : spec_.events) declare_manual_events(e);
  for (StatusEventDecl& e : spec_.status_events) declare_status_events(e);
  for (DerivedEventDecl& e : spec_.derived_events) {
    EventSymbol s;
    s.kind = EventSymbol::Kind::Derived;
    s.name = e.name;
    s.loc = e.loc;
    s.source = e.source.qualified();
    if (e.lifetime) {
      check_duration(*e.lifetime, "the `for` lifetime");
      s.lifetime = e.lifetime->nanos;
    }
    s.fail_open_after = fail_open_after(e.fail_open);
    add_event(std::move(s));
  }
}

void Sema::add_event(EventSymbol symbol) {
  auto it = events_.find(symbol.name);
  if (it != events_.end()) {
    error(symbol.loc,
          "event '" + symbol.name + "' is already declared at " +
              where_defined(spec_.event_symbols[it->second].loc) + kRenameOne,
          diag::Duplicate);
    return;
  }
  events_[symbol.name] = spec_.event_symbols.size();
  event_names_.push_back(symbol.name);
  spec_.event_symbols.push_back(std::move(symbol));
}

void Sema::declare_manual_events(EventDecl& e) {
  if (e.lifetime) check_duration(*e.lifetime, "the event lifetime");
  for (const EventName& n : e.names) {
    EventSymbol s;
    s.kind = EventSymbol::Kind::Manual;
    s.name = n.name;
    s.loc = n.loc;
    if (e.lifetime) s.lifetime = e.lifetime->nanos;
    add_event(std::move(s));
  }
}

// `otherwise absent after D`: the word must be `absent`, D a duration a run can wait.
std::optional<Nanos> Sema::fail_open_after(std::optional<FailOpen>& f) {
  if (!f) return std::nullopt;
  if (f->word != "absent") {
    error(f->word_loc,
          "`otherwise " + f->word +
              " after ...`: a feed that has not spoken can only count as "
              "absent; write `otherwise absent after D`",
          diag::FailOpen);
    return std::nullopt;
  }
  check_duration(f->after, "the time a feed may stay silent");
  return f->after.nanos;
}

void Sema::declare_status_events(StatusEventDecl& e) {
  if (resolve_port(e.source, "source", "`events from`")) {
    TypePtr t = port_type(e.source);
    if (t &&
        !(t->kind == Type::Kind::List && t->element && t->element->kind == Type::Kind::String)) {
      error(e.source.loc,
            "`events from` reads status flags, so " + e.source.qualified() +
                " must carry list<string>, not " + describe(t),
            diag::StatusSourceType);
    }
  }
  if (e.lifetime) check_duration(*e.lifetime, "the event lifetime");
  std::map<std::string, Loc> flags;
  for (const StatusEventDecl::Entry& entry : e.entries) {
    if (flags.count(entry.flag)) {
      error(entry.loc,
            "flag \"" + entry.flag + "\" is already mapped to an event at " +
                where_defined(flags[entry.flag]),
            diag::Duplicate);
    }
    flags[entry.flag] = entry.loc;
    EventSymbol s;
    s.kind = EventSymbol::Kind::Status;
    s.name = entry.event;
    s.loc = entry.loc;
    s.source = e.source.qualified();
    s.flag = entry.flag;
    if (e.lifetime) s.lifetime = e.lifetime->nanos;
    s.fail_open_after = fail_open_after(e.fail_open);
    add_event(std::move(s));
  }
}

// A derived event reads an `out` port's messages, or what an arbitrated `in` port delivers (a
// delivery event, docs/language.md#delivery-events).
bool Sema::resolve_derived_source(DerivedEventDecl& e) {
  if (!resolve_port(e.source, "", "a derived event")) return false;
  if (e.source.port_decl->direction == model::Direction::Out) return true;
  std::string q = e.source.qualified();
  for (const ArbitrateDecl& a : spec_.arbitrations)
    if (a.port.qualified() == q) return true;
  error(e.source.loc,
        q +
            " is an `in` port that is not arbitrated; a derived event reads an `out` port's "
            "messages, or what an arbitrated `in` port delivers (`arbitrate " +
            q + " { ... }`)",
        diag::PortDirection);
  return false;
}

void Sema::check_derived_predicates() {
  for (DerivedEventDecl& e : spec_.derived_events) {
    Scope scope;
    bind_message(scope, e.source, resolve_derived_source(e));
    check_condition(*e.predicate, scope, "the predicate of derived event '" + e.name + "'",
                    diag::PredicateType);
  }
}

void Sema::check_domain() {
  for (ExclusiveDecl& x : spec_.exclusives) {
    std::set<std::string> seen;
    for (const EventName& n : x.events) {
      if (!events_.count(n.name)) {
        unknown_event(n.loc, n.name, false);
      } else if (!seen.insert(n.name).second) {
        error(n.loc, "event '" + n.name + "' is listed twice", diag::Duplicate);
      }
    }
  }
  for (InvariantDecl& inv : spec_.invariants)
    inv.constraint = check_constraint(*inv.formula, "an invariant", false);
}

// ---- arbitrated ports and their rules ---------------------------------------------------------

void Sema::check_arbitration(ArbitrateDecl& a) {
  bool resolved = resolve_port(a.port, "destination", "`arbitrate`");
  std::string port = a.port.qualified();
  if (arbitrated_.count(port)) {
    error(a.port.loc,
          port + " is already arbitrated at " + where_defined(arbitrated_[port]->loc) +
              ": put all its rules in one `arbitrate` block",
          diag::Duplicate);
  } else {
    arbitrated_[port] = &a;
  }
  TypePtr destination = resolved ? port_type(a.port) : nullptr;
  std::map<std::string, const Rule*> names;
  const Rule* otherwise_rule = nullptr;
  for (size_t i = 0; i < a.rules.size(); ++i) {
    Rule& r = a.rules[i];
    r.port = &a;
    r.message_name = r.source.port;
    if (names.count(r.name)) {
      error(r.loc,
            "port " + port + " already has a rule '" + r.name + "' (" +
                where_defined(names[r.name]->loc) + ")" + kRenameOne,
            diag::Duplicate);
    }
    names[r.name] = &r;
    bool source_ok = resolve_port(r.source, "source", "rule '" + r.name + "'");
    check_rule_when(r, port, otherwise_rule);
    check_rule_hold(a, i);
    MonitorSite site{&r.body, &r.source, source_ok, destination, port, r.loc};
    check_monitor(site, "rule '" + r.name + "'", "rule '" + r.name + "'");
  }
}

void Sema::check_rule_when(Rule& r, const std::string& port, const Rule*& otherwise_rule) {
  if (!r.when) {
    r.constraint = Constraint::constant(true);
    return;
  }
  if (r.when->kind != Expr::Kind::Otherwise) {
    r.constraint = check_constraint(*r.when, "the constraint of rule '" + r.name + "'", false);
    return;
  }
  r.otherwise = true;
  r.constraint = Constraint::constant(false);
  if (otherwise_rule) {
    error(r.when->loc,
          "port " + port + " already has an `otherwise` rule ('" + otherwise_rule->name + "', " +
              where_defined(otherwise_rule->loc) + "); at most one per port",
          diag::Otherwise);
  }
  otherwise_rule = &r;
}

void Sema::check_rule_hold(ArbitrateDecl& a, size_t i) {
  Rule& r = a.rules[i];
  const std::string port = a.port.qualified();
  bool lowest = i + 1 == a.rules.size();
  if (r.hold) {
    check_duration(*r.hold, "the `hold` time");
    if (!a.by_priority) {
      error(
          r.hold->expr->loc,
          "`hold` applies only to rules of a `by priority` port; " + port + " is not `by priority`",
          diag::HoldWithoutPriority);
    } else if (lowest) {
      error(r.hold->expr->loc,
            "rule '" + r.name + "' is the lowest priority of " + port +
                ": nothing below it to suppress, so it takes no `hold`",
            diag::HoldOnLowest);
    }
  } else if (a.by_priority && !lowest) {
    error(r.loc,
          "rule '" + r.name + "' outranks later rules of " + port +
              ": say how long it suppresses them with `hold D` (e.g. hold 1s)",
          diag::HoldMissing);
  }
}

void Sema::check_monitor(const MonitorSite& site, const std::string& owner,
                         const std::string& subject) {
  Scope scope;
  bind_message(scope, *site.source, site.source_ok);
  TypePtr message_type = site.source_ok ? port_type(*site.source) : nullptr;
  BodyContext ctx;
  ctx.owner = owner;
  ctx.destination_type = site.destination_type;
  ctx.destination = site.destination;
  Block& body = *site.body;
  check_body(body, scope, ctx);
  bool script = body.size() == 1 && body[0]->kind == Stmt::Kind::Script;
  if (!script && !definitely_emits(body) && message_type && site.destination_type &&
      !assignable(*message_type, *site.destination_type)) {
    error(site.loc,
          subject + " delivers its input unchanged" +
              (body.empty() ? "" : " on a path without `emit`") + ": " + site.source->qualified() +
              " carries " + describe(message_type) + " but " + site.destination + " takes " +
              describe(site.destination_type) + " (add `emit VALUE;`)",
          diag::EmitType);
  }
}

// ---- plain connections and assertions -------------------------------------------------------

void Sema::check_connect(ConnectDecl& c) {
  bool source_ok = resolve_port(c.source, "source", "`connect`");
  bool destination_ok = resolve_port(c.destination, "destination", "`connect`");
  c.message_name = c.source.port;
  std::string port = c.destination.qualified();
  if (destination_ok) {
    if (arbitrated_.count(port)) {
      error(c.destination.loc,
            port + " is arbitrated (" + where_defined(arbitrated_[port]->loc) +
                "): add a rule to its `arbitrate` block instead of a `connect`",
            diag::ConnectIntoArbitrated);
    } else if (fed_.count(port)) {
      error(c.destination.loc,
            port + " already has a source (the connect at " + where_defined(fed_[port]->loc) +
                "): two sources into one port must be arbitrated with `arbitrate " + port +
                " { ... }`",
            diag::FanIn);
    } else {
      fed_[port] = &c;
    }
  }
  TypePtr destination = destination_ok ? port_type(c.destination) : nullptr;
  MonitorSite site{&c.body, &c.source, source_ok, destination, port, c.loc};
  check_monitor(site, "the connect into " + port, "this connect");
}

void Sema::check_assert(AssertDecl& a) {
  if (resolve_port(a.port, "", "`assert`")) {
    auto it = arbitrated_.find(a.port.qualified());
    if (it == arbitrated_.end()) {
      error(a.port.loc,
            a.port.qualified() +
                " has no `arbitrate` block: assertions are about the rules "
                "of an arbitrated port",
            diag::NotArbitrated);
    } else {
      std::vector<std::string> names;
      for (const Rule& r : it->second->rules) {
        names.push_back(r.name);
        if (r.name == a.rule) a.rule_decl = &r;
      }
      if (!a.rule_decl) {
        unknown(a.rule_loc, "port " + a.port.qualified() + " has no rule '" + a.rule + "'",
                diag::UnknownRule, a.rule, names);
      }
    }
  }
  if (mentions_name(*a.property, "emitted")) {
    a.over_data = true;
    check_data_assert(a);  // sema_resource.cc
    return;
  }
  a.constraint = check_constraint(*a.property, "an assertion", false);
}

void check_spec(Spec& spec, std::vector<Diagnostic>& out, const std::string& script_dir) {
  Sema sema(spec, out, script_dir);
  sema.run();
  check_activity_names(spec, out);
  warn_lapsing_permissions(spec, out);
}

}  // namespace arbc::frontend
