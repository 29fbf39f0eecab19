// The `test` declarations of a checked spec as model::TestCase values (core/test_case.h), for
// `arbc test`. Only for a spec without errors: sema has typed every literal.
#pragma once

#include <vector>

#include "compiler/frontend/ast.h"
#include "core/test_case.h"

namespace arbc {

std::vector<model::TestCase> lower_tests(const ast::Spec& spec);

}  // namespace arbc
