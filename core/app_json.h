// app.json: the core model on disk (schema in docs/app-json.md and docs/app.schema.json).
// Writing is deterministic: the same model gives the same bytes.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "core/app_model.h"
#include "core/diagnostic.h"

namespace arbc::model {

std::string to_app_json(const App& app);

// The model in `text`; nullopt and *err on failure, saying where ("connections[3].source", or
// the line and column of a JSON syntax error) and what is wrong.
std::optional<App> from_app_json(std::string_view text, std::string* err);

// The same for `text`, the contents of `file`, with the error as a diagnostic (id "app-json")
// at its place in the file, to render with the line quoted: a syntax error at the offending
// character, a repeated key at the second one, a bad value at the value, a missing one at the
// object that lacks it. Its message names the value's path as *err above does.
std::optional<App> from_app_json(std::string_view text, const std::string& file, Diagnostic* error);

}  // namespace arbc::model
