// Loads the core model named on a command line (DESIGN.md section 2: the verifier and the code
// generators read the core model, never the AST).
//
//   APP.json, or a directory holding app.json   read with runtime/app_json.h
//   SPEC (*.spec)                               compiled by load_spec_model()
#pragma once

#include <string>

#include "runtime/app_model.h"

namespace arbc::cli {

struct ModelLoad {
  bool ok = false;
  model::App app;
  std::string error;  // for the user: "FILE: what is wrong; what to do"
  bool spec = false;  // the input was a spec (its diagnostics are in `error`)
};

// Reads the model from `path`. Never throws.
ModelLoad load_model(const std::string& path);

// Compiles a spec to its core model: the one function to change when the front end and the
// lowering land (call compile_spec_file and move its diagnostics into `error`).
ModelLoad load_spec_model(const std::string& path);

}  // namespace arbc::cli
