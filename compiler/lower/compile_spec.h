// The one call other commands use to turn a spec file into the core model: read, parse, check
// (sema), lower. `arbc build`, `arbc verify SPEC` and `arbc run SPEC` all start here.
//
//   arbc::lower::CompiledSpec c = arbc::lower::compile_spec("specs/table_clean.spec");
//   for (const Diagnostic& d : c.diagnostics) std::cerr << render(d, &c.sources);
//   if (!c.ok) return kExitBadInput;
//   const arbc::model::App& app = c.lowered->app;   // what the verifier and runtime read
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "compiler/lower/lowered_app.h"
#include "core/diagnostic.h"

namespace arbc::lower {

struct CompiledSpec {
  bool ok = false;                      // no error diagnostics: `lowered` is set
  std::vector<Diagnostic> diagnostics;  // errors and warnings of every stage, in file order
  std::shared_ptr<const LoweredApp> lowered;
  SourceCache sources;  // holds the spec's text, for render()
};

// Compiles the spec file at `path`. An unreadable file is a diagnostic, not an exception.
// `script` files are resolved against the spec's directory.
CompiledSpec compile_spec(const std::string& path);

// The same for text already in memory; `file` names it in diagnostics and in app.json, and
// `script_dir` is where `script` files are looked for.
CompiledSpec compile_spec_text(std::string_view text, const std::string& file,
                               const std::string& script_dir = ".");

}  // namespace arbc::lower
