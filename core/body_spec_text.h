// A body expression (core/body.h) written back in the spec's own syntax
// (docs/language.md#expressions), for people and for the spec's parser: the assert over
// `emitted` that a counterexample's tests file states (verify/claim_test.h), and the verifier's
// messages about it. Every operand that is itself an operator is parenthesised, so the text
// parses to the same tree whatever the precedence; a folded constant is written as its value
// (a float as a float literal that reads back as the same double).
#pragma once

#include <string>

#include "core/body.h"

namespace arbc::model {

// `message` names the value Op::Message stands for ("emitted" in an assert over data).
std::string body_expr_spec_text(const BodyExpr& e, const std::string& message);

}  // namespace arbc::model
