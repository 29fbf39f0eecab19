#include "compiler/codegen/lua_expr.h"

#include <cmath>
#include <cstdio>
#include <limits>

#include "compiler/codegen/lua_prelude.h"
#include "compiler/codegen/lua_text.h"

namespace arbc::codegen {

namespace {

using model::BodyExpr;
using Op = BodyExpr::Op;

bool has_kind(const BodyExpr& e, Type::Kind k) { return e.type && e.type->kind == k; }

bool is_uint64_typed(const BodyExpr& e) { return e.type && is_uint64(*e.type); }

bool is_structured(const BodyExpr& e) {
  return has_kind(e, Type::Kind::Vec3) || has_kind(e, Type::Kind::List) ||
         has_kind(e, Type::Kind::Record);
}

// An int literal in Lua: INT64_MIN has no literal (its digits without the sign read as a float).
std::string integer_text(int64_t v) {
  if (v == std::numeric_limits<int64_t>::min()) return "math.mininteger";
  return std::to_string(v);
}

}  // namespace

LuaExprTranslator::LuaExprTranslator(std::string message_name)
    : message_name_(std::move(message_name)) {}

std::string LuaExprTranslator::helper(std::string_view name) {
  helpers_.insert(std::string(name));
  return std::string(name);
}

std::string LuaExprTranslator::local_name(const std::string& spec_name) const {
  auto it = vars_.find(spec_name);
  return it != vars_.end() ? it->second : lua_local_name(spec_name);
}

std::vector<LuaConstant> LuaExprTranslator::constants_used() const {
  std::vector<LuaConstant> out;
  for (const auto& [key, c] : constants_) out.push_back(c);
  return out;
}

std::string LuaExprTranslator::literal(const BodyExpr& e) {
  switch (e.op) {
    case Op::Int:
      return integer_text(e.integer);
    case Op::String:
      return lua_string(e.text);
    case Op::Bool:
      return e.boolean ? "true" : "false";
    default:
      return lua_float(e.number);
  }
}

std::string LuaExprTranslator::operand(const BodyExpr& e) {
  std::string text = expr(e);
  if (e.op == Op::Binary || e.op == Op::Neg || e.op == Op::Not || e.op == Op::Lambda)
    return "(" + text + ")";
  return text;
}

// An operand of `+ - * / %` or of a vec3 operator whose result is a float: Lua converts an
// integer operand there to a float exactly as the ToFloat node says (Lua 5.4 manual, 3.4.1),
// so the node is left implicit and the text stays as the spec wrote it.
std::string LuaExprTranslator::arith_operand(const BodyExpr& e, bool paren) {
  const BodyExpr& x = e.op == Op::ToFloat ? e.args[0] : e;
  return paren ? operand(x) : expr(x);
}

std::string LuaExprTranslator::to_float(const BodyExpr& e) {
  const BodyExpr& x = e.args[0];
  if (x.op == Op::Int && x.constant.empty()) return lua_float(static_cast<double>(x.integer));
  return "(" + operand(x) + " + 0.0)";
}

std::string LuaExprTranslator::expr(const BodyExpr& e) {
  switch (e.op) {
    case Op::Message:
      return lua_local_name(message_name_.empty() ? "msg" : message_name_);
    case Op::Int:
    case Op::Float:
    case Op::String:
    case Op::Bool: {
      if (e.constant.empty()) return literal(e);
      std::string name = lua_local_name(e.constant);
      constants_[{e.constant_line, e.constant_column, e.constant}] = {name, literal(e),
                                                                      e.constant_line};
      return name;
    }
    case Op::Local:
      return local_name(e.text);
    case Op::Param:
      return lua_local_name(e.text);
    case Op::Field: {
      // Lua allows `.f` only after a name, call, index or parenthesised expression.
      const BodyExpr& base = e.args[0];
      bool bare = base.op == Op::Message || base.op == Op::Local || base.op == Op::Param ||
                  base.op == Op::Call || base.op == Op::Field || base.op == Op::Index;
      return (bare ? expr(base) : "(" + expr(base) + ")") + lua_field(e.text);
    }
    case Op::Index:
      return helper(kIndexHelper) + "(" + expr(e.args[0]) + ", " + expr(e.args[1]) + ")";
    case Op::Neg:
    case Op::Not:
      return unary(e);
    case Op::Binary:
      return binary(e);
    case Op::Record:
    case Op::List: {
      if (e.args.empty()) return "{}";
      std::string out = "{ ";
      for (size_t i = 0; i < e.args.size(); ++i) {
        if (i) out += ", ";
        if (e.op == Op::Record) out += lua_table_key(i < e.names.size() ? e.names[i] : "?");
        out += expr(e.args[i]);
      }
      return out + " }";
    }
    case Op::Lambda:
      return "function(" + lua_local_name(e.text) + ") return " + expr(e.args[0]) + " end";
    case Op::Call:
      return call(e);
    case Op::ToFloat:
      return to_float(e);
  }
  return "nil";
}

std::string LuaExprTranslator::unary(const BodyExpr& e) {
  const BodyExpr& a = e.args[0];
  if (e.op == Op::Not) return "not " + operand(a);
  if (has_kind(a, Type::Kind::Vec3)) return helper("arbc_vneg") + "(" + expr(a) + ")";
  return "-" + operand(a);
}

std::string LuaExprTranslator::binary(const BodyExpr& e) {
  const BodyExpr& l = e.args[0];
  const BodyExpr& r = e.args[1];
  const std::string& op = e.text;
  if (op == "==" || op == "!=") {
    if (is_structured(l) || is_structured(r)) {
      std::string eq = helper("arbc_equal") + "(" + expr(l) + ", " + expr(r) + ")";
      return op == "==" ? eq : "not " + eq;
    }
    return operand(l) + (op == "==" ? " == " : " ~= ") + operand(r);
  }
  if (has_kind(l, Type::Kind::Vec3) || has_kind(r, Type::Kind::Vec3)) {
    const char* fn = op == "+"   ? "arbc_vadd"
                     : op == "-" ? "arbc_vsub"
                     : op == "*" ? "arbc_vscale"
                     : op == "/" ? "arbc_vdiv"
                                 : nullptr;
    if (fn)
      return helper(fn) + "(" + arith_operand(l, false) + ", " + arith_operand(r, false) + ")";
  }
  if (op == "+" && has_kind(l, Type::Kind::String)) return operand(l) + " .. " + operand(r);
  if (op == "+" && has_kind(l, Type::Kind::List))
    return helper("arbc_concat") + "(" + expr(l) + ", " + expr(r) + ")";
  // `/` is float division in the spec as in Lua; `%` truncates like the spec's constant folding
  // (C fmod), where Lua's own `%` would floor.
  if (op == "%")
    return helper("arbc_fmod") + "(" + arith_operand(l, false) + ", " + arith_operand(r, false) +
           ")";
  // Lua 5.4 compiles `x - K`, K an integer constant of one byte (after folding: `0`, `-0`,
  // `1 - 1`), as x + -K (lcode.c, finishbinexpneg). For a float x that differs from the
  // subtraction the spec means in one case: x = -0.0 and K = 0 give +0.0, where IEEE (and the
  // proof) give -0.0. So an int subtracted from a float is written as the float Lua would make
  // of it (the ToFloat node, explicit), which Lua subtracts as written.
  if (op == "-" && r.op == Op::ToFloat) return arith_operand(l, true) + " - " + to_float(r);
  if (op == "+" || op == "-" || op == "*" || op == "/")
    return arith_operand(l, true) + " " + op + " " + arith_operand(r, true);
  // A uint64 is held as its bit pattern (core/type.h): its orderings compare unsigned. The
  // checker lets it meet only partners whose bits are their unsigned value (sema_numbers.cc).
  if (is_uint64_typed(l) || is_uint64_typed(r)) {
    bool flip = op == ">" || op == "<=";  // a > b is b < a; a <= b is not (b < a)
    std::string ult = "math.ult(" + expr(flip ? r : l) + ", " + expr(flip ? l : r) + ")";
    return op == "<" || op == ">" ? ult : "not " + ult;
  }
  return operand(l) + " " + op + " " + operand(r);
}

std::string LuaExprTranslator::call(const BodyExpr& e) {
  const BuiltinInfo* b = builtin_info(e.builtin);
  std::string fn = b ? helper(b->lua_helper) : lua_local_name(e.text);
  std::string out = fn + "(";
  for (size_t i = 0; i < e.args.size(); ++i) out += (i ? ", " : "") + expr(e.args[i]);
  return out + ")";
}

void write_helpers_and_constants(const LuaExprTranslator& tr, LuaWriter& out) {
  std::string prelude = lua_prelude(tr.helpers_used());
  if (!prelude.empty()) {
    out.line("-- Builtins of the spec language, in plain Lua.");
    out.raw(prelude);
    out.blank();
  }
  std::vector<LuaConstant> constants = tr.constants_used();
  if (constants.empty()) return;
  out.line("-- Constants.");
  for (const LuaConstant& c : constants)
    out.line("local " + c.name + " = " + c.value + "  -- spec line " + std::to_string(c.line),
             c.line);
  out.blank();
}

}  // namespace arbc::codegen
