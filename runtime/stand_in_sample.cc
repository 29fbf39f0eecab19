#include "runtime/stand_in_sample.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace arbc {

namespace {

double uniform(std::mt19937_64& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

// The parts compared with constants, or null.
const model::ComparedValues* compared(const SamplePlan& plan, const std::string& part) {
  auto it = plan.compared.find(part);
  return it == plan.compared.end() || it->second.numbers.empty() ? nullptr : &it->second;
}

// A range reaching past every finite constant of `cs` on both sides: [lo, hi].
std::pair<double, double> range_around(const std::vector<double>& cs) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (double c : cs) {
    if (std::isfinite(c)) lo = std::min(lo, c), hi = std::max(hi, c);
  }
  if (lo > hi) return {0, 1};  // only infinities: the edges reach them
  double margin = std::max({1.0, (hi - lo) / 2, std::max(std::fabs(lo), std::fabs(hi)) / 4});
  return {lo - margin, hi + margin};
}

// A float around the constants `cs` (sorted, not empty).
double float_around(const std::vector<double>& cs, std::mt19937_64& rng) {
  if (rng() % 2 == 0) {
    double c = cs[rng() % cs.size()];
    if (!std::isfinite(c)) return c;
    double step = std::max(1.0, std::fabs(c)) * 1e-3;
    return c + step * (static_cast<double>(rng() % 3) - 1);  // below, at or above c
  }
  auto [lo, hi] = range_around(cs);
  return uniform(rng, lo, hi);
}

// An int around the constants `cs`, within [least, most].
int64_t int_around(const std::vector<double>& cs, std::mt19937_64& rng, double least, double most) {
  double x = 0;
  if (rng() % 2 == 0) {
    x = cs[rng() % cs.size()] + (static_cast<double>(rng() % 3) - 1);  // below, at or above c
  } else {
    auto [lo, hi] = range_around(cs);
    x = std::floor(uniform(rng, lo, hi + 1));
  }
  // Doubles at 2^63 and beyond do not convert to int64: saturated well inside its range.
  return static_cast<int64_t>(std::clamp(x, least, most));
}

constexpr double kIntEdge = 9.2e18;  // below 2^63, a double an int64 holds

Value draw(const Type& t, std::mt19937_64& rng, const SamplePlan& plan, const std::string& part);

std::string field_part(const std::string& part, const std::string& field) {
  return part.empty() ? field : part + "." + field;
}

Value draw_list(const Type& t, std::mt19937_64& rng, const SamplePlan& plan,
                const std::string& part) {
  Value out = Value::list();
  if (part.empty() && !plan.flags.empty() && t.element->kind == Type::Kind::String && !t.fixed) {
    for (const std::string& f : plan.flags) {
      if (t.size > 0 && out.size() >= static_cast<size_t>(t.size)) break;  // list<string, N>
      if (rng() % 2 == 0) out.push_back(Value(f));  // each flag holds half of the time
    }
    return out;
  }
  const model::ComparedValues* lengths = compared(plan, "len(" + part + ")");
  int64_t n = lengths ? int_around(lengths->numbers, rng, 0, kMaxSampleListLength)
                      : 1 + static_cast<int64_t>(rng() % 3);
  if (t.fixed) n = t.size;                           // T[N]: always N
  if (t.size > 0) n = std::min<int64_t>(n, t.size);  // list<T, N>: at most N
  for (int64_t i = 0; i < n; ++i) out.push_back(draw(*t.element, rng, plan, part + "[]"));
  return out;
}

double draw_float(std::mt19937_64& rng, const SamplePlan& plan, const std::string& part, double lo,
                  double hi) {
  const model::ComparedValues* cs = compared(plan, part);
  return cs ? float_around(cs->numbers, rng) : uniform(rng, lo, hi);
}

Value draw_string(std::mt19937_64& rng, const SamplePlan& plan, const std::string& part) {
  auto it = plan.compared.find(part);
  if (it == plan.compared.end() || it->second.strings.empty()) return Value("sample");
  const std::vector<std::string>& strings = it->second.strings;
  size_t k = rng() % (strings.size() + 1);  // one of them, or one no condition names
  return Value(k < strings.size() ? strings[k] : std::string("sample"));
}

Value draw(const Type& t, std::mt19937_64& rng, const SamplePlan& plan, const std::string& part) {
  switch (t.kind) {
    case Type::Kind::Bool:
      return Value(rng() % 2 == 0);
    case Type::Kind::Int: {
      // Within the field's type: a stand-in for an int8 is an int8 (core/value.h conforms).
      const model::ComparedValues* cs = compared(plan, part);
      double least = t.bits < 64 ? static_cast<double>(t.min_int()) : -kIntEdge;
      double most = t.bits < 64 ? static_cast<double>(t.max_int()) : kIntEdge;
      if (t.is_unsigned) least = 0;
      return Value(cs ? int_around(cs->numbers, rng, least, most)
                      : static_cast<int64_t>(rng() % 10));
    }
    case Type::Kind::Float: {
      double x = draw_float(rng, plan, part, 0, 1);
      if (t.bits == 64 || !std::isfinite(x)) return Value(x);
      // A float32 field gets the float32 nearest the draw, kept inside its range (a cast from
      // beyond it is undefined).
      constexpr double kMax = std::numeric_limits<float>::max();
      return Value(static_cast<double>(static_cast<float>(std::clamp(x, -kMax, kMax))));
    }
    case Type::Kind::String: {
      Value s = draw_string(rng, plan, part);
      if (t.size > 0 && s.as_string().size() > static_cast<size_t>(t.size))
        return Value(s.as_string().substr(0, static_cast<size_t>(t.size)));  // string<N>
      return s;
    }
    case Type::Kind::Vec3: {
      double x = draw_float(rng, plan, field_part(part, "x"), -1, 1);
      double y = draw_float(rng, plan, field_part(part, "y"), -1, 1);
      return Value::vec3(x, y, draw_float(rng, plan, field_part(part, "z"), -1, 1));
    }
    case Type::Kind::List:
      return draw_list(t, rng, plan, part);
    case Type::Kind::Record: {
      Value out = Value::record();
      for (const Field& f : t.fields)
        out.set(f.name, draw(*f.type, rng, plan, field_part(part, f.name)));
      return out;
    }
  }
  return Value();
}

}  // namespace

SamplePlan sample_plan(const model::App& app, const std::string& port) {
  SamplePlan plan;
  for (const model::Event& e : app.events) {
    if (e.source == port && !e.flag.empty()) plan.flags.push_back(e.flag);
  }
  plan.compared = model::compared_parts(app, port);
  return plan;
}

Value sample_value(const Type& t, std::mt19937_64& rng, const SamplePlan& plan) {
  return draw(t, rng, plan, "");
}

}  // namespace arbc
