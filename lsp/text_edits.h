// Incremental document sync (TextDocumentSyncKind.Incremental): applying the client's
// `contentChanges` to the text we hold, in O(size of the text) per change without parsing.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace arbc::lsp {

// Applies one change: with a "range", replaces it; without, replaces the whole text. False
// (and `err`) when the change is malformed; the text is then unchanged.
bool apply_change(std::string& text, const nlohmann::json& change, std::string* err);

}  // namespace arbc::lsp
