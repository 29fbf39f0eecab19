#include "compiler/codegen/lua_expr.h"

#include <cmath>
#include <cstdio>

#include "compiler/codegen/lua_prelude.h"
#include "compiler/codegen/lua_text.h"

namespace arbc::codegen {

namespace {

Type::Kind kind_of(const ast::Expr& e) { return e.type ? e.type->kind : Type::Kind::Float; }

bool is_structured(const ast::Expr& e) {
  Type::Kind k = kind_of(e);
  return e.type && (k == Type::Kind::Vec3 || k == Type::Kind::List || k == Type::Kind::Record);
}

std::string integer_text(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%lld", static_cast<long long>(std::llround(v)));
  return buf;
}

const char* builtin_name(ast::Builtin b) {
  switch (b) {
    case ast::Builtin::Len:
      return "len";
    case ast::Builtin::MinBy:
      return "min_by";
    case ast::Builtin::MaxBy:
      return "max_by";
    case ast::Builtin::Dist:
      return "dist";
    case ast::Builtin::Norm:
      return "norm";
    case ast::Builtin::Abs:
      return "abs";
    case ast::Builtin::Min:
      return "min";
    case ast::Builtin::Max:
      return "max";
    case ast::Builtin::Now:
      return "now";
    case ast::Builtin::Vec3:
      return "vec3";
    case ast::Builtin::None:
      break;
  }
  return nullptr;
}

}  // namespace

LuaExprTranslator::LuaExprTranslator(std::string message_name)
    : message_name_(std::move(message_name)) {}

std::string LuaExprTranslator::helper(const std::string& name) {
  helpers_.insert(name);
  return name;
}

std::string LuaExprTranslator::local_name(const ast::Stmt* decl) const {
  auto it = locals_.find(decl);
  return it != locals_.end() ? it->second : lua_local_name(decl ? decl->name : "?");
}

std::vector<const ast::ConstDecl*> LuaExprTranslator::constants_used() const {
  std::vector<const ast::ConstDecl*> out;
  for (const auto& [pos, c] : constants_) out.push_back(c);
  return out;
}

std::string LuaExprTranslator::constant_value(const ast::ConstDecl& c) {
  const ast::Expr* v = c.value.get();
  if (v && v->type) {
    switch (v->type->kind) {
      case Type::Kind::Bool:
        return c.boolean ? "true" : "false";
      case Type::Kind::String:
        return lua_string(c.text);
      case Type::Kind::Int:
        return integer_text(c.number);
      default:
        break;
    }
  }
  return lua_float(c.number);
}

std::string LuaExprTranslator::constraint(const Constraint& c) {
  switch (c.op) {
    case Constraint::Op::True:
      return "true";
    case Constraint::Op::False:
      return "false";
    case Constraint::Op::Event:
      return "PortMonitor.hasEvent(" + lua_string(c.event) + ")";
    case Constraint::Op::Not:
      return "not (" + constraint(c.args[0]) + ")";
    case Constraint::Op::And:
    case Constraint::Op::Or: {
      std::string out;
      for (size_t i = 0; i < c.args.size(); ++i) {
        if (i) out += c.op == Constraint::Op::And ? " and " : " or ";
        const Constraint& a = c.args[i];
        bool simple = a.op == Constraint::Op::Event || a.op == Constraint::Op::True ||
                      a.op == Constraint::Op::False || a.op == Constraint::Op::Not;
        out += simple ? constraint(a) : "(" + constraint(a) + ")";
      }
      return out;
    }
  }
  return "false";
}

std::string LuaExprTranslator::operand(const ast::Expr& e) {
  std::string text = expr(e);
  if (e.kind == ast::Expr::Kind::Binary || e.kind == ast::Expr::Kind::Unary ||
      e.kind == ast::Expr::Kind::Lambda)
    return "(" + text + ")";
  return text;
}

std::string LuaExprTranslator::expr(const ast::Expr& e) {
  using Kind = ast::Expr::Kind;
  switch (e.kind) {
    case Kind::Number:
      if (e.is_int && e.type && e.type->kind == Type::Kind::Int) return integer_text(e.number);
      return lua_float(e.number);
    case Kind::Duration:
      return lua_float(e.number);
    case Kind::String:
      return lua_string(e.text);
    case Kind::Bool:
      return e.boolean ? "true" : "false";
    case Kind::Name:
      return name(e);
    case Kind::Field: {
      // Lua allows `.f` only after a name, call, index or parenthesised expression.
      const ast::Expr& base = *e.args[0];
      bool bare = base.kind == Kind::Name || base.kind == Kind::Call || base.kind == Kind::Field ||
                  base.kind == Kind::Index;
      return (bare ? expr(base) : "(" + expr(base) + ")") + lua_field(e.text);
    }
    case Kind::Index:
      return helper(std::string(kIndexHelper)) + "(" + expr(*e.args[0]) + ", " + expr(*e.args[1]) +
             ")";
    case Kind::Unary:
      return unary(e);
    case Kind::Binary:
      return binary(e);
    case Kind::Record: {
      if (e.args.empty()) return "{}";
      std::string out = "{ ";
      for (size_t i = 0; i < e.args.size(); ++i) {
        if (i) out += ", ";
        out += lua_table_key(e.names[i].name) + expr(*e.args[i]);
      }
      return out + " }";
    }
    case Kind::List: {
      if (e.args.empty()) return "{}";
      std::string out = "{ ";
      for (size_t i = 0; i < e.args.size(); ++i) out += (i ? ", " : "") + expr(*e.args[i]);
      return out + " }";
    }
    case Kind::Lambda:
      return "function(" + lua_local_name(e.text) + ") return " + expr(*e.args[0]) + " end";
    case Kind::Call:
      return call(e);
    case Kind::Otherwise:
      return "false";
  }
  return "nil";
}

std::string LuaExprTranslator::name(const ast::Expr& e) {
  switch (e.name_kind) {
    case ast::NameKind::Message:
      return lua_local_name(message_name_.empty() ? e.text : message_name_);
    case ast::NameKind::Let:
    case ast::NameKind::Var:
      return local_name(e.local);
    case ast::NameKind::Param:
      return lua_local_name(e.text);
    case ast::NameKind::Const:
      if (e.constant) constants_[{e.constant->loc.line, e.constant->loc.column}] = e.constant;
      return lua_local_name(e.text);
    case ast::NameKind::Event:
      return "PortMonitor.hasEvent(" + lua_string(e.text) + ")";
    case ast::NameKind::Unresolved:
      break;
  }
  return lua_local_name(e.text);
}

std::string LuaExprTranslator::unary(const ast::Expr& e) {
  const ast::Expr& a = *e.args[0];
  if (e.op == "not") return "not " + operand(a);
  if (kind_of(a) == Type::Kind::Vec3 && a.type) return helper("arbc_vneg") + "(" + expr(a) + ")";
  return "-" + operand(a);
}

std::string LuaExprTranslator::binary(const ast::Expr& e) {
  const ast::Expr& l = *e.args[0];
  const ast::Expr& r = *e.args[1];
  std::string_view op = e.op;
  if (op == "==" || op == "!=") {
    if (is_structured(l) || is_structured(r)) {
      std::string eq = helper("arbc_equal") + "(" + expr(l) + ", " + expr(r) + ")";
      return op == "==" ? eq : "not " + eq;
    }
    return operand(l) + (op == "==" ? " == " : " ~= ") + operand(r);
  }
  bool lv = l.type && kind_of(l) == Type::Kind::Vec3;
  bool rv = r.type && kind_of(r) == Type::Kind::Vec3;
  if (lv || rv) {
    if (op == "+") return helper("arbc_vadd") + "(" + expr(l) + ", " + expr(r) + ")";
    if (op == "-") return helper("arbc_vsub") + "(" + expr(l) + ", " + expr(r) + ")";
    if (op == "*") return helper("arbc_vscale") + "(" + expr(l) + ", " + expr(r) + ")";
    if (op == "/") return helper("arbc_vdiv") + "(" + expr(l) + ", " + expr(r) + ")";
  }
  if (op == "+" && l.type && kind_of(l) == Type::Kind::String)
    return operand(l) + " .. " + operand(r);
  if (op == "+" && l.type && kind_of(l) == Type::Kind::List)
    return helper("arbc_concat") + "(" + expr(l) + ", " + expr(r) + ")";
  // `/` is float division in the spec as in Lua; `%` truncates like the spec's constant folding
  // (C fmod), where Lua's own `%` would floor.
  if (op == "%") return "math.fmod(" + expr(l) + ", " + expr(r) + ")";
  return operand(l) + " " + std::string(op) + " " + operand(r);
}

std::string LuaExprTranslator::call(const ast::Expr& e) {
  const char* b = builtin_name(e.builtin);
  std::string fn = b ? helper(b) : lua_local_name(e.text);
  std::string out = fn + "(";
  for (size_t i = 0; i < e.args.size(); ++i) out += (i ? ", " : "") + expr(*e.args[i]);
  return out + ")";
}

}  // namespace arbc::codegen
