// Loads the core model named on a command line (docs/design.md#pipeline: the verifier and the code
// generators read the core model, never the AST).
//
//   APP.json, or a directory holding app.json   read with core/app_json.h
//   SPEC (*.spec)                               compiled by load_spec_model()
#pragma once

#include <string>

#include "core/app_model.h"

namespace arbc::cli {

struct ModelLoad {
  bool ok = false;
  model::App app;
  std::string error;        // for the user: "FILE: what is wrong; what to do"
  std::string diagnostics;  // a spec's rendered diagnostics (errors and warnings), for stderr
  bool spec = false;        // the input was a spec
};

// Reads the model from `path`. Never throws.
ModelLoad load_model(const std::string& path);

// Compiles a spec to its core model with compiler/lower/compile_spec.h when this build has the
// compiler (arbc_compiler); otherwise says that spec support needs it.
ModelLoad load_spec_model(const std::string& path);

}  // namespace arbc::cli
