// Rename of events and rules across the file. Other symbols are refused: a module or port
// name is also the name a running module registers, a type or const rename is rare enough to
// do by hand, and locals are left to the editor.
#include <cctype>

#include "compiler/frontend/grammar_info.h"
#include "lsp/features.h"
#include "lsp/lookup.h"

namespace arbc::lsp {

namespace {

bool renamable(const Symbol* s) {
  return s && (s->kind == SymbolKind::Event || s->kind == SymbolKind::Rule);
}

bool is_identifier(const std::string& name) {
  if (name.empty() || !(std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_'))
    return false;
  for (unsigned char c : name)
    if (!std::isalnum(c) && c != '_') return false;
  for (const std::string& k : frontend::grammar_keywords())
    if (k == name) return false;
  return true;
}

// Whether the index is of the text the client has: edits from an older text would land on the
// wrong characters.
bool index_is_current(const Document& doc) {
  return doc.analysis && doc.analysis->index && doc.analysis->index_text == doc.text;
}

}  // namespace

nlohmann::json prepare_rename(const Document& doc, Position p) {
  Lookup l = look_up(doc, p);
  if (!renamable(l.symbol) || !index_is_current(doc) || in_app_spec(doc, l.symbol->def))
    return nullptr;
  return {{"range", index_range(doc, l.occurrence->loc)}, {"placeholder", l.symbol->name}};
}

std::optional<nlohmann::json> rename(const Document& doc, Position p, const std::string& name,
                                     std::string* err) {
  Lookup l = look_up(doc, p);
  if (!index_is_current(doc)) {
    *err = "the text does not parse now: fix the syntax error first, then rename";
    return std::nullopt;
  }
  if (!renamable(l.symbol)) {
    *err = "only events and rules can be renamed";
    return std::nullopt;
  }
  if (in_app_spec(doc, l.symbol->def)) {
    *err = "'" + l.symbol->name + "' is declared in " + l.symbol->def.file +
           ": rename it there (its tests files are not renamed with it)";
    return std::nullopt;
  }
  if (!is_identifier(name)) {
    *err = "'" + name + "' is not a name (letters, digits and '_', not a keyword)";
    return std::nullopt;
  }
  std::string prefix = l.symbol->kind == SymbolKind::Event ? "event:" : "rule:";
  if (name != l.symbol->name && l.index->find(prefix + name)) {
    *err = "there is already " + std::string(symbol_kind_name(l.symbol->kind)) + " '" + name + "'";
    return std::nullopt;
  }
  nlohmann::json edits = nlohmann::json::array();
  for (const Occurrence* o : l.index->occurrences_of(l.occurrence->symbol)) {
    // `events from M.p { e }`: the module still sends flag "e".
    std::string text = o->implicit_flag ? name + " = \"" + l.symbol->name + "\"" : name;
    edits.push_back({{"range", index_range(doc, o->loc)}, {"newText", text}});
  }
  return nlohmann::json{{"changes", {{doc.uri, edits}}}};
}

}  // namespace arbc::lsp
