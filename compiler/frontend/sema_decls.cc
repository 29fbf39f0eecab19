// Semantic analysis of declarations: duplicates, types, constants, modules and ports, events,
// arbitrated ports and their rules, connects and assertions (docs/language.md#declarations).
#include <set>

#include "compiler/frontend/field_mismatch.h"
#include "compiler/frontend/sema.h"
#include "compiler/frontend/sema_context.h"
#include "compiler/frontend/stray_field.h"
#include "compiler/frontend/type_rules.h"
#include "core/join.h"
#include "core/suggest.h"

namespace arbc::frontend {

// What to do about a name declared twice (the two may mean different things, so not "delete").
const char* const kRenameOne = ": rename one of them";

using namespace ast;

// ---- reporting ----------------------------------------------------------------------------

namespace {

bool same_place(const Loc& a, const Loc& b) {
  return a.file == b.file && a.line == b.line && a.column == b.column;
}

}  // namespace

Diagnostic& Sema::error(const Loc& loc, std::string message, std::string id) {
  Diagnostic d;
  d.loc = loc;
  d.message = std::move(message);
  d.id = std::move(id);
  out_.push_back(std::move(d));
  return out_.back();
}

Diagnostic& Sema::unknown(const Loc& loc, std::string message, std::string id,
                          const std::string& name, const std::vector<std::string>& candidates) {
  Diagnostic& d = error(loc, std::move(message), std::move(id));
  if (auto best = closest_name(name, candidates)) did_you_mean(d, *best);
  return d;
}

Diagnostic& Sema::unknown_event(const Loc& loc, const std::string& name, bool set_by_code) {
  Diagnostic& d = unknown(loc, "unknown event '" + name + "'", "unknown-event", name, event_names_);
  if (!d.notes.empty()) return d;  // "did you mean": most likely a misspelling
  Diagnostic note;
  note.severity = Severity::Note;
  note.message =
      set_by_code ? "declare it: `event " + name + ";` (monitor code sets the events declared so)"
                  : "declare it: `event " + name +
                        ";` for monitor code to set, a status flag in "
                        "`events from Module.port { " +
                        name + " } lifetime D;`, or a derived event `event " + name +
                        " = Module.port : PREDICATE;`";
  d.notes.push_back(std::move(note));
  return d;
}

void Sema::did_you_mean(Diagnostic& d, const std::string& meant) {
  Diagnostic note;
  note.severity = Severity::Note;
  note.message = "did you mean '" + meant + "'?";
  d.notes.push_back(std::move(note));
}

Diagnostic& Sema::value_type_error(const Expr& value, const TypePtr& want, std::string message,
                                   std::string id) {
  if (auto stray = stray_field(value, want)) {
    const std::string& name = stray->name->name;
    message += "; " + describe(stray->record) + " has no field '" + name + "'";
    if (!stray->via)
      return unknown(stray->name->loc, std::move(message), std::move(id), name, stray->missing);
    // A literal bound by a `let` may be used on several paths (`if ... { emit c; } else
    // { emit c; }`): one error at its field, with a note at each use.
    Diagnostic note;
    note.severity = Severity::Note;
    note.loc = stray->via->loc;
    note.message =
        "'" + stray->via->text + "' has the type of that record literal; it is used here";
    for (Diagnostic& d : out_) {
      if (d.id == id && d.message == message && same_place(d.loc, stray->name->loc)) {
        d.notes.push_back(std::move(note));
        return d;
      }
    }
    Diagnostic& d =
        unknown(stray->name->loc, std::move(message), std::move(id), name, stray->missing);
    d.notes.push_back(std::move(note));
    return d;
  }
  if (auto field = field_mismatch(value, want)) {
    if (!field->value) {
      return error(
          field->literal->loc,
          message + "; field '" + field->field + "' (" + describe(field->want) + ") is missing",
          std::move(id));
    }
    return error(field->value->loc,
                 message + "; field '" + field->field + "' is " + describe(field->value->type) +
                     " where " + describe(field->want) + " is expected",
                 std::move(id));
  }
  return error(value.loc, std::move(message), std::move(id));
}

std::string Sema::describe(const TypePtr& t) const {
  if (t) {
    auto it = type_names_.find(t.get());
    if (it != type_names_.end()) return it->second;
  }
  return type_name(t);
}

namespace {

std::string where_defined(const Loc& loc) { return "line " + std::to_string(loc.line); }

const TypePtr& scalar_type(TypeExpr::Kind kind) {
  static const TypePtr kTypes[] = {Type::scalar(Type::Kind::Bool), Type::scalar(Type::Kind::Int),
                                   Type::scalar(Type::Kind::Float),
                                   Type::scalar(Type::Kind::String),
                                   Type::scalar(Type::Kind::Vec3)};
  return kTypes[static_cast<int>(kind)];
}

}  // namespace

// ---- types --------------------------------------------------------------------------------

TypePtr Sema::resolve_type(TypeExpr& t) {
  switch (t.kind) {
    case TypeExpr::Kind::Bool:
    case TypeExpr::Kind::Int:
    case TypeExpr::Kind::Float:
    case TypeExpr::Kind::String:
    case TypeExpr::Kind::Vec3:
      t.resolved = scalar_type(t.kind);
      break;
    case TypeExpr::Kind::List: {
      TypePtr element = resolve_type(*t.element);
      if (element) t.resolved = Type::list(element);
      break;
    }
    case TypeExpr::Kind::Record: {
      std::vector<Field> fields;
      bool ok = true;
      for (size_t i = 0; i < t.fields.size(); ++i) {
        for (size_t j = 0; j < i; ++j)
          if (t.fields[j].first == t.fields[i].first)
            error(t.field_locs[i],
                  "field '" + t.fields[i].first + "' is declared twice" + kRenameOne, "duplicate");
        TypePtr f = resolve_type(*t.fields[i].second);
        if (!f) ok = false;
        fields.push_back({t.fields[i].first, f});
      }
      if (ok) t.resolved = Type::record(std::move(fields));
      break;
    }
    case TypeExpr::Kind::Named:
      t.resolved = resolve_named_type(t);
      break;
  }
  return t.resolved;
}

TypePtr Sema::resolve_type_decl(TypeDecl& decl) {
  if (types_done_.count(&decl)) return decl.type.resolved;
  if (types_active_.count(&decl)) {
    // A message is a finite value that the proof and the Lua monitors copy whole: no type
    // may contain itself, not even through a list.
    error(decl.loc,
          "type '" + decl.name +
              "' is defined in terms of itself: a type cannot contain itself, even through a "
              "list or another type; give the inner value a type of its own",
          "type-cycle");
    types_done_.insert(&decl);
    return nullptr;
  }
  types_active_.insert(&decl);
  TypePtr t = resolve_type(decl.type);
  types_active_.erase(&decl);
  types_done_.insert(&decl);
  // A named record or list keeps its name in messages ("Cmd", not its fields). Only types
  // this declaration creates: an alias (`type A = B;`, `type A = vec3;`) shares B's object.
  bool creates = decl.type.kind == TypeExpr::Kind::Record || decl.type.kind == TypeExpr::Kind::List;
  bool registered = types_.count(decl.name) && types_.at(decl.name) == &decl;
  if (t && creates && registered && !type_names_.count(t.get())) type_names_[t.get()] = decl.name;
  return t;
}

TypePtr Sema::resolve_named_type(TypeExpr& t) {
  auto it = types_.find(t.name);
  if (it == types_.end()) {
    std::vector<std::string> names = {"bool", "int", "float", "string", "vec3", "list"};
    for (auto& [name, decl] : types_) names.push_back(name);
    unknown(t.loc,
            "unknown type '" + t.name +
                "': the types are bool, int, float, string, vec3, list<T>, records and "
                "declared type names",
            "unknown-type", t.name, names);
    return nullptr;
  }
  return resolve_type_decl(*it->second);
}

// ---- port references ----------------------------------------------------------------------

bool Sema::resolve_port(PortRef& ref, const char* role, const std::string& use) {
  auto found = modules_.find(ref.module);
  ref.module_decl = found == modules_.end() ? nullptr : found->second;
  if (!ref.module_decl) {
    std::vector<std::string> names;
    for (const ModuleDecl& m : spec_.modules) names.push_back(m.name);
    // At the module's name alone: an editor's quick fix replaces exactly what is underlined.
    Diagnostic& d = unknown(ref.module_loc, "unknown module '" + ref.module + "'", "unknown-module",
                            ref.module, names);
    if (d.notes.empty()) {  // no close name: what there is, and how to add it
      Diagnostic note;
      note.severity = Severity::Note;
      note.message = "declare it: `module " + ref.module + " { in|out PORT: TYPE; ... }`";
      if (!names.empty() && names.size() <= 10)
        note.message += "; the modules declared are " + join(names, ", ", " and ");
      d.notes.push_back(std::move(note));
    }
    return false;
  }
  ref.port_decl = ref.module_decl->find_port(ref.port);
  if (!ref.port_decl) {
    std::vector<std::string> names, listed;
    for (const PortDecl& p : ref.module_decl->ports) {
      names.push_back(p.name);
      listed.push_back("'" + p.name + "' (" + (p.direction == model::Direction::In ? "in" : "out") +
                       ")");
    }
    Diagnostic& d =
        unknown(ref.port_loc, "module '" + ref.module + "' has no port '" + ref.port + "'",
                "unknown-port", ref.port, names);
    if (d.notes.empty() && !listed.empty()) {  // nothing close (`velocity` for `vel`): list them
      Diagnostic note;
      note.severity = Severity::Note;
      note.message = (listed.size() == 1 ? "the only port of " + ref.module + " is "
                                         : "the ports of " + ref.module + " are ") +
                     join(listed, ", ", " and ");
      d.notes.push_back(std::move(note));
    }
    return false;
  }
  std::string role_s = role;
  if (role_s == "source" && ref.port_decl->direction == model::Direction::In) {
    error(ref.loc,
          ref.qualified() + " is an `in` port; " + use +
              " needs a source, which must be an `out` port",
          "port-direction");
  } else if (role_s == "destination" && ref.port_decl->direction == model::Direction::Out) {
    error(ref.loc,
          ref.qualified() + " is an `out` port; " + use +
              " needs a destination, which must be an `in` port",
          "port-direction");
  }
  return true;
}

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
        "missing-app");
}

// ---- types, constants, modules --------------------------------------------------------------

void Sema::declare_types() {
  for (TypeDecl& t : spec_.types) {
    if (types_.count(t.name) || t.name == "bool" || t.name == "int" || t.name == "float" ||
        t.name == "string" || t.name == "vec3" || t.name == "list") {
      if (types_.count(t.name)) {
        error(t.loc,
              "type '" + t.name + "' is already defined at " + where_defined(types_[t.name]->loc) +
                  kRenameOne,
              "duplicate");
      } else {
        error(t.loc, "'" + t.name + "' is a built-in type and cannot be redefined", "duplicate");
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
            "duplicate");
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
            "duplicate");
    } else {
      modules_[m.name] = &m;
    }
    std::map<std::string, const PortDecl*> ports;
    for (PortDecl& p : m.ports) {
      if (ports.count(p.name)) {
        error(p.loc,
              "module '" + m.name + "' already has a port '" + p.name + "' (" +
                  where_defined(ports[p.name]->loc) + ")" + kRenameOne,
              "duplicate");
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
      s.lifetime = e.lifetime->seconds;
    }
    add_event(std::move(s));
  }
}

void Sema::add_event(EventSymbol symbol) {
  auto it = events_.find(symbol.name);
  if (it != events_.end()) {
    error(symbol.loc,
          "event '" + symbol.name + "' is already declared at " +
              where_defined(spec_.event_symbols[it->second].loc) + kRenameOne,
          "duplicate");
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
    if (e.lifetime) s.lifetime = e.lifetime->seconds;
    add_event(std::move(s));
  }
}

void Sema::declare_status_events(StatusEventDecl& e) {
  if (resolve_port(e.source, "source", "`events from`")) {
    TypePtr t = port_type(e.source);
    if (t &&
        !(t->kind == Type::Kind::List && t->element && t->element->kind == Type::Kind::String)) {
      error(e.source.loc,
            "`events from` reads status flags, so " + e.source.qualified() +
                " must carry list<string>, not " + describe(t),
            "status-source-type");
    }
  }
  if (e.lifetime) check_duration(*e.lifetime, "the event lifetime");
  std::map<std::string, Loc> flags;
  for (const StatusEventDecl::Entry& entry : e.entries) {
    if (flags.count(entry.flag)) {
      error(entry.loc,
            "flag \"" + entry.flag + "\" is already mapped to an event at " +
                where_defined(flags[entry.flag]),
            "duplicate");
    }
    flags[entry.flag] = entry.loc;
    EventSymbol s;
    s.kind = EventSymbol::Kind::Status;
    s.name = entry.event;
    s.loc = entry.loc;
    s.source = e.source.qualified();
    s.flag = entry.flag;
    if (e.lifetime) s.lifetime = e.lifetime->seconds;
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
        "port-direction");
  return false;
}

void Sema::check_derived_predicates() {
  for (DerivedEventDecl& e : spec_.derived_events) {
    Scope scope;
    bind_message(scope, e.source, resolve_derived_source(e));
    check_condition(*e.predicate, scope, "the predicate of derived event '" + e.name + "'",
                    "predicate-type");
  }
}

void Sema::check_domain() {
  for (ExclusiveDecl& x : spec_.exclusives) {
    std::set<std::string> seen;
    for (const EventName& n : x.events) {
      if (!events_.count(n.name)) {
        unknown_event(n.loc, n.name, false);
      } else if (!seen.insert(n.name).second) {
        error(n.loc, "event '" + n.name + "' is listed twice", "duplicate");
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
          "duplicate");
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
            "duplicate");
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
          "otherwise");
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
          "hold-without-priority");
    } else if (lowest) {
      error(r.hold->expr->loc,
            "rule '" + r.name + "' is the lowest priority of " + port +
                ": nothing below it to suppress, so it takes no `hold`",
            "hold-on-lowest");
    }
  } else if (a.by_priority && !lowest) {
    error(r.loc,
          "rule '" + r.name + "' outranks later rules of " + port +
              ": say how long it suppresses them with `hold D` (e.g. hold 1s)",
          "hold-missing");
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
          "emit-type");
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
            "connect-into-arbitrated");
    } else if (fed_.count(port)) {
      error(c.destination.loc,
            port + " already has a source (the connect at " + where_defined(fed_[port]->loc) +
                "): two sources into one port must be arbitrated with `arbitrate " + port +
                " { ... }`",
            "fan-in");
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
            "not-arbitrated");
    } else {
      std::vector<std::string> names;
      for (const Rule& r : it->second->rules) {
        names.push_back(r.name);
        if (r.name == a.rule) a.rule_decl = &r;
      }
      if (!a.rule_decl) {
        unknown(a.rule_loc, "port " + a.port.qualified() + " has no rule '" + a.rule + "'",
                "unknown-rule", a.rule, names);
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
}

}  // namespace arbc::frontend
