// Loads the core model named on a command line (DESIGN.md section 2: the verifier and the code
// generators read the core model, never the AST).
//
//   APP.json, or a directory holding app.json   read with core/app_json.h
//   SPEC (*.spec)                               compiled by load_spec_model()
#pragma once

#include <string>
#include <vector>

#include "core/app_model.h"
#include "core/diagnostic.h"

namespace arbc::cli {

struct ModelLoad {
  bool ok = false;
  model::App app;
  std::string error;        // for the user: "FILE: what is wrong; what to do"
  std::string diagnostics;  // a spec's rendered diagnostics (errors and warnings), for stderr
  bool spec = false;        // the input was a spec
  // When !ok: what is wrong as diagnostics (a spec's own, or one for the file), for the JSON
  // and SARIF reports of a bad input.
  std::vector<Diagnostic> errors;
};

// An error about a whole file (no line): `io` (unreadable), `app-json` (does not load).
Diagnostic file_error(const std::string& file, std::string message, std::string id);

// Reads the model from `path`. Never throws.
ModelLoad load_model(const std::string& path);

// Compiles a spec to its core model with compiler/lower/compile_spec.h when this build has the
// compiler (arbc_compiler); otherwise says that spec support needs it.
ModelLoad load_spec_model(const std::string& path);

}  // namespace arbc::cli
