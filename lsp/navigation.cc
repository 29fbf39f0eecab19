// Go to definition, find references and document highlights: the occurrences of the symbol
// under the cursor (symbol_index.h); a type declared by `use ros2` from a .msg file goes there.
#include <filesystem>

#include "lsp/features.h"
#include "lsp/lookup.h"
#include "lsp/uri.h"

namespace arbc::lsp {

nlohmann::json definition(const Document& doc, Position p) {
  Lookup l = look_up(doc, p);
  if (!l.symbol || l.symbol->def.line <= 0) return nullptr;
  // A type `use ros2` read from a .msg file is defined there: its first line (the `use` is one
  // of its references). One from arbc's built-in definitions has no file: the `use`.
  const ast::TypeDecl* t = l.symbol->kind == SymbolKind::Type ? l.symbol->type_decl : nullptr;
  if (t && !t->msg_file.empty()) {
    std::error_code ec;
    std::string file = std::filesystem::absolute(t->msg_file, ec).lexically_normal().string();
    nlohmann::json start = {{"line", 0}, {"character", 0}};
    return {{"uri", path_to_uri(file)}, {"range", {{"start", start}, {"end", start}}}};
  }
  return location_json(doc, l.symbol->def);
}

nlohmann::json references(const Document& doc, Position p, bool with_declaration) {
  Lookup l = look_up(doc, p);
  nlohmann::json out = nlohmann::json::array();
  if (!l.symbol) return out;
  for (const Occurrence* o : l.index->occurrences_of(l.occurrence->symbol))
    if (with_declaration || !o->definition) out.push_back(location_json(doc, o->loc));
  return out;
}

nlohmann::json highlights(const Document& doc, Position p) {
  Lookup l = look_up(doc, p);
  nlohmann::json out = nlohmann::json::array();
  if (!l.symbol) return out;
  for (const Occurrence* o : l.index->occurrences_of(l.occurrence->symbol))
    out.push_back({{"range", index_range(doc, o->loc)}, {"kind", o->definition ? 3 : 2}});
  return out;
}

}  // namespace arbc::lsp
