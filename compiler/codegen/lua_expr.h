// Body expressions of the core model (model::BodyExpr, the IR the proof encodes) as Lua 5.4
// expressions. Code generation reads no AST: what it writes is what the verifier proved.
//
// Every compound subexpression is parenthesised, so Lua's precedence never differs from the
// spec's. Builtins become calls of the prelude's local functions (lua_prelude.h); a literal that
// folds a named constant is written as the constant's name, which the monitor defines once at
// its top. The translator records both, so a monitor carries only what it uses.
//
// Numbers keep their spec type at run time (docs/design.md#numbers-at-run-time): a `ToFloat`
// node is written `(x + 0.0)`, or a float literal for an int literal; as an operand of an
// arithmetic operator whose other operand is a float (or of `/`), it is written as the bare
// operand, since Lua converts an integer operand there exactly as the node says.
#pragma once

#include <map>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "compiler/codegen/lua_writer.h"
#include "core/body.h"

namespace arbc::codegen {

// A named constant a monitor uses: `local NAME = VALUE  -- spec line LINE`.
struct LuaConstant {
  std::string name;  // the Lua name
  std::string value;
  int line = 0;
};

class LuaExprTranslator {
 public:
  // `message_name` is the spec's name of the incoming message (`objects`); may be empty where
  // there is no message (trig).
  explicit LuaExprTranslator(std::string message_name);

  std::string expr(const model::BodyExpr& e);

  // The Lua name of the `var` called `spec_name` (a local of the body otherwise).
  void bind_var(const std::string& spec_name, std::string lua_name) {
    vars_[spec_name] = std::move(lua_name);
  }

  // The Lua name of the body's local (`let` or `var`) called `spec_name`.
  std::string local_name(const std::string& spec_name) const;

  const std::set<std::string>& helpers_used() const { return helpers_; }
  // Constants used so far, in declaration order.
  std::vector<LuaConstant> constants_used() const;

  // The Lua literal of a literal node (Int, Float, String, Bool).
  static std::string literal(const model::BodyExpr& e);

 private:
  std::string operand(const model::BodyExpr& e);  // parenthesised when compound
  std::string arith_operand(const model::BodyExpr& e, bool paren);
  std::string binary(const model::BodyExpr& e);
  std::string unary(const model::BodyExpr& e);
  std::string call(const model::BodyExpr& e);
  std::string to_float(const model::BodyExpr& e);
  std::string helper(std::string_view name);  // records the use, returns the name

  std::string message_name_;
  std::map<std::string, std::string> vars_;
  std::set<std::string> helpers_;
  std::map<std::tuple<int, int, std::string>, LuaConstant> constants_;  // by declaration
};

// The top of a generated file that uses what `tr` translated: the prelude's helpers it called,
// then its named constants (each with its spec line), each block followed by a blank line.
void write_helpers_and_constants(const LuaExprTranslator& tr, LuaWriter& out);

}  // namespace arbc::codegen
