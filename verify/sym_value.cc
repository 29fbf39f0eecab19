#include "verify/sym_value.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace arbc::verify {

const SymValue* SymValue::field(const std::string& name) const {
  for (size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return &items[i];
  return nullptr;
}

SymValue fresh_value(z3::context& ctx, const Type& t, const std::string& prefix, int bound,
                     std::vector<z3::expr>& domain) {
  using K = SymValue::Kind;
  switch (t.kind) {
    case Type::Kind::Bool:
      return {K::Bool, ctx.bool_const(prefix.c_str())};
    case Type::Kind::Int:
      return {K::Int, ctx.int_const(prefix.c_str())};
    case Type::Kind::Float:
      return {K::Real, ctx.real_const(prefix.c_str())};
    case Type::Kind::String:
      return {K::String, ctx.constant(prefix.c_str(), ctx.string_sort())};
    case Type::Kind::Vec3: {
      SymValue v(K::Vec3, ctx.bool_val(true));
      for (const char* c : {"x", "y", "z"})
        v.items.push_back({K::Real, ctx.real_const((prefix + "." + c).c_str())});
      return v;
    }
    case Type::Kind::List: {
      z3::expr len = ctx.int_const((prefix + ".len").c_str());
      domain.push_back(len >= 0 && len <= bound);
      SymValue v(K::List, len);
      for (int i = 0; i < bound; ++i)
        v.items.push_back(
            fresh_value(ctx, *t.element, prefix + "[" + std::to_string(i) + "]", bound, domain));
      return v;
    }
    case Type::Kind::Record: {
      std::vector<Field> fields = t.fields;
      std::sort(fields.begin(), fields.end(),
                [](const Field& a, const Field& b) { return a.name < b.name; });
      SymValue v(K::Record, ctx.bool_val(true));
      for (const Field& f : fields) {
        v.names.push_back(f.name);
        v.items.push_back(fresh_value(ctx, *f.type, prefix + "." + f.name, bound, domain));
      }
      return v;
    }
  }
  return SymValue(ctx);
}

SymValue constant_value(z3::context& ctx, const Value& v, const Type& t, int bound) {
  using K = SymValue::Kind;
  switch (t.kind) {
    case Type::Kind::Bool:
      return {K::Bool, ctx.bool_val(v.as_bool())};
    case Type::Kind::Int:
      return {K::Int, ctx.int_val(v.as_int())};
    case Type::Kind::Float:
      return {K::Real, exact_real(ctx, v.as_float())};
    case Type::Kind::String:
      return {K::String, byte_string(ctx, v.as_string())};
    case Type::Kind::Vec3: {
      SymValue out(K::Vec3, ctx.bool_val(true));
      Eigen::Vector3d p = v.is_vec3() ? v.as_vec3() : Eigen::Vector3d::Zero();
      for (int k = 0; k < 3; ++k) out.items.push_back({K::Real, exact_real(ctx, p[k])});
      return out;
    }
    case Type::Kind::List: {
      const ValueList& items = v.as_list();
      SymValue out(K::List, ctx.int_val(static_cast<int>(items.size())));
      for (int i = 0; i < bound || i < static_cast<int>(items.size()); ++i)
        out.items.push_back(constant_value(
            ctx, i < static_cast<int>(items.size()) ? items[static_cast<size_t>(i)] : Value(),
            *t.element, bound));
      return out;
    }
    case Type::Kind::Record: {
      std::vector<Field> fields = t.fields;
      std::sort(fields.begin(), fields.end(),
                [](const Field& a, const Field& b) { return a.name < b.name; });
      SymValue out(K::Record, ctx.bool_val(true));
      for (const Field& f : fields) {
        out.names.push_back(f.name);
        out.items.push_back(constant_value(ctx, v[f.name], *f.type, bound));
      }
      return out;
    }
  }
  return SymValue(ctx);
}

SymValue fresh_like(z3::context& ctx, const SymValue& v, const std::string& prefix) {
  using K = SymValue::Kind;
  SymValue out = v;
  switch (v.kind) {
    case K::Bool:
      out.scalar = ctx.bool_const(prefix.c_str());
      break;
    case K::Int:
      out.scalar = ctx.int_const(prefix.c_str());
      break;
    case K::Real:
      out.scalar = ctx.real_const(prefix.c_str());
      break;
    case K::String:
      out.scalar = ctx.constant(prefix.c_str(), ctx.string_sort());
      break;
    case K::List:
      out.scalar = ctx.int_const((prefix + ".len").c_str());
      [[fallthrough]];
    case K::Vec3:
    case K::Record:
      for (size_t i = 0; i < v.items.size(); ++i)
        out.items[i] = fresh_like(ctx, v.items[i], prefix + "." + std::to_string(i));
      break;
  }
  return out;
}

namespace {

// 2^k in decimal (k <= 1100): the denominator of a double's exact value.
std::string pow2_text(int k) {
  std::string digits = "1";  // least significant first
  for (int i = 0; i < k; ++i) {
    int carry = 0;
    for (char& c : digits) {
      int v = (c - '0') * 2 + carry;
      c = static_cast<char>('0' + v % 10);
      carry = v / 10;
    }
    if (carry) digits += static_cast<char>('0' + carry);
  }
  return std::string(digits.rbegin(), digits.rend());
}

}  // namespace

z3::expr byte_string(z3::context& ctx, const std::string& s) {
  Z3_ast r = Z3_mk_lstring(ctx, static_cast<unsigned>(s.size()), s.data());
  ctx.check_error();
  return z3::expr(ctx, r);
}

z3::expr exact_real(z3::context& ctx, double d) {
  int exp = 0;
  double m = std::frexp(d, &exp);  // d = m * 2^exp, 0.5 <= |m| < 1
  auto mantissa = static_cast<int64_t>(std::ldexp(m, 53));
  exp -= 53;
  while (exp < 0 && mantissa % 2 == 0 && mantissa != 0) {
    mantissa /= 2;
    ++exp;
  }
  if (mantissa == 0) return ctx.real_val(0);
  std::string num = std::to_string(mantissa);
  if (exp >= 0) return ctx.real_val((num + "/1").c_str()) * ctx.real_val(pow2_text(exp).c_str());
  return ctx.real_val((num + "/" + pow2_text(-exp)).c_str());
}

z3::expr as_real(const SymValue& v) {
  return v.kind == SymValue::Kind::Int ? z3::to_real(v.scalar) : v.scalar;
}

namespace {

bool same_shape(const SymValue& a, const SymValue& b) {
  if (a.numeric() && b.numeric()) return true;
  if (a.kind != b.kind) return false;
  if (a.kind == SymValue::Kind::Record) return a.names == b.names;
  return true;
}

// The element of a list used to pad the other list to the same capacity (never read: padded
// elements sit at or past the length).
const SymValue* any_element(const SymValue& a, const SymValue& b) {
  if (!a.items.empty()) return &a.items.back();
  if (!b.items.empty()) return &b.items.back();
  return nullptr;
}

}  // namespace

std::optional<SymValue> merge(const z3::expr& c, const SymValue& a, const SymValue& b) {
  using K = SymValue::Kind;
  if (!same_shape(a, b)) return std::nullopt;
  if (a.numeric()) {
    if (a.kind == b.kind) return SymValue(a.kind, z3::ite(c, a.scalar, b.scalar));
    return SymValue(K::Real, z3::ite(c, as_real(a), as_real(b)));
  }
  SymValue out = a;
  out.scalar = z3::ite(c, a.scalar, b.scalar);
  if (a.kind == K::List) {
    const SymValue* pad = any_element(a, b);
    size_t cap = std::max(a.items.size(), b.items.size());
    out.items.clear();
    for (size_t i = 0; i < cap; ++i) {
      const SymValue& x = i < a.items.size() ? a.items[i] : *pad;
      const SymValue& y = i < b.items.size() ? b.items[i] : *pad;
      std::optional<SymValue> m = merge(c, x, y);
      if (!m) return std::nullopt;
      out.items.push_back(std::move(*m));
    }
    return out;
  }
  for (size_t i = 0; i < a.items.size(); ++i) {
    std::optional<SymValue> m = merge(c, a.items[i], b.items[i]);
    if (!m) return std::nullopt;
    out.items[i] = std::move(*m);
  }
  return out;
}

std::optional<z3::expr> sym_equal(const SymValue& a, const SymValue& b) {
  using K = SymValue::Kind;
  if (!same_shape(a, b)) return std::nullopt;
  if (a.numeric()) {
    if (a.kind == b.kind) return a.scalar == b.scalar;
    return as_real(a) == as_real(b);
  }
  if (a.kind == K::Bool || a.kind == K::String) return a.scalar == b.scalar;
  z3::context& ctx = a.scalar.ctx();
  z3::expr all = ctx.bool_val(true);
  if (a.kind == K::List) {
    all = a.scalar == b.scalar;
    size_t cap = std::min(a.items.size(), b.items.size());
    for (size_t i = 0; i < cap; ++i) {
      std::optional<z3::expr> e = sym_equal(a.items[i], b.items[i]);
      if (!e) return std::nullopt;
      all = all && z3::implies(a.scalar > static_cast<int>(i), *e);
    }
    // Past the smaller capacity the shorter list has no elements: equal lengths cannot reach.
    size_t small = cap;
    if (a.items.size() != b.items.size()) all = all && a.scalar <= static_cast<int>(small);
    return all;
  }
  for (size_t i = 0; i < a.items.size(); ++i) {
    std::optional<z3::expr> e = sym_equal(a.items[i], b.items[i]);
    if (!e) return std::nullopt;
    all = all && *e;
  }
  return all;
}

namespace {

double real_value(const z3::expr& e) {
  std::string s = e.get_decimal_string(17);
  if (!s.empty() && s.back() == '?') s.pop_back();
  return std::strtod(s.c_str(), nullptr);
}

}  // namespace

Value concrete(const z3::model& m, const SymValue& v) {
  using K = SymValue::Kind;
  switch (v.kind) {
    case K::Bool:
      return Value(m.eval(v.scalar, true).is_true());
    case K::Int: {
      int64_t i = 0;
      m.eval(v.scalar, true).is_numeral_i64(i);
      return Value(i);
    }
    case K::Real:
      return Value(real_value(m.eval(v.scalar, true)));
    case K::String: {
      // The bytes, not Z3_get_string's escaped text (a newline would come back as `\u{a}`).
      z3::expr s = m.eval(v.scalar, true);
      unsigned n = 0;
      const char* bytes = Z3_get_lstring(s.ctx(), s, &n);
      return Value(std::string(bytes, n));
    }
    case K::Vec3:
      return Value::vec3(real_value(m.eval(v.items[0].scalar, true)),
                         real_value(m.eval(v.items[1].scalar, true)),
                         real_value(m.eval(v.items[2].scalar, true)));
    case K::List: {
      int64_t len = 0;
      m.eval(v.scalar, true).is_numeral_i64(len);
      ValueList items;
      for (int64_t i = 0; i < len && i < static_cast<int64_t>(v.items.size()); ++i)
        items.push_back(concrete(m, v.items[static_cast<size_t>(i)]));
      return Value(std::move(items));
    }
    case K::Record: {
      ValueRecord fields;
      for (size_t i = 0; i < v.names.size(); ++i)
        fields.emplace(v.names[i], concrete(m, v.items[i]));
      return Value(std::move(fields));
    }
  }
  return Value();
}

}  // namespace arbc::verify
