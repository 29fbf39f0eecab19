#include "compiler/frontend/rule_drop_reasons.h"

namespace arbc::frontend {

namespace {

bool has_statement(const ast::Block& block, ast::Stmt::Kind kind) {
  for (const auto& s : block) {
    if (s->kind == kind || s->kind == ast::Stmt::Kind::Script) return true;
    if (has_statement(s->body, kind) || has_statement(s->else_body, kind)) return true;
  }
  return false;
}

}  // namespace

std::string why_rule_never_drops(const ast::Rule& rule, const std::string& reason) {
  if (reason == "rejected" && !has_statement(rule.body, ast::Stmt::Kind::Accept))
    return "it has no `accept`";
  if (reason == "throttled" && !has_statement(rule.body, ast::Stmt::Kind::Throttle))
    return "it has no `throttle`";
  return "";
}

}  // namespace arbc::frontend
