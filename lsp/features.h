// The language features, one file each, each a pure function of a document snapshot (its
// text and latest analysis) and the request's parameters, returning the LSP result.
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "lsp/document_store.h"
#include "lsp/positions.h"

namespace arbc::lsp {

nlohmann::json hover(const Document& doc, Position p);       // hover.cc
nlohmann::json definition(const Document& doc, Position p);  // navigation.cc
nlohmann::json references(const Document& doc, Position p, bool with_declaration);
nlohmann::json highlights(const Document& doc, Position p);
// rename.cc. prepare_rename: null where there is no name, nullopt and `err` (why) for a name
// that cannot be renamed. rename: the edits in `doc` and in `tests_files` (the tests files of
// the app `doc` is, analysed); nullopt and `err` when the symbol cannot be renamed or the new
// name is not an identifier or already taken; `warning`: what is left to rename outside the
// spec (a module's plugin), else untouched.
std::optional<nlohmann::json> prepare_rename(const Document& doc, Position p, std::string* err);
std::optional<nlohmann::json> rename(const Document& doc, Position p, const std::string& name,
                                     const std::vector<Document>& tests_files, std::string* err,
                                     std::string* warning);
nlohmann::json document_symbols(const Document& doc);        // document_symbols.cc
nlohmann::json completion(const Document& doc, Position p);  // completion.cc
nlohmann::json code_actions(const Document& doc, const nlohmann::json& range);  // code_actions.cc

}  // namespace arbc::lsp
