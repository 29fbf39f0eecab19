#include "compiler/frontend/value_fit.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

#include "compiler/frontend/literal_value.h"
#include "compiler/frontend/type_rules.h"

namespace arbc::frontend {

namespace {

using ast::Expr;

bool is_number(const TypePtr& t) {
  return t && (t->kind == Type::Kind::Int || t->kind == Type::Kind::Float);
}

// The nearest float32 to v, in the fewest digits that read back as exactly that value: a
// literal is read as a double, so nine digits ("0.100000001", enough for strtof) are not enough
// for the check above, which would refuse what this note suggests ("0.10000000149011612").
std::string nearest_float32(double v) {
  const double f = static_cast<float>(v);
  char text[40];
  for (int digits = 9; digits <= 17; ++digits) {
    std::snprintf(text, sizeof text, "%.*g", digits, f);
    if (std::strtod(text, nullptr) == f) break;
  }
  return text;
}

std::optional<RangeMiss> number_miss(const Expr& value, const Type& want) {
  std::optional<Value> v = constant_number(value);
  if (!v || !want.narrow()) return std::nullopt;
  // A uint64 constant holds bits (a literal above 2^63 - 1 reads negative): any is a uint64.
  if (is_uint64(want) && value.type && is_uint64(*value.type)) return std::nullopt;
  std::string written = v->to_json();
  if (want.kind == Type::Kind::Int && v->is_int() && !want.holds(v->as_int()))
    return RangeMiss{
        &value, written + " does not fit in " + want.to_string() + " (" + want.range_text() + ")"};
  if (want.kind == Type::Kind::Float && !want.holds(v->as_float())) {
    double d = v->as_float();
    if (std::fabs(d) > std::numeric_limits<float>::max())
      return RangeMiss{&value, written + " is beyond the range of float32 (about 3.4e38)"};
    return RangeMiss{&value, written + " is not a float32 value: it would round to " +
                                 nearest_float32(d) + "; write that, or declare the field float64"};
  }
  return std::nullopt;
}

// The length in bytes of a constant string (a literal, a named constant); nullopt for any other.
std::optional<size_t> string_constant_size(const Expr& value) {
  if (!is_kind(value.type, Type::Kind::String)) return std::nullopt;
  std::string err;
  std::optional<Value> s = literal_value(value, *value.type, &err);
  if (!s || !s->is_string()) return std::nullopt;
  return s->as_string().size();
}

// A literal of n elements (a list) or bytes (a string) where `want` is expected.
bool literal_size_fits(size_t n, const Type& want) {
  if (want.size == 0) return true;
  return want.fixed ? n == static_cast<size_t>(want.size) : n <= static_cast<size_t>(want.size);
}

}  // namespace

std::optional<Value> constant_number(const Expr& e) {
  if (!is_number(e.type)) return std::nullopt;
  std::string err;
  std::optional<Value> v = literal_value(e, *e.type, &err);
  if (!v || !v->is_number()) return std::nullopt;
  return v;
}

bool value_fits(const Expr& value, const TypePtr& want) {
  if (!value.type || !want) return true;  // reported where the type was lost
  if (is_number(want) && is_number(value.type) && constant_number(value))
    return value.type->kind == Type::Kind::Int || want->kind == Type::Kind::Float;
  if (value.kind == Expr::Kind::Record && want->kind == Type::Kind::Record) {
    if (value.args.size() != want->fields.size()) return false;
    for (size_t i = 0; i < value.args.size() && i < value.names.size(); ++i) {
      const Field* f = want->field(value.names[i].name);
      if (!f || !value_fits(*value.args[i], f->type)) return false;
    }
    return true;
  }
  if (value.kind == Expr::Kind::List && want->kind == Type::Kind::List) {
    if (!literal_size_fits(value.args.size(), *want)) return false;
    for (const ast::ExprPtr& item : value.args)
      if (!value_fits(*item, want->element)) return false;
    return true;
  }
  if (want->kind == Type::Kind::String && want->size > 0)
    if (std::optional<size_t> n = string_constant_size(value)) return literal_size_fits(*n, *want);
  return assignable(*value.type, *want);
}

std::optional<std::string> size_miss(const Expr& value, const TypePtr& want) {
  if (!value.type || !want ||
      !(is_kind(want, Type::Kind::List) || is_kind(want, Type::Kind::String)))
    return std::nullopt;
  if (want->size == 0 || value.type->kind != want->kind) return std::nullopt;
  size_t n = 0;
  if (value.kind == Expr::Kind::List) {
    n = value.args.size();
  } else if (std::optional<size_t> bytes = string_constant_size(value)) {
    n = *bytes;
  } else {
    if (size_fits(*value.type, *want)) return std::nullopt;
    return "a " + type_name(value.type) + " may not fit in " + type_name(want) +
           (want->fixed ? ", which has exactly " : ", which holds at most ") +
           std::to_string(want->size) + (want->kind == Type::Kind::String ? " bytes" : " elements");
  }
  if (literal_size_fits(n, *want)) return std::nullopt;
  std::string unit = want->kind == Type::Kind::String ? " bytes" : " elements";
  return "this has " + std::to_string(n) + unit + "; " + type_name(want) +
         (want->fixed ? " has exactly " : " holds at most ") + std::to_string(want->size) + unit;
}

std::optional<RangeMiss> range_miss(const Expr& value, const TypePtr& want) {
  if (!value.type || !want) return std::nullopt;
  if (is_number(want)) return number_miss(value, *want);
  if (value.kind == Expr::Kind::Record && want->kind == Type::Kind::Record) {
    for (size_t i = 0; i < value.args.size() && i < value.names.size(); ++i)
      if (const Field* f = want->field(value.names[i].name))
        if (auto miss = range_miss(*value.args[i], f->type)) return miss;
  }
  if (value.kind == Expr::Kind::List && want->kind == Type::Kind::List)
    for (const ast::ExprPtr& item : value.args)
      if (auto miss = range_miss(*item, want->element)) return miss;
  return std::nullopt;
}

}  // namespace arbc::frontend
