// Sema's rules for the sized number types (docs/language.md#numbers).
//
// A uint64 is held as its bit pattern in a 64-bit signed integer (core/type.h), so the monitor's
// Lua computes it exactly only with + - * (the same bits wrap the same way), == and ~=, and the
// orderings through math.ult; and only against a partner whose int64 value is its uint64 value:
// another uint64, an unsigned narrower integer, or a constant >= 0. Everything else is refused
// where it is written, rather than computed into a wrong answer.
#include <charconv>

#include "compiler/frontend/sema_context.h"
#include "compiler/frontend/type_rules.h"
#include "compiler/frontend/value_fit.h"

namespace arbc::frontend {

using namespace ast;

namespace {

bool uint64_typed(const Expr& e) { return e.type && is_uint64(*e.type); }

// A partner of a uint64 whose int64 value is its value as an unsigned number.
bool unsigned_partner(const Expr& e) {
  if (!e.type || e.type->kind != Type::Kind::Int) return false;
  if (e.type->is_unsigned) return true;
  std::optional<Value> v = constant_number(e);
  return v && v->is_int() && v->as_int() >= 0;
}

}  // namespace

bool Sema::uint64_literal(Expr& e) {
  uint64_t u = 0;
  const std::string& digits = e.text;  // the builder keeps the digits of a literal this large
  auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), u);
  if (digits.empty() || ec != std::errc() || end != digits.data() + digits.size()) return false;
  e.integer = static_cast<int64_t>(u);
  e.type = Type::number("uint64");
  return true;
}

bool Sema::check_uint64_binary(Expr& e) {
  const Expr& a = *e.args[0];
  const Expr& b = *e.args[1];
  if (!uint64_typed(a) && !uint64_typed(b)) return true;
  std::string_view op = e.op;
  if (op == "and" || op == "or") return true;  // the type check says what is wrong
  if (op == "/" || op == "%") {
    error(e.loc,
          "'" + std::string(op) +
              "' on a uint64: arbc computes in 64-bit signed integers, which cannot divide a "
              "uint64 above 2^63 - 1; compare it instead, or declare the field int64 if its "
              "values stay below 2^63",
          diag::Uint64);
    return false;
  }
  const Expr& other = uint64_typed(a) ? b : a;
  if (unsigned_partner(other)) return true;
  std::optional<Value> k = constant_number(other);
  std::string why =
      k && k->is_int() ? "the negative constant " + k->to_json() + ": a uint64 is never negative"
      : other.type->kind == Type::Kind::Float
          ? describe(other.type) +
                ": a uint64 above 2^53 has no exact float; compare with a uint64, an "
                "unsigned integer or a constant >= 0 (a literal above 2^63 - 1 is a "
                "uint64: write it with a decimal point for a float)"
          : describe(other.type) +
                ": C++ would convert it to uint64 (a negative value becomes a huge one); "
                "compare with a uint64, an unsigned integer or a constant >= 0";
  error(e.loc, "operator '" + std::string(op) + "' combines a uint64 with " + why, diag::Uint64);
  return false;
}

bool Sema::check_uint64_operand(const Expr& operand, const std::string& what) {
  if (!uint64_typed(operand)) return true;
  error(operand.loc,
        what +
            " of a uint64: arbc computes in 64-bit signed integers, in which a uint64 above "
            "2^63 - 1 is negative; compare it with a uint64 or a constant >= 0 instead",
        diag::Uint64);
  return false;
}

bool Sema::check_uint64_list_item(const Expr& item, const TypePtr& element) {
  // A uint64 item beside a signed one would read the signed -1 as 2^64 - 1.
  if (!(is_uint64(*element) || is_uint64(*item.type)) ||
      (element->is_unsigned && item.type->is_unsigned))
    return true;
  error(item.loc,
        "list items must have one type: a uint64 cannot share a list with " +
            describe(is_uint64(*element) ? item.type : element) +
            " (a negative value would read as a huge uint64)",
        diag::Uint64);
  return false;
}

bool Sema::check_value_fits(const Expr& value, const TypePtr& want, const std::string& message,
                            DiagId id) {
  if (!value_fits(value, want)) {
    value_type_error(value, want, message, id);
    return false;
  }
  if (std::optional<RangeMiss> miss = range_miss(value, want)) {
    error(miss->at->loc, miss->message, diag::NumberRange);
    return false;
  }
  return true;
}

}  // namespace arbc::frontend
