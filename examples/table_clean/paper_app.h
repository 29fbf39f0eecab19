// The core model of the paper's table-cleaning app with its hand-written monitors
// (paper_monitors/), i.e. what `arbc build specs/table_clean.spec` produces, written by hand.
// It runs the simulated world on the embedded runtime without the compiler.
#pragma once

#include <string>

#include "core/app_model.h"

namespace arbc::table_clean {

// The directory holding paper_monitors/ (the app_dir to pass to Runtime::create).
std::string paper_monitors_dir();

// The app: eight modules, the rules take/put/pull/track/search/ask and their event feeds.
model::App paper_app();

// Replaces the constraint of connection `name` (for mutation tests). False if no such rule.
bool set_constraint(model::App& app, const std::string& name, const std::string& constraint);

}  // namespace arbc::table_clean
