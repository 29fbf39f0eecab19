// What to suggest to a test that expects nothing (`test-expect`): such a test passes whatever
// the app does, so a green result would prove nothing. The suggestion fits the test: the port
// its last input reaches through a rule, at that input's time.
#pragma once

#include <string>

#include "compiler/frontend/ast.h"

namespace arbc::frontend {

// An expectation as the test would write it (`expect HeadControl.gaze receives at 100ms;`),
// after the steps' times and the rules' ports were checked; "" when no input reaches a rule.
std::string expectation_hint(const ast::TestDecl& test, const ast::Spec& spec);

}  // namespace arbc::frontend
