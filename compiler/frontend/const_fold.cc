#include "compiler/frontend/const_fold.h"

#include <cmath>
#include <string>

namespace arbc::frontend {

namespace {

using Kind = Type::Kind;

constexpr double kTwo63 = 9223372036854775808.0;  // 2^63, the first double past INT64_MAX

ConstValue int_value(int64_t i) {
  ConstValue v;
  v.kind = Kind::Int;
  v.integer = i;
  return v;
}

ConstValue float_value(double d) {
  ConstValue v;
  v.kind = Kind::Float;
  v.number = d;
  return v;
}

ConstValue bool_value(bool b) {
  ConstValue v;
  v.kind = Kind::Bool;
  v.boolean = b;
  return v;
}

double as_double(const ConstValue& v) {
  return v.kind == Kind::Int ? static_cast<double>(v.integer) : v.number;  // C's cast, as Lua's
}

// Lua 5.4 compares an int with a float by their mathematical values. For an int i and a
// finite f strictly inside (-2^63, 2^63): i < f iff i < ceil(f), i <= f iff i <= floor(f).
bool int_less_float(int64_t i, double f, bool or_equal) {
  if (std::isnan(f)) return false;
  if (f >= kTwo63) return true;
  if (f <= -kTwo63) return or_equal && f == -kTwo63 && i == INT64_MIN;
  return or_equal ? i <= static_cast<int64_t>(std::floor(f))
                  : i < static_cast<int64_t>(std::ceil(f));
}

bool float_less_int(double f, int64_t i, bool or_equal) {
  if (std::isnan(f)) return false;
  if (f >= kTwo63) return false;
  if (f <= -kTwo63) return f < -kTwo63 || or_equal || i > INT64_MIN;
  return or_equal ? static_cast<int64_t>(std::ceil(f)) <= i
                  : static_cast<int64_t>(std::floor(f)) < i;
}

bool less(const ConstValue& a, const ConstValue& b, bool or_equal) {
  if (a.kind == Kind::String) return or_equal ? a.text <= b.text : a.text < b.text;
  if (a.kind == Kind::Int && b.kind == Kind::Int)
    return or_equal ? a.integer <= b.integer : a.integer < b.integer;
  if (a.kind == Kind::Int) return int_less_float(a.integer, b.number, or_equal);
  if (b.kind == Kind::Int) return float_less_int(a.number, b.integer, or_equal);
  return or_equal ? a.number <= b.number : a.number < b.number;
}

bool equal(const ConstValue& a, const ConstValue& b) {
  if (a.kind == Kind::String || a.kind == Kind::Bool)
    return a.kind == Kind::String ? a.text == b.text : a.boolean == b.boolean;
  if (a.kind == Kind::Int && b.kind == Kind::Int) return a.integer == b.integer;
  if (a.kind == Kind::Float && b.kind == Kind::Float) return a.number == b.number;
  int64_t i = a.kind == Kind::Int ? a.integer : b.integer;
  double f = a.kind == Kind::Int ? b.number : a.number;
  return std::floor(f) == f && f >= -kTwo63 && f < kTwo63 && static_cast<int64_t>(f) == i;
}

std::optional<ConstValue> overflow(std::string* error) {
  *error =
      "this int expression overflows 64 bits (ints are -9223372036854775808 to "
      "9223372036854775807, and a monitor would wrap it around): compute it in floats "
      "(write a decimal point, as in 2.0) or with smaller values";
  return std::nullopt;
}

std::optional<ConstValue> arith(char op, const ConstValue& a, const ConstValue& b,
                                std::string* error) {
  if (a.kind == Kind::Int && b.kind == Kind::Int) {
    int64_t r = 0;
    bool over = op == '+'   ? __builtin_add_overflow(a.integer, b.integer, &r)
                : op == '-' ? __builtin_sub_overflow(a.integer, b.integer, &r)
                            : __builtin_mul_overflow(a.integer, b.integer, &r);
    if (over) return overflow(error);
    return int_value(r);
  }
  double x = as_double(a), y = as_double(b);
  return float_value(op == '+' ? x + y : op == '-' ? x - y : x * y);
}

std::optional<ConstValue> divide(char op, const ConstValue& a, const ConstValue& b,
                                 std::string* error) {
  if (is_zero(b)) {
    *error = op == '/' ? "division by zero: `/ 0` has no finite value (a monitor computes inf or "
                         "nan); divide by something else"
                       : "`% 0` has no value (a monitor's math.fmod raises on an int 0 and gives "
                         "nan for 0.0); take the remainder by something else";
    return std::nullopt;
  }
  if (op == '/') return float_value(as_double(a) / as_double(b));
  if (a.kind == Kind::Int && b.kind == Kind::Int)  // math.fmod: C's %, and 0 for -1
    return int_value(b.integer == -1 ? 0 : a.integer % b.integer);
  return float_value(std::fmod(as_double(a), as_double(b)));
}

}  // namespace

bool is_zero(const ConstValue& v) {
  return (v.kind == Kind::Int && v.integer == 0) || (v.kind == Kind::Float && v.number == 0);
}

std::optional<ConstValue> fold_binary(std::string_view op, const ConstValue& a, const ConstValue& b,
                                      std::string* error) {
  if (op == "and") return bool_value(a.boolean && b.boolean);
  if (op == "or") return bool_value(a.boolean || b.boolean);
  if (op == "==") return bool_value(equal(a, b));
  if (op == "!=") return bool_value(!equal(a, b));
  if (op == "<") return bool_value(less(a, b, false));
  if (op == "<=") return bool_value(less(a, b, true));
  if (op == ">") return bool_value(less(b, a, false));
  if (op == ">=") return bool_value(less(b, a, true));
  if (op == "+" && a.kind == Kind::String) {
    ConstValue s = a;
    s.text += b.text;
    return s;
  }
  if (op == "+" || op == "-" || op == "*") return arith(op[0], a, b, error);
  if (op == "/" || op == "%") return divide(op[0], a, b, error);
  *error = "the operator '" + std::string(op) + "' has no constant value";
  return std::nullopt;
}

std::optional<ConstValue> fold_unary(std::string_view op, const ConstValue& a, std::string* error) {
  if (op == "not") return bool_value(!a.boolean);
  if (a.kind == Kind::Float) return float_value(-a.number);
  if (a.integer == INT64_MIN) return overflow(error);
  return int_value(-a.integer);
}

}  // namespace arbc::frontend
