// app.json: the core model on disk (schema in docs/app-json.md and docs/app.schema.json).
// Writing is deterministic: the same model gives the same bytes.
#pragma once

#include <string>
#include <string_view>

#include "core/app_model.h"

namespace arbc::model {

std::string to_app_json(const App& app);

// Errors are values: on failure `ok` is false and `error` says where ("connections[3].source")
// and what is wrong.
struct AppLoad {
  bool ok = false;
  App app;
  std::string error;
};

AppLoad from_app_json(std::string_view text);

}  // namespace arbc::model
