// Finding what is under the cursor, shared by the features. Locations in the index refer to
// Analysis::index_text (the last text that parsed); results are converted against it.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "lsp/document_store.h"
#include "lsp/positions.h"
#include "lsp/symbol_index.h"

namespace arbc::lsp {

struct Lookup {
  const SymbolIndex* index = nullptr;  // null: nothing parsed yet
  const Occurrence* occurrence = nullptr;
  const Symbol* symbol = nullptr;
  int line = 0, column = 0;  // the cursor, 1-based code points
};

Lookup look_up(const Document& doc, Position p);

// Whether `loc` is in the app's spec of a tests file (`tests for`), not in the document.
bool in_app_spec(const Document& doc, const Loc& loc);

// {"uri", "range"} of a location in the indexed text (or in a tests file's app spec).
nlohmann::json location_json(const Document& doc, const Loc& loc);
nlohmann::json index_range(const Document& doc, const Loc& loc);

// The source text a location covers (in the indexed text), for quoting in hovers.
std::string source_text(const Document& doc, const Loc& loc);

}  // namespace arbc::lsp
