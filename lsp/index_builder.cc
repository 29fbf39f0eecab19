// build_index (symbol_index.h): one walk over the checked AST. Declarations first, so that
// every use found afterwards has its symbol.
#include <string>

#include "lsp/symbol_index.h"

namespace arbc::lsp {

namespace {

std::string loc_key(const char* prefix, const Loc& l, const std::string& name) {
  return std::string(prefix) + std::to_string(l.line) + ":" + std::to_string(l.column) + ":" + name;
}

// A rule's key: its arbitrated port and its name, since rule names are unique only within a
// port (two `arbitrate` blocks may each have a `track`). `a` is the rule's block; null: the
// block sema resolved for it.
std::string rule_key(const ast::Rule* r, const ast::ArbitrateDecl* a = nullptr) {
  if (!a) a = r->port;
  return "rule:" + (a ? a->port.qualified() : std::string()) + ":" + r->name;
}

class Builder {
 public:
  Builder(const ast::Spec& spec, SymbolIndex& ix) : spec_(spec), ix_(ix) {}

  void run() {
    declare_all();
    for (const ast::TypeDecl& t : spec_.types) type_expr(t.type);
    for (const ast::ConstDecl& c : spec_.consts) expr(c.value.get());
    for (const ast::ModuleDecl& m : spec_.modules)
      for (const ast::PortDecl& p : m.ports) type_expr(p.type);
    event_uses();
    for (const ast::ArbitrateDecl& a : spec_.arbitrations) arbitrate(a);
    for (const ast::ConnectDecl& c : spec_.connects) connect(c);
    for (const ast::AssertDecl& a : spec_.asserts) assertion(a);
    for (const ast::TemporalDecl& n : spec_.temporal) temporal(n);
    for (const ast::AssumeDecl& a : spec_.assumptions) {
      expr(a.absent_for.expr.get());  // `for D`
      if (!a.after_decl) continue;    // reported: its names may not resolve
      ix_.add_occurrence("event:" + a.event, name_loc(a.event_loc, a.event));
      ix_.add_occurrence(rule_key(a.after_decl), name_loc(a.after_loc, a.after));
      if (a.until_decl) ix_.add_occurrence(rule_key(a.until_decl), name_loc(a.until_loc, a.until));
    }
    for (const ast::RateDecl& r : spec_.rates) {
      port_ref(r.port);
      expr(r.period.expr.get());
    }
    for (const ast::ResourceDecl& r : spec_.resources) {
      for (const ast::PortRef& p : r.ports) port_ref(p);
      expr(r.uses.get());
    }
    for (const ast::InvariantDecl& i : spec_.invariants) expr(i.formula.get());
    for (const ast::TestDecl& t : spec_.tests) test(t);
  }

 private:
  void declare(Symbol s, bool implicit_flag = false) {
    Loc at = s.def;
    std::string key = s.key;
    ix_.add_symbol(std::move(s));
    ix_.add_occurrence(key, at, true, implicit_flag);
  }

  void declare_all() {
    if (spec_.app)
      declare({.kind = SymbolKind::App,
               .name = spec_.app->name,
               .key = "app",
               .def = name_loc(spec_.app->loc, spec_.app->name)});
    for (const ast::TypeDecl& t : spec_.types) {
      if (t.type.resolved) ix_.type_names.emplace(t.type.resolved.get(), t.name);
      declare({.kind = SymbolKind::Type,
               .name = t.name,
               .key = "type:" + t.name,
               .def = name_loc(t.loc, t.name),
               .type = t.type.resolved,
               .type_decl = &t});
    }
    for (const ast::ConstDecl& c : spec_.consts)
      declare({.kind = SymbolKind::Const,
               .name = c.name,
               .key = "const:" + c.name,
               .def = name_loc(c.loc, c.name),
               .type = c.value ? c.value->type : nullptr,
               .constant = &c});
    for (const ast::ModuleDecl& m : spec_.modules) declare_module(m);
    declare_events();
    for (const ast::ArbitrateDecl& a : spec_.arbitrations)
      for (const ast::Rule& r : a.rules)
        declare({.kind = SymbolKind::Rule,
                 .name = r.name,
                 .key = rule_key(&r, &a),
                 .def = name_loc(r.loc, r.name),
                 .container = a.port.qualified(),
                 .rule = &r});
  }

  void declare_module(const ast::ModuleDecl& m) {
    declare({.kind = SymbolKind::Module,
             .name = m.name,
             .key = "module:" + m.name,
             .def = name_loc(m.loc, m.name),
             .module = &m});
    for (const ast::PortDecl& p : m.ports)
      declare({.kind = SymbolKind::Port,
               .name = p.name,
               .key = "port:" + m.name + "." + p.name,
               .def = name_loc(p.loc, p.name),
               .container = m.name,
               .type = p.type.resolved,
               .module = &m});
  }

  // Events in declaration order, from sema's table (which knows each one's kind).
  void declare_events() {
    for (const ast::EventSymbol& e : spec_.event_symbols) {
      bool implicit_flag = false;
      if (e.kind == ast::EventSymbol::Kind::Status) {
        // `{ e }` writes only the name; `{ e = "flag" }` is wider than it.
        Loc n = name_loc(e.loc, e.name);
        implicit_flag =
            e.flag == e.name &&
            (e.loc.end_line <= 0 || (e.loc.end_line == n.line && e.loc.end_column <= n.end_column));
      }
      declare({.kind = SymbolKind::Event,
               .name = e.name,
               .key = "event:" + e.name,
               .def = name_loc(e.loc, e.name),
               .event = &e},
              implicit_flag);
    }
  }

  void event_uses() {
    for (const ast::StatusEventDecl& s : spec_.status_events) {
      port_ref(s.source);
      if (s.lifetime) expr(s.lifetime->expr.get());
    }
    for (const ast::EventDecl& e : spec_.events)
      if (e.lifetime) expr(e.lifetime->expr.get());
    for (const ast::DerivedEventDecl& d : spec_.derived_events) {
      port_ref(d.source);
      if (d.lifetime) expr(d.lifetime->expr.get());
      with_message(d.source, d.source.port, [&] { expr(d.predicate.get()); });
    }
    for (const ast::ExclusiveDecl& x : spec_.exclusives)
      for (const ast::EventName& e : x.events)
        ix_.add_occurrence("event:" + e.name, name_loc(e.loc, e.name));
  }

  void arbitrate(const ast::ArbitrateDecl& a) {
    port_ref(a.port);
    for (const ast::Rule& r : a.rules) {
      port_ref(r.source);
      expr(r.when.get());
      if (r.hold) expr(r.hold->expr.get());
      owner_ = r.name;
      owner_key_ = rule_key(&r, &a);
      with_message(r.source, r.message_name, [&] { block(r.body); });
    }
  }

  void connect(const ast::ConnectDecl& c) {
    port_ref(c.source);
    port_ref(c.destination);
    owner_ = "connect " + c.source.qualified() + " -> " + c.destination.qualified();
    owner_key_ = owner_;
    with_message(c.source, c.message_name, [&] { block(c.body); });
  }

  void assertion(const ast::AssertDecl& a) {
    port_ref(a.port);
    if (a.rule_decl) ix_.add_occurrence(rule_key(a.rule_decl), name_loc(a.rule_loc, a.rule));
    expr(a.property.get());
  }

  // A `test`: its rule, ports, events and the names in its values and times. A test's
  // `set` is not a rule's: set_by stays the rules'.
  // A property over time, declared or expected by a test (`expect only put after take;`).
  void temporal(const ast::TemporalDecl& n) {
    if (n.rule_decl) ix_.add_occurrence(rule_key(n.rule_decl), name_loc(n.rule_loc, n.rule));
    if (n.other_decl) ix_.add_occurrence(rule_key(n.other_decl), name_loc(n.other_loc, n.other));
    // An absence's event, a response's trigger event; a port for a stability or a response
    // the port answers.
    if ((n.rule_decl || n.port_decl) && !n.event.empty())
      ix_.add_occurrence("event:" + n.event, name_loc(n.event_loc, n.event));
    expr(n.condition.get());    // a response's `while`
    expr(n.window.expr.get());  // `within D`: D may be a constant
    if (n.port_decl) port_ref(n.port);
  }

  void test(const ast::TestDecl& t) {
    if (t.on_rule) ix_.add_occurrence(rule_key(t.on_rule), name_loc(t.on_loc, t.on));
    for (const ast::TestStep& s : t.steps) {
      expr(s.at.expr.get());
      if (s.kind == ast::TestStep::Kind::Input) {
        port_ref(s.port);
        expr(s.value.get());
      } else {
        ix_.add_occurrence("event:" + s.event, name_loc(s.event_loc, s.event));
      }
    }
    for (const ast::TestExpect& x : t.expects) {
      if (x.rule_decl)  // Drops, Delivers, DeliversNothing
        ix_.add_occurrence(rule_key(x.rule_decl), name_loc(x.rule_loc, x.rule));
      if (x.kind == ast::TestExpect::Kind::Receives || x.kind == ast::TestExpect::Kind::Nothing ||
          x.kind == ast::TestExpect::Kind::Exclusive ||
          (x.kind == ast::TestExpect::Kind::State && !x.port.module.empty()))  // `in M.p`
        port_ref(x.port);
      if (x.property) temporal(*x.property);
      if (x.assertion) assertion(*x.assertion);  // `expect assert M.p: RULE -> EXPR;`
      expr(x.value.get());
      if (x.window.present) {
        expr(x.window.from.expr.get());
        expr(x.window.to.expr.get());
      }
    }
  }

  // Declares the message name a body or predicate sees, at the source port's name.
  template <typename F>
  void with_message(const ast::PortRef& source, const std::string& name, F body) {
    Loc at = source.port_loc;
    message_key_ = loc_key("message:", at, name);
    // No occurrence at the definition: the port's own occurrence is there.
    ix_.add_symbol({.kind = SymbolKind::Local,
                    .name = name.empty() ? source.port : name,
                    .key = message_key_,
                    .def = at,
                    .container = owner_key_,
                    .type = source.port_decl ? source.port_decl->type.resolved : nullptr});
    body();
    message_key_.clear();
  }

  void port_ref(const ast::PortRef& r) {
    if (!r.module_decl) return;
    ix_.add_occurrence("module:" + r.module, r.module_loc);
    if (r.port_decl) ix_.add_occurrence("port:" + r.qualified(), r.port_loc);
  }

  void type_expr(const ast::TypeExpr& t) {
    if (t.kind == ast::TypeExpr::Kind::Named) ix_.add_occurrence("type:" + t.name, t.loc);
    if (t.element) type_expr(*t.element);
    for (const auto& [name, field] : t.fields)
      if (field) type_expr(*field);
  }

  void block(const ast::Block& b) {
    for (const auto& s : b)
      if (s) stmt(*s);
  }

  void stmt(const ast::Stmt& s);
  void expr(const ast::Expr* e);
  void name(const ast::Expr& e);

  const ast::Spec& spec_;
  SymbolIndex& ix_;
  std::string owner_;        // the rule or connection whose body is walked
  std::string owner_key_;    // the same, unique: a rule's key (rule_key), or owner_
  std::string message_key_;  // the symbol the message name resolves to there
};

void Builder::stmt(const ast::Stmt& s) {
  using K = ast::Stmt::Kind;
  expr(s.expr.get());
  if (s.duration) expr(s.duration->expr.get());
  switch (s.kind) {
    case K::Let:
    case K::Var:
      declare({.kind = SymbolKind::Local,
               .name = s.name,
               .key = loc_key("local:", s.name_loc, s.name),
               .def = name_loc(s.name_loc, s.name),
               .container = owner_key_,
               .type = s.expr ? s.expr->type : nullptr,
               .stmt = &s});
      break;
    case K::Assign:
      if (s.var_decl)
        ix_.add_occurrence(loc_key("local:", s.var_decl->name_loc, s.name),
                           name_loc(s.name_loc, s.name));
      break;
    case K::Set:
    case K::Unset:
      ix_.add_occurrence("event:" + s.name, name_loc(s.name_loc, s.name));
      (s.kind == K::Set ? ix_.set_by : ix_.unset_by)[s.name].push_back(owner_);
      break;
    default:
      break;
  }
  block(s.body);
  block(s.else_body);
}

void Builder::expr(const ast::Expr* e) {
  if (!e) return;
  if (e->kind == ast::Expr::Kind::Lambda && !e->names.empty()) {
    const Loc& at = e->names[0].loc;
    declare({.kind = SymbolKind::Local,
             .name = e->text,
             .key = loc_key("param:", at, e->text),
             .def = name_loc(at, e->text),
             .container = owner_key_});
  } else {
    ix_.expressions.push_back(e);
  }
  if (e->kind == ast::Expr::Kind::Name) name(*e);
  for (const ast::ExprPtr& a : e->args) expr(a.get());
}

void Builder::name(const ast::Expr& e) {
  Loc at = name_loc(e.loc, e.text);
  switch (e.name_kind) {
    case ast::NameKind::Message:
      ix_.add_occurrence(message_key_, at);
      break;
    case ast::NameKind::Let:
    case ast::NameKind::Var:
      if (e.local) ix_.add_occurrence(loc_key("local:", e.local->name_loc, e.text), at);
      break;
    case ast::NameKind::Param:
      if (e.lambda && !e.lambda->names.empty())
        ix_.add_occurrence(loc_key("param:", e.lambda->names[0].loc, e.text), at);
      break;
    case ast::NameKind::Const:
      ix_.add_occurrence("const:" + e.text, at);
      break;
    case ast::NameKind::Event:
      ix_.add_occurrence("event:" + e.text, at);
      break;
    case ast::NameKind::Unresolved:
      break;
  }
}

}  // namespace

std::unique_ptr<SymbolIndex> build_index(const ast::Spec& spec, const std::string& file) {
  auto ix = std::make_unique<SymbolIndex>();
  ix->file = file;
  Builder(spec, *ix).run();
  return ix;
}

}  // namespace arbc::lsp
