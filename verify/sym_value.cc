#include "verify/sym_value.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "verify/lua_number.h"

namespace arbc::verify {

const SymValue* SymValue::field(const std::string& name) const {
  for (size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return &items[i];
  return nullptr;
}

SymValue fresh_value(z3::context& ctx, const Type& t, const std::string& prefix, int bound,
                     std::vector<z3::expr>& domain, std::vector<z3::expr>& within_bound,
                     int tail_slots) {
  using K = SymValue::Kind;
  switch (t.kind) {
    case Type::Kind::Bool:
      return {K::Bool, ctx.bool_const(prefix.c_str())};
    case Type::Kind::Int:
      return {K::Int, lua::sized_int_const(ctx, prefix, t)};
    case Type::Kind::Float:
      return {K::Float, lua::sized_float_const(ctx, prefix, t)};
    case Type::Kind::String: {
      z3::expr s = ctx.constant(prefix.c_str(), ctx.string_sort());
      // string<N>: at most N bytes, one character each (byte_string), as the runtime checks.
      if (t.size > 0) domain.push_back(s.length() <= ctx.int_val(t.size));
      return {K::String, s};
    }
    case Type::Kind::Vec3: {
      SymValue v(K::Vec3, ctx.bool_val(true));
      for (const char* c : {"x", "y", "z"})
        v.items.push_back({K::Float, lua::float_const(ctx, prefix + "." + c)});
      return v;
    }
    case Type::Kind::List: {
      if (t.fixed) {
        // T[N]: every value has exactly N elements, each one encoded; no list bound applies.
        SymValue v(K::List, lua::int_val(ctx, t.size));
        for (int i = 0; i < t.size; ++i)
          v.items.push_back(fresh_value(ctx, *t.element, prefix + "[" + std::to_string(i) + "]",
                                        bound, domain, within_bound, tail_slots));
        return v;
      }
      z3::expr len = lua::int_const(ctx, prefix + ".len");
      if (t.size > 0) domain.push_back(len <= lua::int_val(ctx, t.size));  // list<T, N>
      domain.push_back(len >= 0);
      within_bound.push_back(len <= bound);
      SymValue v(K::List, len);
      for (int i = 0; i < bound; ++i)
        v.items.push_back(fresh_value(ctx, *t.element, prefix + "[" + std::to_string(i) + "]",
                                      bound, domain, within_bound, tail_slots));
      for (int j = 0; j < tail_slots && bound > 0; ++j)
        v.tail.push_back(fresh_value(ctx, *t.element, prefix + "[tail " + std::to_string(j) + "]",
                                     bound, domain, within_bound, tail_slots));
      return v;
    }
    case Type::Kind::Record: {
      std::vector<Field> fields = t.fields;
      std::sort(fields.begin(), fields.end(),
                [](const Field& a, const Field& b) { return a.name < b.name; });
      SymValue v(K::Record, ctx.bool_val(true));
      for (const Field& f : fields) {
        v.names.push_back(f.name);
        v.items.push_back(fresh_value(ctx, *f.type, prefix + "." + f.name, bound, domain,
                                      within_bound, tail_slots));
      }
      return v;
    }
  }
  return SymValue(ctx);
}

size_t exact_prefix(const SymValue& list) { return std::min(list.items.size(), list.exact_items); }

bool open_list(const SymValue& v) {
  if (v.kind == SymValue::Kind::List && !v.scalar.simplify().is_numeral()) return true;
  return std::any_of(v.items.begin(), v.items.end(),
                     [](const SymValue& i) { return open_list(i); });
}

SymValue constant_value(z3::context& ctx, const Value& v, const Type& t, int bound) {
  using K = SymValue::Kind;
  switch (t.kind) {
    case Type::Kind::Bool:
      return {K::Bool, ctx.bool_val(v.as_bool())};
    case Type::Kind::Int:
      return {K::Int, lua::int_val(ctx, v.as_int())};
    case Type::Kind::Float:
      return {K::Float, lua::float_val(ctx, v.as_float())};
    case Type::Kind::String:
      return {K::String, byte_string(ctx, v.as_string())};
    case Type::Kind::Vec3: {
      SymValue out(K::Vec3, ctx.bool_val(true));
      Eigen::Vector3d p = v.is_vec3() ? v.as_vec3() : Eigen::Vector3d::Zero();
      for (int k = 0; k < 3; ++k) out.items.push_back({K::Float, lua::float_val(ctx, p[k])});
      return out;
    }
    case Type::Kind::List: {
      const ValueList& items = v.as_list();
      SymValue out(K::List, lua::int_val(ctx, static_cast<int64_t>(items.size())));
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
      out.scalar = lua::int_const(ctx, prefix);
      break;
    case K::Float:
      out.scalar = lua::float_const(ctx, prefix);
      break;
    case K::String:
      out.scalar = ctx.constant(prefix.c_str(), ctx.string_sort());
      break;
    case K::List:
      out.scalar = lua::int_const(ctx, prefix + ".len");
      [[fallthrough]];
    case K::Vec3:
    case K::Record:
      for (size_t i = 0; i < v.items.size(); ++i)
        out.items[i] = fresh_like(ctx, v.items[i], prefix + "." + std::to_string(i));
      for (size_t j = 0; j < v.tail.size(); ++j)
        out.tail[j] = fresh_like(ctx, v.tail[j], prefix + ".tail" + std::to_string(j));
      break;
  }
  return out;
}

z3::expr byte_string(z3::context& ctx, const std::string& s) {
  Z3_ast r = Z3_mk_lstring(ctx, static_cast<unsigned>(s.size()), s.data());
  ctx.check_error();
  return z3::expr(ctx, r);
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

// Whether the list's length is a constant (a literal, or a list built from literals).
bool closed(const SymValue& list) { return list.scalar.simplify().is_numeral(); }

// `if c then a else b` for two lists: items padded to the larger capacity. Past the capacity
// of an open list its padding stands in for elements it does not encode, so the merged list
// is exact only up to that capacity (exact_items), and it keeps stand-ins past the capacity
// (SymValue::tail) only where both sides agree on where they start.
std::optional<SymValue> merge_lists(const z3::expr& c, const SymValue& a, const SymValue& b) {
  SymValue out = a;
  out.scalar = z3::ite(c, a.scalar, b.scalar);
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
  out.exact_items = std::min(exact_prefix(a), exact_prefix(b));
  for (const SymValue* side : {&a, &b})
    if (!closed(*side) && side->items.size() < cap)
      out.exact_items = std::min(out.exact_items, side->items.size());
  // A closed list never reaches its tail; an open one without the other's slots loses them.
  size_t slots = std::max(a.tail.size(), b.tail.size());
  bool aligned = a.items.size() == b.items.size() && out.exact_items >= cap;
  for (const SymValue* side : {&a, &b})
    if (side->tail.size() < slots && !closed(*side)) aligned = false;
  out.tail.clear();
  for (size_t j = 0; aligned && j < slots; ++j) {
    const SymValue& x = j < a.tail.size() ? a.tail[j] : *pad;
    const SymValue& y = j < b.tail.size() ? b.tail[j] : *pad;
    std::optional<SymValue> m = merge(c, x, y);
    if (!m) return std::nullopt;
    out.tail.push_back(std::move(*m));
  }
  return out;
}

}  // namespace

std::optional<SymValue> merge(const z3::expr& c, const SymValue& a, const SymValue& b) {
  using K = SymValue::Kind;
  if (!same_shape(a, b)) return std::nullopt;
  if (a.numeric()) {
    if (a.kind == b.kind) return SymValue(a.kind, z3::ite(c, a.scalar, b.scalar));
    // An int and a float: the float kind, the int converted. Lua keeps the int's subtype;
    // explicit conversions in model::Body (issue 38, item 1) make both agree.
    return SymValue(K::Float, z3::ite(c, lua::to_float(a), lua::to_float(b)));
  }
  SymValue out = a;
  out.scalar = z3::ite(c, a.scalar, b.scalar);
  if (a.kind == K::List) return merge_lists(c, a, b);
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
  if (a.numeric()) return lua::equal(a, b);  // Lua's ==: NaN ~= NaN, 0.0 == -0.0
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

// A number of a model as a double: an int converted as Lua's tonumber does (C's cast).
double number_value(const z3::model& m, const SymValue& v) {
  z3::expr x = m.eval(v.scalar, true);
  if (v.kind == SymValue::Kind::Int) return static_cast<double>(lua::int_of(x));
  return lua::float_of(x);
}

}  // namespace

Value concrete(const z3::model& m, const SymValue& v) {
  using K = SymValue::Kind;
  switch (v.kind) {
    case K::Bool:
      return Value(m.eval(v.scalar, true).is_true());
    case K::Int:
      return Value(lua::int_of(m.eval(v.scalar, true)));
    case K::Float:
      return Value(lua::float_of(m.eval(v.scalar, true)));
    case K::String: {
      // The bytes, not Z3_get_string's escaped text (a newline would come back as `\u{a}`).
      z3::expr s = m.eval(v.scalar, true);
      unsigned n = 0;
      const char* bytes = Z3_get_lstring(s.ctx(), s, &n);
      return Value(std::string(bytes, n));
    }
    case K::Vec3:
      return Value::vec3(number_value(m, v.items[0]), number_value(m, v.items[1]),
                         number_value(m, v.items[2]));
    case K::List: {
      int64_t len = lua::int_of(m.eval(v.scalar, true));
      ValueList items;
      for (int64_t i = 0; i < len && i < static_cast<int64_t>(v.items.size()); ++i)
        items.push_back(concrete(m, v.items[static_cast<size_t>(i)]));
      // Past the capacity: the stand-ins in range, then the last element repeated (what the
      // encoding of SymValue::tail means; without stand-ins nothing exact reads them). A
      // witness longer than kMaxWitnessElements is not built (no message carries it).
      for (size_t j = 0; j < v.tail.size() && static_cast<int64_t>(v.items.size() + j) < len; ++j)
        items.push_back(concrete(m, v.tail[j]));
      Value pad = v.items.empty() ? Value()
                  : items.empty() ? concrete(m, v.items.back())
                                  : items.back();
      for (int64_t i = static_cast<int64_t>(items.size()); i < len && i < kMaxWitnessElements; ++i)
        items.push_back(pad);
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
