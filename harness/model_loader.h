// Loads the core model named on a command line (docs/design.md#pipeline: the verifier and the code
// generators read the core model, never the AST).
//
//   APP.json, or a directory holding app.json   read with core/app_json.h
//   SPEC (*.spec)                               compiled by load_spec_model()
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/app_model.h"
#include "core/check_ids.h"
#include "core/diagnostic.h"

namespace arbc::harness {

// Whether load_model reads `path` as a spec (it ends in .spec) rather than an app.json.
bool is_spec_path(const std::string& path);

// An error about a whole file (no line): `io` (unreadable), `app-json` (does not load).
Diagnostic file_error(const std::string& file, std::string message, DiagId id);

// What loading says besides the model.
struct LoadNotes {
  std::string rendered;  // a spec's rendered diagnostics (errors and warnings), for stderr
  std::vector<Diagnostic> errors;  // when loading fails: why, for the JSON and SARIF reports
  // A spec that loads: the front end's warnings (`lapsing-permission`), for those reports too.
  std::vector<Diagnostic> warnings;
};

// Reads the model from `path`; nullopt and `err` for the user ("FILE: what is wrong; what to
// do") when it cannot. Never throws.
std::optional<model::App> load_model(const std::string& path, LoadNotes* notes, std::string* err);

// Compiles a spec to its core model with compiler/lower/compile_spec.h.
std::optional<model::App> load_spec_model(const std::string& path, LoadNotes* notes,
                                          std::string* err);

}  // namespace arbc::harness
