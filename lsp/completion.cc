// Completion: after `X.`, the ports of module X or the fields of X's record (or vec3) type;
// elsewhere the language's keywords, its builtin functions (core/builtins.h) and the names in
// scope: declarations, and the locals of the rule being written. Works from the last text that
// parsed, since the text being typed usually does not.
#include <cctype>
#include <set>

#include "compiler/frontend/grammar_info.h"
#include "core/builtins.h"
#include "lsp/features.h"
#include "lsp/lookup.h"

namespace arbc::lsp {

namespace {

// LSP CompletionItemKind numbers.
namespace item_kind {
enum : int {
  kField = 5,
  kVariable = 6,
  kModule = 9,
  kKeyword = 14,
  kFunction = 3,
  kConstant = 21,
  kStruct = 22,
  kEvent = 23
};
}  // namespace item_kind

bool ident_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// The dotted chain ending just before `end` ("a.b" for "x = a.b." with end after the dot):
// empty when the cursor is not after a dot.
std::vector<std::string> chain_before(std::string_view line, size_t end) {
  size_t i = end;
  while (i > 0 && ident_char(line[i - 1])) --i;  // the word being typed
  std::vector<std::string> parts;
  while (i > 0 && line[i - 1] == '.') {
    size_t stop = --i;
    while (i > 0 && ident_char(line[i - 1])) --i;
    if (i == stop) return {};
    parts.insert(parts.begin(), std::string(line.substr(i, stop - i)));
  }
  return parts;
}

int kind_of(SymbolKind k) {
  switch (k) {
    case SymbolKind::Event:
      return item_kind::kEvent;
    case SymbolKind::Const:
      return item_kind::kConstant;
    case SymbolKind::Type:
      return item_kind::kStruct;
    case SymbolKind::Module:
      return item_kind::kModule;
    case SymbolKind::Rule:
      return item_kind::kFunction;
    default:
      return item_kind::kVariable;
  }
}

// The symbol `name` means at `line`: a local of the nearest rule above, else a declaration.
const Symbol* resolve(const SymbolIndex& ix, const std::string& name, int line) {
  const Symbol* best = nullptr;
  for (const Symbol& s : ix.symbols) {
    if (s.name != name || s.kind == SymbolKind::Port || s.kind == SymbolKind::Rule) continue;
    if (s.kind == SymbolKind::Local && s.def.line > line) continue;
    if (!best || (s.kind == SymbolKind::Local && s.def.line >= best->def.line)) best = &s;
  }
  return best;
}

void add_members(const SymbolIndex& ix, const std::vector<std::string>& chain, int line,
                 nlohmann::json& items) {
  if (chain.size() == 1)
    if (const Symbol* m = ix.find("module:" + chain[0])) {
      for (const Symbol& s : ix.symbols)
        if (s.kind == SymbolKind::Port && s.container == m->name)
          items.push_back({{"label", s.name}, {"kind", item_kind::kField}});
      return;
    }
  const Symbol* root = resolve(ix, chain[0], line);
  TypePtr t = root ? root->type : nullptr;
  for (size_t i = 1; t && i < chain.size(); ++i) {
    TypePtr next;
    for (const Field& f : t->fields)
      if (f.name == chain[i]) next = f.type;
    t = next;
  }
  if (t && t->kind == Type::Kind::Vec3)
    for (const char* axis : {"x", "y", "z"})
      items.push_back({{"label", axis}, {"kind", item_kind::kField}, {"detail", "float"}});
  if (t && t->kind == Type::Kind::Record)
    for (const Field& f : t->fields)
      items.push_back({{"label", f.name},
                       {"kind", item_kind::kField},
                       {"detail", f.type ? f.type->to_string() : "?"}});
}

// The rule whose body the cursor is probably in: the last declared above the cursor; its key,
// which its locals name as their container (two ports may each have a rule of that name).
std::string enclosing_rule(const SymbolIndex& ix, int line) {
  const Symbol* best = nullptr;
  for (const Symbol& s : ix.symbols)
    if (s.kind == SymbolKind::Rule && s.def.line <= line && (!best || s.def.line > best->def.line))
      best = &s;
  return best ? best->key : "";
}

void add_names(const SymbolIndex& ix, int line, nlohmann::json& items) {
  std::string rule = enclosing_rule(ix, line);
  std::set<std::string> seen;
  for (const Symbol& s : ix.symbols) {
    if (s.kind == SymbolKind::Port || s.kind == SymbolKind::App) continue;
    if (s.kind == SymbolKind::Local && (s.container != rule || s.def.line > line)) continue;
    if (!seen.insert(s.name).second) continue;
    items.push_back(
        {{"label", s.name}, {"kind", kind_of(s.kind)}, {"detail", symbol_kind_name(s.kind)}});
  }
}

}  // namespace

nlohmann::json completion(const Document& doc, Position p) {
  nlohmann::json items = nlohmann::json::array();
  size_t start = line_start(doc.text, p.line);
  size_t cursor = offset_of(doc.text, p);
  std::string_view line = std::string_view(doc.text).substr(start, cursor - start);
  std::vector<std::string> chain = chain_before(line, line.size());
  const SymbolIndex* ix = doc.analysis && doc.analysis->index ? doc.analysis->index.get() : nullptr;
  if (!chain.empty()) {
    if (ix) add_members(*ix, chain, p.line + 1, items);
    return {{"isIncomplete", false}, {"items", items}};
  }
  for (const std::string& k : frontend::grammar_keywords())
    items.push_back({{"label", k}, {"kind", item_kind::kKeyword}});
  for (const BuiltinInfo& b : kBuiltins)
    items.push_back({{"label", std::string(b.name)},
                     {"kind", item_kind::kFunction},
                     {"detail", std::string(b.signature)},
                     {"documentation", std::string(b.summary)}});
  if (ix) add_names(*ix, p.line + 1, items);
  return {{"isIncomplete", false}, {"items", items}};
}

}  // namespace arbc::lsp
