// arbc diagnostics as LSP Diagnostic objects: the same message and id (`code`) as
// `arbc check` / `arbc verify`, notes as relatedInformation, and the fix a "did you mean"
// note suggests (for code actions).
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>

#include "core/diagnostic.h"

namespace arbc::lsp {

// `text` is the document's text (positions are converted against it); `uri` names it. Notes
// in other files point there; notes without a location point at the diagnostic itself.
nlohmann::json diagnostic_json(const Diagnostic& d, std::string_view text, const std::string& uri);

// The replacement a "did you mean 'X'?" note offers for the diagnostic's range, if any.
std::optional<std::string> suggested_fix(const Diagnostic& d);

}  // namespace arbc::lsp
