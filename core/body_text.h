// The text form of a body (core/body.h) in app.json (docs/app-json.md#bodies): one
// S-expression per top-level statement, e.g. `(accept 33 (<= (field dist (local obj)) 0.4))`.
// Writing then reading gives the same body; reading checks the shape, not the types.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "core/body.h"

namespace arbc::model {

std::string body_stmt_text(const BodyStmt& s);
std::string body_expr_text(const BodyExpr& e);

// Parses one statement; nullopt and *err (what and at which offset) on malformed text.
std::optional<BodyStmt> parse_body_stmt(std::string_view text, std::string* err);
std::optional<BodyExpr> parse_body_expr(std::string_view text, std::string* err);

}  // namespace arbc::model
