// Spec expressions (checked AST) and selection constraints as Lua 5.4 expressions.
//
// Every compound subexpression is parenthesised, so Lua's precedence never differs from the
// spec's. Builtins become calls of the prelude's local functions (lua_prelude.h); constants
// become locals the monitor defines at its top. The translator records both, so a monitor
// carries only what it uses.
#pragma once

#include <map>
#include <set>
#include <string>
#include <vector>

#include "compiler/frontend/ast.h"
#include "core/constraint.h"

namespace arbc::codegen {

class LuaExprTranslator {
 public:
  // `message_name` is the spec's name of the incoming message (`objects`); may be empty where
  // there is no message (trig).
  explicit LuaExprTranslator(std::string message_name);

  std::string expr(const ast::Expr& e);

  // A constraint as a Lua boolean over PortMonitor.hasEvent: the `by priority` pre-check.
  static std::string constraint(const Constraint& c);

  // The Lua name of a `let` / `var` statement's variable (bound with `bind`).
  void bind(const ast::Stmt* decl, std::string lua_name) { locals_[decl] = std::move(lua_name); }
  std::string local_name(const ast::Stmt* decl) const;

  const std::set<std::string>& helpers_used() const { return helpers_; }
  // Constants used so far, in declaration order.
  std::vector<const ast::ConstDecl*> constants_used() const;

  // The Lua literal of a folded constant.
  static std::string constant_value(const ast::ConstDecl& c);

 private:
  std::string operand(const ast::Expr& e);  // parenthesised when compound
  std::string binary(const ast::Expr& e);
  std::string unary(const ast::Expr& e);
  std::string call(const ast::Expr& e);
  std::string name(const ast::Expr& e);
  std::string helper(const std::string& name);  // records the use, returns the name

  std::string message_name_;
  std::map<const ast::Stmt*, std::string> locals_;
  std::set<std::string> helpers_;
  std::map<std::pair<int, int>, const ast::ConstDecl*> constants_;  // by (line, column)
};

}  // namespace arbc::codegen
