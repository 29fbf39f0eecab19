#include "compiler/frontend/ros2_constants.h"

#include <charconv>
#include <cmath>
#include <cstdlib>

namespace arbc::frontend {

namespace {

using ast::Expr;
using ast::ExprPtr;

ExprPtr literal(Expr::Kind kind, const ast::Loc& at) {
  auto e = std::make_unique<Expr>();
  e->kind = kind;
  e->loc = at;
  return e;
}

// Quotes around a string constant are not part of it (rosidl accepts both forms).
std::string unquoted(const std::string& text) {
  if (text.size() >= 2 && (text.front() == '"' || text.front() == '\'') &&
      text.back() == text.front())
    return text.substr(1, text.size() - 2);
  return text;
}

std::optional<ExprPtr> integer(const std::string& text, const Type& t, const ast::Loc& at,
                               std::string* why) {
  const char* last = text.data() + text.size();
  int64_t v = 0;
  auto [end, ec] = std::from_chars(text.data(), last, v);
  ExprPtr e = literal(Expr::Kind::Number, at);
  e->is_int = true;
  if (is_uint64(t) && ec == std::errc::result_out_of_range) {
    // 2^63 to 2^64 - 1: the literal a spec writes with those digits, a uint64 constant (sema's
    // uint64_literal reads e->text).
    uint64_t u = 0;
    auto [uend, uec] = std::from_chars(text.data(), last, u);
    if (uec == std::errc() && uend == last) {
      e->int_too_big = true;
      e->text = text;
      e->number = static_cast<double>(u);
      return e;
    }
  }
  if (ec != std::errc() || end != last || (!is_uint64(t) && !t.holds(v)) ||
      (is_uint64(t) && v < 0)) {
    *why = "'" + text + "' is not a " + t.to_string() + " (" + t.range_text() + ")";
    return std::nullopt;
  }
  e->integer = v;
  e->number = static_cast<double>(v);
  return e;
}

std::optional<ExprPtr> real(const std::string& text, const Type& t, const ast::Loc& at,
                            std::string* why) {
  char* end = nullptr;
  double v = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !t.holds(v)) {
    *why = "'" + text + "' is not a " + t.to_string() +
           (t.bits == 32 ? " value (a number that a float32 holds exactly)" : " number");
    return std::nullopt;
  }
  ExprPtr e = literal(Expr::Kind::Number, at);
  e->number = v;
  return e;
}

}  // namespace

std::optional<ExprPtr> msg_constant_literal(const ros2::MsgConstant& c, const ast::Loc& at,
                                            std::string* why) {
  const std::string& name = c.type.name;
  if (c.type.array != ros2::MsgType::Array::None || !c.type.primitive) {
    *why = "a constant is of a primitive type, not " + c.type.text();
    return std::nullopt;
  }
  if (name == "string" || name == "wstring") {
    ExprPtr e = literal(Expr::Kind::String, at);
    e->text = unquoted(c.value);
    if (c.type.string_bound > 0 && e->text.size() > static_cast<size_t>(c.type.string_bound)) {
      *why = "the string is longer than its bound " + std::to_string(c.type.string_bound);
      return std::nullopt;
    }
    return e;
  }
  if (name == "bool") {
    if (c.value != "true" && c.value != "false" && c.value != "True" && c.value != "False" &&
        c.value != "1" && c.value != "0") {
      *why = "'" + c.value + "' is not a bool (true or false)";
      return std::nullopt;
    }
    ExprPtr e = literal(Expr::Kind::Bool, at);
    e->boolean = c.value == "true" || c.value == "True" || c.value == "1";
    return e;
  }
  TypePtr t = Type::number(name);
  if (!t) {
    *why = "'" + name + "' is not a type a constant can have";
    return std::nullopt;
  }
  return t->kind == Type::Kind::Int ? integer(c.value, *t, at, why) : real(c.value, *t, at, why);
}

}  // namespace arbc::frontend
