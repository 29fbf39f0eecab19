// Core models built by hand for the verifier's tests: the paper's table-cleaning application as
// the lowering produces it (docs/lowering.md: feeds, `by priority` activity events) and the
// search-and-track pair that verifies only thanks to must_set.
#pragma once

#include <string>
#include <vector>

#include "core/app_model.h"

namespace arbc::verify::testing {

// The spec these models come from, relative to the repository root (where golden tests run).
std::string table_clean_spec_path();

model::App table_clean_model();
// table_clean with `not e_taken and` removed from `take`
// (tests/verify/table_clean_take_mutant.spec).
model::App table_clean_take_mutant();
// table_clean with warnings only: `pull` made dead, and a feed into Speak.text carrying an
// event no rule there reads (unused). Proved; refuted with --strict.
model::App table_clean_with_warnings();
model::App search_and_track_model();

// Helpers to edit models in tests.
model::Connection& connection(model::App& app, const std::string& name);
model::ArbitratedPort& arbitrated(model::App& app, const std::string& port);
Constraint parse(const std::string& text);  // constraint text; aborts the test on bad text

}  // namespace arbc::verify::testing
