// Diagnostics about a JSON file the user wrote (a deployment file): at the line and column of
// the key or value they are about, found again from its path (core/json_place.h), so that they
// render as a compiler's do, with the line quoted and the value underlined.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/diagnostic.h"
#include "core/json_parse.h"
#include "core/json_place.h"

namespace arbc {

// An error about the key or value at `path` of `text`, the contents of `file`; at the file
// alone when the path is not in the text.
Diagnostic json_diagnostic(const std::string& file, std::string_view text,
                           const std::vector<std::string>& path, JsonPart part,
                           std::string message);

// An error for text that is not JSON, or repeats a key in one object (core/json_parse.h), at
// the offending character or the second key.
Diagnostic json_syntax_diagnostic(const std::string& file, const JsonParseError& e);

}  // namespace arbc
