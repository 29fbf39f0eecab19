// Hover: what a name is, in Markdown. Events tell where their value comes from (a module's
// status flag, a derived predicate, or the rules that set it); rules their effective guard
// (docs/design.md#effective-guards) and their port's decision table, as `arbc docs` prints it;
// a builtin function its signature (core/builtins.h).
#include <sstream>

#include "compiler/docs/decision_table.h"
#include "compiler/docs/markdown_docs.h"
#include "compiler/frontend/type_rules.h"
#include "core/builtins.h"
#include "core/duration_literal.h"
#include "core/effective_guard.h"
#include "core/join.h"
#include "lsp/features.h"
#include "lsp/lookup.h"

namespace arbc::lsp {

namespace {

std::string type_text(const SymbolIndex& ix, const TypePtr& t) {
  if (!t) return "?";
  auto it = ix.type_names.find(t.get());
  if (it != ix.type_names.end()) return it->second + " = " + t->to_string();
  return frontend::type_name(t);
}

std::string code(const std::string& s) { return "`" + s + "`"; }

std::string names(const std::vector<std::string>& v) {
  std::vector<std::string> quoted;
  for (const std::string& s : v) quoted.push_back(code(s));
  return join(quoted);
}

// The lowered model, and a note when it is older than the text (the spec has errors now).
const model::App* lowered_app(const Document& doc, std::ostringstream& out) {
  if (!doc.analysis || !doc.analysis->lowered) return nullptr;
  if (!doc.analysis->lowered_current) out << "\n*(from the last version without errors)*\n";
  return &doc.analysis->lowered->app;
}

void port_table(const model::App& app, const std::string& port, std::ostringstream& out) {
  const model::ArbitratedPort* p = app.find_arbitrated(port);
  if (!p) return;
  out << "\n\n**Decision table of " << code(port) << "**"
      << (p->by_priority ? " (by priority)" : "") << "\n\n";
  docs::DecisionTable table = docs::decision_table(app, *p);
  // A hover is read in a small window: past 16 states, only those that select a rule (arbc docs
  // prints them all).
  size_t all = table.rows.size();
  if (all > 16)
    std::erase_if(table.rows, [](const docs::DecisionRow& r) { return r.selected.empty(); });
  docs::decision_table_markdown(table, out);
  if (table.rows.size() < all)
    out << "\n" << all - table.rows.size() << " of the " << all << " states select no rule.\n";
}

void describe_event(const Document& doc, const SymbolIndex& ix, const Symbol& s,
                    std::ostringstream& out) {
  out << "**event** " << code(s.name);
  if (const ast::EventSymbol* e = s.event) {
    if (e->kind == ast::EventSymbol::Kind::Status)
      out << "\n\nfed by the status flag " << code("\"" + e->flag + "\"") << " of "
          << code(e->source);
    else if (e->kind == ast::EventSymbol::Kind::Derived)
      out << "\n\nderived from " << code(e->source);
    else
      out << "\n\nset by monitor code";
    if (e->lifetime) out << "; lifetime " << duration_literal(*e->lifetime);
  }
  auto list = [&](const char* what, const std::map<std::string, std::vector<std::string>>& m) {
    auto it = m.find(s.name);
    if (it != m.end()) out << "\n\n" << what << ": " << names(it->second);
  };
  list("set by", ix.set_by);
  list("unset by", ix.unset_by);
  std::vector<std::string> used;
  if (doc.analysis && doc.analysis->spec)
    for (const ast::ArbitrateDecl& a : doc.analysis->spec->arbitrations)
      for (const ast::Rule& r : a.rules) {
        std::set<std::string> events;
        r.constraint.collect_events(events);
        if (events.count(s.name)) used.push_back(r.name);
      }
  if (!used.empty()) out << "\n\nin the `when` of: " << names(used);
}

void describe_rule(const Document& doc, const Symbol& s, std::ostringstream& out) {
  const ast::Rule* r = s.rule;
  out << "**rule** " << code(s.name) << " into " << code(s.container);
  if (!r) return;
  out << " from " << code(r->source.qualified());
  // As written: with errors in the text, sema's constraint tree may be incomplete.
  out << "\n\nwhen: " << code(r->when ? source_text(doc, r->when->loc) : "true");
  if (r->hold) out << "; hold " << duration_literal(r->hold->nanos);
  const model::App* app = lowered_app(doc, out);
  if (!app) return;
  for (const model::Connection& c : app->connections)
    if (c.name == s.name && c.destination == s.container)
      out << "\n\neffective guard: "
          << code(model::effective_guard(*app, s.container, c).to_string());
  port_table(*app, s.container, out);
}

void describe_port(const Document& doc, const SymbolIndex& ix, const Symbol& s,
                   std::ostringstream& out) {
  const ast::PortDecl* p = s.module ? s.module->find_port(s.name) : nullptr;
  bool in = p && p->direction == model::Direction::In;
  out << "**" << (in ? "in" : "out") << " port** " << code(s.container + "." + s.name) << ": "
      << code(type_text(ix, s.type));
  if (!in) return;
  std::ostringstream tail;
  const model::App* app = lowered_app(doc, tail);
  if (app && app->find_arbitrated(s.container + "." + s.name)) {
    out << tail.str();
    port_table(*app, s.container + "." + s.name, out);
  }
}

void describe(const Document& doc, const SymbolIndex& ix, const Symbol& s,
              std::ostringstream& out) {
  switch (s.kind) {
    case SymbolKind::Event:
      describe_event(doc, ix, s, out);
      break;
    case SymbolKind::Rule:
      describe_rule(doc, s, out);
      break;
    case SymbolKind::Port:
      describe_port(doc, ix, s, out);
      break;
    case SymbolKind::Module:
      out << "**module** " << code(s.name);
      if (s.module && !s.module->doc.empty()) out << "\n\n" << s.module->doc;
      if (s.module)
        for (const ast::PortDecl& p : s.module->ports)
          out << "\n- " << (p.direction == model::Direction::In ? "in " : "out ") << code(p.name)
              << ": " << code(type_text(ix, p.type.resolved));
      break;
    case SymbolKind::Type:
      out << "**type** " << code(type_text(ix, s.type));
      if (s.type_decl && !s.type_decl->ros2.empty())  // declared by `use ros2`: from where
        out << "\n\nROS 2 message " << code(s.type_decl->ros2) << ", "
            << (s.type_decl->msg_file.empty() ? "arbc's built-in definition"
                                              : "read from " + code(s.type_decl->msg_file));
      break;
    case SymbolKind::Const:
      out << "**const** " << code(s.name) << ": " << code(type_text(ix, s.type));
      if (s.constant && s.constant->value)
        out << " = " << code(source_text(doc, s.constant->value->loc));
      break;
    case SymbolKind::Local:
      out << code(s.name) << ": " << code(type_text(ix, s.type));
      break;
    case SymbolKind::App:
      out << "**app** " << code(s.name);
      if (doc.analysis && doc.analysis->spec && doc.analysis->spec->app)
        out << "\n\n" << doc.analysis->spec->app->doc;
      break;
  }
}

// The builtin whose name (in a call) is under the cursor; null otherwise.
const BuiltinInfo* builtin_under(const ast::Expr* e, const Lookup& l) {
  if (!e || e->kind != ast::Expr::Kind::Call || e->names.empty()) return nullptr;
  if (!contains(e->names[0].loc, l.line, l.column)) return nullptr;
  return find_builtin(e->text);
}

}  // namespace

nlohmann::json hover(const Document& doc, Position p) {
  Lookup l = look_up(doc, p);
  if (!l.index) return nullptr;
  std::ostringstream out;
  Loc at;
  const ast::Expr* e = l.index->expression_at(l.line, l.column);
  if (l.symbol) {
    describe(doc, *l.index, *l.symbol, out);
    at = l.occurrence->loc;
    // A name bound in a body: the expression's type is the precise one.
    if (l.symbol->kind == SymbolKind::Local && e && e->type) {
      out.str("");
      out << code(l.symbol->name) << ": " << code(type_text(*l.index, e->type));
    }
  } else if (const BuiltinInfo* b = builtin_under(e, l)) {
    out << "**builtin** " << code(std::string(b->signature)) << "\n\n" << b->summary;
    at = e->names[0].loc;
  } else if (e && e->type) {
    out << code(source_text(doc, e->loc)) << ": " << code(type_text(*l.index, e->type));
    at = e->loc;
  } else {
    return nullptr;
  }
  return {{"contents", {{"kind", "markdown"}, {"value", out.str()}}},
          {"range", index_range(doc, at)}};
}

}  // namespace arbc::lsp
