// A property over time as the app model states it (core/app_model.h), from its declaration: for
// the app's own properties (lower.cc) and for a test's `expect PROPERTY;` (test_cases.cc), so a
// test states a property exactly as the proof reads it.
#pragma once

#include <optional>

#include "compiler/frontend/ast.h"
#include "core/app_model.h"

namespace arbc {

// nullopt when sema left the property without a port (it reported why).
std::optional<model::TemporalProperty> lower_temporal(const ast::TemporalDecl& n);

}  // namespace arbc
