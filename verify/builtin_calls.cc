// Calls of builtins in the body encoder (body_encoder.h): one case per builtin of the table
// (core/builtins.h), each computed as the prelude's Lua helper computes it.
#include <algorithm>
#include <cmath>

#include "verify/body_encoder.h"

namespace arbc::verify::body {

// Dispatch on the builtin's id (core/builtins.h): a builtin added to the table without a case
// here does not compile (-Wswitch), and verify's builtin_encoding_test encodes each one.
Ev Encoder::call(const BodyExpr& e) {
  const std::string& f = e.text;
  switch (e.builtin) {
    case Builtin::MinBy:
    case Builtin::MaxBy:
      return best_by(e, e.builtin == Builtin::MinBy);
    case Builtin::Now:  // PortMonitor.now(): the runtime's clock in seconds, not negative
      return {clock_value("now", "now()", false), ctx_.bool_val(true)};
    case Builtin::Min:
    case Builtin::Max:
      return min_max(e, e.builtin == Builtin::Min);
    case Builtin::None:
      return bad("the call " + f + "()");
    case Builtin::Len:
    case Builtin::Abs:
    case Builtin::Vec3:
    case Builtin::Norm:
    case Builtin::Dist:
    case Builtin::Age:
      break;  // of their evaluated arguments, below
  }
  std::vector<Ev> args;
  z3::expr ok = ctx_.bool_val(true);
  for (const BodyExpr& a : e.args) {
    args.push_back(eval(a));
    if (args.back().unread) return unread();
    ok = ok && args.back().ok;
  }
  if (e.builtin == Builtin::Len) {
    if (args.size() != 1 || args[0].v.kind != K::List)
      return bad("len of a string (byte length is not encoded)");
    return {{K::Int, args[0].v.scalar}, ok};
  }
  if (e.builtin == Builtin::Abs && args.size() == 1 && args[0].v.numeric())
    return {lua::abs(args[0].v), ok};
  if (e.builtin == Builtin::Age && args.size() == 1) return age(args[0]);
  if (e.builtin == Builtin::Vec3 && args.size() == 3) {
    SymValue v(K::Vec3, ctx_.bool_val(true));
    for (const Ev& a : args) v.items.push_back(a.v);
    return {v, ok};
  }
  bool dist = e.builtin == Builtin::Dist;
  if ((e.builtin == Builtin::Norm && args.size() == 1) || (dist && args.size() == 2)) {
    for (const Ev& a : args)
      if (a.v.kind != K::Vec3) return bad(f + " of a value that is not a vec3");
    return length(dist, args, ok);
  }
  return bad("the call " + f + "()");
}

// The clock is stamp_now(): not negative, finite, and unknown, so the verdict assumes nothing of
// it (abstracted; a counterexample that needs it is not replayed). One Z3 constant per clock
// name: the rules of one message read the same clock, hence the same age of the same stamp.
// The age is a function of the clock and the stamp, left uninterpreted but finite: the double
// arithmetic itself made a query with two overlapping age rules time out, and what a decision
// needs is only that equal clocks and stamps give equal ages (the monitor's Lua is
// deterministic), and that the age is a number.
Ev Encoder::age(const Ev& stamp) {
  const SymValue* sec = stamp.v.field("sec");
  const SymValue* nanosec = stamp.v.field("nanosec");
  if (stamp.v.kind != K::Record || !sec || !nanosec) return bad("age of a value that is no stamp");
  SymValue clock = clock_.empty() ? clock_value("stamp_now", "stamp_now()", false)
                                  : SymValue(K::Float, lua::float_const(ctx_, clock_));
  if (!clock_.empty()) {
    out_.side.push_back(lua::less_equal({K::Float, lua::float_val(ctx_, 0.0)}, clock) &&
                        lua::less(clock, {K::Float, lua::float_val(ctx_, HUGE_VAL)}));
    out_.abstracted.push_back("stamp_now()");
    out_.state.emplace_back("stamp_now()", clock);
  }
  z3::sort f = lua::float_sort(ctx_);
  z3::func_decl fn =
      ctx_.function("arbc_age", f, sec->scalar.get_sort(), nanosec->scalar.get_sort(), f);
  SymValue a(K::Float, fn(clock.scalar, sec->scalar, nanosec->scalar));
  out_.side.push_back(lua::less({K::Float, lua::float_val(ctx_, -HUGE_VAL)}, a) &&
                      lua::less(a, {K::Float, lua::float_val(ctx_, HUGE_VAL)}));
  return {a, stamp.ok};
}

SymValue Encoder::clock_value(const std::string& what, const std::string& text, bool signed_) {
  SymValue t(K::Float, lua::float_const(ctx_, fresh_name(what)));
  SymValue low{K::Float, lua::float_val(ctx_, signed_ ? -HUGE_VAL : 0.0)};
  out_.side.push_back((signed_ ? lua::less(low, t) : lua::less_equal(low, t)) &&
                      lua::less(t, {K::Float, lua::float_val(ctx_, HUGE_VAL)}));
  out_.abstracted.push_back(what + "()");
  out_.state.emplace_back(text, t);
  return t;
}

// norm(v) and dist(a, b) in the prelude's order: math.sqrt(x * x + y * y + z * z), the sum from
// the left, each operation rounded; dist first takes the differences a.x - b.x, ...
Ev Encoder::length(bool dist, const std::vector<Ev>& args, const z3::expr& ok) {
  std::vector<SymValue> d;
  for (size_t k = 0; k < 3; ++k) {
    d.push_back(args[0].v.items[k]);
    if (dist) d.back() = lua::arith('-', d.back(), args[1].v.items[k]);
  }
  SymValue exact = lua::norm(d[0], d[1], d[2]);
  bool floats =
      std::all_of(d.begin(), d.end(), [](const SymValue& c) { return c.kind == K::Float; });
  if (!abstract_lengths_ || !floats) return {exact, ok};
  z3::sort f = lua::float_sort(ctx_);
  z3::func_decl norm = ctx_.function("arbc_norm", f, f, f, f);
  z3::expr r = norm(d[0].scalar, d[1].scalar, d[2].scalar);
  out_.side.push_back(lua::norm_facts(r, d[0].scalar, d[1].scalar, d[2].scalar));
  out_.lengths.push_back({r, exact.scalar, {d[0].scalar, d[1].scalar, d[2].scalar}});
  return {{K::Float, r}, ok};
}

// min_by / max_by: arbc_best_by, the first element whose key is better than every earlier
// best key (`k < best` or `k > best` as Lua compares: a NaN key never wins, and a NaN first
// key is never beaten); none of an empty list.
Ev Encoder::best_by(const BodyExpr& e, bool min) {
  if (e.args.size() != 2 || e.args[1].op != BodyExpr::Op::Lambda)
    return bad(e.text + " without a lambda");
  Ev list = eval(e.args[0]);
  if (list.unread) return unread();
  if (list.v.kind != K::List || list.v.items.empty()) return bad(e.text + " of an empty literal");
  const BodyExpr& lambda = e.args[1];
  z3::expr ok = list.ok && list.v.scalar > 0;
  std::optional<SymValue> best, best_key;
  for (const auto& [item, in] : scanned(list.v)) {
    std::optional<SymValue> saved;
    if (auto it = params_.find(lambda.text); it != params_.end()) saved = it->second;
    params_.insert_or_assign(lambda.text, *item);
    Ev key = eval(lambda.args[0]);
    if (key.unread) return unread();
    if (saved)
      params_.insert_or_assign(lambda.text, *saved);
    else
      params_.erase(lambda.text);
    if (!key.v.numeric()) return bad(e.text + " with a key that is not a number");
    ok = ok && z3::implies(in, key.ok);
    if (!best) {
      best = *item;
      best_key = key.v;
      continue;
    }
    z3::expr better = in && (min ? lua::less(key.v, *best_key) : lua::less(*best_key, key.v));
    best = merge(better, *item, *best);
    if (!best) return bad("a list whose elements differ in shape");
    best_key = merge(better, key.v, *best_key);
  }
  return {*best, ok};
}

// The elements a read of every element visits, each with when it is one: the items, then
// the stand-ins past the capacity of an open list (SymValue::tail), one of the reads they
// allow (EncodedBody::tail_reads). An open list without them is read exactly only up to the
// capacity (EncodedBody::bounded).
std::vector<std::pair<const SymValue*, z3::expr>> Encoder::scanned(const SymValue& list) {
  std::vector<std::pair<const SymValue*, z3::expr>> out;
  for (size_t k = 0; k < list.items.size(); ++k)
    out.emplace_back(&list.items[k], list.scalar > static_cast<int>(k));
  if (list.scalar.simplify().is_numeral()) return out;  // a literal's length
  if (list.tail.empty() || exact_prefix(list) < list.items.size()) {
    out_.bounded = true;
    return out;
  }
  for (size_t j = 0; j < list.tail.size(); ++j)
    out.emplace_back(&list.tail[j], list.scalar > static_cast<int>(list.items.size() + j));
  ++out_.tail_reads;
  return out;
}

// min / max of numbers, or of one list (none of an empty list): math.min keeps the first
// argument and takes a later one only if it is less than the kept one (math.max: greater), so
// with NaNs the result depends on their order, as in Lua.
Ev Encoder::min_max(const BodyExpr& e, bool min) {
  std::vector<std::pair<SymValue, z3::expr>> xs;  // each with when it is one
  z3::expr ok = ctx_.bool_val(true);
  for (const BodyExpr& a : e.args) {
    Ev x = eval(a);
    if (x.unread) return unread();
    ok = ok && x.ok;
    if (x.v.kind == K::List && e.args.size() == 1) {
      ok = ok && x.v.scalar > 0;
      for (const auto& [item, in] : scanned(x.v)) xs.emplace_back(*item, in);
    } else {
      xs.emplace_back(x.v, ctx_.bool_val(true));
    }
  }
  if (xs.empty()) return bad(e.text + " of an empty literal");
  for (const auto& x : xs)
    if (!x.first.numeric()) return bad(e.text + " of values that are not numbers");
  SymValue best = xs[0].first;
  for (size_t k = 1; k < xs.size(); ++k) {
    const SymValue& x = xs[k].first;
    z3::expr better = xs[k].second && (min ? lua::less(x, best) : lua::less(best, x));
    best = *merge(better, x, best);  // numbers always merge
  }
  return {best, ok};
}

}  // namespace arbc::verify::body
