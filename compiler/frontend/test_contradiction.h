// Two expectations of one test that cannot both hold: `expect M.p receives nothing` over a
// window that holds the whole window of an `expect M.p receives ...` on the same port. Such a
// test fails on every run, whatever the app does, so the checker says so before it runs.
#pragma once

#include <optional>
#include <utility>

#include "compiler/frontend/ast.h"

namespace arbc::frontend {

// The first (receives, nothing) pair of `test`'s expectations that contradict, after the
// windows' times were checked; nullopt when none do.
std::optional<std::pair<const ast::TestExpect*, const ast::TestExpect*>> contradicting_receives(
    const ast::TestDecl& test);

}  // namespace arbc::frontend
