// Lowering: a checked spec (the AST after sema) to the core model plus monitor plans
// (docs/lowering.md walks through each rule; docs/design.md explains why).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "compiler/frontend/ast.h"
#include "compiler/lower/lowered_app.h"
#include "core/diagnostic.h"

namespace arbc::lower {

struct LowerOptions {
  // Directory against which `script "file.lua"` names are resolved (the spec's directory).
  std::string script_dir = ".";
};

struct LowerResult {
  bool ok = false;                      // no error diagnostics
  std::shared_ptr<LoweredApp> lowered;  // set when ok
  std::vector<Diagnostic> diagnostics;
};

// Lowers a spec that passed semantic analysis without errors. Errors that only lowering can
// see (an unreadable script file, an activity event name already taken) are diagnostics.
LowerResult lower_spec(std::shared_ptr<const ast::Spec> spec, const LowerOptions& options = {});

// "monitors/PickAndPlace.cmd__take.lua": where connection `name` into `port` keeps its monitor.
std::string monitor_path(const std::string& port, const std::string& name);

// "act_track": the activity event of rule `rule` under `by priority`.
std::string activity_event_name(const std::string& rule);

}  // namespace arbc::lower
