// Go to definition, find references and document highlights: the occurrences of the symbol
// under the cursor (symbol_index.h).
#include "lsp/features.h"
#include "lsp/lookup.h"

namespace arbc::lsp {

nlohmann::json definition(const Document& doc, Position p) {
  Lookup l = look_up(doc, p);
  if (!l.symbol || l.symbol->def.line <= 0) return nullptr;
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
