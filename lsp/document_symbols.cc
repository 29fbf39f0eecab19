// The outline (textDocument/documentSymbol): declarations in file order, ports under their
// module and rules under their port, from the last text that parsed.
#include <algorithm>

#include "lsp/features.h"
#include "lsp/lookup.h"

namespace arbc::lsp {

namespace {

// LSP SymbolKind numbers.
namespace symbol_kind {
enum : int {
  kModule = 2,
  kNamespace = 3,
  kPackage = 4,
  kMethod = 6,
  kProperty = 7,
  kFunction = 12,
  kConstant = 14,
  kBoolean = 17,
  kOperator = 25,
  kStruct = 23,
  kEvent = 24
};
}  // namespace symbol_kind

// The smallest location covering both.
Loc span(Loc a, const Loc& b) {
  if (b.line <= 0) return a;
  int a_end_line = a.end_line > 0 ? a.end_line : a.line;
  int b_end_line = b.end_line > 0 ? b.end_line : b.line;
  if (b_end_line > a_end_line || (b_end_line == a_end_line && b.end_column > a.end_column)) {
    a.end_line = b_end_line;
    a.end_column = b.end_column;
  }
  return a;
}

// Null for a declaration in another file (a tests file's app spec).
nlohmann::json item(const Document& doc, const std::string& name, int kind, const Loc& range,
                    const Loc& selection, const std::string& detail = "") {
  if (in_app_spec(doc, selection)) return nullptr;
  nlohmann::json j = {{"name", name.empty() ? "?" : name},
                      {"kind", kind},
                      {"range", index_range(doc, span(range, selection))},
                      {"selectionRange", index_range(doc, selection)}};
  if (!detail.empty()) j["detail"] = detail;
  return j;
}

// A test from its name to its last step or expectation.
Loc test_span(const ast::TestDecl& t) {
  Loc whole = t.loc;
  for (const ast::TestStep& s : t.steps) whole = span(whole, s.loc);
  for (const ast::TestExpect& x : t.expects) whole = span(whole, x.loc);
  return whole;
}

void add_modules(const Document& doc, const ast::Spec& spec, nlohmann::json& out) {
  for (const ast::ModuleDecl& m : spec.modules) {
    Loc name = name_loc(m.loc, m.name);
    nlohmann::json children = nlohmann::json::array();
    Loc whole = name;
    for (const ast::PortDecl& p : m.ports) {
      Loc pl = span(name_loc(p.loc, p.name), p.type.loc);
      whole = span(whole, pl);
      children.push_back(item(doc, p.name, symbol_kind::kProperty, pl, name_loc(p.loc, p.name),
                              p.direction == model::Direction::In ? "in" : "out"));
    }
    nlohmann::json j = item(doc, m.name, symbol_kind::kModule, whole, name, m.doc);
    if (j.is_null()) continue;
    j["children"] = children;
    out.push_back(j);
  }
}

void add_arbitrations(const Document& doc, const ast::Spec& spec, nlohmann::json& out) {
  for (const ast::ArbitrateDecl& a : spec.arbitrations) {
    nlohmann::json children = nlohmann::json::array();
    Loc whole = span(a.loc, a.port.loc);
    for (const ast::Rule& r : a.rules) {
      Loc rl = span(name_loc(r.loc, r.name), r.source.loc);
      if (r.when) rl = span(rl, r.when->loc);
      whole = span(whole, rl);
      children.push_back(item(doc, r.name, symbol_kind::kFunction, rl, name_loc(r.loc, r.name),
                              "from " + r.source.qualified()));
    }
    nlohmann::json j = item(doc, "arbitrate " + a.port.qualified(), symbol_kind::kNamespace, whole,
                            a.port.loc, a.by_priority ? "by priority" : "");
    if (j.is_null()) continue;
    j["children"] = children;
    out.push_back(j);
  }
}

}  // namespace

nlohmann::json document_symbols(const Document& doc) {
  nlohmann::json out = nlohmann::json::array();
  if (!doc.analysis || !doc.analysis->spec) return out;
  const ast::Spec& spec = *doc.analysis->spec;
  if (spec.app)
    out.push_back(item(doc, spec.app->name, symbol_kind::kPackage, spec.app->loc,
                       name_loc(spec.app->loc, spec.app->name), "app"));
  for (const ast::TypeDecl& t : spec.types)
    out.push_back(
        item(doc, t.name, symbol_kind::kStruct, span(t.loc, t.type.loc), name_loc(t.loc, t.name)));
  for (const ast::ConstDecl& c : spec.consts)
    out.push_back(item(doc, c.name, symbol_kind::kConstant, c.loc, name_loc(c.loc, c.name)));
  add_modules(doc, spec, out);
  for (const ast::EventSymbol& e : spec.event_symbols)
    out.push_back(item(doc, e.name, symbol_kind::kEvent, e.loc, name_loc(e.loc, e.name), e.source));
  add_arbitrations(doc, spec, out);
  for (const ast::ConnectDecl& c : spec.connects)
    out.push_back(item(doc, "connect " + c.source.qualified() + " -> " + c.destination.qualified(),
                       symbol_kind::kOperator, span(c.loc, c.destination.loc), c.source.loc));
  for (const ast::AssertDecl& a : spec.asserts)
    out.push_back(item(doc, "assert " + a.port.qualified() + ": " + a.rule, symbol_kind::kBoolean,
                       a.property ? span(a.loc, a.property->loc) : a.loc, a.port.loc));
  for (const ast::TestDecl& t : spec.tests)
    out.push_back(item(doc, "test \"" + t.name + "\"", symbol_kind::kMethod, test_span(t), t.loc,
                       t.on.empty() ? "" : "on " + t.on));
  out.erase(std::remove(out.begin(), out.end(), nullptr), out.end());
  return out;
}

}  // namespace arbc::lsp
